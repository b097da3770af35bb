"""Fetches the npm client the browser tests run `npm ci` with, from the npm registry.

    /usr/bin/python3 fetch_npm.py DESTINATION

Debian's `npm` package is npm split into 349 packages (node-*): in a fresh bookworm root their
install took 67 s of CPU, more than half of what the test-only packages cost
(docs/development.md, CI). The registry's npm tarball bundles those same dependencies in one
2.7 MB file. This script downloads the version pinned below, checks it against the pinned
SHA-512 (the `integrity` the registry publishes for it, as package-lock.json pins
playwright-core's), and unpacks it to DESTINATION, so that `node DESTINATION/bin/npm-cli.js ci`
is npm. A DESTINATION holding that version already is kept. Exits 1, naming the cause, when
the download fails or the bytes do not match.
"""

import base64
import hashlib
import io
import json
import pathlib
import shutil
import sys
import tarfile
import urllib.request

# npm 10 runs on node ^18.17 || >=20.5: Debian bookworm's nodejs is 18.20.
NPM_VERSION = "10.9.4"
NPM_TARBALL = f"https://registry.npmjs.org/npm/-/npm-{NPM_VERSION}.tgz"
NPM_INTEGRITY = (
    "sha512-OnUG836FwboQIbqtefDNlyR0gTHzIfwRfE3DuiNewBvnMnWEpB0VEXwBlFVgqpNzIgYo/MHh3d2Hel/pszapAA=="
)


def installed_version(destination: pathlib.Path) -> str | None:
    try:
        return json.loads((destination / "package.json").read_text())["version"]
    except (OSError, ValueError, KeyError):
        return None


def download(url: str) -> bytes:
    try:
        with urllib.request.urlopen(url, timeout=120) as response:
            return response.read()
    except OSError as error:
        sys.exit(f"fetch_npm: cannot download {url}: {error}")


def integrity_of(data: bytes) -> str:
    return "sha512-" + base64.b64encode(hashlib.sha512(data).digest()).decode()


def unpack(data: bytes, destination: pathlib.Path) -> None:
    # The registry's tarballs hold everything under package/; nothing may land outside it, and
    # a refused tarball writes nothing.
    with tarfile.open(fileobj=io.BytesIO(data), mode="r:gz") as archive:
        members = [(member, pathlib.PurePosixPath(member.name).parts) for member in archive]
        for member, parts in members:
            if not parts or parts[0] != "package" or ".." in parts:
                sys.exit(f"fetch_npm: unexpected path in {NPM_TARBALL}: {member.name}")
        staging = destination.with_name(destination.name + ".partial")
        shutil.rmtree(staging, ignore_errors=True)
        for member, parts in members:
            if len(parts) > 1 and (member.isfile() or member.isdir()):
                member.name = str(pathlib.PurePosixPath(*parts[1:]))
                archive.extract(member, staging)
    shutil.rmtree(destination, ignore_errors=True)
    staging.rename(destination)


def main() -> None:
    if len(sys.argv) != 2:
        sys.exit("usage: fetch_npm.py DESTINATION")
    destination = pathlib.Path(sys.argv[1])
    if installed_version(destination) == NPM_VERSION:
        print(f"fetch_npm: npm {NPM_VERSION} already in {destination}")
        return
    data = download(NPM_TARBALL)
    found = integrity_of(data)
    if found != NPM_INTEGRITY:
        sys.exit(f"fetch_npm: {NPM_TARBALL} has integrity {found}, expected {NPM_INTEGRITY}")
    unpack(data, destination)
    if installed_version(destination) != NPM_VERSION:
        sys.exit(f"fetch_npm: {destination}/package.json does not name npm {NPM_VERSION}")
    print(f"fetch_npm: npm {NPM_VERSION} ({len(data)} bytes, {NPM_INTEGRITY[:19]}...) in {destination}")


if __name__ == "__main__":
    main()
