#!/usr/bin/python3
"""The F2 profile checker must pass the reference itself, fail a profile off by more than the tolerance,
catch a mirrored cavity and a wrong reference, interpolate to its stated order, and reject bad input
with one line and exit status 2."""
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import cavity_profile_check as cpc  # noqa: E402

SCRIPT = os.path.join(HERE, "cavity_profile_check.py")
SUMMARY = re.compile(r"^F2 Re (\d+) ([uv])\(([xy])\) at ([xy])=0\.5: max \|[uv] - [uv]_(\w+)\| = (\S+) "
                     r"\(tolerance (\S+)\) (ok|FAIL)$", re.M)


def profile_rows(yu, u, xv, v, box=(0.0, 0.0, 1.0, 1.0), scale=1.0):
    """CSV text of a profile with line y carrying u(y) and line x carrying v(x), in a box."""
    xlo, ylo, xhi, yhi = box
    xc, yc = 0.5 * (xlo + xhi), 0.5 * (ylo + yhi)
    out = ["line,s,x,y,z,u,v,w"]
    for s, val in zip(yu, u):
        y = ylo + s * (yhi - ylo)
        out.append("y,%.17g,%.17g,%.17g,0.05,%.17g,0,0" % (y - ylo, xc, y, scale * val))
    for s, val in zip(xv, v):
        x = xlo + s * (xhi - xlo)
        out.append("x,%.17g,%.17g,%.17g,0.05,0,%.17g,0" % (x - xlo, x, yc, scale * val))
    return "\n".join(out) + "\n"


class CheckerTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def run_checker(self, text, *args):
        path = os.path.join(self.tmp.name, "profile.csv")
        with open(path, "w") as f:
            f.write(text)
        p = subprocess.run([sys.executable, SCRIPT, path] + list(args), capture_output=True, text=True)
        return p.returncode, p.stdout + p.stderr

    def summaries(self, out):
        return {m.group(2): (m.group(5), float(m.group(6)), float(m.group(7)), m.group(8))
                for m in SUMMARY.finditer(out)}

    def reference(self, stem):
        ys, us = cpc.read_reference(stem, "u")
        xs, vs = cpc.read_reference(stem, "v")
        return ys, us, xs, vs

    def test_reference_itself_passes_with_zero_error(self):
        for re_, stem in ((100, "ghia1982-re100"), (1000, "botella1998-re1000")):
            for kind in ("cubic", "linear"):
                rc, out = self.run_checker(profile_rows(*self.reference(stem)), "--re", str(re_), "--interp", kind)
                self.assertEqual(rc, 0, out)
                s = self.summaries(out)
                self.assertEqual(s["u"][1], 0.0, out)
                self.assertEqual(s["v"][1], 0.0, out)
                self.assertEqual(len(re.findall(r"^  [xy] \d", out, re.M)), 34, out)  # one line per station

    def test_shift_beyond_tolerance_fails(self):
        ys, us, xs, vs = self.reference("ghia1982-re100")
        rc, out = self.run_checker(profile_rows(ys, us + 0.02, xs, vs), "--re", "100")
        self.assertEqual(rc, 1, out)
        s = self.summaries(out)
        self.assertEqual(s["u"][3], "FAIL")
        self.assertAlmostEqual(s["u"][1], 0.02, places=9)
        self.assertEqual(s["v"][3], "ok")
        self.assertIn("result: F2 Re 100 u(y) at x=0.5, max abs(u - u_Ghia) | 2.00e-02 | Ghia, < 1.0e-02 | FAIL", out)
        rc, out = self.run_checker(profile_rows(ys, us, xs, vs - 0.02), "--re", "100")
        self.assertEqual((rc, self.summaries(out)["v"][3]), (1, "FAIL"), out)

    def test_shift_within_tolerance_passes_and_tolerance_option_bites(self):
        ys, us, xs, vs = self.reference("botella1998-re1000")
        text = profile_rows(ys, us + 0.005, xs, vs - 0.005)
        rc, out = self.run_checker(text, "--re", "1000")
        self.assertEqual(rc, 0, out)
        self.assertAlmostEqual(self.summaries(out)["u"][1], 0.005, places=9)
        rc, out = self.run_checker(text, "--re", "1000", "--tolerance", "0.004")
        self.assertEqual(rc, 1, out)

    def test_box_and_lid_speed_are_normalised(self):
        box = (2.0, -1.0, 2.5, -0.5)
        text = profile_rows(*self.reference("ghia1982-re100"), box=box, scale=2.5)
        rc, out = self.run_checker(text, "--re", "100", "--box", "2,-1,2.5,-0.5", "--lid-speed", "2.5")
        self.assertEqual(rc, 0, out)
        self.assertLess(self.summaries(out)["u"][1], 1e-12)  # round-off of the mapping only
        rc, out = self.run_checker(text, "--re", "100", "--box", "2,-1,2.5,-0.5")  # lid speed forgotten
        self.assertEqual(rc, 1, out)
        rc, out = self.run_checker(text, "--re", "100")  # box forgotten
        self.assertEqual(rc, 2, out)

    def test_mirrored_cavity_fails(self):
        # Botella & Peyret's own convention (lid moving in -x): u negated, v at 1 - x.
        ys, us, xs, vs = self.reference("botella1998-re1000")
        rc, out = self.run_checker(profile_rows(ys, -us, 1.0 - xs[::-1], vs[::-1]), "--re", "1000")
        self.assertEqual(rc, 1, out)
        self.assertEqual((self.summaries(out)["u"][3], self.summaries(out)["v"][3]), ("FAIL", "FAIL"))

    def test_ghia_re1000_is_outside_tolerance_of_botella(self):
        text = profile_rows(*self.reference("ghia1982-re1000"))
        rc, out = self.run_checker(text, "--re", "1000")
        self.assertEqual(rc, 1, out)
        s = self.summaries(out)
        self.assertEqual(s["v"][0], "Botella")
        self.assertTrue(0.0175 < s["v"][1] < 0.0195, out)  # 1.85e-2, v at x = 0.9453
        self.assertLess(s["u"][1], 0.01)
        rc, out = self.run_checker(text, "--re", "1000", "--reference", "ghia")
        self.assertEqual(rc, 0, out)

    def test_interpolation_orders(self):
        # Cell centres of 16 cells plus the two walls: uneven spacing at the ends.
        s = np.concatenate(([0.0], (np.arange(16) + 0.5) / 16, [1.0]))
        t = np.linspace(0, 1, 41)
        cubic = lambda x: 3 * x ** 3 - 2 * x ** 2 + 0.5 * x - 0.1
        self.assertLess(np.abs(cpc.interpolate(s, cubic(s), t, "cubic") - cubic(t)).max(), 1e-13)
        line = lambda x: 0.7 * x - 0.2
        self.assertLess(np.abs(cpc.interpolate(s, line(s), t, "linear") - line(t)).max(), 1e-15)
        # Observed orders on a smooth profile: ~4 for cubic, ~2 for linear.
        errs = {"cubic": [], "linear": []}
        for n in (16, 32, 64):
            s = np.concatenate(([0.0], (np.arange(n) + 0.5) / n, [1.0]))
            for kind in errs:
                errs[kind].append(np.abs(cpc.interpolate(s, np.sin(3 * s), t, kind) - np.sin(3 * t)).max())
        for kind, want in (("cubic", 4.0), ("linear", 2.0)):
            order = math.log2(errs[kind][-2] / errs[kind][-1])
            self.assertGreater(order, want - 0.3, (kind, errs[kind]))

    def synthetic_with_extrema(self, shift=0.0):
        """Smooth profiles whose extrema are the Re 100 grid-converged ones (plus shift), on the 64
        cell centres and the wall points (not zero at the walls: not needed here)."""
        ref = cpc.read_extrema(100)
        s = np.concatenate(([0.0], (np.arange(64) + 0.5) / 64, [1.0]))
        (umin, yu), (vmax, xmax), (vmin, xmin) = ref["u_min"], ref["v_max"], ref["v_min"]
        u = (umin + shift) * (1 - ((s - yu) / 0.6) ** 2) ** 2
        v = (vmax + shift) * np.exp(-((s - xmax) / 0.12) ** 2) + (vmin + shift) * np.exp(-((s - xmin) / 0.08) ** 2)
        return s, u, s, v

    def test_extrema_found_and_checked(self):
        ys, us, xs, vs = self.synthetic_with_extrema()
        value, where = cpc.extremum(ys, us, "cubic", False)
        self.assertLess(abs(value - cpc.read_extrema(100)["u_min"][0]), 1e-5)
        self.assertLess(abs(where - cpc.read_extrema(100)["u_min"][1]), 1e-3)
        for shift, code in ((0.0, 0), (0.003, 1)):
            ys, us, xs, vs = self.synthetic_with_extrema(shift)
            rc, out = self.run_checker(profile_rows(ys, us, xs, vs), "--re", "100", "--tolerance", "10",
                                       "--extrema-tolerance", "0.001")
            self.assertEqual(rc, code, out)
            self.assertEqual(out.count("result: F2 Re 100 v_min"), 1, out)
        # without --extrema-tolerance the extrema are printed, not judged
        rc, out = self.run_checker(profile_rows(ys, us, xs, vs), "--re", "100", "--tolerance", "10")
        self.assertEqual(rc, 0, out)
        self.assertIn("F2 Re 100 v_min = ", out)
        self.assertNotIn("result: F2 Re 100 v_min", out)

    def test_bad_input_one_line_exit_2(self):
        ys, us, xs, vs = self.reference("ghia1982-re100")
        good = profile_rows(ys, us, xs, vs)
        cases = [
            (good.replace("line,s,x,y,z,u,v,w", "line,s,x,y,z,U,v,w"), ("--re", "100"), "no column 'u'"),
            ("\n".join(l for l in good.splitlines() if not l.startswith("x,")) + "\n", ("--re", "100"), "no line x"),
            (profile_rows(ys[:-1], us[:-1], xs, vs), ("--re", "100"), "must run wall to wall"),
            (good.replace("\ny,", "\nq,", 1), ("--re", "100"), "line 'q' is not x, y or z"),
            (good.replace(",0.05,", ",abc,", 1), ("--re", "100"), "z 'abc' is not a number"),
            (good, ("--re", "100", "--box", "0,0,1,2"), "is not square"),
            (good, ("--re", "100", "--reference", "botella"), "no botella table at Re 100"),
            (good, ("--re", "100", "--box", "0.25,0,1.25,1"), "off the box centre"),
        ]
        for text, args, message in cases:
            rc, out = self.run_checker(text, *args)
            self.assertEqual(rc, 2, out)
            self.assertIn(message, out)
            self.assertEqual(len(out.strip().splitlines()), 1, out)


if __name__ == "__main__":
    unittest.main()
