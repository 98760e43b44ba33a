#!/usr/bin/env python3
"""tests/ mirrors the source tree: every folder of tests/core, tests/runtime, tests/devices and tests/ui is named
after a folder of core/, runtime/, devices/ or ui/ (at the same depth), or after a file at the top of it (a test of
ui/keypad.cpp lives in tests/ui/keypad/); support/ holds shared helpers. Usage: check_test_mirror.py SOURCE_DIR"""
import os
import sys

AREAS = ("core", "runtime", "devices", "ui")
HELPERS = {"support"}


def stems(folder):
    """The names a test folder may take in `folder`: its sub-folders and its source files without extension."""
    names = set()
    for entry in os.listdir(folder):
        path = os.path.join(folder, entry)
        if os.path.isdir(path):
            names.add(entry)
        elif entry.endswith((".cpp", ".h")):
            names.add(entry.rsplit(".", 1)[0])
    return names


def strays(root, area):
    """Test folders under tests/<area> with no counterpart in <area>/, as paths relative to root."""
    found = []
    tests_area = os.path.join(root, "tests", area)
    if not os.path.isdir(tests_area):
        return found
    for here, dirs, _files in os.walk(tests_area):
        rel = os.path.relpath(here, tests_area)
        source = os.path.join(root, area) if rel == "." else os.path.join(root, area, rel)
        allowed = stems(source) if os.path.isdir(source) else set()
        for d in sorted(dirs):
            if d in HELPERS or (rel == "." and d in HELPERS):
                continue
            if d not in allowed:
                found.append(os.path.join("tests", area, rel, d).replace("/./", "/"))
        dirs[:] = [d for d in dirs if d not in HELPERS and d in allowed and os.path.isdir(os.path.join(source, d))]
    return found


def main():
    root = sys.argv[1]
    bad = [p for area in AREAS for p in strays(root, area)]
    if bad:
        print("Test folders with no source folder or file of that name (tests/ mirrors the source tree):")
        for p in bad:
            print("  " + p)
        return 1
    print("tests/ mirrors " + ", ".join(AREAS))
    return 0


if __name__ == "__main__":
    sys.exit(main())
