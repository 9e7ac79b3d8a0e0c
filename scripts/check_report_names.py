#!/usr/bin/env python3
"""Checks that no string literal under harness/report/ names a measure or a metric: the report
reads figures through the decision inputs the measures declare (harness/results/decision_input.h),
never by name. Prints one line per offender (file:line, the literal, the name) and exits 1 when
there is any; 0 otherwise.

Usage: scripts/check_report_names.py [ROOT] [--selftest]

The names are every measure id and metric name declared under harness/measures/ (MeasureInfo's
`.id = "..."` and each MetricTable entry `{"name", results::Unit::...}`). A literal names one
when it equals it, or when it holds a name with an underscore as a whole word (snake_case
names are not English words; a one-word id such as "error" counts only as the whole literal).
Comments are not literals; #include paths are not either.
"""
import argparse
import os
import re
import sys
import tempfile

ID = re.compile(r'\.id\s*=\s*"([a-z0-9_\-]+)"')
METRIC = re.compile(r'\{\s*"([A-Za-z0-9_\-]+)"\s*,\s*(?:results::)?Unit::')
LITERAL = re.compile(r'"((?:[^"\\\n]|\\.)*)"')


def declared_names(root):
    names = set()
    for folder, _, files in os.walk(os.path.join(root, "harness", "measures")):
        for name in files:
            if not name.endswith((".cpp", ".h")):
                continue
            with open(os.path.join(folder, name), encoding="utf-8") as f:
                text = f.read()
            names.update(ID.findall(text))
            names.update(METRIC.findall(text))
    return names


def strip_comments(line):
    """The line without its // comment (a // inside a literal is kept)."""
    out, in_string, i = [], False, 0
    while i < len(line):
        c = line[i]
        if in_string and c == "\\":
            out.append(line[i:i + 2])
            i += 2
            continue
        if c == '"':
            in_string = not in_string
        elif not in_string and line.startswith("//", i):
            break
        out.append(c)
        i += 1
    return "".join(out)


def offenders(root, names):
    problems = []
    snake = sorted(n for n in names if "_" in n)
    report = os.path.join(root, "harness", "report")
    for folder, _, files in os.walk(report):
        for name in sorted(files):
            if not name.endswith((".cpp", ".h")):
                continue
            path = os.path.join(folder, name)
            rel = os.path.relpath(path, root)
            in_block = False
            with open(path, encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    if in_block:
                        if "*/" not in line:
                            continue
                        line, in_block = line.split("*/", 1)[1], False
                    if "/*" in line and "*/" not in line.split("/*", 1)[1]:
                        line, in_block = line.split("/*", 1)[0], True
                    code = strip_comments(line)
                    if code.lstrip().startswith("#include"):
                        continue
                    for literal in LITERAL.findall(code):
                        hit = literal if literal in names else None
                        for n in snake:
                            if hit is None and re.search(r"(?<![A-Za-z0-9_])" + re.escape(n) +
                                                         r"(?![A-Za-z0-9_])", literal):
                                hit = n
                        if hit is not None:
                            problems.append(f'{rel}:{number}: "{literal}" names {hit}')
    return problems


def selftest():
    """A tree with one measure and a report file that names its metric, one that names its id,
    and one clean: the check must find exactly the two."""
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "harness", "measures", "m"))
        os.makedirs(os.path.join(root, "harness", "report"))
        with open(os.path.join(root, "harness", "measures", "m", "m_measure.cpp"), "w") as f:
            f.write('MeasureInfo{.id = "memory",\n'
                    '  {"plain_bytes", results::Unit::kBytes, D::kNone}};\n')
        files = {
            "metric.cpp": 'auto v = rowMetric(row, "plain_bytes");\n',
            "measure.cpp": 'if (m.measure == "memory") return;\n',
            "clean.cpp": '// "memory" in a comment\nstd::string s = "memory ratio";\n'
                         '#include "harness/report/plain_bytes.h"\n',
        }
        for name, text in files.items():
            with open(os.path.join(root, "harness", "report", name), "w") as f:
                f.write(text)
        found = offenders(root, declared_names(root))
        caught = {p.split(":")[0].split(os.sep)[-1] for p in found}
        if caught != {"metric.cpp", "measure.cpp"}:
            print("selftest: FAILED, found", found)
            return 1
        print("selftest: the check caught a metric and a measure named in harness/report")
        return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("root", nargs="?", default=".")
    parser.add_argument("--selftest", action="store_true")
    args = parser.parse_args()
    if args.selftest:
        return selftest()
    names = declared_names(args.root)
    if len(names) < 10:
        print(f"check_report_names: only {len(names)} names found under harness/measures")
        return 1
    problems = offenders(args.root, names)
    for p in problems:
        print(p)
    print(f"check_report_names: {len(names)} declared names, {len(problems)} literals name one")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
