#!/usr/bin/env python3
"""Checks docs/STYLE.md's size rules over the C++ and GLSL sources: no file over 600 lines and
no function body over 100 lines. Prints one line per offender (file:line, what, how long) and
exits 1 when there is any; 0 when every file and function is within the limits.

Usage: scripts/check_sizes.py [ROOT] [--max-file N] [--max-function N]

A function is a brace block whose opening brace follows a parameter list `)` (with optional
qualifiers, a trailing return type or a constructor's initialiser list) outside any other
function; control statements, lambdas and class bodies are not functions. Its length counts the
lines from its signature's first line to its closing brace, as an editor shows them.
"""
import argparse
import os
import re
import sys

SOURCE_DIRS = ["core", "techniques", "reference", "harness", "bench", "tests", "examples", "shaders"]
EXTENSIONS = (".cpp", ".h", ".hpp", ".cc", ".glsl", ".tesc", ".tese", ".vert", ".frag", ".comp")
CONTROL = re.compile(r"\b(if|for|while|switch|catch|do|else)\s*$")


def strip_code(text):
    """Blanks comments, strings and character literals, keeping newlines (so line numbers hold)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = ")" + m.group(1) + '"'
            j = text.find(end, i + m.end())
            j = n if j < 0 else j + len(end)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(" " * (j - i))
            i = j
        else:
            out.append(c)
            i += 1
    code = "".join(out)
    # Blank preprocessor lines (and their backslash continuations): not part of any statement.
    lines = code.split("\n")
    continued = False
    for k, ln in enumerate(lines):
        if continued or ln.lstrip().startswith("#"):
            continued = ln.rstrip().endswith("\\")
            lines[k] = " " * len(ln)
    return "\n".join(lines)


def head_before(code, brace):
    """The statement text before an opening brace: back to the previous ; { or }."""
    j = brace - 1
    depth = 0
    while j >= 0:
        ch = code[j]
        if ch == ")":
            depth += 1
        elif ch == "(":
            depth -= 1
        elif depth == 0 and ch in ";{}":
            break
        j -= 1
    return code[j + 1:brace], j + 1


def is_function_head(head):
    text = " ".join(head.split())
    if not text or text.startswith("#"):
        return False
    # Drop a constructor's initialiser list: ") : member(x), other{y}".
    m = re.search(r"\)\s*(const|noexcept|override|final|mutable|&|\s)*(->[^{]*)?$", text)
    if m is None:
        m2 = re.search(r"\)\s*(noexcept\s*)?:\s*[A-Za-z_]", text)
        if m2 is None:
            return False
        text = text[: m2.start() + 1]
    # The name before the parameter list's opening parenthesis.
    depth, k = 0, len(text) - 1
    while k >= 0:
        if text[k] == ")":
            depth += 1
        elif text[k] == "(":
            depth -= 1
            if depth == 0:
                break
        k -= 1
    before = text[:k].rstrip()
    if not before or before.endswith("]") or CONTROL.search(before):
        return False
    if re.search(r"(=|\breturn|,|\()\s*[\w:<>]*$", before) and not re.search(r"operator\s*\S*$", before):
        return False
    return bool(re.search(r"[\w~>\]=!<+*/%&|^-]$", before))


def functions(code):
    """(first line, last line) of every function body outside other functions."""
    found = []
    stack = []  # per open brace: True when it opens a function
    inside = 0
    line_of = [0] * (len(code) + 1)
    line = 1
    for i, ch in enumerate(code):
        line_of[i] = line
        if ch == "\n":
            line += 1
    for i, ch in enumerate(code):
        if ch == "{":
            is_fn = False
            if inside == 0:
                head, start = head_before(code, i)
                if is_function_head(head):
                    is_fn = True
                    first = start
                    while first < i and code[first].isspace():
                        first += 1
                    stack.append((True, line_of[first]))
                    inside += 1
                    continue
            stack.append((is_fn, 0))
        elif ch == "}" and stack:
            is_fn, first_line = stack.pop()
            if is_fn:
                inside -= 1
                found.append((first_line, line_of[i]))
    return found


def selftest():
    """A tree with a 601-line file and a 101-line function: both must be caught, and a
    100-line function with a long lambda, comments and strings inside it must not."""
    import subprocess
    import tempfile
    body = "".join(f"  x += {i};\n" for i in range(98))
    ok_fn = "int ok(int x) {\n" + body.replace("x += 5;", 'auto f = [] { return "}"; };') + "}\n"
    long_fn = "int tooLong(int x) {\n" + body + "  x += 1;\n}\n"
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "core"))
        with open(os.path.join(root, "core", "fine.cpp"), "w") as f:
            f.write("// {\n" + ok_fn)
        with open(os.path.join(root, "core", "long_function.cpp"), "w") as f:
            f.write(long_fn)
        with open(os.path.join(root, "core", "long_file.h"), "w") as f:
            f.write("int a;\n" * 601)
        out = subprocess.run([sys.executable, __file__, root], capture_output=True, text=True).stdout
    print(out, end="")
    wanted = ["core/long_function.cpp:1: function has 101 lines", "core/long_file.h: file has 601 lines"]
    missing = [w for w in wanted if w not in out]
    wrong = "fine.cpp" in out
    for w in missing:
        print(f"selftest: NOT caught: {w}")
    if wrong:
        print("selftest: a function within the limit was flagged")
    return 1 if missing or wrong else 0


def main():
    if "--selftest" in sys.argv[1:]:
        return selftest()
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root", nargs="?", default=os.path.join(os.path.dirname(__file__), ".."))
    parser.add_argument("--max-file", type=int, default=600)
    parser.add_argument("--max-function", type=int, default=100)
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    problems = []
    checked = 0
    for top in SOURCE_DIRS:
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
            dirnames.sort()
            for name in sorted(filenames):
                if not name.endswith(EXTENSIONS):
                    continue
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root)
                with open(path, encoding="utf-8", errors="replace") as f:
                    text = f.read()
                checked += 1
                lines = text.count("\n") + (0 if text.endswith("\n") else 1)
                if lines > args.max_file:
                    problems.append(f"{rel}: file has {lines} lines (limit {args.max_file})")
                for first, last in functions(strip_code(text)):
                    length = last - first + 1
                    if length > args.max_function:
                        problems.append(
                            f"{rel}:{first}: function has {length} lines (limit {args.max_function})")
    for p in problems:
        print(p)
    print(f"check_sizes: {checked} files, {len(problems)} over the limits")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
