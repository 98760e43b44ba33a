#!/usr/bin/env python3
"""The runtime layer's boundaries in the sources (the target graph is checked by check_target_graph.py):

- runtime/ includes no QtGui, QtWidgets or QtPrintSupport header (an include <QName> is looked up in the
  Qt include folder given);
- app/cli/ includes nothing from ui/, and ui/ nothing from app/;
- ui/ does not branch on the kind of machine: none of the names of the former branches (realLatheChosen, operatorCycle,
  kOwnPass, onSourcesPass, boringTruth, kDevicesMachineKey) and no machine key compared with a literal.

Usage: check_runtime_layer.py SOURCE_DIR QT_INCLUDE_DIR
"""
import os
import re
import sys

GUI_MODULES = ("QtGui", "QtWidgets", "QtPrintSupport")
BRANCH_NAMES = re.compile(r"\b(realLatheChosen|operatorCycle|kOwnPass|onSourcesPass|boringTruth|kDevicesMachineKey|kBuiltInLatheKey|"
                          r"kDevicesLatheKey)\b")
MACHINE_KEYS = re.compile(r'"(simulated-lathe|devices-lathe|real-lathe|real)"')
KEY_COMPARED = re.compile(r"\bmachine\w*(\(\))?\s*(==|!=)\s*(QStringLiteral|QLatin1String|u\"|\")")


def sources(root, folder):
    base = os.path.join(root, folder)
    for dirpath, _, files in os.walk(base):
        for f in sorted(files):
            if f.endswith((".h", ".cpp")):
                yield os.path.join(dirpath, f)


def code_lines(path):
    for n, line in enumerate(open(path, encoding="utf-8"), 1):
        stripped = line.strip()
        if not stripped.startswith("//"):
            yield n, line


def gui_header(qt_dir, name):
    return next((m for m in GUI_MODULES if os.path.exists(os.path.join(qt_dir, m, name))), None)


def main(root, qt_dir):
    problems, counted = [], 0
    for path in sources(root, "runtime"):
        counted += 1
        for n, line in code_lines(path):
            include = re.match(r'\s*#include\s*<(Q\w+)>', line)
            module = include and gui_header(qt_dir, include.group(1))
            if module:
                problems.append(f"{os.path.relpath(path, root)}:{n}: includes {include.group(1)} ({module})")
    for folder, banned in (("app/cli", '"ui/'), ("ui", '"app/')):
        for path in sources(root, folder):
            for n, line in code_lines(path):
                if line.lstrip().startswith("#include") and banned in line:
                    problems.append(f"{os.path.relpath(path, root)}:{n}: {line.strip()}")
    for path in sources(root, "ui"):
        for n, line in code_lines(path):
            where = f"{os.path.relpath(path, root)}:{n}"
            if BRANCH_NAMES.search(line):
                problems.append(f"{where}: branches on the machine ({BRANCH_NAMES.search(line).group(1)})")
            elif MACHINE_KEYS.search(line) or KEY_COMPARED.search(line):
                problems.append(f"{where}: compares a machine key with a literal: {line.strip()}")
    if counted == 0:
        problems.append("runtime/ holds no source: is SOURCE_DIR the project?")
    if problems:
        sys.exit("the runtime layer's boundaries are crossed:\n  " + "\n  ".join(problems))
    print(f"runtime/: {counted} files, no QtGui or QtWidgets; app/cli and ui/ apart; ui/ asks capabilities")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
