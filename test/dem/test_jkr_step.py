#!/usr/bin/python3
"""JKR bonds at rest and the DEM time step (HertzMindlin.hpp SpinStep, Dem::SetUp):
  - a pile of 100 soft, strongly adhesive spheres with low restitution (E 1e7 Pa, gamma 0.05 J/m^2, e 0.3,
    mu 0.5, R 0.1 mm) takes the step its bonds allow, below 0.3 Rayleigh times, and the banner says so;
  - at that step the pile comes to rest: kinetic energy below 1e-16 J at t = 0.2 s;
  - at the Rayleigh step the scene had before (0.3 T_R, forced) it does not: its bonds chatter and the
    kinetic energy stays above 1e-12 J (the check that the first one can fail).
  On 1 rank (2 ranks for the forced run).
  test_jkr_step.py VOFDEM"""
import os
import re
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

SCENE = ["-physics", "dem", "-grid_upper", "1e-3,1e-3,3e-3", "-grid_cells", "2,2,6", "-dem_radius", "1e-4", "-dem_density", "2500",
         "-dem_youngs_modulus", "1e7", "-dem_restitution", "0.3", "-dem_friction", "0.5", "-dem_cohesion", "jkr", "-dem_surface_energy", "0.05",
         "-dem_fill_count", "100", "-dem_fill_spacing", "2.1e-4", "-dem_fill_jitter", "0.3", "-dem_fill_velocity_spread", "0.05", "-seed", "5",
         "-monitor_timing", "0", "-monitor_every", "10000", "-final_time", "0.2", "-max_steps", "10000000"]


def kinetic(outdir):
    """The last monitor row's translational plus rotational kinetic energy."""
    with open(os.path.join(outdir, "monitor.csv")) as f:
        head, *rows = [line.strip().split(",") for line in f if line.strip()]
    return float(rows[-1][head.index("kinetic_energy_J")]) + float(rows[-1][head.index("rotational_energy_J")])


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-jkr-step-")
    try:
        p = run_vofdem(exe, 1, SCENE + ["-output_dir", os.path.join(tmp, "default")])
        m = re.search(r"time step: ([0-9.e+-]+) s \(set by (.*)\); gravity", p.stdout)
        tr = re.search(r"Rayleigh time ([0-9.e+-]+) s", p.stdout)
        check(m is not None and tr is not None, "the banner gives the time step, its basis and the Rayleigh time")
        if m is None or tr is None:
            return
        dt, trayleigh = float(m.group(1)), float(tr.group(1))
        check("JKR bonds at rest" in m.group(2) and dt < 0.3 * trayleigh,
              "the step is set by the JKR bonds: %.3e s = %.3f Rayleigh times (%s)" % (dt, dt / trayleigh, m.group(2)))
        e = kinetic(os.path.join(tmp, "default"))
        check(e < 1e-16, "at that step the pile comes to rest: kinetic energy %.2e J at t = 0.2 s (< 1e-16)" % e)
        run_vofdem(exe, 2, SCENE + ["-grid_ranks", "1,1,2", "-dt", "%.17g" % (0.3 * trayleigh), "-dt_force", "-output_dir", os.path.join(tmp, "rayleigh")])
        e = kinetic(os.path.join(tmp, "rayleigh"))
        check(e > 1e-12, "at 0.3 Rayleigh times (forced) it does not: kinetic energy %.2e J at t = 0.2 s (> 1e-12)" % e)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
