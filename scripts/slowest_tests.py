#!/usr/bin/python3
"""The cost of a test run: the count and summed time of the tests in a ctest JUnit file
(`ctest --output-junit FILE`) and the slowest of them with their times, so that CI shows where
its minutes go and when the suite grows.

  slowest_tests.py JUNIT.xml [--top N] [--title TEXT]
"""

import argparse
import sys
import xml.etree.ElementTree as ET


def read_tests(path):
    """(seconds, name, status) of every test case in the file."""
    tests = []
    for case in ET.parse(path).getroot().iter("testcase"):
        status = case.get("status", "run")
        if case.find("failure") is not None:
            status = "failed"
        elif case.find("skipped") is not None:
            status = "skipped"
        tests.append((float(case.get("time", "0")), case.get("name", "?"), status))
    return tests


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("junit")
    parser.add_argument("--top", type=int, default=20)
    parser.add_argument("--title", default="")
    args = parser.parse_args()
    try:
        tests = read_tests(args.junit)
    except (OSError, ET.ParseError) as e:
        print(f"slowest_tests: cannot read {args.junit}: {e}")
        return 1
    total = sum(t[0] for t in tests)
    title = f"{args.title}: " if args.title else ""
    print(f"{title}{len(tests)} tests, {total:.0f} s of test time; the {min(args.top, len(tests))} "
          f"slowest:")
    for seconds, name, status in sorted(tests, key=lambda t: -t[0])[: args.top]:
        mark = "" if status == "run" else f"  ({status})"
        print(f"  {seconds:8.1f} s  {100 * seconds / total if total else 0:4.1f} %  {name}{mark}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
