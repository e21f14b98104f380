#!/usr/bin/python3
"""-help lists the options of named things (insertion sources, walls) instead of stopping at their first missing
option: without names once for NAME, with -dem_inserts/-dem_walls for each name given; exits 0 on 1 and 2 ranks.
  test_help_sources.py VOFDEM"""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import ENV, check, finish  # noqa: E402

exe = os.path.abspath(sys.argv[1])
for ranks in (1, 2):
    for extra, wanted in (([], ["-dem_insert_NAME_lower", "-dem_insert_NAME_every", "-dem_wall_NAME_type"]),
                          (["-dem_inserts", "pour,feed", "-dem_walls", "blade"],
                           ["-dem_insert_pour_lower", "-dem_insert_pour_rate", "-dem_insert_feed_upper", "-dem_wall_blade_type"])):
        p = subprocess.run(["mpiexec", "--oversubscribe", "-n", str(ranks), exe, "-physics", "dem", "-help"] + extra,
                           env=ENV, capture_output=True, text=True, timeout=120)
        out = p.stdout + p.stderr
        missing = [w for w in wanted if w + " " not in out]
        check(p.returncode == 0 and not missing and "vofdem: error" not in out,
              "%d rank(s), -help %s: exit %d, options missing from the listing: %s" % (ranks, " ".join(extra), p.returncode, missing or "none"))
        if p.returncode or missing:
            print(out[-2000:])
finish()
