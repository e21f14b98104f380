#!/usr/bin/python3
"""Smoke runs of the full-size lunar-regolith spreading scene (config/scenes/lunar-spreading.yaml, seed 002),
which only the validate tier runs whole (test/validate/d8-lunar-spreading): the scene file is read as it is
from the source root, with the feed 25,000x faster so that ~1000 clumps enter within 200 steps on 2 ranks;
then the moon setting without van der Waals, and the super-ellipse blade instead of the rollers (the
options the scene file gives), 20 steps each. Checks: exit 0, every wall set up (and the unchosen ones removed from t = 0), the time step of the
linear law (0.3 x a tenth of the contact time pi sqrt(m/(2 k_n)) of the smallest member sphere, P4), all
steps run, clumps inserted and none lost (particles = inserted - deleted), van der Waals on or off.
Usage: test_lunar_smoke.py VOFDEM"""
import math
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, failures, run_vofdem  # noqa: E402

SCENE = os.path.join("config", "scenes", "lunar-spreading.yaml")
BLADE = "-dem_wall_blade_remove_time 1e9 -dem_wall_rollera_remove_time 0 -dem_wall_rollerb_remove_time 0".split()


def smoke(exe, name, extra, steps, walls, vdw, gone):
    p = run_vofdem(exe, 2, ["-options_file_yaml", SCENE, "-dem_insert_feed_mass_rate", "5", "-max_steps", str(steps), "-monitor_every", str(steps),
                            "-analysis_metrics", ""] + extra)
    out = p.stdout
    missing = [w for w in walls if not re.search(r"^dem: wall %s: " % w, out, re.M)]
    removed = sorted(w for w in walls if re.search(r"^dem: wall %s: .*removed at t = 0 s" % w, out, re.M))
    check(removed == gone, "%s: walls removed from t = 0: %s (expected %s)" % (name, ",".join(removed) or "none", ",".join(gone)))
    check(not missing, "%s: every wall set up (%s)%s" % (name, ",".join(walls), "; missing " + ",".join(missing) if missing else ""))
    check(bool(re.search(r"^dem: van der Waals", out, re.M)) == vdw, "%s: van der Waals %s" % (name, "on" if vdw else "off"))
    rmin = re.search(r"^dem: \d+ spheres of radius (\S+) to", out, re.M)
    dt = re.search(r"^time step: (\S+) s", out, re.M)
    if rmin and dt:
        r = float(rmin.group(1))
        want = 0.3 * 0.1 * math.pi * math.sqrt(2770 * 4 / 3 * math.pi * r ** 3 / (2 * 1e5))
        check(abs(float(dt.group(1)) / want - 1) < 1e-3, "%s: time step %s s (0.3 x contact time/10 at the smallest member radius %.3g m: %.4g s)" % (name, dt.group(1), r, want))
    else:
        check(False, "%s: the set-up prints the radius range and the time step" % name)
    last = [l for l in out.splitlines() if l.startswith("step")]
    if not last:
        check(False, "%s: no step line" % name)
        return
    last = last[-1]
    n, parts = int(last.split()[1]), int(re.search(r"particles (\d+)", last).group(1))
    ins, dele = (int(x) for x in re.search(r"inserted (\d+) deleted (\d+)", last).groups())
    check(n == steps and ins > 0 and parts == ins - dele, "%s: %d steps run, %d spheres inserted, %d deleted, %d present" % (name, n, ins, dele, parts))


def main():
    exe = os.path.abspath(sys.argv[1])
    os.chdir(ROOT)
    smoke(exe, "earth, van der Waals, rollers", [], 200, ["slot", "rollera", "rollerb", "blade"], True, ["blade"])
    smoke(exe, "moon, no van der Waals", ["-gravity", "0,0,-1.63", "-dem_hamaker", "0"], 20, ["slot", "rollera", "rollerb", "blade"], False, ["blade"])
    smoke(exe, "super-ellipse blade", BLADE, 20, ["slot", "rollera", "rollerb", "blade"], True, ["rollera", "rollerb"])
    if failures:
        print("FAIL: %d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
