#!/usr/bin/python3
"""Checkpoints of the Darcy seepage (docs/modules/darcy.md): a run stopped at half time with -checkpoint_final and continued
with -restart latest ends on the same monitor line as the run that was not stopped (every column but the wall time, to the
digit), on 1 and 2 ranks, for -physics darcy (a ramped head, Ergun's law: the Picard iterations start from the saved
pressure) and -physics dem,darcy (a bed lifting under a ramped head). Usage: test_darcy_restart.py VOFDEM"""
import csv
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

COLUMN = ["-physics", "darcy", "-grid_cells", "2,2,16", "-grid_upper", "0.1,0.1,1", "-darcy_axis", "z", "-darcy_head_difference", "0.5",
          "-darcy_head_ramp", "0.1,1", "-darcy_permeability_law", "ergun", "-darcy_fluid_fraction", "0.4,0.35", "-dt", "1"]
STEPS = {"column": 6, "bed": 200}


def bed(tmp):
    path = os.path.join(tmp, "bed.csv")
    with open(path, "w") as f:
        f.write("x,y,z\n")
        for k in range(8):
            for j in range(4):
                for i in range(4):
                    f.write("%g,%g,%g\n" % ((i + 0.5) * 1e-3, (j + 0.5) * 1e-3, (k + 0.5) * 1e-3))
    return ["-physics", "dem,darcy", "-grid_cells", "4,4,16", "-grid_upper", "0.004,0.004,0.016", "-grid_periodic", "x,y", "-dem_particles_file", path,
            "-dem_radius", "0.5e-3", "-dem_density", "2650", "-dem_youngs_modulus", "5e6", "-dem_restitution", "0.3", "-darcy_axis", "z",
            "-darcy_head_difference", "0.0072", "-darcy_head_ramp", "0.002,0.001", "-darcy_permeability_law", "kozenycarman_d10", "-seepage_kernel", "divided"]


def last_line(out):
    path = os.path.join(out, "monitor.csv")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: v for k, v in rows[-1].items() if k != "wall_time_s"} if rows else {}


def main():
    tmp = tempfile.mkdtemp(prefix="vofdem-darcy-restart-")
    scenes = {"column": COLUMN, "bed": bed(tmp)}
    exe = sys.argv[1]
    for name, scene in scenes.items():
        steps = STEPS[name]
        common = scene + ["-monitor_every", str(steps // 2), "-monitor_timing", "0"]
        for n in (1, 2):
            full, half = os.path.join(tmp, "%s-full-%d" % (name, n)), os.path.join(tmp, "%s-half-%d" % (name, n))
            run_vofdem(exe, n, common + ["-max_steps", str(steps), "-output_dir", full])
            run_vofdem(exe, n, common + ["-max_steps", str(steps // 2), "-checkpoint_final", "-output_dir", half])
            p = run_vofdem(exe, n, common + ["-max_steps", str(steps), "-restart", "latest", "-output_dir", half])
            a, b = last_line(full), last_line(half)
            differ = [k for k in a if a.get(k) != b.get(k)]
            check(bool(a) and a.get("step") == str(steps) and not differ,
                  "%s, %d rank(s): the restarted run ends on the uninterrupted run's line at step %d%s" % (name, n, steps, (" (differ: %s)" % differ) if differ else ""))
            check("restart" in p.stdout.lower() or "checkpoint" in p.stdout.lower(), "%s, %d rank(s): the second run says it restarted" % (name, n))
    finish()


main()
