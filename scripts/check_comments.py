#!/usr/bin/env python3
"""Checks docs/STYLE.md's comment rule over the C++ and GLSL sources under core/, techniques/,
reference/ and harness/: no comment block longer than 10 lines. A block is a run of consecutive
lines that hold only a `//` comment, or one /* */ comment (its first to its last line). Long
derivations and specifications belong in docs/derivations/, with a one-line citation in code.
Prints one line per offender (file:line, how long) and exits 1 when there is any.

Usage: scripts/check_comments.py [ROOT] [--max-block N] [--exclude PREFIX ...] | --selftest
"""
import argparse
import fnmatch
import os
import re
import sys

SOURCE_DIRS = ["core", "techniques", "reference", "harness"]
EXTENSIONS = (".cpp", ".h", ".hpp", ".cc", ".glsl", ".tesc", ".tese", ".vert", ".frag", ".comp")


def comment_blocks(text):
    """(first line, line count) of every comment block in a C++ or GLSL text."""
    blocks = []
    line_only = []  # line numbers whose whole content is a // comment
    i, n, line = 0, len(text), 1
    line_start = True  # nothing but blanks since the line began
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            line_start = True
            i += 1
        elif c in " \t\r":
            i += 1
        elif text.startswith("//", i):
            if line_start:
                line_only.append(line)
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            span = text.count("\n", i, j)
            blocks.append((line, span + 1))
            line += span
            line_start = False
            i = j
        elif text.startswith('R"', i) and re.match(r'R"([^(\s]*)\(', text[i:]):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = ")" + m.group(1) + '"'
            j = text.find(end, i + m.end())
            j = n if j < 0 else j + len(end)
            line += text.count("\n", i, j)
            line_start = False
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            i = min(j + 1, n)
            line_start = False
        else:
            line_start = False
            i += 1
    run_start, prev = None, None
    for ln in line_only + [None]:
        if ln is not None and prev is not None and ln == prev + 1:
            prev = ln
            continue
        if run_start is not None:
            blocks.append((run_start, prev - run_start + 1))
        run_start, prev = ln, ln
    return sorted(blocks)


def scan(root, max_block, excludes):
    problems, skipped, checked = [], [], 0
    for top in SOURCE_DIRS:
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
            dirnames.sort()
            for name in sorted(filenames):
                if not name.endswith(EXTENSIONS):
                    continue
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root).replace(os.sep, "/")
                with open(path, encoding="utf-8", errors="replace") as f:
                    text = f.read()
                checked += 1
                excluded = any(fnmatch.fnmatch(rel, e) or rel.startswith(e) for e in excludes)
                for first, length in comment_blocks(text):
                    if length > max_block:
                        msg = f"{rel}:{first}: comment block has {length} lines (limit {max_block})"
                        (skipped if excluded else problems).append(msg)
    return problems, skipped, checked


def selftest():
    """A tree with an 11-line // block and an 11-line /* */ comment: both must be caught; a
    10-line block, two 6-line blocks split by code, and comment markers inside strings must not."""
    import subprocess
    import tempfile
    long_slashes = "int a;\n" + "// line\n" * 11 + "int b;\n"
    long_star = "/* one\n" + " * line\n" * 9 + " */\nint c;\n"
    fine = ("// x\n" * 10 + "int d;\n" + "  // y\n" * 6 + "int e; // trailing\n" + "// z\n" * 5
            + 'const char* s = "/* not a comment\\n";\nauto r = R"(\n' + "// raw\n" * 12 + ')";\n')
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "core"))
        os.makedirs(os.path.join(root, "harness", "lod"))
        files = {"core/long_slashes.cpp": long_slashes, "harness/lod/long_star.h": long_star,
                 "core/fine.cpp": fine}
        for rel, text in files.items():
            with open(os.path.join(root, rel), "w") as f:
                f.write(text)
        run = subprocess.run([sys.executable, __file__, root], capture_output=True, text=True)
    print(run.stdout, end="")
    wanted = ["core/long_slashes.cpp:2: comment block has 11 lines",
              "harness/lod/long_star.h:1: comment block has 11 lines"]
    missing = [w for w in wanted if w not in run.stdout]
    wrong = "fine.cpp" in run.stdout
    for w in missing:
        print(f"selftest: NOT caught: {w}")
    if wrong:
        print("selftest: a block within the limit (or a string) was flagged")
    if run.returncode != 1:
        print(f"selftest: exit status {run.returncode}, wanted 1")
    return 1 if missing or wrong or run.returncode != 1 else 0


def main():
    if "--selftest" in sys.argv[1:]:
        return selftest()
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root", nargs="?", default=os.path.join(os.path.dirname(__file__), ".."))
    parser.add_argument("--max-block", type=int, default=10)
    parser.add_argument("--exclude", action="append", default=[],
                        help="a path prefix or glob (relative to ROOT) reported but not failed")
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    problems, skipped, checked = scan(root, args.max_block, args.exclude)
    for p in problems:
        print(p)
    for s in skipped:
        print(f"(excluded) {s}")
    print(f"check_comments: {checked} files, {len(problems)} blocks over {args.max_block} lines"
          + (f", {len(skipped)} more in excluded paths" if skipped else ""))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
