#!/usr/bin/python3
"""The convergence-table helper must report exact orders of synthetic error ladders, pass second order,
fail first order (and a too-high order when bounded), and reject bad input with one line and exit 2."""
import os
import re
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "convergence_table.py")
SUMMARY = re.compile(r"^(.*): observed order (\S+) \((last pair|smallest, pair), (\d+) -> (\d+); "
                     r"expected (\S+), tolerance ([^)]*)\) (ok|FAIL)$", re.M)


def ladder(order, grids=(16, 32, 64, 128), c=0.7):
    return [(n, c * n ** -order) for n in grids]


class ConvergenceTableTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def run_table(self, text, *args, stdin=False):
        if stdin:
            p = subprocess.run([sys.executable, SCRIPT] + list(args), input=text, capture_output=True, text=True)
        else:
            path = os.path.join(self.tmp.name, "errors.txt")
            with open(path, "w") as f:
                f.write(text)
            p = subprocess.run([sys.executable, SCRIPT, path] + list(args), capture_output=True, text=True)
        m = SUMMARY.search(p.stdout)
        return p.returncode, p.stdout + p.stderr, m

    def test_second_order_passes_with_exact_orders(self):
        text = "".join("grid %d error %.17g\n" % ne for ne in ladder(2.0))
        rc, out, m = self.run_table(text, "--expect", "2", "--min-order", "1.8")
        self.assertEqual(rc, 0, out)
        self.assertEqual((m.group(2), m.group(4), m.group(5), m.group(8)), ("2.00", "64", "128", "ok"), out)
        table = re.findall(r"^\s+(\d+)\s+(\S+)\s+(\S+)$", out, re.M)
        self.assertEqual([t[0] for t in table], ["16", "32", "64", "128"])
        self.assertEqual([t[2] for t in table], ["-", "2.00", "2.00", "2.00"])
        self.assertIn("result: convergence observed order (last, 64 -> 128) | 2.00", out)

    def test_first_order_fails(self):
        text = "".join("grid %d error %.17g\n" % ne for ne in ladder(1.0))
        rc, out, m = self.run_table(text, "--expect", "2", "--min-order", "1.8")
        self.assertEqual((rc, m.group(2), m.group(8)), (1, "1.00", "FAIL"), out)

    def test_default_min_order_is_nine_tenths_of_expected(self):
        text = "".join("grid %d error %.17g\n" % ne for ne in ladder(1.85))
        self.assertEqual(self.run_table(text)[0], 0)            # 1.85 >= 0.9 * 2
        self.assertEqual(self.run_table(text, "--expect", "3")[0], 1)  # 1.85 < 2.7

    def test_last_against_min(self):
        # Pre-asymptotic coarse pair (order 1.5), then second order.
        errs = [1.0e-2, 1.0e-2 / 2 ** 1.5, 1.0e-2 / 2 ** 1.5 / 4]
        text = "".join("grid %d error %.17g\n" % (n, e) for n, e in zip((16, 32, 64), errs))
        rc, out, m = self.run_table(text, "--min-order", "1.8")
        self.assertEqual((rc, m.group(2)), (0, "2.00"), out)
        rc, out, m = self.run_table(text, "--min-order", "1.8", "--check", "min")
        self.assertEqual((rc, m.group(2), m.group(3), m.group(4), m.group(5)), (1, "1.50", "smallest, pair", "16", "32"), out)

    def test_max_order_catches_superconvergence(self):
        text = "".join("grid %d error %.17g\n" % ne for ne in ladder(4.0))
        self.assertEqual(self.run_table(text)[0], 0)
        rc, out, m = self.run_table(text, "--max-order", "2.5", "--label", "F1 Taylor-Green")
        self.assertEqual((rc, m.group(1), m.group(7)), (1, "F1 Taylor-Green", "in [1.8, 2.5]"), out)

    def test_grid_lines_inside_other_output_unsorted(self):
        text = ("F1 Taylor-Green vortex, t = 1\n"
                "  grid 64 error 2.5e-04 (L2 of u)\n"
                "some other line with 3 numbers 4 5\n"
                "  grid 32 error 1.0e-03 (L2 of u)\n")
        rc, out, m = self.run_table(text)
        self.assertEqual((rc, m.group(2), m.group(4), m.group(5)), (0, "2.00", "32", "64"), out)

    def test_csv_with_and_without_header_and_stdin(self):
        body = "".join("%d,%.17g\n" % ne for ne in ladder(2.0))
        for text in (body, "N,error\n" + body, "# errors\n" + body,
                     "error_extra,cells,error\n" + "".join("x,%d,%.17g\n" % ne for ne in ladder(2.0))):
            rc, out, m = self.run_table(text)
            self.assertEqual((rc, m.group(2)), (0, "2.00"), text + out)
        rc, out, m = self.run_table(body, stdin=True)
        self.assertEqual((rc, m.group(2)), (0, "2.00"), out)

    def test_bad_input_one_line_exit_2(self):
        cases = [("grid 32 error 1e-3\n", "1 grid; an order needs at least 2"),
                 ("grid 32 error 1e-3\ngrid 64 error 0\n", "error 0 at N = 64"),
                 ("grid 32 error 1e-3\ngrid 32 error 2e-3\n", "grid N = 32 appears twice"),
                 ("grid 32 error abc\n", "error 'abc' is not a number"),
                 ("", "no data"),
                 ("N,error\n32\n", "expected at least 2 comma-separated fields")]
        for text, message in cases:
            rc, out, _ = self.run_table(text)
            self.assertEqual(rc, 2, out)
            self.assertIn(message, out)
            self.assertEqual(len(out.strip().splitlines()), 1, out)
        rc, out, _ = self.run_table("grid 1 error 1\ngrid 2 error 0.25\n", "--max-order", "1")
        self.assertEqual(rc, 2, out)
        self.assertIn("option --max-order", out)


if __name__ == "__main__":
    unittest.main()
