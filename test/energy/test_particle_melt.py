#!/usr/bin/python3
"""Melted particles join the melt (docs/physics.md P12; coupling/ParticleMelt.hpp): -physics dem,flow,vof,energy, 16^3
cells of 77 um (0.8 d), an IN718 pool 2 cells deep, argon, all liquid at 1700 K; IN718 spheres (d 96 um) at 1650 K, above
the liquidus (1609 K), placed by a particles file; 1 us steps. Checked:
  (a) a drop in the gas moving at (0.1, 0, -0.5) m/s and spinning at 2000 rad/s: it leaves the swarm before the first
      step (particles 0, particles_melted 1, the DEM's deletion books count it); after the step the metal volume has
      grown by m/rho_m to 1e-12 of the total; the books of the conversion itself (volume, energy, momentum) within 1e-12; the spin energy reported is
      I w^2/2 = m r^2 w^2/5 to 1e-12; the fluid's kinetic energy after the merge is at most the drop's (no energy made);
      the energy account closes to 1e-12; T stays within [1650, 1700] K;
  (b) one sphere half in the pool (its metal passes alpha = 1 where the pool is full) and one in the gas: both melt,
      the excess goes to neighbours with room: alpha within [0, 1] to 1e-12 (vof_bound_violation), the volume grows by
      both spheres' to 1e-12, the books within 1e-12;
  (c) a sphere at 1500 K (below the solidus) in the gas does not melt in 3 steps; with -coupling_heat_melt 0 neither
      does one at 1650 K;
  (d) 1 and 2 ranks (split in x through the drop) agree: metal volume, energy and the fluid's kinetic energy to 1e-12.
  test_particle_melt.py VOFDEM"""
import csv
import math
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

H, N, R, RHO = 77e-6, 16, 48e-6, 8380.0
L = N * H
C = 0.5 * L
MASS = RHO * 4 / 3 * math.pi * R ** 3


def arguments(out, particles, t0=1650, extra=()):
    return ["-physics", "dem,flow,vof,energy", "-grid_upper", "%.10g,%.10g,%.10g" % (L, L, L), "-grid_cells", "%d,%d,%d" % (N, N, N), "-gravity", "0,0,-9.81",
            "-flow_density", "1.6", "-flow_viscosity", "2.1e-5", "-vof_density", "%g" % RHO, "-vof_viscosity", "6e-3",
            "-vof_boxes", "0,0,0,%.10g,%.10g,%.10g" % (L, L, 2 * H), "-energy_interface_radiation", "0", "-energy_initial_temperature", "1700",
            "-dem_radius", "%g" % R, "-dem_density", "%g" % RHO, "-dem_youngs_modulus", "1e6", "-dem_particles_file", particles,
            "-coupling_heat_initial_temperature", "%g" % t0, "-dt", "1e-6", "-max_steps", "3", "-monitor_every", "1", "-monitor_timing", "0",
            "-output_dir", out] + list(extra)


def rows(out):
    with open(os.path.join(out, "monitor.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def write(path, spheres):
    with open(path, "w") as f:
        f.write("x,y,z,radius,vx,vy,vz,wx,wy,wz\n")
        for s in spheres:
            f.write(",".join("%.12g" % v for v in s) + "\n")


def books(label, r, count):
    first = r[1]
    check(first["particles"] == 0 and first["particles_melted"] == count and first["deleted"] == count,
          "%s: %d particle(s) melted before the first step, out of the swarm and in the deletion books (particles %d, melted %d, deleted %d)"
          % (label, count, first["particles"], first["particles_melted"], first["deleted"]))
    # after the whole first step: the conversion and the step's transport (its own volume book, relative to the total)
    grown = (first["vof_volume_m3"] - r[0]["vof_volume_m3"] - count * MASS / RHO) / first["vof_volume_m3"]
    check(abs(grown) <= 1e-12, "%s: after the step the metal volume has grown by m/rho_m to %.2e of the total (tolerance 1e-12)" % (label, grown))
    worst = max(first["melt_volume_error"], first["melt_energy_error"], first["melt_momentum_error"])
    check(worst <= 1e-12, "%s: the conversion's books: volume %.1e, energy %.1e, momentum %.1e (tolerance 1e-12)"
          % (label, first["melt_volume_error"], first["melt_energy_error"], first["melt_momentum_error"]))
    acc = max(abs(x["energy_total_J"] - x["energy_accounted_J"]) for x in r) / r[0]["energy_total_J"]
    check(acc <= 1e-12, "%s: |energy_total_J - energy_accounted_J| at most %.1e of the total (tolerance 1e-12)" % (label, acc))


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-particle-melt-")
    try:
        drop = os.path.join(tmp, "drop.csv")
        write(drop, [(C, C, 6 * H, R, 0.1, 0, -0.5, 0, 2000, 0)])
        runs = {}
        for ranks in (1, 2):
            out = os.path.join(tmp, "drop-%d" % ranks)
            run_vofdem(exe, ranks, arguments(out, drop, extra=["-grid_ranks", "2,1,1"] if ranks == 2 else []))
            r = runs[ranks] = rows(out)
            label = "drop, %d rank(s)" % ranks
            books(label, r, 1)
            spin = MASS * R * R * 2000 ** 2 / 5
            check(abs(r[1]["melt_spin_energy_J"] / spin - 1) <= 1e-6, "%s: spin energy reported %.6e J against I w^2/2 = %.6e J" % (label, r[1]["melt_spin_energy_J"], spin))
            ke = 0.5 * MASS * (0.1 ** 2 + 0.5 ** 2)
            check(r[1]["flow_kinetic_energy_J"] <= ke, "%s: the fluid's kinetic energy after the merge %.4e J, the drop's %.4e J (no energy made)" % (label, r[1]["flow_kinetic_energy_J"], ke))
            lo, hi = min(x["temperature_min_K"] for x in r), max(x["temperature_max_K"] for x in r)
            check(lo >= 1650 - 1e-9 and hi <= 1700 + 1e-9, "%s: T within [1650, 1700] K: %.6f - %.6f K" % (label, lo, hi))
        a, b = runs[1], runs[2]
        d = max(abs(x[k] / y[k] - 1) for x, y in zip(a[1:], b[1:]) for k in ("vof_volume_m3", "energy_total_J", "flow_kinetic_energy_J"))
        check(d <= 1e-12, "drop: 1 and 2 ranks agree to %.1e (tolerance 1e-12)" % d)
        landing = os.path.join(tmp, "landing.csv")
        write(landing, [(C, C, 2 * H, R, 0, 0, -0.5, 0, 0, 0), (C - 4 * H, C, 5 * H, R, 0, 0, 0, 0, 0, 0)])
        out = os.path.join(tmp, "landing")
        run_vofdem(exe, 1, arguments(out, landing))
        r = rows(out)
        books("landing", r, 2)
        viol = max(x["vof_bound_violation"] for x in r)
        check(viol <= 1e-12, "landing: alpha within [0, 1] to %.1e after the excess went to the neighbours (tolerance 1e-12)" % viol)
        for name, t0, extra in (("below the solidus", 1500, []), ("-coupling_heat_melt 0", 1650, ["-coupling_heat_melt", "0"])):
            out = os.path.join(tmp, "none")
            shutil.rmtree(out, ignore_errors=True)
            run_vofdem(exe, 1, arguments(out, drop, t0, extra))
            r = rows(out)
            check(all(x["particles"] == 1 and x["particles_melted"] == 0 for x in r), "%s: the sphere stays a particle for 3 steps" % name)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
