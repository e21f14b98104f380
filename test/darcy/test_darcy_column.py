#!/usr/bin/python3
"""G4, the column (docs/verification.md; docs/physics.md F11): -physics darcy on a 1-D column of fixed eps, fixed head on
its two ends. The head difference is raised in steps (-darcy_head_ramp), so one run gives the flow rate at several head
losses. Checked against the values computed here from the inputs alone (never from a run's output):
  - linear laws (kozenycarman, kozenycarman_d10, evolving): Q = A (k/mu) rho g dH/L to 1e-10 at every head loss, i.e. the
    head loss is linear in the flow rate with Darcy's slope;
  - a layered column (four equal layers of different eps): Q = A rho g dH/(mu sum_i L_i/k_i) (layers in series) to 1e-10;
  - Ergun's law with its inertial term: dp/L = a q + b q^2 solved for q, to 1e-10 (the head loss is not linear there);
  - the same columns on 1 and 2 ranks (the grid cut across the column) agree to round-off (1e-12).
Each check can fail: the tolerance is far below the differences between the laws, which the script also checks.
Usage: test_darcy_column.py VOFDEM"""
import csv
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

TOL, ROUNDOFF = 1e-10, 1e-12
G, RHO, MU = 9.81, 1000.0, 1e-3                    # the run's gravity magnitude, water
BOX = (0.1, 0.1, 1.0)                               # m; the column along z
STEP, FINAL = 0.1, 0.4                              # m: the ramp's step and the final head difference (4 levels)
D, K0, EPS0 = 1e-3, 2e-10, 0.35                     # grain size, the evolving law's reference state


def k_law(law, eps, q=0.0):
    """Intrinsic permeability (m^2) of seed 004 table 3, written here from the table, not from the code."""
    if law == "kozenycarman":
        e = min(eps, 0.7)
        return e ** 3 / (1 - e) ** 2 * D ** 2 / 180
    if law == "kozenycarman_d10":
        return D ** 2 * eps ** 3 / (150 * (1 - eps) ** 2)
    if law == "evolving":
        return K0 * (eps / EPS0) ** 3 * ((1 - EPS0) / (1 - eps)) ** 2
    raise ValueError(law)


def run(tmp, name, n, law, eps, cells="1,1,32", ranks=None):
    out = os.path.join(tmp, "%s-%d" % (name, n))
    args = ["-physics", "darcy", "-grid_cells", cells, "-grid_upper", ",".join(map(str, BOX)), "-gravity", "0,0,-%g" % G,
            "-darcy_axis", "z", "-darcy_head_difference", str(FINAL), "-darcy_head_ramp", "%g,1" % STEP,
            "-darcy_permeability_law", law, "-darcy_diameter", str(D), "-darcy_reference_permeability", str(K0),
            "-darcy_reference_fluid_fraction", str(EPS0), "-darcy_density", str(RHO), "-darcy_viscosity", str(MU),
            "-darcy_fluid_fraction", ",".join(map(str, eps)), "-dt", "1", "-max_steps", "3", "-monitor_every", "1",
            "-output_dir", out, "-darcy_ksp_rtol", "1e-15"]
    if ranks:
        args += ["-grid_ranks", ranks]
    run_vofdem(sys.argv[1], n, args)
    path = os.path.join(out, "monitor.csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [(float(r["darcy_head_difference_m"]), float(r["darcy_outflow_m3_s"]), float(r["darcy_inflow_m3_s"])) for r in csv.DictReader(f)]


def rel(a, b):
    return abs(a - b) / abs(b)


def main():
    tmp = tempfile.mkdtemp(prefix="vofdem-darcy-")
    A, L = BOX[0] * BOX[1], BOX[2]
    expected_levels = [STEP * (i + 1) for i in range(4)]
    slopes = {}
    cases = [("kc", "kozenycarman", [0.4]), ("kc-capped", "kozenycarman", [0.8]), ("d10", "kozenycarman_d10", [0.4]),
             ("evolving", "evolving", [0.42]), ("layered", "kozenycarman", [0.4, 0.3, 0.45, 0.35])]
    for name, law, eps in cases:
        # Layers in series: dp = Q mu/A sum_i (L/n)/k_i.
        resistance = sum((L / len(eps)) / k_law(law, e) for e in eps)
        slope = A * RHO * G / (MU * resistance)  # Q per m of head, Darcy's law
        slopes[name] = slope
        results = {}
        for n, cells, ranks in ((1, "1,1,32", None), (2, "2,2,32", "1,1,2")):
            rows = run(tmp, name, n, law, eps, cells, ranks)
            results[n] = rows
            levels = [r[0] for r in rows]
            check(len(rows) == 4 and all(rel(a, b) < 1e-14 for a, b in zip(levels, expected_levels)),
                  "%s, %d rank(s): the ramp gives head differences %s m (%s)" % (name, n, expected_levels, levels))
            worst = max([rel(q, slope * dH) for dH, q, _ in rows] or [1])
            check(worst < TOL, "%s (%s, eps %s), %d rank(s): Q = A k/mu rho g dH/L = %.10e m^3/s per m at every level: worst relative error %.2e < %g"
                  % (name, law, eps, n, slope, worst, TOL))
            balance = max([rel(qi, qo) for _, qo, qi in rows] or [1])
            check(balance < TOL, "%s, %d rank(s): inflow = outflow (%.2e)" % (name, n, balance))
        if results[1] and results[2]:
            diff = max(rel(a[1], b[1]) for a, b in zip(results[1], results[2]))
            check(diff < ROUNDOFF, "%s: 1 rank (1x1x32) and 2 ranks (2x2x32, cut across z) agree: %.2e < %g" % (name, diff, ROUNDOFF))
    # The checks discriminate: the laws' slopes differ by far more than the tolerance.
    gap = min(rel(slopes[a], slopes[b]) for a in slopes for b in slopes if a < b and {a, b} != {"kc", "kc-capped"})
    check(gap > 1e3 * TOL, "the cases' Darcy slopes differ by at least %.2e (>> %g): a wrong law or layer rule would fail" % (gap, TOL))
    check(rel(slopes["kc-capped"], slopes["kc"]) > 1e3 * TOL, "eps 0.8 above the cap gives k(0.7), not k(0.4)")

    # Ergun with its inertial term: dp/L = a q + b q^2 (a, b from Ergun 1952), q = (-a + sqrt(a^2 + 4 b dp/L))/(2 b).
    eps = 0.4
    a = 150 * MU * (1 - eps) ** 2 / (D ** 2 * eps ** 3)
    b = 1.75 * RHO * (1 - eps) / (D * eps ** 3)
    for n, cells, ranks in ((1, "1,1,32", None), (2, "2,2,32", "1,1,2")):
        rows = run(tmp, "ergun", n, "ergun", [eps], cells, ranks)
        worst, inertia = 1, 0
        if rows:
            worst = 0
            for dH, Q, _ in rows:
                grad = RHO * G * dH / L
                q = (-a + math.sqrt(a * a + 4 * b * grad)) / (2 * b)
                worst = max(worst, rel(Q, A * q))
                inertia = max(inertia, b * q * q / grad)
        check(worst < TOL, "ergun, %d rank(s): Q from dp/L = a q + b q^2 at every level: worst relative error %.2e < %g (inertial share of the head loss up to %.3f)"
              % (n, worst, TOL, inertia))
        check(inertia > 0.05, "ergun: the inertial term matters (%.3f of the head loss), so the linear law would fail" % inertia)
    finish()


main()
