#!/usr/bin/python3
"""Particles inserted into a closed box over a pool (docs/physics.md F1; -physics dem,flow,vof): 0.1 mm IN718 spheres
inserted at 20,000 per second 1 mm above a pool that fills 30 % of a closed 2 mm box (20^3 cells), falling into it at
1 m/s, 150 steps. A new particle pushes the fluid out where it appears, and the same volume is taken back from the
cells without metal, so in a closed box the continuity's source still sums to zero. Checked on 1 and 2 ranks:
  (a) the pool's metal volume (vof_volume_m3) stays at its start to 1e-12 (relative) through every insertion and as the
      spheres enter it: before, each inserted sphere took the metal's share of its volume out of the pool (1.571e-13 m^3
      each, 3.7e-3 of the pool by step 150);
  (b) the gas (vof_phase0_volume_m3) loses exactly the volume of the spheres inserted, to 1e-12 of it;
  (c) the divergence the projection leaves stays below 1e-6 1/s (the insertion steps left 3.4 1/s).
  test_insertion_closed_box.py VOFDEM"""
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, monitor_rows, run_vofdem  # noqa: E402
import shutil  # noqa: E402
import tempfile  # noqa: E402

R = 5e-5
ARGS = ("-physics dem,flow,vof -grid_upper 2e-3,2e-3,2e-3 -grid_cells 20,20,20 -gravity 0,0,-9.81 -flow_density 1.6 -flow_viscosity 2.1e-5 "
        "-flow_pressure_ksp_rtol 1e-12 -vof_density 8380 -vof_viscosity 6e-3 -vof_surface_tension 1.8 -vof_boxes 0,0,0,2e-3,2e-3,0.6e-3 "
        "-dem_radius 5e-5 -dem_density 8380 -dem_youngs_modulus 2e9 -dem_inserts a -dem_insert_a_lower 0.8e-3,0.8e-3,1.6e-3 "
        "-dem_insert_a_upper 1.2e-3,1.2e-3,1.8e-3 -dem_insert_a_rate 20000 -dem_insert_a_velocity 0,0,-1 -coupling_fluid_drag implicit "
        "-max_steps 150 -monitor_every 1 -monitor_timing 0").split()


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-insertion-closed-box-")
    try:
        for ranks in (1, 2):
            out = os.path.join(tmp, "r%d" % ranks)
            run_vofdem(exe, ranks, ARGS + ["-output_dir", out])
            r = monitor_rows(out)
            label = "%d rank(s)" % ranks
            v0, g0 = r[0]["vof_volume_m3"], r[0]["vof_phase0_volume_m3"]
            metal = max(abs(x["vof_volume_m3"] / v0 - 1) for x in r)
            inserted = int(r[-1]["inserted"])
            into = r[-1]["particles"] == inserted and min(x["coupling_min_eps"] for x in r) < 0.95
            check(inserted >= 50 and into, "%s: %d spheres inserted, all in the box (min eps %.3f)" % (label, inserted, min(x["coupling_min_eps"] for x in r)))
            check(metal <= 1e-12, "%s: the pool's metal volume stays to %.2e of its start (tolerance 1e-12)" % (label, metal))
            vp = inserted * 4.0 / 3.0 * math.pi * R ** 3
            gas = abs((g0 - r[-1]["vof_phase0_volume_m3"]) / vp - 1)
            check(gas <= 1e-12, "%s: the gas lost the %d spheres' volume %.6e m^3 to %.2e of it (tolerance 1e-12)" % (label, inserted, vp, gas))
            div = max(x["flow_max_divergence_1_s"] for x in r)
            check(div <= 1e-6, "%s: the largest divergence left %.2e 1/s (tolerance 1e-6)" % (label, div))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
