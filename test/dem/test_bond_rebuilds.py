#!/usr/bin/python3
"""Bonds (docs/physics.md P13) keep their history through neighbour-list rebuilds and migration between ranks:
  two spheres (r = 1 mm, 1 um apart) bonded at t = 0 fly at 10 m/s along z across the rank boundary (z = 5 mm, with
  -grid_ranks 1,1,2) while vibrating along the bond (relative speed 1 mm/s at the start). With -dem_skin 2e-5 m the
  lists are rebuilt about every 20 steps, some 200 times, and the pair migrates to the other rank.
  - the bond stays intact and its vibration keeps its amplitude: sqrt(s^2 + (v_rel/omega)^2) at the end, s the
    stretch and omega = sqrt(k_n A / (m/2)), equals v_rel,0/omega within 2 % (leapfrog's energy wobbles by about
    (omega dt)^2/4 ~ 0.5 %; a history lost at one rebuild while stretched moves the pair's rest distance by the
    stretch, and the amplitude by up to 100 %);
  - the end state on 2 ranks with many rebuilds equals the one on 1 rank with the default skin (few rebuilds)
    to 1e-12 (positions relative to the box, velocities to 10 m/s).
  test_bond_rebuilds.py VOFDEM"""
import math
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, read_particles, run_vofdem  # noqa: E402

r, rho, gap, kn = 1e-3, 2500.0, 1e-6, 1e13
V, vrel = 10.0, 1e-3
A = math.pi * r * r
m = rho * 4.0 / 3.0 * math.pi * r**3
omega = math.sqrt(kn * A / (m / 2))
STEPS = 5000
SCENE = ["-physics", "dem", "-grid_upper", "0.01,0.01,0.01", "-grid_cells", "2,2,2", "-gravity", "0,0,0", "-dem_radius", "%.17g" % r,
         "-dem_density", "%.17g" % rho, "-dem_cohesion", "bond", "-dem_bond_normal_stiffness", "%.17g" % kn, "-dem_bond_shear_stiffness", "%.17g" % kn,
         "-dem_bond_tensile_strength", "1e30", "-dem_bond_shear_strength", "1e30", "-dem_bond_gap", "1e-5", "-max_steps", str(STEPS), "-final_time", "1",
         "-monitor_every", str(STEPS), "-monitor_timing", "0"]


def run(exe, ranks, tmp, label, extra):
    out = os.path.join(tmp, label)
    os.makedirs(out)
    path = os.path.join(out, "pair.csv")
    z0 = 0.0035  # the pair's centre crosses z = 5 mm after about 3000 steps
    with open(path, "w") as fh:
        fh.write("x,y,z,vx,vy,vz\n")
        fh.write("0.005,0.005,%.17g,0,0,%.17g\n" % (z0 - r - gap / 2, V - vrel / 2))
        fh.write("0.005,0.005,%.17g,0,0,%.17g\n" % (z0 + r + gap / 2, V + vrel / 2))
    p = run_vofdem(exe, ranks, SCENE + extra + ["-dem_particles_file", path, "-dem_save_particles", os.path.join(out, "after.csv"), "-output_dir", out])
    with open(os.path.join(out, "monitor.csv")) as fh:
        head, *rows = [line.strip().split(",") for line in fh if line.strip()]
    return read_particles(os.path.join(out, "after.csv")), dict(zip(head, rows[-1])) if rows else {}, p.stdout


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-bond-rebuilds-")
    try:
        ref, _, _ = run(exe, 1, tmp, "ref", [])
        end, last, out = run(exe, 2, tmp, "many", ["-grid_ranks", "1,1,2", "-dem_skin", "2e-5"])
        if len(ref) != 2 or len(end) != 2 or not last:
            check(False, "both runs wrote their particles and monitor")
            return
        dt = float(last["dt_s"]) if "dt_s" in last else float(last["time_s"]) / STEPS
        zc = 0.5 * (end[0]["z"] + end[1]["z"])
        check(zc > 0.0055, "the pair crossed the rank boundary at z = 5 mm: its centre is at z = %.4f mm (%d steps of %.3e s, one rebuild per %.1f steps)"
              % (1e3 * zc, STEPS, dt, 1e-5 / (V * dt)))
        check(int(last["bonds_intact"]) == 1 and int(last["bonds_broken"]) == 0, "the bond holds (intact %s, broken %s)" % (last["bonds_intact"], last["bonds_broken"]))
        s = end[1]["z"] - end[0]["z"] - (2 * r + gap)
        v = end[1]["vz"] - end[0]["vz"]
        amp, amp0 = math.sqrt(s * s + (v / omega) ** 2), vrel / omega
        check(abs(amp / amp0 - 1) < 0.02, "its vibration keeps its amplitude: %.6e m against %.6e m at the start (%.3f %%, tolerance 2 %%; omega dt = %.3f)"
              % (amp, amp0, 100 * abs(amp / amp0 - 1), omega * dt))
        dx = max(abs(end[i][k] - ref[i][k]) for i in range(2) for k in "xyz") / 0.01
        dv = max(abs(end[i][k] - ref[i][k]) for i in range(2) for k in ("vx", "vy", "vz")) / V
        check(dx < 1e-12 and dv < 1e-12, "2 ranks with ~%d rebuilds equal 1 rank with the default skin: positions to %.1e, velocities to %.1e (tolerance 1e-12)"
              % (STEPS * V * dt / 1e-5, dx, dv))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
