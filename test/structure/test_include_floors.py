#!/usr/bin/python3
"""The floors of the source tree (docs/architecture.md, "Floors"): every #include "vofdem/<folder>/..." in
src/<folder> and include/vofdem/<folder> must point to the same floor or one below it. The particles (dem)
know no fluid, the fluid (flow, vof) knows no particles, base and grid know no physics; only the coupling
bridges them, and only sim and app see everything.
  test_include_floors.py ROOT       check the tree under ROOT; one line per offending include, exit 1
  test_include_floors.py --self-test  build a small tree with one offence per rule and check each is caught"""
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import structurecheck  # noqa: E402

# The folders each floor may include (itself always).
ALLOWED = {
    "base": set(),
    "io": {"base"},
    "grid": {"base", "io"},
    "dem": {"base", "io", "grid"},
    "flow": {"base", "io", "grid"},
    "vof": {"base", "io", "grid", "flow"},
    "coupling": {"base", "io", "grid", "dem", "flow", "vof"},
    "analysis": {"base", "io", "grid", "dem"},
    "sim": {"base", "io", "grid", "dem", "flow", "vof", "coupling", "analysis"},
    "app": {"base", "io", "grid", "dem", "flow", "vof", "coupling", "analysis", "sim"},
    "examples": {"base", "io", "grid", "dem", "flow", "vof", "coupling", "analysis", "sim"},
}
INCLUDE = re.compile(r'^\s*#\s*include\s*"vofdem/([A-Za-z0-9_]+)/')
# A module added later (a vofdem_add_module line of CMakeLists.txt naming a folder not above) is a physics
# module: it may build on base, io, grid and the other physics modules, never on coupling or the floors above;
# the coupling (which bridges particles and any fluid: the seepage coupling and darcy), sim, app and the examples
# may include it.
NEW_MODULE = {"base", "io", "grid", "dem", "flow", "vof"}


def floors(root):
    allowed = {k: set(v) for k, v in ALLOWED.items()}
    cmake = os.path.join(root, "CMakeLists.txt")
    names = re.findall(r"^\s*vofdem_add_module\((\w+)\)", open(cmake).read(), re.M) if os.path.exists(cmake) else []
    for name in names:
        if name not in allowed:
            allowed[name] = set(NEW_MODULE)
            for top in ("coupling", "sim", "app", "examples"):
                allowed[top].add(name)
    return allowed


def check(root):
    problems, ALLOWED = [], floors(root)
    for top in ("src", os.path.join("include", "vofdem")):
        base = os.path.join(root, top)
        if not os.path.isdir(base):
            continue
        for folder in sorted(os.listdir(base)):
            here = os.path.join(base, folder)
            if not os.path.isdir(here):
                continue
            if folder not in ALLOWED:
                problems.append(f"{os.path.join(top, folder)}: a folder no floor names (add it to ALLOWED in {__file__})")
                continue
            for dirpath, _, files in os.walk(here):
                for name in sorted(files):
                    if not name.endswith((".hpp", ".cpp", ".h")):
                        continue
                    path = os.path.join(dirpath, name)
                    with open(path, encoding="utf-8") as f:
                        for number, line in enumerate(f, 1):
                            m = INCLUDE.match(line)
                            if not m or m.group(1) == folder:
                                continue
                            if m.group(1) not in ALLOWED[folder]:
                                problems.append(f"{os.path.relpath(path, root)}:{number}: {folder} includes {m.group(1)} "
                                                f"({line.strip()}); {folder} may include {', '.join(sorted(ALLOWED[folder])) or 'only itself'}")
    return problems


def self_test():
    offences = [("src/dem/A.cpp", "coupling"), ("src/dem/B.cpp", "flow"), ("include/vofdem/dem/C.hpp", "vof"),
                ("src/flow/D.cpp", "dem"), ("src/flow/E.cpp", "coupling"), ("src/flow/F.cpp", "vof"),
                ("src/base/G.cpp", "dem"), ("src/base/H.cpp", "grid"), ("src/grid/I.cpp", "flow"),
                ("include/vofdem/grid/J.hpp", "dem"), ("src/vof/K.cpp", "dem"), ("src/coupling/L.cpp", "sim")]
    with tempfile.TemporaryDirectory() as root:
        for rel, target in offences:
            os.makedirs(os.path.join(root, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w") as f:
                f.write(f'#include <vector>\n#include "vofdem/{os.path.basename(os.path.dirname(rel))}/Own.hpp"\n'
                        f'#include "vofdem/{target}/X.hpp"\n')
        os.makedirs(os.path.join(root, "src", "coupling"), exist_ok=True)
        with open(os.path.join(root, "src", "coupling", "Fine.cpp"), "w") as f:
            f.write('#include "vofdem/dem/Dem.hpp"\n#include "vofdem/flow/Flow.hpp"\n')
        found = check(root)
        missed = [rel for rel, _ in offences if not any(p.startswith(rel + ":3:") for p in found)]
        extra = [p for p in found if not any(p.startswith(rel + ":") for rel, _ in offences)]
        return structurecheck.self_test_verdict([rel for rel, _ in offences], missed, extra, "offence")


def main():
    return structurecheck.main(__doc__, check, self_test, "include floors", "offending includes")


if __name__ == "__main__":
    sys.exit(main())
