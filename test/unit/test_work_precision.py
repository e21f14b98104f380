"""scripts/work-precision: the F1 parser reads ex24's grid line (error and wall time of that grid only)
and refuses lines without the time; every case entry is complete."""
import importlib.machinery
import importlib.util
import os
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
_loader = importlib.machinery.SourceFileLoader("work_precision", os.path.join(ROOT, "scripts", "work-precision"))
_spec = importlib.util.spec_from_loader("work_precision", _loader)
wp = importlib.util.module_from_spec(_spec)
_loader.exec_module(wp)

# ex24 -cells_list 32,64 -show_time, as printed
OUT = """Taylor-Green vortex, nu 0.05 m^2/s, t = 1. s, dt = 0.5 h/U
grid 32^2: steps 11  u RMS error 3.5879e-04  max 1.2149e-03  p RMS error 1.1385e-03  wall 0.236 s
grid 64^2: steps 21  u RMS error 3.1294e-05  max 1.0624e-04  p RMS error 1.6796e-04  orders u 3.52 max 3.52 p 2.76  wall 1.712 s
F1 velocity RMS order between 32^2 and 64^2: 3.52 (tolerance >= 1.8) ok
"""


class F1ParseTest(unittest.TestCase):
    def test_reads_the_grid_asked_for(self):
        self.assertEqual(wp.f1_parse(OUT, 64), {"steps": 21, "error": 3.1294e-05, "wall": 1.712})
        self.assertEqual(wp.f1_parse(OUT, 32), {"steps": 11, "error": 3.5879e-04, "wall": 0.236})

    def test_other_grid_is_none(self):
        self.assertIsNone(wp.f1_parse(OUT, 128))

    def test_line_without_time_is_none(self):
        # without -show_time there is no wall time to plot: not a result
        self.assertIsNone(wp.f1_parse(OUT.replace("  wall 1.712 s", ""), 64))

    def test_arguments_name_grid_and_variant(self):
        args = wp.CASES["F1"].args(48, "koren")
        self.assertEqual(args[args.index("-cells_list") + 1], "48")
        self.assertEqual(args[args.index("-flow_advection") + 1], "koren")
        self.assertIn("-show_time", args)


class CasesTest(unittest.TestCase):
    def test_every_case_is_complete(self):
        for name, c in wp.CASES.items():
            with self.subTest(case=name):
                self.assertTrue(c.program and c.grids and c.variants and c.error_name and c.variant_name)
                self.assertTrue(callable(c.args) and callable(c.parse))


if __name__ == "__main__":
    unittest.main()


# ex28 -cells_list 32,64 -show_time, as printed (two lines per grid)
V1_OUT = """V1 single vortex, T = 8., velocity-adapted time step
grid 32^2: steps 328  shape error 5.2264e-02 (Basilisk 7.0e-02, OpenFOAM 7.8e-02; ratio to Basilisk 0.75 ok)
  volume error <= 1e-12 ok, bound violation <= 1e-12 ok, height-function normals 89 %  volume error 1.77e-15 bound 4.44e-16  wall 0.571 s
grid 64^2: steps 656  shape error 9.7189e-03 (Basilisk 1.5e-02, OpenFOAM 1.5e-02; ratio to Basilisk 0.65 ok)  order 2.43
  volume error <= 1e-12 ok, bound violation <= 1e-12 ok, height-function normals 81 %  volume error 4.91e-15 bound 4.44e-16  wall 3.451 s
V1 ok
"""


class V1ParseTest(unittest.TestCase):
    def test_reads_the_grid_asked_for(self):
        self.assertEqual(wp.v1_parse(V1_OUT, 64), {"steps": 656, "error": 9.7189e-03, "wall": 3.451})
        self.assertEqual(wp.v1_parse(V1_OUT, 32), {"steps": 328, "error": 5.2264e-02, "wall": 0.571})

    def test_without_time_is_none(self):
        self.assertIsNone(wp.v1_parse(V1_OUT.replace("  wall 3.451 s", ""), 64))
