#!/usr/bin/python3
"""Prints, for each failed test in a ctest JUnit file, its name and the lines that say why.

scripts/test.sh calls this at the end of a run, after every stage, so that the last lines of a
CI log (often all one gets to see) name what failed instead of only which stage did.
Usage: ctest_failures.py JUNIT_XML [--max-tests N]
"""

import argparse
import re
import sys
import xml.etree.ElementTree as ElementTree

# GoogleTest marks an assertion with "file:line: Failure"; a sanitizer report or a crash has its
# own first line. The lines after the first marker are the useful ones.
FAILURE_MARKER = re.compile(r": Failure$|^==\d+==ERROR|runtime error:|Segmentation fault|"
                            r"Traceback \(most recent call last\)|^(FAIL|ERROR):|Timeout")
LINES_AFTER_MARKER = 8
TAIL_LINES = 12


def why(output: str) -> list[str]:
    lines = output.rstrip("\n").splitlines()
    for index, line in enumerate(lines):
        if FAILURE_MARKER.search(line):
            return lines[index:index + LINES_AFTER_MARKER]
    return lines[-TAIL_LINES:]


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("junit")
    parser.add_argument("--max-tests", type=int, default=6)
    args = parser.parse_args()
    try:
        suite = ElementTree.parse(args.junit).getroot()
    except (OSError, ElementTree.ParseError) as error:
        print(f"(no test report: {error})")
        return 0
    failed = [case for case in suite.iter("testcase") if case.get("status") == "fail"]
    for case in failed[:args.max_tests]:
        print(f"--- {case.get('name')} ({float(case.get('time', 0)):.1f} s)")
        for line in why(case.findtext("system-out") or ""):
            print(f"    {line[:160]}")
    if len(failed) > args.max_tests:
        print(f"--- and {len(failed) - args.max_tests} more")
    return 0


if __name__ == "__main__":
    sys.exit(main())
