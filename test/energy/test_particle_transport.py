#!/usr/bin/python3
"""The energy with moving particles (docs/physics.md F7 with eps, F9; docs/modules/energy.md): V6's glass sphere
(d 2.7 mm, cells 0.8 d) falls 20 mm through air into water, -physics dem,flow,vof,energy, with water and air given
their own rho, cp and k (the metal of the energy is the water: liquid throughout, nothing held; the sphere takes the
water's h(T) and does not melt, -coupling_heat_melt 0). The cells' energy
counts the fluid's share eps of each cell, the sweeps move it with eps_f u and d(eps)/dt, and the interface's
redistribution of alpha (particles push it out of [0, 1]) moves the phases' enthalpy with it.
  (a) all at 350 K: T stays uniform through the entry to 1e-9 K (cells counting their whole volume left 0.17 K, and
      the redistribution without the energy 1e-5 K), and the closed, adiabatic box keeps its energy to 1e-12;
  (b) water at 350 K, air and sphere at 300 K: the account closes to 1e-12 of the total; no cell goes below 300 K by
      more than 1e-2 K (the heat the sphere takes is shared by the cells' capacities: by volume alone the air above the
      water went to 283 K); the sphere warms by more than 3 K (it is in the water);
  (c) 1 and 2 ranks (split in z across the surface) agree: the energy to 1e-12 (relative), T_p to 1e-10.
  test_particle_transport.py VOFDEM"""
import csv
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

SCENE = (["-options_file_yaml", os.path.join(ROOT, "config", "scenes", "sphere-entry.yaml")] +
         ("-physics dem,flow,vof,energy -energy_metal_density 1000 -energy_gas_density 1.2 -energy_metal_specific_heat 4180 "
          "-energy_gas_specific_heat 1005 -energy_metal_conductivity 0.6 -energy_gas_conductivity 0.026 -energy_metal_latent_heat 0 "
          "-energy_metal_solidus 250 -energy_metal_liquidus 260 -energy_reference_temperature 300 -energy_interface_radiation 0 "
          "-energy_tolerance 1e-10 -coupling_heat_material energy_metal -coupling_heat_melt 0 -final_time 0.12 -monitor_every 4 -monitor_timing 0 "
          "-flow_output_every 0 -dem_output_every 0").split())
CASES = {"uniform": "-energy_initial_temperature 350 -coupling_heat_initial_temperature 350".split(),
         "hot_water": "-energy_initial_temperature 300 -energy_substrate_top 0.11 -energy_substrate_temperature 350 -coupling_heat_initial_temperature 300".split()}


def rows(out):
    with open(os.path.join(out, "monitor.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-particle-transport-")
    try:
        for name, extra in CASES.items():
            runs = {}
            for ranks in (1, 2):
                out = os.path.join(tmp, "%s-%d" % (name, ranks))
                run_vofdem(exe, ranks, SCENE + extra + ["-output_dir", out] + (["-grid_ranks", "1,1,2"] if ranks == 2 else []))
                r = runs[ranks] = rows(out)
                label = "%s, %d rank(s)" % (name, ranks)
                total = r[0]["energy_total_J"]
                account = max(abs(x["energy_total_J"] - x["energy_accounted_J"]) for x in r) / total
                check(abs(r[-1]["time_s"] - 0.12) < 1e-9 and max(x["held_cells"] for x in r) == 0, "%s: ran to 0.12 s, no cell held" % label)
                check(account <= 1e-12, "%s: |energy_total_J - energy_accounted_J| at most %.2e of %.6g J (tolerance 1e-12)" % (label, account, total))
                hi = max(x["temperature_max_K"] for x in r) - 350
                lo = min(x["temperature_min_K"] for x in r)
                if name == "uniform":
                    dev = max(hi, 350 - lo)
                    check(dev <= 1e-9, "%s: T stays 350 K to %.2e K through the entry (tolerance 1e-9)" % (label, dev))
                else:
                    check(hi <= 1e-9 and lo >= 300 - 1e-2, "%s: T within [300, 350] K: %.3e K above, %.3e K below (tolerances 1e-9, 1e-2)" % (label, max(hi, 0), max(300 - lo, 0)))
                    rise = r[-1]["particle_temperature_max_K"] - 300
                    check(rise > 3, "%s: the sphere warms by %.3f K in the water" % (label, rise))
            a, b = runs[1], runs[2]
            dE = max(abs(x["energy_total_J"] / y["energy_total_J"] - 1) for x, y in zip(a, b))
            dT = max(abs(x["particle_temperature_max_K"] / y["particle_temperature_max_K"] - 1) for x, y in zip(a, b))
            check(len(a) == len(b) and dE <= 1e-12 and dT <= 1e-10, "%s: 1 and 2 ranks agree: the energy to %.2e, T_p to %.2e (tolerances 1e-12, 1e-10)" % (name, dE, dT))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
