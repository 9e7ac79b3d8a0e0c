#!/usr/bin/env python3
"""Checks README.md against the program it describes (README for a newcomer):
  - under 150 lines, opening (within its first 15 lines) with a picture that exists under docs/
    as a PNG of at most 300 KB;
  - every `tessbench ...` command it shows, in a code block or inline code: its subcommand exists
    and `tessbench SUB --help` lists each --option it uses; the fast ones (list, tessellate,
    --version) are run and must exit 0;
  - every script it shows exists and is executable, with a preset argument CMakePresets.json has.
Prints one line per problem and exits 1 when there is any.

Usage: check_readme.py ROOT TESSBENCH      (--selftest ROOT TESSBENCH: a README naming an option
that does not exist must fail the check)
"""
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile

MAX_LINES = 150
FAST = {"list", "tessellate"}


def commands(text):
    """(line number, argv after the binary) of every tessbench command shown."""
    found = []
    in_block = False
    for number, line in enumerate(text.splitlines(), 1):
        if line.strip().startswith("```"):
            in_block = not in_block
            continue
        spans = [line.strip()] if in_block else re.findall(r"`([^`]+)`", line)
        for span in spans:
            span = span.split("#")[0].strip()
            m = re.match(r"^(?:\./)?(?:build/release/bin/)?tessbench(\s.*)?$", span)
            if m and m.group(1):  # a bare `tessbench` names the program, runs nothing
                found.append((number, shlex.split(m.group(1))))
    return found


def scripts(text):
    return [(n, m.group(1), m.group(2)) for n, line in enumerate(text.splitlines(), 1)
            for m in re.finditer(r"\./(scripts/[\w.]+\.sh)(?:\s+([\w-]+))?", line)]


def help_of(tessbench, sub, cache):
    if sub not in cache:
        argv = [tessbench] + ([sub] if sub else []) + ["--help"]
        cache[sub] = subprocess.run(argv, capture_output=True, text=True, timeout=60).stdout
    return cache[sub]


def check(root, tessbench):
    problems = []
    readme = os.path.join(root, "README.md")
    with open(readme, encoding="utf-8") as f:
        text = f.read()
    lines = text.splitlines()
    if len(lines) >= MAX_LINES:
        problems.append(f"README.md: {len(lines)} lines (must be under {MAX_LINES})")
    picture = None
    for line in lines[:15]:
        m = re.search(r"!\[[^\]]*\]\((docs/[^)]+\.png)\)", line)
        if m:
            picture = m.group(1)
            break
    if picture is None:
        problems.append("README.md: no picture (![..](docs/...png)) in its first 15 lines")
    else:
        path = os.path.join(root, picture)
        if not os.path.isfile(path):
            problems.append(f"README.md: picture {picture} does not exist")
        else:
            with open(path, "rb") as f:
                if f.read(8) != b"\x89PNG\r\n\x1a\n":
                    problems.append(f"README.md: {picture} is not a PNG")
            if os.path.getsize(path) > 300 * 1024:
                problems.append(f"README.md: {picture} is {os.path.getsize(path)} bytes (max 300 KB)")
    top_help = help_of(tessbench, None, {})
    subs = set(re.findall(r"^\s{2}(\w+)\s", top_help.split("SUBCOMMANDS:")[-1], re.M))
    cache = {}
    shown = commands(text)
    if not shown:
        problems.append("README.md: shows no tessbench command")
    for number, argv in shown:
        sub = next((a for a in argv if not a.startswith("-") and not a.startswith("<")), None)
        options = [a.split("=")[0] for a in argv if a.startswith("--")]
        if sub is not None and sub not in subs:
            problems.append(f"README.md:{number}: subcommand '{sub}' does not exist")
            continue
        before_sub = argv[:argv.index(sub)] if sub else argv
        for opt in options:
            scope = None if opt in before_sub else sub
            if not re.search(r"(^|[\s,])" + re.escape(opt) + r"\b", help_of(tessbench, scope, cache)):
                problems.append(f"README.md:{number}: `tessbench {sub or ''}` has no option {opt}")
        if sub in FAST or sub is None:
            run = subprocess.run([tessbench] + argv, capture_output=True, text=True, timeout=120)
            if run.returncode != 0:
                problems.append(f"README.md:{number}: `tessbench {' '.join(argv)}` exited "
                                f"{run.returncode}: {run.stderr.strip()[:200]}")
    presets = {p["name"] for p in json.load(open(os.path.join(root, "CMakePresets.json")))
               .get("configurePresets", [])}
    for number, script, arg in scripts(text):
        path = os.path.join(root, script)
        if not os.access(path, os.X_OK):
            problems.append(f"README.md:{number}: {script} is missing or not executable")
        if script == "scripts/test.sh" and arg and arg not in presets:
            problems.append(f"README.md:{number}: scripts/test.sh {arg}: no such preset")
    return problems, len(shown)


def selftest(root, tessbench):
    with tempfile.TemporaryDirectory() as fake:
        with open(os.path.join(root, "README.md"), encoding="utf-8") as f:
            text = f.read()
        with open(os.path.join(fake, "README.md"), "w", encoding="utf-8") as f:
            f.write(text + "\n`tessbench run --no-such-option`\n")
        os.symlink(os.path.join(root, "docs"), os.path.join(fake, "docs"))
        os.symlink(os.path.join(root, "scripts"), os.path.join(fake, "scripts"))
        os.symlink(os.path.join(root, "CMakePresets.json"), os.path.join(fake, "CMakePresets.json"))
        problems, _ = check(fake, tessbench)
    caught = [p for p in problems if "--no-such-option" in p]
    print(caught[0] if caught else "selftest: an option that does not exist was NOT caught")
    return 0 if caught else 1


def main():
    args = [a for a in sys.argv[1:] if a != "--selftest"]
    if len(args) != 2:
        print(__doc__)
        return 2
    root, tessbench = os.path.abspath(args[0]), os.path.abspath(args[1])
    if "--selftest" in sys.argv:
        return selftest(root, tessbench)
    problems, count = check(root, tessbench)
    for p in problems:
        print(p)
    print(f"check_readme: {count} commands checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
