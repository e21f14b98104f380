#!/usr/bin/python3
"""Smoke runs of the full-size powder scenes that only the validate tier runs whole (config/scenes/
tungsten-spreading.yaml, tungsten-repose.yaml, tungsten-density.yaml): each scene file is read as it
is, with 300 particles and 300 steps on 2 ranks, from the source root (the scenes name their STL files
relative to it). Checks: exit 0, every wall of the scene set up (its line in the set-up), the time step
of seed 001 (0.3 Rayleigh times at R = 6 um, E' = 3.4 GPa: 2.34e-8 s, P9), all 300 steps run, no
particle lost. The poured repose check (tungsten-repose-pour.yaml, no initial fill) runs 3,000 steps:
its source has put particles in by then, all still present.
Usage: test_scene_smoke.py VOFDEM"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, failures, run_vofdem  # noqa: E402

SCENES = {"tungsten-spreading": ["blade", "hopperleft", "hopperright"], "tungsten-repose": ["funnel", "cup"], "tungsten-density": [],
          "tungsten-repose-pour": ["cup"]}
POURED = {"tungsten-repose-pour"}  # no fill: particles come from an insertion source


def main():
    exe = os.path.abspath(sys.argv[1])
    os.chdir(ROOT)
    for name, walls in SCENES.items():
        steps_asked = 3000 if name in POURED else 300
        fill = [] if name in POURED else ["-dem_fill_count", "300"]
        p = run_vofdem(exe, 2, ["-options_file_yaml", os.path.join("config", "scenes", name + ".yaml")] + fill + ["-max_steps", str(steps_asked),
                                "-monitor_every", str(steps_asked), "-analysis_metrics", ""])
        out = p.stdout
        missing = [w for w in walls if not re.search(r"^dem: wall %s: " % w, out, re.M)]
        check(not missing, "%s: every wall set up (%s)%s" % (name, ",".join(walls) or "none", "; missing " + ",".join(missing) if missing else ""))
        dt = re.search(r"^time step: (\S+) s", out, re.M)
        check(dt is not None and abs(float(dt.group(1)) / 2.34e-8 - 1) < 0.01, "%s: time step %s s (seed 001: 2.38e-8 s; 0.3 T_R at 6 um: 2.34e-8 s)" % (name, dt.group(1) if dt else "?"))
        last = [l for l in out.splitlines() if l.startswith("step")][-1]
        steps, parts = int(last.split()[1]), int(re.search(r"particles (\d+)", last).group(1))
        if name in POURED:
            inserted = int(re.search(r"inserted (\d+)", last).group(1))
            check(steps == steps_asked and parts == inserted > 0, "%s: %d steps run, %d particles inserted, %d present" % (name, steps, inserted, parts))
        else:
            check(steps == 300 and parts == 300, "%s: %d steps run, %d of 300 particles left" % (name, steps, parts))
    if failures:
        print("FAIL: %d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
