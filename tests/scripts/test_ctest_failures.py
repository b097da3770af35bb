#!/usr/bin/python3
"""scripts/ctest_failures.py on JUnit files shaped as ctest 3.25 writes them (--output-junit)."""

import subprocess
import sys
import tempfile
import unittest
from pathlib import Path
from xml.sax.saxutils import escape

SCRIPT = sys.argv.pop(1) if len(sys.argv) > 1 else "scripts/ctest_failures.py"


def junit(cases: list[tuple[str, str, str]]) -> str:
    """cases: (name, status 'run' or 'fail', output) as ctest records them."""
    body = []
    for name, status, output in cases:
        failure = '\t\t<failure message=""/>\n' if status == "fail" else ""
        body.append(f'\t<testcase name="{name}" classname="{name}" time="1.25" status="{status}">\n'
                    f"{failure}\t\t<system-out>{escape(output)}</system-out>\n\t</testcase>\n")
    return ('<?xml version="1.0" encoding="UTF-8"?>\n<testsuite name="(empty)"\n\ttests="2"\n>\n'
            + "".join(body) + "</testsuite>\n")


def run(xml: str, *arguments: str) -> list[str]:
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / "ctest-junit.xml"
        path.write_text(xml)
        done = subprocess.run(["/usr/bin/python3", SCRIPT, str(path), *arguments],
                              capture_output=True, text=True, check=True)
    return done.stdout.splitlines()


class CtestFailuresTest(unittest.TestCase):
    def test_names_only_failed_tests_with_the_gtest_failure_and_the_lines_after_it(self):
        gtest = "\n".join(["Running main()", "[ RUN      ] A.B", "log line",
                           "/src/a_test.cc:12: Failure", "Expected equality of these values:",
                           "  x", "    Which is: 1 < 2 & 3"] + [f"more {i}" for i in range(10)])
        lines = run(junit([("Ok.Test", "run", "fine"), ("A.B", "fail", gtest)]))
        self.assertEqual(lines[0], "--- A.B (1.2 s)")
        self.assertEqual(lines[1], "    /src/a_test.cc:12: Failure")
        self.assertIn("        Which is: 1 < 2 & 3", lines)
        self.assertEqual(len(lines), 1 + 8)  # the marker and the 7 lines after it
        self.assertNotIn("Ok.Test", "\n".join(lines))

    def test_sanitizer_report_and_traceback_are_found(self):
        asan = "noise\n==123==ERROR: AddressSanitizer: heap-use-after-free\n#0 frame"
        python = "ok\nTraceback (most recent call last):\n  File x\nValueError: bad"
        lines = run(junit([("asan", "fail", asan), ("py", "fail", python)]))
        self.assertEqual(lines[1], "    ==123==ERROR: AddressSanitizer: heap-use-after-free")
        self.assertIn("    Traceback (most recent call last):", lines)
        self.assertNotIn("    noise", lines)

    def test_without_a_marker_the_last_lines_are_shown(self):
        output = "\n".join(f"line {i}" for i in range(30))
        lines = run(junit([("shell", "fail", output)]))
        self.assertEqual(lines[1:], [f"    line {i}" for i in range(18, 30)])

    def test_at_most_max_tests_then_a_count(self):
        lines = run(junit([(f"T{i}", "fail", "x") for i in range(5)]), "--max-tests", "2")
        self.assertEqual([line for line in lines if line.startswith("---")],
                         ["--- T0 (1.2 s)", "--- T1 (1.2 s)", "--- and 3 more"])

    def test_a_missing_report_is_said_not_raised(self):
        done = subprocess.run(["/usr/bin/python3", SCRIPT, "/nonexistent/junit.xml"],
                              capture_output=True, text=True)
        self.assertEqual(done.returncode, 0)
        self.assertTrue(done.stdout.startswith("(no test report:"))


if __name__ == "__main__":
    unittest.main()
