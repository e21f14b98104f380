#!/usr/bin/python3
"""-help prints and exits, writing nothing (issue 55): vofdem and every example run with -help in an empty folder on
2 ranks exit 0, print their options, and leave the folder empty; vofdem's -physics line lists only the modules this
build has (the vofdem_add_module lines of CMakeLists.txt, in order). Before: ex03, ex06 and ex12 ran part of their work and left CSV files, and -physics listed energy, which a
run then refused; -dem_fill_size_distribution's help read as if the discrete fractions were by number. Usage: test_help.py VOFDEM EXAMPLE_DIR"""
import glob
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import ENV, check, finish  # noqa: E402


def main():
    exe, exdir = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    programs = [exe] + sorted(p for p in glob.glob(os.path.join(exdir, "ex[0-9]*")) if os.access(p, os.X_OK) and not p.endswith(".out"))
    check(len(programs) > 40, "vofdem and the examples found (%d programs)" % len(programs))
    for prog in programs:
        tmp = tempfile.mkdtemp(prefix="vofdem-help-")
        p = subprocess.run(["mpiexec", "-n", "2", "--oversubscribe", prog, "-help"], cwd=tmp, env=ENV, capture_output=True, text=True, timeout=120)
        left = sorted(os.listdir(tmp))
        name = os.path.basename(prog)
        check(p.returncode == 0 and "-dem_radius" in p.stdout and not left,
              "%s -help: exit %d, lists the module options (%s), writes nothing (left: %s)" % (name, p.returncode, "-dem_radius" in p.stdout, left))
        if prog == exe:
            line = next((l for l in p.stdout.splitlines() if l.strip().startswith("-physics")), "")
            with open(os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "CMakeLists.txt")) as f:
                built = re.findall(r"^vofdem_add_module\((\w+)\)", f.read(), re.M)
            listed = re.search(r"any of: ([\w, ]+)\)", line)
            built = [m for m in built if m != "coupling"]  # implied by dem and flow together, not a -physics word
            check(listed is not None and listed.group(1).split(", ") == built,
                  "vofdem -help: -physics lists the modules this build has (CMakeLists.txt: %s): %s" % (", ".join(built), line.strip()))
            line = next((l for l in p.stdout.splitlines() if l.strip().startswith("-dem_fill_size_distribution")), "")
            check("MASS fractions" in line and "BY NUMBER" in line,
                  "vofdem -help: -dem_fill_size_distribution says which law is by mass and which by number: %s" % line.strip())
        for f in left:
            os.remove(os.path.join(tmp, f)) if os.path.isfile(os.path.join(tmp, f)) else None
        try:
            os.rmdir(tmp)
        except OSError:
            pass
    finish()


if __name__ == "__main__":
    main()
