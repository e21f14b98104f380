#!/usr/bin/python3
"""Loaded contacts and the DEM time step (HertzMindlin.hpp SpinContact/SpinStep, Dem::UpdateContactStepLimit):
  - a deep bed of soft, low-restitution spheres (400 spheres of d 1 mm in a 5 x 5 mm periodic column, E 5 MPa,
    e 0.3, under 200 m/s^2: the load of a bed 20 times as deep under gravity, overlaps to 2.5 % of d) at the
    default 0.3 Rayleigh times: the contacts, measured as they are, lower the step; the run says so once, and
    the bed comes to rest (kinetic energy below 1e-10 J, rotation below 1e-12 J at t = 0.3 s) on 1 and 2 ranks,
    with the same number of steps;
  - without the measurement (-dem_contact_step_every 0) the lowest spheres keep spinning: rotational energy
    above 1e-9 J at t = 0.3 s (the check that the first can fail).
  test_contact_step.py VOFDEM"""
import os
import re
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

SCENE = ["-physics", "dem", "-grid_upper", "5e-3,5e-3,30e-3", "-grid_cells", "2,2,12", "-grid_periodic", "x,y", "-dem_radius", "5e-4",
         "-dem_density", "2000", "-dem_youngs_modulus", "5e6", "-dem_restitution", "0.3", "-dem_fill_mode", "random", "-dem_fill_count", "400",
         "-dem_fill_lower", "0,0,1e-3", "-gravity", "0,0,-200", "-seed", "3", "-monitor_timing", "0", "-monitor_every", "4000",
         "-final_time", "0.3", "-max_steps", "10000000"]


def last_row(outdir):
    """The last monitor row as a dict of floats."""
    with open(os.path.join(outdir, "monitor.csv")) as f:
        head, *rows = [line.strip().split(",") for line in f if line.strip()]
    return {k: float(v) for k, v in zip(head, rows[-1])}


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-contact-step-")
    try:
        steps = []
        for n in (1, 2):
            out = os.path.join(tmp, "on%d" % n)
            p = run_vofdem(exe, n, SCENE + (["-grid_ranks", "1,1,2"] if n == 2 else []) + ["-output_dir", out])
            tr = re.search(r"Rayleigh time ([0-9.e+-]+) s", p.stdout)
            note = re.search(r"the contacts as they are allow steps of at most ([0-9.e+-]+) s", p.stdout)
            check(tr is not None and note is not None and p.stdout.count("the contacts as they are allow steps") == 1,
                  "%d rank(s): the run says once that the contacts bound the step (and takes it: below)" % n)
            if tr is None or note is None:
                continue
            row = last_row(out)
            steps.append(int(row["step"]))
            check(row["dt_s"] < 0.3 * float(tr.group(1)), "%d rank(s): the step at the end %.3e s is below 0.3 Rayleigh times (%.3e s)" % (n, row["dt_s"], 0.3 * float(tr.group(1))))
            check(row["kinetic_energy_J"] < 1e-10 and row["rotational_energy_J"] < 1e-12,
                  "%d rank(s): the bed comes to rest: kinetic %.2e J (< 1e-10), rotational %.2e J (< 1e-12) at t = 0.3 s" % (n, row["kinetic_energy_J"], row["rotational_energy_J"]))
        check(len(steps) == 2 and steps[0] == steps[1], "1 and 2 ranks take the same number of steps: %s" % steps)
        out = os.path.join(tmp, "off")
        run_vofdem(exe, 2, SCENE + ["-grid_ranks", "1,1,2", "-dem_contact_step_every", "0", "-output_dir", out])
        row = last_row(out)
        check(row["rotational_energy_J"] > 1e-9, "at 0.3 Rayleigh times without the measurement the spheres keep spinning: rotational %.2e J at t = 0.3 s (> 1e-9)" % row["rotational_energy_J"])
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
