"""scripts/work-precision: the F1 parser reads ex24's grid line (error and wall time of that grid only)
and refuses lines without the time; every case entry is complete; E1 and E4 pass the grid and the time scheme
to vofdem and read their error and wall time from its monitor.csv (a stand-in for vofdem writes it here)."""
import importlib.machinery
import importlib.util
import math
import os
import subprocess
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
                self.assertTrue(callable(c.run) or (callable(c.args) and callable(c.parse)))



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


class EnergyCasesTest(unittest.TestCase):
    """E1 and E4 through a stand-in launcher that writes the monitor.csv vofdem would."""

    @staticmethod
    def launcher(seen, rows):
        def launch(args):
            seen.append(args)
            with open(os.path.join(args[args.index("-output_dir") + 1], "monitor.csv"), "w") as f:
                f.write("\n".join(",".join(str(v) for v in r) for r in rows) + "\n")
            return subprocess.CompletedProcess(args, 0, "", "")
        return launch

    def test_e1_front_error_and_wall(self):
        st = wp.test_module("test_stefan")
        stl, sts, lam, _ = st.CASES["one phase St 1"]
        t_end, _ = st.arguments("x", 2, stl, sts, lam, 50)
        front = 1.01 * 2 * lam * math.sqrt(st.ALPHA * t_end)  # 1 % ahead of Neumann's at the end
        seen = []
        rows = [("step", "time_s", "melt_volume_m3", "wall_time_s"), (0, 0.0, 0.0, 0.0), (200, t_end / 4, 0.98 * front / 1.01 * 0.5 * st.AREA, 2.0),
                (400, t_end / 2, front / 1.01 * math.sqrt(0.5) * st.AREA, 3.5), (801, t_end, front * st.AREA, 7.25)]
        result, why = wp.CASES["E1"].run(50, "euler", 2, self.launcher(seen, rows), ["-extra", "1"])
        self.assertEqual(why, "")
        self.assertAlmostEqual(result["error"], 0.02, places=12)  # the largest from t_end/4 on: -2 % there, 0 and +1 % later
        self.assertEqual((result["wall"], result["steps"]), (7.25, 801))
        args = seen[0]
        self.assertEqual(args[args.index("-grid_cells") + 1], "1,1,100")  # one phase: twice the melted cells
        self.assertEqual(args[args.index("-energy_time_scheme") + 1], "euler")
        self.assertEqual(args[args.index("-monitor_every", args.index("-monitor_every") + 1) + 1], "1")  # every step, after the test's 20
        self.assertEqual(args[-2:], ["-extra", "1"])
        self.assertEqual(wp.CASES["E1"].target, "vofdem_app")  # the program vofdem is CMake's vofdem_app (vofdem is the library)

    def test_e1_short_run_and_unknown_case_fail(self):
        rows = [("step", "time_s", "melt_volume_m3", "wall_time_s"), (0, 0.0, 0.0, 0.0), (10, 1.0, 1e-9, 0.5)]
        result, why = wp.CASES["E1"].run(25, "bdf2", 1, self.launcher([], rows), [])
        self.assertIsNone(result)
        self.assertIn("stopped", why)
        result, why = wp.CASES["E1"].run(25, "bdf2:three-phase", 1, self.launcher([], rows), [])
        self.assertIsNone(result)

    def test_e4_grid_keeps_the_box(self):
        ms = wp.test_module("test_moving_source")
        self.assertEqual(ms.grid(), ((64, 16, 16), 5e-4))  # the quick test's R_l/h = 2
        self.assertEqual(ms.grid(1)[0], (32, 8, 8))
        self.assertEqual(ms.grid(1.5)[0], (48, 12, 12))
        self.assertEqual(ms.grid(4)[0], (128, 32, 32))
        with self.assertRaises(ValueError):
            ms.grid(1.3)
        args = ms.arguments("out", 2, 825.0, 4)
        self.assertEqual(args[args.index("-grid_cells") + 1], "128,32,32")
        self.assertEqual(args[args.index("-grid_upper") + 1], "0.032,0.008,0.008")
        self.assertEqual(args[args.index("-grid_ranks") + 1], "2,1,1")


    def test_e4_largest_error_and_step(self):
        ms = wp.test_module("test_moving_source")
        saved = ms.exact, ms.exact_on_grid  # the exact solution takes seconds: stand-ins here
        ms.exact = lambda xbeam, ratio: (1300.0, 600.0, 4e-3, 1e-3)
        ms.exact_on_grid = lambda xbeam, iso, ratio: (4e-3, 1e-3)
        try:
            seen = []
            rows = [("step", "time_s", "temperature_max_K", "pool_length_m", "pool_width_m", "wall_time_s"),
                    (160, ms.T_END, 1310.0, 4.04e-3, 0.97e-3, 61.5)]  # rise +1 %, length +1 %, width -3 %
            result, why = wp.CASES["E4"].run(4, "bdf2", 2, self.launcher(seen, rows), [])
        finally:
            ms.exact, ms.exact_on_grid = saved
        self.assertEqual(why, "")
        self.assertAlmostEqual(result["error"], 0.03, places=12)
        self.assertEqual((result["wall"], result["steps"]), (61.5, 160))
        args = seen[0]
        self.assertEqual(args[args.index("-grid_cells") + 1], "128,32,32")
        self.assertEqual(args[args.index("-laser_step_fraction") + 1], "0.125")  # the beam h/2 per step
        self.assertEqual(args[args.index("-energy_time_scheme") + 1], "bdf2")


if __name__ == "__main__":
    unittest.main()
