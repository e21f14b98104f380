#!/usr/bin/python3
"""-physics dem,darcy (docs/physics.md F11, docs/modules/darcy.md): a bed of 128 spheres (d = 1 mm, 2650 kg/m^3) on a simple
cubic lattice, 8 layers in a 4 x 4 mm periodic column 16 mm high (cells of 1 mm, -seepage_kernel divided: each sphere lies in
one cell), under upward seepage of water. Checked against values computed here from the inputs:
  - the exchange: the particles' total seepage force equals the grid's sum_c -grad p_c V_c over the cells that hold solid
    to 1e-12 at every monitor line, and the deposited volume is the particles' (1e-12);
  - the bed's share of the head loss: at the start (lattice eps = 1 - pi/6 in 8 cells, the empty cells' eps capped at
    -darcy_max_fluid_fraction) the force is A rho_w g dH R_bed/(R_bed + R_empty), R = L/k (layers in series), to 1e-10;
  - 1 and 2 ranks give the same forces (1e-12);
  - G5, heave: Terzaghi's critical gradient i_c = (rho_s/rho_w - 1)(1 - n) across the bed. The model's own critical head
    (where its static seepage force equals the bed's buoyant weight) is within 5 % of Terzaghi's, and the bed behaves so:
    at 0.95 of it the bed stays on the floor (the floor carries load at every line), at 1.05 it lifts (no floor load at
    the end, the kinetic energy growing).
Usage: test_seepage_bed.py VOFDEM"""
import csv
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

D, RHO_S, RHO_W, MU, G = 1e-3, 2650.0, 1000.0, 1e-3, 9.81
NX, LAYERS, NZ = 4, 8, 16          # spheres (and cells) across, bed layers, cells up the column
EPS_CAP = 0.99
A, L_BED, L_EMPTY = (NX * D) ** 2, LAYERS * D, (NZ - LAYERS) * D
V = math.pi * D ** 3 / 6
N = NX * NX * LAYERS
N_BED = 1 - math.pi / 6            # the lattice's porosity, in every bed cell


def k_d10(eps):
    return D ** 2 * eps ** 3 / (150 * (1 - eps) ** 2)


def write_bed(path):
    with open(path, "w") as f:
        f.write("x,y,z\n")
        for k in range(LAYERS):
            for j in range(NX):
                for i in range(NX):
                    f.write("%.17g,%.17g,%.17g\n" % ((i + 0.5) * D, (j + 0.5) * D, (k + 0.5) * D))


def run(tmp, name, n, dH, final_time, extra=()):
    out = os.path.join(tmp, "%s-%d" % (name, n))
    args = ["-physics", "dem,darcy", "-grid_cells", "%d,%d,%d" % (NX, NX, NZ), "-grid_upper", "%g,%g,%g" % (NX * D, NX * D, NZ * D),
            "-grid_periodic", "x,y", "-gravity", "0,0,-%g" % G, "-dem_particles_file", os.path.join(tmp, "bed.csv"), "-dem_radius", str(D / 2),
            "-dem_density", str(RHO_S), "-dem_youngs_modulus", "5e6", "-dem_restitution", "0.3", "-darcy_axis", "z",
            "-darcy_head_difference", repr(dH), "-darcy_permeability_law", "kozenycarman_d10", "-darcy_diameter", str(D),
            "-darcy_density", str(RHO_W), "-darcy_viscosity", str(MU), "-darcy_max_fluid_fraction", str(EPS_CAP),
            "-darcy_ksp_rtol", "1e-15", "-seepage_kernel", "divided", "-final_time", str(final_time), "-max_steps", "100000",
            "-monitor_every", "50", "-monitor_timing", "0", "-output_dir", out] + list(extra)
    run_vofdem(sys.argv[1], n, args)
    path = os.path.join(out, "monitor.csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def rel(a, b):
    return abs(a - b) / abs(b)


def main():
    tmp = tempfile.mkdtemp(prefix="vofdem-seepage-")
    write_bed(os.path.join(tmp, "bed.csv"))
    r_bed, r_empty = L_BED / k_d10(N_BED), L_EMPTY / k_d10(EPS_CAP)
    share = r_bed / (r_bed + r_empty)                     # the bed's part of the head loss
    weight = N * V * (RHO_S - RHO_W) * G                  # the bed's buoyant weight, N
    i_c = (RHO_S / RHO_W - 1) * (1 - N_BED)               # Terzaghi
    dH_c = i_c * L_BED / share                            # the head difference whose bed share is i_c L_bed
    runs = {}
    for f in (0.95, 1.05):
        for n in (1, 2):
            rows = run(tmp, "f%g" % f, n, f * dH_c, 0.02)
            runs[(f, n)] = rows
            if not rows:
                check(False, "f = %g, %d rank(s): a monitor table" % (f, n))
                continue
            exch = max(abs(r["seepage_force_z_N"] - r["seepage_grid_force_z_N"]) / abs(r["seepage_grid_force_z_N"]) for r in rows)
            check(exch < 1e-12, "f = %g, %d rank(s): the particles' total force = sum_c -grad p_c V_c at every line (%.2e)" % (f, n, exch))
            verr = max(r["seepage_volume_error"] for r in rows)
            check(verr < 1e-12, "f = %g, %d rank(s): deposited volume = particle volume (%.1e)" % (f, n, verr))
            F0, expected = rows[0]["seepage_force_z_N"], A * RHO_W * G * f * dH_c * share
            check(rel(F0, expected) < 1e-10, "f = %g, %d rank(s): the bed's force at the start %.10e N = A rho_w g dH R_bed/(R_bed + R_empty) %.10e N (%.2e)"
                  % (f, n, F0, expected, rel(F0, expected)))
            # The model's critical head: where its (linear) static force reaches the buoyant weight.
            dH_model = f * dH_c * weight / F0
            i_model = dH_model * share / L_BED
            check(rel(i_model, i_c) < 0.05, "f = %g, %d rank(s): the model's critical gradient across the bed %.6f against Terzaghi's (rho_s/rho_w - 1)(1 - n) = %.6f (%.2e < 5 %%)"
                  % (f, n, i_model, i_c, rel(i_model, i_c)))
    for n in (1, 2):
        below, above = runs.get((0.95, n)), runs.get((1.05, n))
        if not below or not above:
            continue
        check(all(r["floor_force_z_N"] < 0 for r in below[1:]), "0.95 i_c, %d rank(s): the bed stays on the floor (floor load %.3e to %.3e N)"
              % (n, min(r["floor_force_z_N"] for r in below[1:]), max(r["floor_force_z_N"] for r in below[1:])))
        check(above[-1]["floor_force_z_N"] == 0 and above[-1]["kinetic_energy_J"] > 10 * max(r["kinetic_energy_J"] for r in below),
              "1.05 i_c, %d rank(s): the bed lifts (floor load %g N at t = %g s, kinetic energy %.3e J against at most %.3e J at 0.95)"
              % (n, above[-1]["floor_force_z_N"], above[-1]["time_s"], above[-1]["kinetic_energy_J"], max(r["kinetic_energy_J"] for r in below)))
    for f in (0.95, 1.05):
        a, b = runs.get((f, 1)), runs.get((f, 2))
        if a and b:
            diff = max(rel(x["seepage_force_z_N"], y["seepage_force_z_N"]) for x, y in zip(a[:1], b[:1]))
            check(diff < 1e-12, "f = %g: 1 and 2 ranks give the same force at the start (%.2e)" % (f, diff))
    finish()


main()
