#!/usr/bin/python3
"""E4's power check (docs/physics.md F8; docs/verification.md E4): the laser's column powers are exact integrals of
the Gaussian over each column's footprint, and the first metal of each column absorbs eta of its column's power, so
the power deposited in the cells is eta P to 1e-12 for R_l/h from 0.35 to 2 and beam centres off the grid lines:
  - a 24 x 24 x 6 plate of 1e-4 m cells, P 200 W, eta 0.4, the beam fixed at an off-grid point; one step;
  - the metal's top at 3.3 cells (gas above, a part-filled cell, the rest of the beam meets metal on the rank
    below when the box is split in z), split 1, 2 (in z) and 2 (in x) ways;
  - the adiabatic plate gains dt times the absorbed power (to 1e-10: the energies are of order 1e0 J, the gain 8e-5 J);
  - a column with less than one cell's worth of metal (a layer 0.3 cells deep) takes 0.3 of eta P_col (the rim of a
    drop smaller than a cell took a whole column's power before and reached 2e5 K);
  - the centre-value rule it replaces would be wrong: the test prints the ratio I(centre) h^2 / column power of
    the beam's own column at R_l/h 0.35 (seed 000's resolution), far from 1.
  test_laser_power.py VOFDEM"""
import math
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

H, P, ETA = 1e-4, 200.0, 0.4
CENTRE = (1.2137e-3, 1.1071e-3)  # off every grid line


def run(exe, tmp, name, ranks, split, radius, top=3.3):
    out = os.path.join(tmp, name)
    args = ["-physics", "energy", "-grid_cells", "24,24,6", "-grid_upper", "%g,%g,%g" % (24 * H, 24 * H, 6 * H), "-grid_ranks", split,
            "-energy_metal_top", "%g" % (top * H), "-energy_interface_radiation", "0", "-laser_power", "%g" % P, "-laser_radius", "%.10g" % radius,
            "-laser_absorptivity", "%g" % ETA, "-laser_path", "%.10g,%.10g" % CENTRE, "-dt", "1e-6", "-max_steps", "1", "-monitor_timing", "0",
            "-output_dir", out]
    run_vofdem(exe, ranks, args)
    with open(os.path.join(out, "monitor.csv")) as f:
        head, *rows = [line.strip().split(",") for line in f if line.strip()]
    first, last = dict(zip(head, rows[0])), dict(zip(head, rows[-1]))
    gained = float(last["energy_total_J"]) - float(first["energy_total_J"])
    return float(last["laser_beam_W"]), float(last["laser_absorbed_W"]), gained


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-laser-power-")
    try:
        for ratio in (0.35, 0.7, 1.0, 2.0):
            radius = ratio * H
            for ranks, split in ((1, "1,1,1"), (2, "1,1,2"), (2, "2,1,1")):
                beam, absorbed, gained = run(exe, tmp, "r%g-%s" % (ratio, split.replace(",", "")), ranks, split, radius)
                check(abs(gained - 1e-6 * absorbed) <= 1e-10 * 1e-6 * absorbed,
                      "R_l/h %.2f, ranks %s: the adiabatic plate gained %.12e J in the step of 1e-6 s, dt times the absorbed power %.12e J (tolerance 1e-10)"
                      % (ratio, split, gained, 1e-6 * absorbed))
                check(abs(beam - P) <= 1e-12 * P and abs(absorbed - ETA * P) <= 1e-12 * ETA * P,
                      "R_l/h %.2f, ranks %s: beam into the box %.15g W (P %g), absorbed %.15g W, off eta P by %.1e (tolerance 1e-12)"
                      % (ratio, split, beam, P, absorbed, abs(absorbed - ETA * P) / (ETA * P)))
        # A column with less than a cell's worth of metal (a layer 0.3 cells deep: the rim of a drop smaller than a cell
        # stands for it) takes that share of eta P_col, not all of it: the rest leaves through the bottom.
        for ranks, split in ((1, "1,1,1"), (2, "1,1,2")):
            beam, absorbed, gained = run(exe, tmp, "thin-%s" % split.replace(",", ""), ranks, split, H, top=0.3)
            check(abs(absorbed - 0.3 * ETA * P) <= 1e-12 * ETA * P and abs(gained - 1e-6 * absorbed) <= 1e-10 * 1e-6 * absorbed,
                  "0.3 cells of metal, ranks %s: absorbed %.15g W, 0.3 eta P to %.1e (tolerance 1e-12); the plate gained dt times it"
                  % (split, absorbed, abs(absorbed - 0.3 * ETA * P) / (ETA * P)))
        # The centre-value rule at R_l/h = 0.35 for the column holding the beam centre.
        r = 0.35 * H
        i, j = math.floor(CENTRE[0] / H), math.floor(CENTRE[1] / H)
        s = math.sqrt(2) / r
        exact = 0.25 * P * (math.erf(s * ((i + 1) * H - CENTRE[0])) - math.erf(s * (i * H - CENTRE[0]))) * \
            (math.erf(s * ((j + 1) * H - CENTRE[1])) - math.erf(s * (j * H - CENTRE[1])))
        xc, yc = (i + 0.5) * H, (j + 0.5) * H
        centre = 2 * P / (math.pi * r * r) * math.exp(-2 * ((xc - CENTRE[0]) ** 2 + (yc - CENTRE[1]) ** 2) / (r * r)) * H * H
        check(abs(centre / exact - 1) > 0.1, "R_l/h 0.35: the centre value would give the beam's column %.4g of its power (the exact integral: %.4g W)"
              % (centre / exact, exact))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
