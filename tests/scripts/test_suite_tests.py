#!/usr/bin/python3
"""tests/cmake/suite_tests.cmake on stand-in GoogleTest executables: the ctest tests it registers,
read back through ctest itself (--show-only=json-v1)."""

import json
import os
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

SCRIPT = sys.argv.pop(1) if len(sys.argv) > 1 else "tests/cmake/suite_tests.cmake"

# gtest_main's greeting, a plain suite, a typed suite, a parameterised suite with a slow test and
# a suite larger than a group, as --gtest_list_tests prints them.
LISTING = """Running main() from ./googletest/src/gtest_main.cc
Plain.
  First
  Second
Typed/hexahedron.  # TypeParam = getme::test::TypeTag<(getme::ElementType)1>
  IsValid
Meshes/RoundTrip.
  Reads/vtk  # GetParam() = "a.vtk"
  TakesMinutes/vtk  # GetParam() = "a.vtk"
  Writes/vtk  # GetParam() = "a.vtk"
Large.
""" + "".join(f"  Case{index}\n" for index in range(5))


def fake_executable(directory: Path, listing: str, exit_code: int = 0) -> Path:
    executable = directory / "fake_tests"
    listing_file = directory / "listing.txt"
    listing_file.write_text(listing)
    executable.write_text(f"#!/bin/sh\ncat '{listing_file}'\nexit {exit_code}\n")
    executable.chmod(0o755)
    return executable


def generate(directory: Path, executable: Path, slow_regex: str, group_size: int):
    ctest_file = directory / "fake_suites.cmake"
    done = subprocess.run(
        ["cmake", "-DTEST_TARGET=fake", f"-DTEST_EXECUTABLE={executable}",
         f"-DTEST_WORKING_DIR={directory}", f"-DSLOW_REGEX={slow_regex}",
         f"-DGROUP_SIZE={group_size}", f"-DCTEST_FILE={ctest_file}", "-P", SCRIPT],
        capture_output=True, text=True)
    return done, ctest_file


def registered(directory: Path, ctest_file: Path) -> dict[str, list[str]]:
    """Test name -> its command, as ctest reads them, plus the NAME_TESTS list under '_list'."""
    (directory / "CTestTestfile.cmake").write_text(
        f'include("{ctest_file}")\n'
        'add_test(listed_names echo ${fake_TESTS})\n')
    shown = subprocess.run(["ctest", "--test-dir", str(directory), "--show-only=json-v1"],
                           capture_output=True, text=True, check=True)
    tests = {test["name"]: test["command"] for test in json.loads(shown.stdout)["tests"]}
    tests["_list"] = tests.pop("listed_names")[1:]
    return tests


class SuiteTests(unittest.TestCase):
    def setUp(self):
        self.temporary = tempfile.TemporaryDirectory()
        self.directory = Path(self.temporary.name)

    def tearDown(self):
        self.temporary.cleanup()

    def test_suites_groups_and_slow_tests(self):
        executable = fake_executable(self.directory, LISTING)
        done, ctest_file = generate(self.directory, executable, r"RoundTrip\.TakesMinutes", 2)
        self.assertEqual(done.returncode, 0, done.stderr)
        tests = registered(self.directory, ctest_file)
        filters = {name: command[1] for name, command in tests.items() if name != "_list"}
        self.assertEqual(filters, {
            # Whole suites of at most a group run by wildcard.
            "Plain.*": "--gtest_filter=Plain.*",
            "Typed/hexahedron.*": "--gtest_filter=Typed/hexahedron.*",
            # A slow test is left out of its suite's group and registered alone.
            "Meshes/RoundTrip.*": "--gtest_filter=Meshes/RoundTrip.Reads/vtk:"
                                  "Meshes/RoundTrip.Writes/vtk",
            "Meshes/RoundTrip.TakesMinutes/vtk":
                "--gtest_filter=Meshes/RoundTrip.TakesMinutes/vtk",
            # Five tests in groups of two.
            "Large.*(1/3)": "--gtest_filter=Large.Case0:Large.Case1",
            "Large.*(2/3)": "--gtest_filter=Large.Case2:Large.Case3",
            "Large.*(3/3)": "--gtest_filter=Large.Case4",
        })
        for name, command in tests.items():
            if name != "_list":
                self.assertEqual(command[0], str(executable), name)
        # The list the label scripts walk names every registered test, once.
        self.assertEqual(sorted(tests["_list"]), sorted(filters))

    def test_no_slow_pattern_keeps_every_test_in_its_group(self):
        executable = fake_executable(self.directory, LISTING)
        done, ctest_file = generate(self.directory, executable, "", 12)
        self.assertEqual(done.returncode, 0, done.stderr)
        tests = registered(self.directory, ctest_file)
        self.assertEqual(tests["Meshes/RoundTrip.*"][1], "--gtest_filter=Meshes/RoundTrip.*")
        self.assertEqual(tests["Large.*"][1], "--gtest_filter=Large.*")
        self.assertEqual(len(tests), 5)  # four suites and the list

    def test_failing_listing_fails_the_build_step_and_writes_nothing(self):
        executable = fake_executable(self.directory, "Plain.\n  First\n", exit_code=3)
        done, ctest_file = generate(self.directory, executable, "", 12)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("exited with '3'", done.stderr)
        self.assertFalse(ctest_file.exists())

    def test_empty_listing_is_refused(self):
        executable = fake_executable(self.directory, "Running main() from gtest_main.cc\n")
        done, ctest_file = generate(self.directory, executable, "", 12)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("listed no test", done.stderr)
        self.assertFalse(ctest_file.exists())


if __name__ == "__main__":
    os.environ.setdefault("LC_ALL", "C")
    unittest.main()
