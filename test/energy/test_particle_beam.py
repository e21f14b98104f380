#!/usr/bin/python3
"""The laser's share that particles take (docs/physics.md P11, F8; coupling/ParticleBeam.hpp): -physics
dem,flow,vof,energy, no gravity, IN718 particles (d 96 um, absorptivity 0.51) at rest in argon above an IN718 plate,
16^3 cells of 77 um (0.8 d), a fixed beam of 100 W, R_l 60 um at the box's centre, 3 steps of 1 us. Checked:
  (a) one particle on the axis absorbs eta_p P (1 - exp(-2 r^2/R^2)) (the disc's exact integral) to 2e-3 with the
      default rays, and closer with 4 times as many (the quadrature converges);
  (b) one particle off the axis (its centre 40 um away): the disc's integral by 400 x 400 Gauss-Legendre quadrature in
      polar coordinates, to 2e-3;
  (c) two particles one above the other on the axis: the upper takes what (a) takes, the lower nothing (shadowing);
  (d) the columns keep what the particles did not take: the plate absorbs eta_m (P - intercepted) to 1e-12, and the
      beam entering the box is P to 1e-12;
  (e) the account: |energy_total_J - energy_accounted_J| within 1e-10 of the energy the beam brought;
  (f) 1 and 2 ranks (split in x at the beam axis): the particles' absorbed power and the plate's to 1e-12.
  test_particle_beam.py VOFDEM"""
import csv
import math
import os
import shutil
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

P, R, ETA_P, ETA_M = 100.0, 60e-6, 0.51, 0.51   # in718.yaml's absorptivity for the particles and the plate
H, N = 77e-6, 16
L = N * H
RP = 48e-6
C = 0.5 * L


def disc_power(b, r):
    """int over a disc of radius r whose centre is b from the beam axis of I = 2P/(pi R^2) exp(-2 rho^2/R^2)."""
    x, w = np.polynomial.legendre.leggauss(400)
    rho = 0.5 * r * (x + 1)
    th = math.pi * (x + 1)
    RR, TT = np.meshgrid(rho, th, indexing="ij")
    d2 = b * b + RR * RR + 2 * b * RR * np.cos(TT)
    f = 2 * P / (math.pi * R * R) * np.exp(-2 * d2 / (R * R)) * RR
    return float(np.einsum("i,j,ij->", w, w, f)) * 0.5 * r * math.pi


def arguments(out, particles, extra=()):
    return ["-physics", "dem,flow,vof,energy", "-grid_upper", "%.10g,%.10g,%.10g" % (L, L, L), "-grid_cells", "%d,%d,%d" % (N, N, N), "-gravity", "0,0,0",
            "-flow_density", "1.6", "-flow_viscosity", "2.1e-5", "-vof_density", "8380", "-vof_viscosity", "6e-3",
            "-vof_boxes", "0,0,0,%.10g,%.10g,%.10g" % (L, L, 2 * H), "-energy_interface_radiation", "0", "-energy_initial_temperature", "300",
            "-laser_power", "%g" % P, "-laser_radius", "%g" % R, "-laser_path", "%.10g,%.10g" % (C, C),
            "-dem_radius", "%g" % RP, "-dem_density", "8380", "-dem_youngs_modulus", "1e4", "-dem_particles_file", particles,
            "-coupling_heat_initial_temperature", "300", "-dt", "1e-6", "-max_steps", "3", "-monitor_every", "1", "-monitor_timing", "0",
            "-output_dir", out] + list(extra)


def rows(out):
    with open(os.path.join(out, "monitor.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-particle-beam-")
    z0 = 6 * H
    cases = {"axis": [(C, C, z0)], "off_axis": [(C + 40e-6, C, z0)], "stacked": [(C, C, z0), (C, C, z0 + 2.5 * RP)]}
    exact = {"axis": ETA_P * P * (1 - math.exp(-2 * RP * RP / (R * R))), "off_axis": ETA_P * disc_power(40e-6, RP)}
    check(abs(disc_power(0, RP) / (P * (1 - math.exp(-2 * RP * RP / (R * R)))) - 1) < 1e-12, "the reference quadrature gives the axis's closed form to 1e-12")
    exact["stacked"] = exact["axis"]
    try:
        results = {}
        for name, centres in cases.items():
            pfile = os.path.join(tmp, name + ".csv")
            with open(pfile, "w") as f:
                f.write("x,y,z,radius\n" + "".join("%.12g,%.12g,%.12g,%.12g\n" % (x, y, z, RP) for x, y, z in centres))
            for ranks in ((1, 2) if name == "axis" else (1,)):
                out = os.path.join(tmp, "%s-%d" % (name, ranks))
                run_vofdem(exe, ranks, arguments(out, pfile, ["-grid_ranks", "2,1,1"] if ranks == 2 else []))
                r = rows(out)
                results[(name, ranks)] = r
                label = "%s, %d rank(s)" % (name, ranks)
                last = r[-1]
                err = abs(last["particle_beam_absorbed_W"] / exact[name] - 1)
                check(err <= 2e-3, "%s: the particles absorb %.6f W against the disc's %.6f W: %.2e (tolerance 2e-3)" % (label, last["particle_beam_absorbed_W"], exact[name], err))
                plate = ETA_M * (P - last["particle_beam_intercepted_W"])
                perr = abs(last["laser_absorbed_W"] / plate - 1)
                berr = abs(last["laser_beam_W"] / P - 1)
                check(perr <= 1e-12 and berr <= 1e-12, "%s: the plate absorbs eta_m (P - intercepted) to %.2e, the beam enters with P to %.2e (tolerance 1e-12)" % (label, perr, berr))
                brought = sum(x["laser_absorbed_W"] + x["particle_beam_absorbed_W"] for x in r[1:]) * 1e-6
                acc = max(abs(x["energy_total_J"] - x["energy_accounted_J"]) for x in r) / brought
                check(acc <= 1e-10, "%s: |energy_total_J - energy_accounted_J| at most %.2e of the %.3e J the beam brought (tolerance 1e-10)" % (label, acc, brought))
                if name == "stacked":
                    check(abs(last["particle_beam_intercepted_W"] * ETA_P - last["particle_beam_absorbed_W"]) <= 1e-12 * P and
                          abs(last["particle_beam_absorbed_W"] / results[("axis", 1)][-1]["particle_beam_absorbed_W"] - 1) <= 1e-12,
                          "%s: the pair absorbs what the upper one alone does (%.6f W against %.6f W): the lower is in its shadow" %
                          (label, last["particle_beam_absorbed_W"], results[("axis", 1)][-1]["particle_beam_absorbed_W"]))
                    check(last["particle_temperature_min_K"] == 300.0 or last["particle_temperature_min_K"] <= 300.0 + 1e-6,
                          "%s: the lower particle stays at %.9f K (the upper at %.3f K)" % (label, last["particle_temperature_min_K"], last["particle_temperature_max_K"]))
        a, b = results[("axis", 1)][-1], results[("axis", 2)][-1]
        d = max(abs(a[k] / b[k] - 1) for k in ("particle_beam_absorbed_W", "laser_absorbed_W"))
        check(d <= 1e-12, "axis: 1 and 2 ranks agree to %.2e (tolerance 1e-12)" % d)
        # (a) the quadrature converges: 4x the rays
        out = os.path.join(tmp, "axis-fine")
        run_vofdem(exe, 1, arguments(out, os.path.join(tmp, "axis.csv"), ["-coupling_heat_beam_rays", "4"]))
        coarse = abs(results[("axis", 1)][-1]["particle_beam_absorbed_W"] / exact["axis"] - 1)
        out2 = os.path.join(tmp, "axis-finer")
        run_vofdem(exe, 1, arguments(out2, os.path.join(tmp, "axis.csv"), ["-coupling_heat_beam_rays", "64"]))
        e4 = abs(rows(out)[-1]["particle_beam_absorbed_W"] / exact["axis"] - 1)
        e64 = abs(rows(out2)[-1]["particle_beam_absorbed_W"] / exact["axis"] - 1)
        check(e64 < e4 and e64 <= 1e-3, "axis: 4 rays per cell edge %.2e, the default %.2e, 64 rays %.2e: the share converges" % (e4, coarse, e64))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
