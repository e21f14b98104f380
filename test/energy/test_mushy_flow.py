#!/usr/bin/python3
"""The melt's flow physics (docs/physics.md F2; docs/modules/energy.md): the Darcy term, solid metal held at rest, and
sigma(T) with Marangoni from the computed temperature. The dam break (config/scenes/dam-break.yaml at 40 x 20 x 1 cells)
with -physics flow,vof,energy, water-like metal (rho 1000, air 1):
  (a) solid: the column at 350 K, below the solidus (1533 K): every step max |u| below 1e-10 m/s (free, it collapses at
      1.6 m/s), the 128 column cells held, alpha at t = 0.162 s bitwise the initial one;
  (b) a pool that freezes: the column at 400 K with solidus 340 K, liquidus 350 K, cooled through two walls at 300 K
      (k 2000 W/(m K), cp 400 J/(kg K), L 1e4 J/kg) to t = 1.5 s: it collapses, then freezes completely (melt volume
      below 1e-20 m^3, every cell over half metal at rest exactly), every step as long as the flow allows (a shorter step
      than the frozen pool's has CFL >= 0.3: no step collapse), the energy account closing to 1e-10 of the heat that left;
  (c) Marangoni from T: with T = 300 K + (2000, 1000, 0) K/m . x in liquid metal, the first step's change of the velocity
      due to -vof_dsigma_dT -1e-4 N/(m K) (against the same run without it) equals that of the prescribed gradient
      (-vof_temperature_gradient, flow,vof) to 1e-9 relative; with only the x part of the gradient it differs (the
      comparison can fail);
on 1 and 2 ranks.
  test_mushy_flow.py VOFDEM"""
import csv
import os
import shutil
import sys
import tempfile

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

SCENE = ["-options_file_yaml", os.path.join(ROOT, "config", "scenes", "dam-break.yaml"), "-grid_cells", "40,20,1", "-monitor_timing", "0"]
ENERGY = ["-physics", "flow,vof,energy", "-energy_metal_density", "1000", "-energy_gas_density", "1", "-energy_gas_specific_heat", "1000",
          "-energy_gas_conductivity", "0.025", "-energy_interface_radiation", "0", "-energy_pc", "boomeramg"]


def rows(out):
    with open(os.path.join(out, "monitor.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def field(path, name):
    with h5py.File(path) as f:
        return np.array(f[name])


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-mushy-")
    try:
        for ranks in (1, 2):
            # (a) solid metal
            out = os.path.join(tmp, "solid-%d" % ranks)
            run_vofdem(exe, ranks, SCENE + ENERGY + ["-energy_metal_specific_heat", "4000", "-energy_metal_conductivity", "0.6", "-energy_initial_temperature", "350",
                                                     "-monitor_every", "1", "-flow_output_every", "1", "-output_dir", out])
            r = rows(out)
            umax = max(x["flow_max_velocity_m_s"] for x in r)
            held = {int(x["held_cells"]) for x in r}
            a0, a1 = field(os.path.join(out, "flow_00000000.h5"), "vof_alpha"), None
            last = sorted(f for f in os.listdir(out) if f.startswith("flow_0") and f.endswith(".h5"))[-1]
            a1 = field(os.path.join(out, last), "vof_alpha") if last != "flow_00000000.h5" else None
            check(r[-1]["time_s"] > 0.16 and umax <= 1e-10 and held == {128},
                  "%d rank(s): solid column: max |u| %.2e m/s over %d steps to t = %.3f s (<= 1e-10), held cells %s (128)" % (ranks, umax, len(r) - 1, r[-1]["time_s"], sorted(held)))
            check(a1 is not None and np.array_equal(a0, a1), "%d rank(s): solid column: alpha at the end bitwise the initial one (%s)" % (ranks, last))
            # (b) a pool that freezes
            out = os.path.join(tmp, "freeze-%d" % ranks)
            run_vofdem(exe, ranks, SCENE + ENERGY + ["-energy_metal_specific_heat", "400", "-energy_metal_conductivity", "2000", "-energy_metal_solidus", "340",
                                                     "-energy_metal_liquidus", "350", "-energy_metal_latent_heat", "1e4", "-energy_initial_temperature", "400",
                                                     "-energy_bc_xlo", "temperature", "-energy_bc_xlo_value", "300", "-energy_bc_ylo", "temperature", "-energy_bc_ylo_value", "300",
                                                     "-final_time", "1.5", "-monitor_every", "1", "-flow_output_every", "100000", "-output_dir", out])
            r = rows(out)
            moved = max(x["flow_max_velocity_m_s"] for x in r)
            # No step collapse: every step is as long as the flow's own limits allow. While the melt moves the
            # Courant number binds (CFL >= 0.3); once it is frozen, the step is back at its limit at rest.
            frozen = [x["dt_s"] for x in r[1:-1] if x["melt_volume_m3"] <= 1e-20]  # the last step ends on -final_time
            rest = max(frozen) if frozen else 0
            short = [x for x in r[1:-1] if x["dt_s"] < 0.9 * rest]
            lowest = min((x["flow_cfl"] for x in short), default=1)
            check(moved > 1 and r[-1]["melt_volume_m3"] <= 1e-20 and abs(r[-1]["time_s"] - 1.5) < 1e-12,
                  "%d rank(s): the pool collapses (max |u| %.2f m/s) and freezes: melt volume %.2e m^3 at t = %.4g s (<= 1e-20)" % (ranks, moved, r[-1]["melt_volume_m3"], r[-1]["time_s"]))
            check(rest > 0 and lowest >= 0.3,
                  "%d rank(s): no step collapse: frozen, the step is %.3e s; the %d shorter steps have CFL >= %.3f (>= 0.3: the motion binds them), the shortest %.3e s"
                  % (ranks, rest, len(short), lowest, min(x["dt_s"] for x in r[1:-1])))
            lost = r[0]["energy_total_J"] - r[-1]["energy_total_J"]
            drift = abs(r[-1]["energy_total_J"] - r[-1]["energy_accounted_J"])
            check(drift <= 1e-10 * lost, "%d rank(s): energy account: |total - accounted| %.2e J of %.4e J that left (%.1e, tolerance 1e-10)" % (ranks, drift, lost, drift / lost))
            steps = int(r[-1]["step"])  # the same run again, writing the flow at its last step
            out2 = os.path.join(tmp, "freeze-out-%d" % ranks)
            run_vofdem(exe, ranks, SCENE + ENERGY + ["-energy_metal_specific_heat", "400", "-energy_metal_conductivity", "2000", "-energy_metal_solidus", "340",
                                                     "-energy_metal_liquidus", "350", "-energy_metal_latent_heat", "1e4", "-energy_initial_temperature", "400",
                                                     "-energy_bc_xlo", "temperature", "-energy_bc_xlo_value", "300", "-energy_bc_ylo", "temperature", "-energy_bc_ylo_value", "300",
                                                     "-final_time", "1.5", "-monitor_every", "1000", "-flow_output_every", str(steps), "-output_dir", out2])
            path = os.path.join(out2, "flow_%08d.h5" % steps)
            if os.path.exists(path):
                a, u = field(path, "vof_alpha"), field(path, "velocity")
                metal = a >= 0.5
                um = np.abs(u[metal]).max()
                check(um == 0 and int(r[-1]["held_cells"]) == int(metal.sum()),
                      "%d rank(s): frozen metal at rest: max |u| %.1e m/s in the %d cells over half metal (0 exactly), held %d" % (ranks, um, metal.sum(), r[-1]["held_cells"]))
            else:
                check(False, "%d rank(s): the final flow output %s exists" % (ranks, path))
            # (c) Marangoni from the computed T against the prescribed gradient
            liquid = ["-energy_metal_specific_heat", "4000", "-energy_metal_conductivity", "0.6", "-energy_metal_solidus", "200", "-energy_metal_liquidus", "250",
                      "-energy_initial_temperature", "300"]
            common = ["-vof_surface_tension", "0.07", "-max_steps", "1", "-monitor_every", "1", "-flow_output_every", "1"]
            runs = {
                "prescribed": ["-physics", "flow,vof", "-vof_dsigma_dT", "-1e-4", "-vof_temperature_gradient", "2000,1000,0"],
                "prescribed0": ["-physics", "flow,vof"],
                "computed": ENERGY + liquid + ["-vof_dsigma_dT", "-1e-4", "-vof_surface_tension_temperature", "300", "-energy_initial_gradient", "2000,1000,0"],
                "computed0": ENERGY + liquid + ["-energy_initial_gradient", "2000,1000,0"],
                "computedx": ENERGY + liquid + ["-vof_dsigma_dT", "-1e-4", "-vof_surface_tension_temperature", "300", "-energy_initial_gradient", "2000,0,0"],
            }
            u = {}
            for name, args in runs.items():
                out = os.path.join(tmp, "%s-%d" % (name, ranks))
                run_vofdem(exe, ranks, SCENE + common + args + ["-output_dir", out])
                u[name] = field(os.path.join(out, "flow_00000001.h5"), "velocity")
            dp, dc, dx = u["prescribed"] - u["prescribed0"], u["computed"] - u["computed0"], u["computedx"] - u["computed0"]
            err = np.abs(dc - dp).max() / np.abs(dp).max()
            errx = np.abs(dx - dp).max() / np.abs(dp).max()
            check(np.abs(dp).max() > 1e-6 and err <= 1e-9,
                  "%d rank(s): Marangoni's share of the first step %.3e m/s, computed T against prescribed: %.1e relative (<= 1e-9)" % (ranks, np.abs(dp).max(), err))
            check(errx > 1e-3, "%d rank(s): with only the x gradient the share differs by %.1e relative (> 1e-3: the check can fail)" % (ranks, errx))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
