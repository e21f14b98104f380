#!/usr/bin/python3
"""G5 under -physics dem,flow (docs/verification.md G5; docs/physics.md F6): test/darcy/test_seepage_bed.py's bed (128 spheres,
d = 1 mm, 2650 kg/m^3, a simple cubic lattice of 8 layers, n = 1 - pi/6, in a 4 x 4 mm periodic column 16 mm high, cells
of d, -coupling_kernel divided) resting on the inflow face, water rising through it (-coupling_drag ergun). Heave is
Terzaghi's: the bed lifts when the seepage gradient across it reaches i_c = (rho_s/rho_w - 1)(1 - n).
  - The gradient the water exerts on the bed at rest, i = F/(A rho_w g L) with F the buoyant weight less the floor's load
    (the water's force on the bed beyond buoyancy), at two velocities (0.005, 0.01 m/s): within 5 % of Ergun's for a
    uniform bed of the lattice's n (the law the run uses; the bed's ends differ from a uniform bed).
  - From those two, F(U) = a U + b U^2; at the U where it gives 0.95 i_c the bed stays on the floor (the floor carries load
    at every line after the first), at the U for 1.05 i_c it lifts (the floor carries nothing over the run's second half).
  - 1 and 2 ranks (split in z through the bed) give the same floor load to 1e-10.
Usage: test_heave_flow.py VOFDEM"""
import csv
import math
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

D, RHO_S, RHO_W, MU, G = 1e-3, 2650.0, 1000.0, 1e-3, 9.81
NX, LAYERS, NZ = 4, 8, 16
A, L = (NX * D) ** 2, LAYERS * D
N = NX * NX * LAYERS
V = math.pi * D ** 3 / 6
POROSITY = 1 - math.pi / 6
WEIGHT = N * V * (RHO_S - RHO_W) * G      # the bed's buoyant weight, N
I_C = (RHO_S / RHO_W - 1) * (1 - POROSITY)  # Terzaghi


def ergun_gradient(u):
    e = POROSITY
    return (150 * (1 - e) ** 2 * MU * u / (e ** 3 * D ** 2) + 1.75 * (1 - e) * RHO_W * u * u / (e ** 3 * D)) / (RHO_W * G)


def run(tmp, name, ranks, u, final_time):
    out = os.path.join(tmp, "%s-%d" % (name, ranks))
    args = ["-physics", "dem,flow", "-grid_cells", "%d,%d,%d" % (NX, NX, NZ), "-grid_upper", "%g,%g,%g" % (NX * D, NX * D, NZ * D),
            "-grid_periodic", "x,y", "-gravity", "0,0,-%g" % G, "-dem_particles_file", os.path.join(tmp, "bed.csv"), "-dem_radius", str(D / 2),
            "-dem_density", str(RHO_S), "-dem_youngs_modulus", "5e6", "-dem_restitution", "0.3", "-flow_density", str(RHO_W),
            "-flow_viscosity", str(MU), "-flow_bc_zlo", "inflow", "-flow_bc_zlo_velocity", "0,0,%.12g" % u, "-flow_bc_zhi", "outflow",
            "-coupling_drag", "ergun", "-coupling_kernel", "divided", "-dt_max", "1e-3", "-final_time", str(final_time), "-max_steps", "100000",
            "-monitor_every", "10", "-monitor_timing", "0", "-output_dir", out]
    run_vofdem(sys.argv[1], ranks, args)
    path = os.path.join(out, "monitor.csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def main():
    tmp = tempfile.mkdtemp(prefix="vofdem-heave-flow-")
    try:
        with open(os.path.join(tmp, "bed.csv"), "w") as f:
            f.write("x,y,z\n")
            for k in range(LAYERS):
                for j in range(NX):
                    for i in range(NX):
                        f.write("%.17g,%.17g,%.17g\n" % ((i + 0.5) * D, (j + 0.5) * D, (k + 0.5) * D))
        forces = []
        for u in (0.005, 0.01):
            rows = run(tmp, "u%g" % u, 1, u, 0.1)
            if not rows:
                check(False, "U = %g m/s: a monitor table" % u)
                return
            F = WEIGHT + rows[-1]["floor_force_z_N"]  # the floor's load is negative (downward on the floor)
            i = F / (A * RHO_W * G * L)
            err = i / ergun_gradient(u) - 1
            check(abs(err) <= 0.05, "U = %g m/s, bed at rest: gradient across it %.5f against Ergun's %.5f for a uniform bed: %+.2f %% (tolerance 5 %%)"
                  % (u, i, ergun_gradient(u), 100 * err))
            forces.append((u, F))
        (u1, f1), (u2, f2) = forces
        b = (f2 / u2 - f1 / u1) / (u2 - u1)
        a = f1 / u1 - b * u1
        speeds = {}
        for frac in (0.95, 1.05):
            target = frac * WEIGHT
            speeds[frac] = (-a + math.sqrt(a * a + 4 * b * target)) / (2 * b)
        u_c = (-a + math.sqrt(a * a + 4 * b * WEIGHT)) / (2 * b)
        print("# Terzaghi's i_c %.5f; the model's critical velocity %.5g m/s (gradient i_c); 0.95 i_c at %.5g m/s, 1.05 i_c at %.5g m/s"
              % (I_C, u_c, speeds[0.95], speeds[1.05]))
        runs = {}
        for frac in (0.95, 1.05):
            for ranks in (1, 2):
                runs[(frac, ranks)] = run(tmp, "f%g" % frac, ranks, speeds[frac], 0.15)
        for ranks in (1, 2):
            below, above = runs[(0.95, ranks)], runs[(1.05, ranks)]
            if not below or not above:
                check(False, "%d rank(s): monitor tables" % ranks)
                continue
            check(all(r["floor_force_z_N"] < 0 for r in below[1:]), "0.95 i_c, %d rank(s): the bed stays on the floor (floor load %.3e to %.3e N of %.4e)"
                  % (ranks, min(r["floor_force_z_N"] for r in below[1:]), max(r["floor_force_z_N"] for r in below[1:]), WEIGHT))
            # Heave is the effective stress at the bed's base gone: the floor carries nothing. A plug rising at
            # U - U_c would carry 0.5 m (U - U_c)^2 of kinetic energy (printed beside the run's).
            late = above[len(above) // 2:]
            plug = 0.5 * N * V * RHO_S * (speeds[1.05] - u_c) ** 2
            check(all(r["floor_force_z_N"] == 0 for r in late), "1.05 i_c, %d rank(s): the bed lifts: the floor carries nothing from t = %g s to %g s "
                  "(kinetic energy at the end %.2e J; a plug rising at U - U_c: %.2e J; at 0.95 at most %.2e J)"
                  % (ranks, late[0]["time_s"], late[-1]["time_s"], above[-1]["kinetic_energy_J"], plug, max(r["kinetic_energy_J"] for r in below)))
        one, two = runs[(0.95, 1)], runs[(0.95, 2)]
        if one and two:
            diff = max(abs(x["floor_force_z_N"] - y["floor_force_z_N"]) / WEIGHT for x, y in zip(one, two))
            check(diff <= 1e-10, "0.95 i_c: 1 and 2 ranks give the same floor load at every line (%.1e of the weight)" % diff)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


main()
