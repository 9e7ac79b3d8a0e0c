#!/usr/bin/env python3
"""Checks the house rules of docs/ARCHITECTURE.md section 1 on the include graph and the
measures' sources. Prints one line per breach (file:line and the rule) and exits 1 when there is
any, 0 otherwise.

Rules:
  1. Layers depend only downward: a file in a layer includes only its own layer and the layers
     below it (LAYERS, lowest first; techniques/ and reference/ stand side by side).
  2. A measure is a folder: harness/measures/<m>/ (a folder holding a *_measure.cpp) includes
     nothing from another measure's folder; shared algorithms live in folders that hold no
     measure. harness/measures/*.h is the measure interface.
  3. The policies' CPU twins live in harness/lod/, outside harness/measures/, and include none
     of it.
  4. Measures select techniques by capability: no source under harness/measures/ holds a
     string literal naming a technique id (the folders under techniques/).
  5. One namespace per layer, matching its folder (NAMESPACES): a source opens only its
     folder's namespace or one nested in it (anonymous namespaces and aliases aside); a
     technique's folder has tb::<technique>.

Usage: scripts/check_layers.py [ROOT]      --selftest: shows each rule catching a breach
"""
import os
import re
import sys
import tempfile

# (layer, the path prefixes that belong to it, the layers it may include besides itself).
LAYERS = [
    ("core/mesh", ["core/mesh/", "core/view/"], []),
    ("core/tess", ["core/tess/"], ["core/mesh"]),
    ("core/displacement", ["core/displacement/"], ["core/mesh"]),
    ("core/osd", ["core/osd/"], ["core/mesh"]),
    ("core/gpu", ["core/gpu/"], ["core/mesh", "core/tess", "shaders"]),
    ("shaders", ["shaders/"], []),
    ("techniques", ["techniques/"],
     ["core/mesh", "core/tess", "core/displacement", "core/osd", "core/gpu", "shaders"]),
    ("reference", ["reference/"], ["core/mesh", "core/tess", "core/osd", "shaders"]),
]
LOWER = ["core/mesh", "core/tess", "core/displacement", "core/osd", "core/gpu", "shaders",
         "techniques", "reference"]
LAYERS += [
    ("harness/results", ["harness/results/"], ["core/mesh"]),
    ("harness/lod", ["harness/lod/"], LOWER + ["harness/results"]),
    ("harness/measures", ["harness/measures/"], LOWER + ["harness/results", "harness/lod"]),
    # The results database across commits: the results model, and report.html's escaping.
    ("harness/history", ["harness/history/"], ["core/mesh", "harness/results", "harness/report"]),
    ("harness/report", ["harness/report/"], ["core/mesh", "harness/results"]),
]
# (folder prefix, its namespace); the longest prefix wins. techniques/<id>/ is tb::<id>.
NAMESPACES = [
    ("core/mesh/", "tb::mesh"), ("core/view/", "tb::view"), ("core/tess/", "tb::tess"),
    ("core/displacement/", "tb::displacement"), ("core/osd/", "tb::osd"), ("core/gpu/", "tb::gpu"),
    ("techniques/", "tb::techniques"), ("reference/", "tb::ref"),
    ("harness/results/", "tb::results"), ("harness/lod/", "tb::lod"),
    ("harness/measures/", "tb::measures"), ("harness/suite/", "tb::suite"),
    ("harness/pictures/", "tb::pictures"), ("harness/report/", "tb::report"),
    ("harness/bake/", "tb::bake"), ("harness/history/", "tb::history"),
    ("harness/cli/", "tb::cli"),
]
FORWARD_ONLY = re.compile(r"(?:\s*(?:class|struct)\s+\w+\s*;)+\s*\}")
NAMESPACE = re.compile(r"^\s*namespace\s+([\w:]+)\s*\{", re.M)
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
STRING = re.compile(r'"((?:[^"\\\n]|\\.)*)"')
SOURCES = (".h", ".hpp", ".cpp", ".cc", ".glsl", ".tesc", ".tese", ".comp", ".vert", ".frag")


def layer_of(rel):
    for name, prefixes, _ in LAYERS:
        if any(rel.startswith(p) for p in prefixes):
            return name
    return None


def files(root, top):
    for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
        dirnames.sort()
        for name in sorted(filenames):
            if name.endswith(SOURCES):
                path = os.path.join(dirpath, name)
                yield os.path.relpath(path, root).replace(os.sep, "/"), path


def includes(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    for m in INCLUDE.finditer(text):
        yield text.count("\n", 0, m.start()) + 1, m.group(1)


def measure_folders(root):
    base = os.path.join(root, "harness", "measures")
    found = set()
    if os.path.isdir(base):
        for dirpath, _, filenames in os.walk(base):
            if any(n.endswith("_measure.cpp") for n in filenames):
                rel = os.path.relpath(dirpath, base).replace(os.sep, "/")
                if rel != ".":
                    found.add(rel.split("/")[0])
    return found


def technique_ids(root):
    base = os.path.join(root, "techniques")
    if not os.path.isdir(base):
        return []
    return sorted(d for d in os.listdir(base)
                  if os.path.isdir(os.path.join(base, d)) and d != "common")


def check(root):
    problems = []
    allowed = {name: set(deps) | {name} for name, _, deps in LAYERS}
    layer_names = [name for name, _, _ in LAYERS]
    for top in ["core", "shaders", "techniques", "reference", "harness"]:
        for rel, path in files(root, top):
            own = layer_of(rel)
            if own is None:
                continue
            for line, inc in includes(path):
                target = layer_of(inc)
                if target is None or target not in layer_names:
                    continue
                if target not in allowed[own]:
                    problems.append(f"{rel}:{line}: {own} includes {inc} ({target} is not below it)")
    measures = measure_folders(root)
    if not measures and os.path.isdir(os.path.join(root, "harness", "measures")):
        problems.append("harness/measures: no measure folder (a folder holding a *_measure.cpp)")
    for rel, path in files(root, "harness/measures"):
        parts = rel.split("/")
        if len(parts) == 3:
            if rel.endswith("_measure.cpp"):
                problems.append(f"{rel}: a measure at the top of harness/measures (a measure is a folder)")
            continue
        own = parts[2]
        for line, inc in includes(path):
            ip = inc.split("/")
            if len(ip) > 3 and ip[0] == "harness" and ip[1] == "measures":
                other = ip[2]
                if other in measures and other != own:
                    problems.append(f"{rel}:{line}: measure folder '{own}' includes {inc} from measure '{other}'")
    for name in ("factor_policy", "cull_policy"):
        for rel, _ in files(root, "harness/measures"):
            if os.path.basename(rel).startswith(name + "."):
                problems.append(f"{rel}: a policy twin inside harness/measures (its room is harness/lod)")
    ids = technique_ids(root)
    for rel, path in files(root, "harness/measures"):
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        code = re.sub(r"//[^\n]*", "", text)
        for m in STRING.finditer(code):
            if code[max(0, m.start() - 9):m.start()].strip().endswith("include"):
                continue
            for tid in ids:
                if re.search(r"(?<![\w])" + re.escape(tid) + r"(?![\w])", m.group(1)):
                    line = code.count("\n", 0, m.start()) + 1
                    problems.append(f"{rel}:{line}: string \"{m.group(1)}\" names technique '{tid}' "
                                    "(select by capability)")
    problems += namespace_problems(root)
    return problems


def expected_namespace(rel):
    parts = rel.split("/")
    if parts[0] == "techniques" and len(parts) > 2 and parts[1] != "common":
        return "tb::" + parts[1]
    best = None
    for prefix, ns in NAMESPACES:
        if rel.startswith(prefix) and (best is None or len(prefix) > len(best[0])):
            best = (prefix, ns)
    return best[1] if best else None


def namespace_problems(root):
    problems = []
    for top in ["core", "techniques", "reference", "harness"]:
        for rel, path in files(root, top):
            want = expected_namespace(rel)
            if want is None or not rel.endswith((".h", ".cpp")):
                continue
            with open(path, encoding="utf-8", errors="replace") as f:
                code = re.sub(r"//[^\n]*", "", f.read())
            for m in NAMESPACE.finditer(code):
                ns = m.group(1)
                if ns.split("::")[0] != "tb" or ns == want or ns.startswith(want + "::"):
                    continue
                if FORWARD_ONLY.match(code, m.end()):
                    continue  # forward declarations of a lower layer's classes
                line = code.count("\n", 0, m.start()) + 1
                problems.append(f"{rel}:{line}: namespace {ns} (this folder's is {want})")
    return problems


def selftest():
    """Each rule on a small tree with one breach: every one must be caught."""
    cases = {
        "layer": {"core/mesh/a.h": '#include "techniques/technique.h"\n'},
        "technique includes reference": {"techniques/acc/acc.cpp": '#include "reference/x.h"\n'},
        "measure into measure": {
            "harness/measures/cracks/cracks_measure.cpp": "",
            "harness/measures/memory/memory_measure.cpp": '#include "harness/measures/cracks/cracks.h"\n'},
        "policy twin in measures": {"harness/measures/adaptivity/adaptivity_measure.cpp": "",
                                    "harness/measures/adaptivity/factor_policy.h": ""},
        "lod includes measures": {"harness/lod/cull_policy.cpp": '#include "harness/measures/error/error.h"\n',
                                  "harness/measures/error/error_measure.cpp": ""},
        "technique id": {"techniques/wave_particles/w.h": "",
                         "harness/measures/wave/wave_measure.cpp": 'auto id = "wave_particles";\n'},
        "namespace": {"harness/results/a.h": "namespace tb::gpu {\nclass C;\n}\nnamespace tb {\nstruct A {};\n}  // namespace tb\n"},
    }
    failures = 0
    for name, tree in cases.items():
        with tempfile.TemporaryDirectory() as root:
            for rel, text in tree.items():
                path = os.path.join(root, rel)
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, "w") as f:
                    f.write(text)
            caught = check(root)
            print(f"selftest {name}: {'caught: ' + caught[0] if caught else 'NOT caught'}")
            failures += 0 if caught else 1
    return 1 if failures else 0


def main():
    if "--selftest" in sys.argv[1:]:
        return selftest()
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    root = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    problems = check(root)
    for p in problems:
        print(p)
    print(f"check_layers: {len(problems)} breaches")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
