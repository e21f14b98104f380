#!/usr/bin/python3
"""What the code cites is in the repository (docs/architecture.md, "Include rules"): every docs/<page>.md that
a source, test, script or CMake file names exists; every equation tag cited as docs/physics.md F2 (or
"docs/physics.md (K1b)") has its section "## F2 ..." there; and nothing cites the design files outside the
repository (PHYSICS.md, VERIFICATION.md, ARCHITECTURE.md, notes/petsc-3.18.md, notes/peer-codes.md, ../shared).
  test_doc_citations.py ROOT          one line per broken citation, exit 1
  test_doc_citations.py --self-test   plants one broken citation of each kind and checks each is caught"""
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import structurecheck  # noqa: E402

TREES = ["src", "include", "examples", "test", "scripts", "config", "CMakeLists.txt"]
SKIP = {os.path.join("examples", "output")}  # reference outputs: what the programs print, checked elsewhere
OUTSIDE = re.compile(r"(?<![a-z/])(PHYSICS|VERIFICATION|ARCHITECTURE)\.md|petsc-3\.18\.md|peer-codes\.md|\.\./shared/|/work/shared")
PAGE = re.compile(r"docs/([A-Za-z0-9_/-]+\.md)")
TAG = re.compile(r"docs/physics\.md[,;:]?\s*\(?(?:section\s+)?([FPKMS][0-9]*[a-z]?)\b")


def files(root):
    for t in TREES:
        top = os.path.join(root, t)
        if os.path.isfile(top):
            yield top
            continue
        for dirpath, dirs, names in os.walk(top):
            dirs[:] = [d for d in dirs if os.path.relpath(os.path.join(dirpath, d), root) not in SKIP and d != "__pycache__"]
            for n in sorted(names):
                yield os.path.join(dirpath, n)


def check(root):
    problems, headings = [], set()
    physics = os.path.join(root, "docs", "physics.md")
    if os.path.exists(physics):
        for line in open(physics, encoding="utf-8"):
            m = re.match(r"##\s+([A-Z][0-9]*[a-z]?)\s", line)
            if m:
                headings.add(m.group(1))
    for path in files(root):
        try:
            text = open(path, encoding="utf-8").read()
        except (UnicodeDecodeError, OSError):
            continue
        rel = os.path.relpath(path, root)
        if rel == os.path.join("test", "structure", "test_doc_citations.py"):
            continue
        for number, line in enumerate(text.splitlines(), 1):
            for m in OUTSIDE.finditer(line):
                problems.append(f"{rel}:{number}: cites {m.group(0)}, which is not in the repository (cite docs/)")
            for m in PAGE.finditer(line):
                if not os.path.exists(os.path.join(root, "docs", m.group(1))):
                    problems.append(f"{rel}:{number}: cites docs/{m.group(1)}, which does not exist")
            for m in TAG.finditer(line):
                if m.group(1) not in headings:
                    problems.append(f"{rel}:{number}: cites docs/physics.md {m.group(1)}, which has no section '## {m.group(1)} ...'")
    return problems


def self_test():
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "docs"))
        os.makedirs(os.path.join(root, "src", "flow"))
        with open(os.path.join(root, "docs", "physics.md"), "w") as f:
            f.write("# Physics\n\n## F2 Momentum\n\n## K1b Self\n")
        planted = {"src/flow/A.cpp": "// the face density (PHYSICS.md F2)\n",
                   "src/flow/B.cpp": "// see docs/nowhere.md\n",
                   "src/flow/C.cpp": "// docs/physics.md (F9) heat\n",
                   "src/flow/D.cpp": "// ../shared/notes/petsc-3.18.md\n"}
        fine = "// docs/physics.md F2 and docs/physics.md (K1b)\n"
        for rel, text in planted.items():
            with open(os.path.join(root, rel), "w") as f:
                f.write(text)
        with open(os.path.join(root, "src", "flow", "Fine.cpp"), "w") as f:
            f.write(fine)
        found = check(root)
        missed = [rel for rel in planted if not any(p.startswith(rel + ":") for p in found)]
        extra = [p for p in found if p.startswith("src/flow/Fine.cpp")]
        return structurecheck.self_test_verdict(list(planted), missed, extra, "broken citation")


def main():
    return structurecheck.main(__doc__, check, self_test, "doc citations", "broken")


if __name__ == "__main__":
    sys.exit(main())
