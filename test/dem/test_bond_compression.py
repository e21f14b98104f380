#!/usr/bin/python3
"""Verification G3, quick tier (docs/physics.md P13; docs/verification.md): the smallest bonded cylinder of
scripts/bond-compression (114 spheres in an fcc lattice, 472 parallel bonds, D = 10 r, scripts/lib/bondcompression.py)
compressed between two platens closing at v = 0.1 and 0.05 m/s (v / c 1.2e-4 and 5.8e-5, c the specimen's P-wave speed:
the start's wave strain v / c is 2 % and 1 % of the strain at the peak; scripts/bond-compression runs 5 and 10 times slower),
to a strain of 0.0075, past the peak.
  - The rise is linear: between 10 % and 50 % of the peak the points are within 1 % of the peak from their
    least-squares line, and both platens carry the same load there to 1 % (the specimen is in equilibrium).
  - Rate independence: Young's modulus E (that line's slope) and the peak stress at the two speeds agree within 2 %.
  - A peak exists: the stress falls below half the peak before the end, no bond is broken on the rows before the
    peak, and bonds are broken after it.
  - 1 and 2 ranks (the rank boundary across the cylinder's middle) at v = 0.1 m/s: the same bonds broken on every row
    up to two rows past the peak, and the stresses equal to 1e-10 of the peak on those rows.
  test_bond_compression.py VOFDEM"""
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
import bondcompression as bc  # noqa: E402
from testcheck import check, finish  # noqa: E402

DIAMETER, STRAIN_END, FAST, SLOW = 10, 0.0075, 0.1, 0.05


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-bond-compression-")
    try:
        curves = {}
        for ranks, v in ((1, FAST), (1, SLOW), (2, FAST)):
            # the same monitor rows for the same speed on either rank count
            curves[ranks, v] = bc.run(exe, ranks, DIAMETER, v, STRAIN_END, os.path.join(tmp, "r%d-v%g" % (ranks, v)), rows=300, timeout=600)
        if any(c is None for c in curves.values()):
            check(False, "every run wrote its monitor")
            finish()
            return
        res = {k: bc.analyse(c) for k, c in curves.items()}
        for (ranks, v), s in res.items():
            c = curves[ranks, v]
            print("%d rank(s), v %g m/s (v/c %.3e): E %.6e Pa from %d points, peak %.6e Pa at strain %.6e, broken %d on the peak row, %d at the end of %d"
                  % (ranks, v, s["rate"], s["E"], s["fit_points"], s["peak"], s["strain_peak"], s["broken_peak"], s["broken_end"], s["made"]))
            k = c["stress"].index(s["peak"])
            check(s["fit_residual"] < 0.01, "%d rank(s), v %g: linear rise, the points between 10 %% and 50 %% of the peak within %.2e of the peak from their line (tolerance 0.01)"
                  % (ranks, v, s["fit_residual"]))
            fit = [i for i in range(k + 1) if 0.1 * s["peak"] <= c["stress"][i] <= 0.5 * s["peak"]]
            imbalance = max(abs(c["stress_bottom"][i] - c["stress_top"][i]) / c["stress"][i] for i in fit)
            check(imbalance < 0.01, "%d rank(s), v %g: the platens carry the same load to %.2e on the rise (tolerance 0.01)" % (ranks, v, imbalance))
            drop = min(c["stress"][k:])
            check(s["has_peak"] and drop < 0.5 * s["peak"], "%d rank(s), v %g: a peak, the stress falling to %.3e of it after" % (ranks, v, drop / s["peak"]))
            check(max(c["broken"][:k]) == 0 and s["broken_end"] > 0, "%d rank(s), v %g: no bond broken before the peak (%d), %d broken after"
                  % (ranks, v, max(c["broken"][:k]), s["broken_end"]))
        fast, slow = res[1, FAST], res[1, SLOW]
        dE, dP = fast["E"] / slow["E"] - 1, fast["peak"] / slow["peak"] - 1
        check(abs(dE) < 0.02, "rate independence: E at v/c %.2e and %.2e, %.6e and %.6e Pa, differ by %.3e (tolerance 0.02)" % (fast["rate"], slow["rate"], fast["E"], slow["E"], dE))
        check(abs(dP) < 0.02, "rate independence: peak stresses %.6e and %.6e Pa differ by %.3e (tolerance 0.02)" % (fast["peak"], slow["peak"], dP))
        one, two = curves[1, FAST], curves[2, FAST]
        k = one["stress"].index(res[1, FAST]["peak"])
        n = min(k + 3, len(one["t"]), len(two["t"]))
        same_rows = len(one["t"]) == len(two["t"]) and all(one["t"][i] == two["t"][i] for i in range(n))
        check(same_rows, "1 and 2 ranks: the same monitor rows (%d and %d)" % (len(one["t"]), len(two["t"])))
        if same_rows:
            diff = max(abs(one["stress"][i] - two["stress"][i]) for i in range(n)) / res[1, FAST]["peak"]
            check(all(one["broken"][i] == two["broken"][i] for i in range(n)), "1 and 2 ranks: the same bonds broken on the %d rows to two past the peak (%d and %d on the last)"
                  % (n, one["broken"][n - 1], two["broken"][n - 1]))
            check(diff < 1e-10, "1 and 2 ranks: stresses equal to %.2e of the peak on those rows (tolerance 1e-10)" % diff)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
