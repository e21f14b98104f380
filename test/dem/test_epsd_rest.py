#!/usr/bin/python3
"""EPSD rolling resistance lets a JKR pile rest (docs/physics.md P5; HertzMindlin.hpp RollingTorque):
  - the 100-sphere JKR pile of dem/jkr_step (E 1e7 Pa, gamma 0.05 J/m^2, mu 0.5, R 0.1 mm) with
    -dem_rolling epsd -dem_rolling_friction 0.1, (a) e 0.3 with -dem_rolling_load adhesion and (b) e 0.6 with
    the default load, settles: its largest kinetic energy (translational plus rotational) over t = 0.36-0.4 s
    is below 1e-20 J, or below the same pile's with cdt if that is lower, on 1 and 2 ranks;
  - with -dem_rolling_twist 0 (EPSD for rolling only, the model before the twist was resisted) pile (a) does
    not: spheres spin about the line of their contacts' normals, above 1e-16 J (the check that the first
    one can fail).
  test_epsd_rest.py VOFDEM"""
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

SCENE = ["-physics", "dem", "-grid_upper", "1e-3,1e-3,3e-3", "-grid_cells", "2,2,6", "-dem_radius", "1e-4", "-dem_density", "2500",
         "-dem_youngs_modulus", "1e7", "-dem_friction", "0.5", "-dem_cohesion", "jkr", "-dem_surface_energy", "0.05",
         "-dem_fill_count", "100", "-dem_fill_spacing", "2.1e-4", "-dem_fill_jitter", "0.3", "-dem_fill_velocity_spread", "0.05", "-seed", "5",
         "-dem_rolling_friction", "0.1", "-monitor_timing", "0", "-monitor_every", "1000", "-final_time", "0.4", "-max_steps", "10000000"]
PILES = {"a": ["-dem_restitution", "0.3", "-dem_rolling_load", "adhesion"], "b": ["-dem_restitution", "0.6"]}
NAMES = {"a": "e 0.3, load F_n + 2 F_c", "b": "e 0.6, load max(F_n, 0)"}


def late_energy(outdir):
    """The largest translational plus rotational kinetic energy of the monitor rows from t = 0.36 s on (None without any)."""
    path = os.path.join(outdir, "monitor.csv")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        head, *rows = [line.strip().split(",") for line in f if line.strip()]
    t, k, r = head.index("time_s"), head.index("kinetic_energy_J"), head.index("rotational_energy_J")
    late = [float(row[k]) + float(row[r]) for row in rows if float(row[t]) >= 0.36]
    return max(late) if late else None


def run(exe, tmp, name, ranks, args):
    out = os.path.join(tmp, name)
    run_vofdem(exe, ranks, SCENE + args + ["-grid_ranks", "1,1,%d" % ranks, "-output_dir", out])
    return late_energy(out)


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-epsd-rest-")
    try:
        for pile, args in PILES.items():
            cdt = run(exe, tmp, pile + "-cdt", 1, args + ["-dem_rolling", "cdt"])
            check(cdt is not None, "pile (%s) with cdt: kinetic energy %s J over t = 0.36-0.4 s" % (pile, "%.3g" % cdt if cdt is not None else "none"))
            tol = min(1e-20, cdt) if cdt is not None else 1e-20
            for ranks in (1, 2):
                e = run(exe, tmp, "%s-epsd-%d" % (pile, ranks), ranks, args + ["-dem_rolling", "epsd"])
                check(e is not None and e < tol, "pile (%s: %s) with epsd on %d rank(s) comes to rest: kinetic energy %s J over t = 0.36-0.4 s "
                      "(tolerance %.3g J: 1e-20 or cdt's %.3g, the lower)" % (pile, NAMES[pile], ranks, "%.3g" % e if e is not None else "none", tol,
                                                                              cdt if cdt is not None else float("nan")))
        e = run(exe, tmp, "a-twist-free", 1, PILES["a"] + ["-dem_rolling", "epsd", "-dem_rolling_twist", "0"])
        check(e is not None and e > 1e-16, "pile (a) with -dem_rolling_twist 0 does not: kinetic energy %s J over t = 0.36-0.4 s (> 1e-16)"
              % ("%.3g" % e if e is not None else "none"))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
