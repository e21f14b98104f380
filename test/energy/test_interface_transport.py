#!/usr/bin/python3
"""E5 (docs/physics.md F7 a; docs/verification.md E5): energy carried across a moving interface. The dam break
(config/scenes/dam-break.yaml at 40 x 20 x 1 cells, to T = 3, t = 0.162 s) with -physics flow,vof,energy, water
as the metal phase (rho 1000 kg/m^3, cp 4000 J/(kg K), liquid: solidus and liquidus below 300 K) under air (rho 1, cp 1000): a rho cp ratio of 4000.
  (a) T uniform at 350 K: it stays uniform, max |T - 350 K| / 350 K below 1e-12 at every step, while the column
      collapses (max |u| above 1 m/s);
  (b) the column at 400 K in air at 300 K, conducting (k 0.6 and 0.025 W/(m K)), the box closed and adiabatic:
      the total energy changes by less than 1e-12 of itself in any step and 1e-10 over the run, and T stays
      within [300, 400] K (to 1e-9 K: bounded transport, implicit diffusion);
on 1 and 2 ranks.
  test_interface_transport.py VOFDEM"""
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

BASE = ["-options_file_yaml", os.path.join(ROOT, "config", "scenes", "dam-break.yaml"), "-physics", "flow,vof,energy", "-grid_cells", "40,20,1",
        "-energy_metal_density", "1000", "-energy_gas_density", "1", "-energy_metal_specific_heat", "4000", "-energy_gas_specific_heat", "1000",
        "-energy_metal_conductivity", "0.6", "-energy_gas_conductivity", "0.025", "-energy_interface_radiation", "0", "-energy_pc", "boomeramg",
        "-energy_metal_solidus", "200", "-energy_metal_liquidus", "250",  # liquid throughout (else held at rest: docs/physics.md F2)
        "-monitor_every", "1", "-monitor_timing", "0"]
HOT = ["-energy_initial_temperature", "300", "-energy_box_lower", "0,0,0", "-energy_box_upper", "0.05715,0.1143,0.0035719", "-energy_box_temperature", "400"]


def run(exe, tmp, name, ranks, args):
    out = os.path.join(tmp, "%s-%d" % (name, ranks))
    run_vofdem(exe, ranks, BASE + args + ["-output_dir", out])
    with open(os.path.join(out, "monitor.csv")) as f:
        head, *rows = [line.strip().split(",") for line in f if line.strip()]
    return [dict(zip(head, map(float, r))) for r in rows]


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-interface-transport-")
    try:
        for ranks in (1, 2):
            rows = run(exe, tmp, "uniform", ranks, ["-energy_initial_temperature", "350"])
            dev = max(max(abs(r["temperature_max_K"] - 350), abs(r["temperature_min_K"] - 350)) / 350 for r in rows)
            umax = max(r["flow_max_velocity_m_s"] for r in rows)
            check(abs(rows[-1]["time_s"] - 0.162) < 1e-9 and umax > 1, "(a) %d rank(s): the column collapses: max |u| %.3f m/s, to t = %.4g s in %d steps" % (ranks, umax, rows[-1]["time_s"], len(rows) - 1))
            check(dev <= 1e-12, "(a) %d rank(s): a uniform 350 K stays uniform: max |T - 350 K|/350 K = %.2e over the run (tolerance 1e-12)" % (ranks, dev))
            rows = run(exe, tmp, "hot", ranks, HOT)
            e0 = rows[0]["energy_total_J"]
            step = max(abs(b["energy_total_J"] - a["energy_total_J"]) / e0 for a, b in zip(rows, rows[1:]))
            drift = abs(rows[-1]["energy_total_J"] - e0) / e0
            lo, hi = min(r["temperature_min_K"] for r in rows), max(r["temperature_max_K"] for r in rows)
            check(step <= 1e-12 and drift <= 1e-10, "(b) %d rank(s): closed adiabatic box: total energy %.10e J, largest change in a step %.2e of it (1e-12), "
                  "over the run %.2e (1e-10)" % (ranks, e0, step, drift))
            check(lo >= 300 - 1e-9 and hi <= 400 + 1e-9, "(b) %d rank(s): T within [%.12f, %.12f] K (bounds 300 and 400 K)" % (ranks, lo, hi))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
