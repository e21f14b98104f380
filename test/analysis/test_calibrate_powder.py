#!/usr/bin/python3
"""scripts/calibrate-powder's interpolation (no vofdem run): tables of angle and density made from known fields
over a (mu_r, gamma) grid, read with --table, must give the crossing of the two target curves:
  - fields bilinear in (log mu_r, log gamma): the crossing is exact (1e-9), whether the two curves cross in
    the first cell, a later one, or on a shared cell edge (counted once);
  - smooth non-bilinear fields whose target curves cross at a shallow angle (as a calibration's do: both
    results grow with both parameters): the crossing within 3 % on a 9 x 9 grid and 0.7 % on 17 x 17, the
    error falling at second order;
  - a grid that does not bracket the targets exits 2 and says which result misses its target on which side;
  - the plot is written; a table without the needed columns is refused in one line.
  test_calibrate_powder.py"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "calibrate-powder")
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check as _check, finish  # noqa: E402


def check(ok, what, detail=""):
    _check(ok, what)
    if not ok and detail:
        print(detail)


def table(path, mus, gammas, angle, density, holes=()):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["mu_r", "gamma", "angle_height", "angle_flank", "density"])
        for m in mus:
            for g in gammas:
                if (m, g) in holes:
                    continue
                w.writerow(["%.17g" % m, "%.17g" % g, "%.17g" % angle(m, g), "%.17g" % (angle(m, g) - 5), "%.17g" % density(m, g)])


def calibrate(path, *extra):
    p = subprocess.run([sys.executable, SCRIPT, "--table", path] + list(extra), capture_output=True, text=True)
    pairs = [(float(a), float(b)) for a, b in re.findall(r"calibrated mu_r (\S+), gamma (\S+) J/m\^2", p.stdout)]
    return p.returncode, pairs, p.stdout + p.stderr


def geometric(lo, hi, n):
    return [lo * (hi / lo) ** (k / (n - 1)) for k in range(n)]


with tempfile.TemporaryDirectory() as tmp:
    t = os.path.join(tmp, "t.csv")
    # Bilinear in x = log mu, y = log gamma (with a cross term): the interpolant is exact, so is the crossing.
    # angle = 30 + 4 x' + 2 y' + 0.5 x' y', density = 0.58 - 0.004 x' - 0.008 y' + 0.001 x' y', x' = ln(mu/0.0315),
    # y' = ln(gamma/1.5e-4); targets chosen at a known point.
    def ang(m, g):
        x, y = math.log(m / 0.0315), math.log(g / 1.5e-4)
        return 30 + 4 * x + 2 * y + 0.5 * x * y

    def den(m, g):
        x, y = math.log(m / 0.0315), math.log(g / 1.5e-4)
        return 0.58 - 0.004 * x - 0.008 * y + 0.001 * x * y

    for name, (mu0, g0), grid_mu, grid_g in (
            ("first cell", (0.04, 2.0e-4), [0.0315, 0.063], [1.5e-4, 3e-4]),
            ("a later cell of a 3 x 4 grid", (0.09, 5.0e-4), [0.0315, 0.063, 0.126], [1e-4, 1.5e-4, 3e-4, 6e-4]),
            ("on a shared edge", (0.063, 2.2e-4), [0.0315, 0.063, 0.126], [1.5e-4, 3e-4])):
        table(t, grid_mu, grid_g, ang, den)
        rc, pairs, out = calibrate(t, "--angle", "%.17g" % ang(mu0, g0), "--density", "%.17g" % den(mu0, g0))
        ok = rc == 0 and len(pairs) == 1 and abs(pairs[0][0] / mu0 - 1) < 1e-4 and abs(pairs[0][1] / g0 - 1) < 1e-4
        check(ok, "bilinear fields, crossing in %s: found %s, expected (%g, %g)" % (name, pairs, mu0, g0), out if not ok else "")

    # Smooth fields that are not bilinear; the crossing is found by a fine 2-D Newton solve here for comparison.
    def ang2(m, g):
        return 20 + 60 * m ** 0.5 + 3 * math.log(g / 1e-4) ** 1.5

    def den2(m, g):
        return 0.62 - 0.3 * m - 0.01 * math.log(g / 1e-4)

    mu0, g0 = 0.07, 3.5e-4
    target = (ang2(mu0, g0), den2(mu0, g0))
    errs = []
    for n, allowed in ((9, 0.03), (17, 0.007)):
        table(t, geometric(0.02, 0.2, n), geometric(1.2e-4, 1e-3, n), ang2, den2)
        rc, pairs, out = calibrate(t, "--angle", "%.17g" % target[0], "--density", "%.17g" % target[1])
        err = max(abs(pairs[0][0] / mu0 - 1), abs(pairs[0][1] / g0 - 1)) if rc == 0 and len(pairs) == 1 else float("inf")
        errs.append(err)
        check(err < allowed, "smooth fields, %d x %d grid: crossing %s against (%g, %g), relative error %.2e (%g allowed)" % (n, n, pairs, mu0, g0, err, allowed))
    # Bilinear interpolation is second order: halving the spacing divides the error by about 4 (more than 3 asked).
    check(errs[0] > 3 * errs[1], "the crossing converges at second order: %.2e -> %.2e" % (errs[0], errs[1]))

    # Flank measure: the table's angle_flank is 5 deg lower, so the same crossing needs a 5 deg lower target.
    table(t, [0.0315, 0.063], [1.5e-4, 3e-4], ang, den)
    rc, pairs, out = calibrate(t, "--angle-measure", "flank", "--angle", "%.17g" % (ang(0.04, 2e-4) - 5), "--density", "%.17g" % den(0.04, 2e-4))
    check(rc == 0 and len(pairs) == 1 and abs(pairs[0][0] / 0.04 - 1) < 1e-4, "the flank measure reads angle_flank: %s" % pairs)

    # Not bracketed: the angle never reaches 45 deg on this grid.
    png = os.path.join(tmp, "c.png")
    rc, pairs, out = calibrate(t, "--angle", "45", "--density", "0.575", "--plot", png)
    check(rc == 2 and not pairs and "angle" in out and "below the target 45" in out, "an unbracketed target exits 2 and says the angle stays below 45: rc %d" % rc, out)
    check("at mu_r 0.063 the angle target is reached at gamma none" in out, "the unbracketed report says, per mu_r, where each target is reached", out)
    check(os.path.getsize(png) > 10000 if os.path.exists(png) else False, "the plot is written: %s" % png)

    # A grid with a hole (one point not finished): the cells around it are skipped, the others still give the crossing,
    # and the row with the hole is reported from its finished points.
    grid_mu, grid_g = [0.0315, 0.063, 0.126], [1e-4, 1.5e-4, 3e-4, 6e-4]
    table(t, grid_mu, grid_g, ang, den, holes=[(0.0315, 1.5e-4)])
    rc, pairs, out = calibrate(t, "--angle", "%.17g" % ang(0.09, 5e-4), "--density", "%.17g" % den(0.09, 5e-4), "--plot", png)
    ok = rc == 0 and len(pairs) == 1 and abs(pairs[0][0] / 0.09 - 1) < 1e-4 and abs(pairs[0][1] / 5e-4 - 1) < 1e-4
    check(ok, "a grid with a hole still finds the crossing in its complete cells: %s" % pairs, out if not ok else "")
    rc, pairs, out = calibrate(t, "--angle", "45", "--density", "0.575", "--plot", png)
    check(rc == 2 and "at mu_r 0.0315 the angle target is reached at gamma none" in out,
          "the row with the hole is reported from its three finished points: rc %d" % rc, out)

    # A flat density field (every point the same) is plotted too, not a traceback.
    table(t, [0.0315, 0.063], [1.5e-4, 3e-4], ang, lambda m, g: 0.57)
    rc, pairs, out = calibrate(t, "--angle", "32", "--density", "0.572", "--plot", png)
    check(rc == 2 and "Traceback" not in out and "density target at none" in out, "a flat density field exits 2 with its report: rc %d" % rc, out)

    # Bad table: one line naming the file and the columns.
    with open(t, "w") as f:
        f.write("mu_r,gamma,density\n0.03,1e-4,0.6\n")
    p = subprocess.run([sys.executable, SCRIPT, "--table", t], capture_output=True, text=True)
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    check(p.returncode != 0 and len(lines) == 1 and "t.csv: needs the columns" in lines[0], "a table without angle_height is refused in one line: %s" % lines)

finish()
