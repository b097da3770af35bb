"""Tests of fetch_npm.py without the network: the download is replaced by tarballs built here.

    /usr/bin/python3 test_fetch_npm.py PATH/TO/fetch_npm.py
"""

import importlib.util
import io
import json
import pathlib
import sys
import tarfile
import tempfile
import unittest
import urllib.error
from unittest import mock

fetch_npm = None  # the module under test, loaded in __main__ from the path given


def tarball(files: dict[str, bytes]) -> bytes:
    buffer = io.BytesIO()
    with tarfile.open(fileobj=buffer, mode="w:gz") as archive:
        for name, content in files.items():
            member = tarfile.TarInfo(name)
            member.size = len(content)
            archive.addfile(member, io.BytesIO(content))
    return buffer.getvalue()


def npm_like(version: str) -> bytes:
    return tarball({
        "package/package.json": json.dumps({"name": "npm", "version": version}).encode(),
        "package/bin/npm-cli.js": b"// npm\n",
        "package/node_modules/dep/index.js": b"// a bundled dependency\n",
    })


class FetchNpmTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()
        self.root = pathlib.Path(self.directory.name)
        self.destination = self.root / "npm-client"

    def tearDown(self):
        self.directory.cleanup()

    def run_main(self, data: bytes, integrity: str, version: str | None = None):
        with mock.patch.object(fetch_npm, "download", return_value=data) as download, \
                mock.patch.object(fetch_npm, "NPM_INTEGRITY", integrity), \
                mock.patch.object(fetch_npm, "NPM_VERSION", version or fetch_npm.NPM_VERSION), \
                mock.patch.object(sys, "argv", ["fetch_npm.py", str(self.destination)]):
            fetch_npm.main()
        return download

    def test_matching_bytes_unpack_without_the_package_folder(self):
        data = npm_like(fetch_npm.NPM_VERSION)
        self.run_main(data, fetch_npm.integrity_of(data))
        self.assertEqual(json.loads((self.destination / "package.json").read_text())["version"],
                         fetch_npm.NPM_VERSION)
        self.assertEqual((self.destination / "bin/npm-cli.js").read_bytes(), b"// npm\n")
        self.assertTrue((self.destination / "node_modules/dep/index.js").is_file())
        self.assertFalse((self.root / "npm-client.partial").exists())

    def test_the_pinned_version_in_place_is_kept_without_a_download(self):
        data = npm_like(fetch_npm.NPM_VERSION)
        self.run_main(data, fetch_npm.integrity_of(data))
        download = self.run_main(b"never read", "sha512-never-compared")
        download.assert_not_called()

    def test_another_version_in_place_is_replaced(self):
        old = npm_like("9.2.0")
        self.run_main(old, fetch_npm.integrity_of(old), version="9.2.0")
        (self.destination / "stale.js").write_text("left from 9.2.0")
        new = npm_like(fetch_npm.NPM_VERSION)
        self.run_main(new, fetch_npm.integrity_of(new))
        self.assertFalse((self.destination / "stale.js").exists())

    def test_a_tarball_of_another_version_is_refused(self):
        data = npm_like("9.2.0")
        with self.assertRaises(SystemExit) as refused:
            self.run_main(data, fetch_npm.integrity_of(data))
        self.assertIn(f"package.json does not name npm {fetch_npm.NPM_VERSION}",
                      str(refused.exception.code))

    def test_bytes_that_do_not_match_the_pin_are_refused_and_nothing_is_written(self):
        data = npm_like(fetch_npm.NPM_VERSION)
        pinned = fetch_npm.integrity_of(data + b"x")
        with self.assertRaises(SystemExit) as refused:
            self.run_main(data, pinned)
        self.assertIn(f"has integrity {fetch_npm.integrity_of(data)}, expected {pinned}",
                      str(refused.exception.code))
        self.assertFalse(self.destination.exists())

    def test_an_entry_outside_the_package_folder_is_refused(self):
        for name in ("../escaped.js", "elsewhere/file.js", "package/../../escaped.js"):
            with self.subTest(name=name):
                data = tarball({"package/package.json": b"{}", name: b"x"})
                with self.assertRaises(SystemExit) as refused:
                    self.run_main(data, fetch_npm.integrity_of(data))
                self.assertIn(f"unexpected path in {fetch_npm.NPM_TARBALL}: {name}",
                              str(refused.exception.code))
                self.assertFalse((self.root / "escaped.js").exists())
                self.assertFalse(self.destination.exists())

    def test_a_failed_download_names_the_address(self):
        with mock.patch.object(fetch_npm.urllib.request, "urlopen",
                               side_effect=urllib.error.URLError("no route to host")):
            with self.assertRaises(SystemExit) as refused:
                fetch_npm.download(fetch_npm.NPM_TARBALL)
        self.assertIn(f"cannot download {fetch_npm.NPM_TARBALL}", str(refused.exception.code))
        self.assertIn("no route to host", str(refused.exception.code))

    def test_the_integrity_is_npms_base64_sha512(self):
        # The SHA-512 of "abc" (FIPS 180-2, appendix C), in npm's `sha512-<base64>` form.
        self.assertEqual(
            fetch_npm.integrity_of(b"abc"),
            "sha512-3a81oZNherrMQXNJriBBMRLm+k6JqX6iCp7u5ktV05ohkpkqJ0/BqDa6PCOj/uu9RU1EI2Q86A4qmslPpUyknw==")


if __name__ == "__main__":
    spec = importlib.util.spec_from_file_location("fetch_npm", sys.argv.pop(1))
    fetch_npm = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(fetch_npm)
    unittest.main()
