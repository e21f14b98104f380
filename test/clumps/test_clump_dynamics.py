#!/usr/bin/python3
"""Rigid clumps (P10, src/dem/Clumps.cpp) in vofdem runs:
  - free precession: a two-sphere clump (equal spheres, centres 1.2 R apart) spinning in zero gravity keeps
    its shape, its kinetic energy, and its symmetry axis turns about the angular momentum L at the rate
    |L| / I_perp of torque-free motion, with I_perp and I_axis of the union computed here independently
    (slices of the union are discs);
  - two dumbbells collide off-centre across the rank boundary: momentum kept, energy lost, both spin;
  - a three-sphere clump dropped across the rank boundary onto the floor falls without turning (its weight
    acts at its centroid), stays rigid and whole, comes to rest, and 1 and 2 ranks agree.
  test_clump_dynamics.py VOFDEM"""
import csv
import math
import os
import shutil
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, failures, run_vofdem  # noqa: E402

R, RHO = 1e-4, 2500.0
BASE = ["-physics", "dem", "-grid_lower", "0,0,0", "-grid_upper", "2e-3,2e-3,2e-3", "-grid_cells", "4,4,4", "-dem_radius", "%g" % R,
        "-dem_density", "%g" % RHO, "-dem_youngs_modulus", "1e8", "-dem_poisson_ratio", "0.28", "-dem_fill_count", "0", "-monitor_timing", "0"]


def write(path, rows):
    with open(path, "w") as f:
        f.write("x,y,z,vx,vy,vz,wx,wy,wz,radius,clump\n")
        for r in rows:
            f.write(",".join("%.17g" % v for v in r) + "\n")


def read(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def dumbbell_inertia(r, d):
    """I_axis, I_perp (about the centroid) per unit density of two spheres of radius r, centres d apart."""
    x, w = np.polynomial.legendre.leggauss(12)
    z = 0.5 * (d / 2 + r) * (x + 1)  # z >= 0 half, doubled
    w = 0.5 * (d / 2 + r) * w
    rho2 = np.maximum(0, r * r - (z - d / 2) ** 2)
    return 2 * np.sum(w * np.pi / 2 * rho2 ** 2), 2 * np.sum(w * (np.pi / 4 * rho2 ** 2 + np.pi * rho2 * z * z))


def rotate(v, axis, angle):
    k = axis / np.linalg.norm(axis)
    return v * math.cos(angle) + np.cross(k, v) * math.sin(angle) + k * np.dot(k, v) * (1 - math.cos(angle))


def monitor(out):
    with open(os.path.join(out, "monitor.csv")) as f:
        return list(csv.DictReader(f))


def precession(exe, tmp):
    d = 1.2 * R
    c = np.array([1e-3, 1e-3, 1e-3])
    a0 = np.array([1.0, 0.4, -0.3])
    a0 /= np.linalg.norm(a0)
    w = np.array([120.0, -260.0, 180.0])  # rad/s: components along and across the axis
    rows = []
    for s in (-1, 1):
        x = c + s * 0.5 * d * a0
        v = np.cross(w, x - c)
        rows.append(list(x) + list(v) + list(w) + [R, 0])
    path = os.path.join(tmp, "dumbbell.csv")
    write(path, rows)
    out = os.path.join(tmp, "precession")
    steps, dt = 20000, 5e-7
    run_vofdem(exe, 1, BASE + ["-gravity", "0,0,0", "-dem_particles_file", path, "-dt", "%g" % dt, "-max_steps", str(steps), "-monitor_every", "1000",
                               "-output_dir", out, "-dem_save_particles", out + "-end.csv"])
    end = read(out + "-end.csv")
    x = [np.array([p["x"], p["y"], p["z"]]) for p in end]
    check(abs(np.linalg.norm(x[1] - x[0]) - d) < 1e-12 * d, "precession: the members stay %.3g m apart (error %.2e m)" % (d, abs(np.linalg.norm(x[1] - x[0]) - d)))
    Ia, Ip = dumbbell_inertia(R, d)
    wa = np.dot(w, a0) * a0
    L = RHO * (Ia * wa + Ip * (w - wa))
    t = steps * dt
    expect = rotate(a0, L, np.linalg.norm(L) / (RHO * Ip) * t)
    got = (x[1] - x[0]) / np.linalg.norm(x[1] - x[0])
    err = math.acos(min(1.0, float(np.dot(expect, got))))
    check(err < 1e-6, "precession: the axis after %.3g s (%.2f turns about L) is %.2e rad from the analytic one" % (t, np.linalg.norm(L) / (RHO * Ip) * t / (2 * math.pi), err))
    mid = 0.5 * (x[0] + x[1])
    check(np.linalg.norm(mid - c) < 1e-12, "precession: the centre stays put (moved %.2e m)" % np.linalg.norm(mid - c))
    E0 = 0.5 * RHO * (Ia * np.dot(wa, wa) + Ip * np.dot(w - wa, w - wa))
    rot = [float(r["rotational_energy_J"]) for r in monitor(out)]
    drift = max(abs(e - E0) for e in rot) / E0
    check(drift < 1e-8, "precession: rotational energy %.6e J (analytic %.6e J) kept to %.1e" % (rot[-1], E0, drift))


def drop(exe, tmp):
    # A bent three-sphere clump over the middle of the box (cut into two ranks along x) drops and settles.
    rows = [[1.0e-3 - 0.9 * R, 1e-3, 0.6e-3, 0, 0, 0, 0, 0, 0, R, 0],
            [1.0e-3 + 0.5 * R, 1e-3 + 0.6 * R, 0.65e-3, 0, 0, 0, 0, 0, 0, 0.8 * R, 0],
            [1.0e-3 + 0.2 * R, 1e-3 - 0.9 * R, 0.5e-3, 0, 0, 0, 0, 0, 0, 0.7 * R, 0],
            [0.5e-3, 0.5e-3, 0.3e-3, 0, 0, 0, 0, 0, 0, R, -1]]  # and a loose sphere
    path = os.path.join(tmp, "tripod.csv")
    write(path, rows)
    ends = {}
    for n in (1, 2):
        out = os.path.join(tmp, "drop%d" % n)
        run_vofdem(exe, n, BASE + ["-dem_particles_file", path, "-dem_restitution", "0.3", "-dem_friction", "0.5", "-max_steps", "40000", "-monitor_every", "500",
                                   "-dem_youngs_modulus", "1e7",
                                   "-grid_ranks", "%d,1,1" % n, "-output_dir", out, "-dem_save_particles", out + "-end.csv"])
        end = ends[n] = read(out + "-end.csv")
        # Before the first contact the clump falls without turning: its weight acts at its centroid.
        falling = [r for r in monitor(out) if int(r["wall_contacts"]) == 0 and float(r["time_s"]) < 0.005]
        check(len(falling) > 5 and all(float(r["rotational_energy_J"]) == 0 for r in falling),
              "drop on %d rank(s): no rotation in free fall (%d monitor rows, largest rotational energy %.1e J)"
              % (n, len(falling), max(float(r["rotational_energy_J"]) for r in falling)))
        check(len(end) == 4, "drop on %d rank(s): 4 spheres at the end" % n)
        x = np.array([[p["x"], p["y"], p["z"]] for p in end[:3]])
        x0 = np.array([r[:3] for r in rows[:3]])
        worst = max(abs(np.linalg.norm(x[i] - x[j]) - np.linalg.norm(x0[i] - x0[j])) for i in range(3) for j in range(i + 1, 3))
        check(worst < 1e-12, "drop on %d rank(s): member distances kept (worst change %.1e m)" % (n, worst))
        speed = max(math.sqrt(p["vx"] ** 2 + p["vy"] ** 2 + p["vz"] ** 2) for p in end[:3])
        low = sorted(p["z"] - p["radius"] for p in end[:3])
        check(low[2] < 1e-6 and speed < 1e-6, "drop on %d rank(s): the clump rests on the floor on its 3 spheres (gaps %s m, largest speed %.1e m/s)"
              % (n, ", ".join("%.1e" % g for g in low), speed))
    worst = max(abs(ends[1][i][k] - ends[2][i][k]) for i in range(4) for k in ("x", "y", "z"))
    check(worst < 1e-10, "drop: 1 and 2 ranks agree to %.1e m" % worst)


def collision(exe, tmp):
    # Two equal dumbbells (members overlapping: no contact inside a clump) collide off-centre in zero
    # gravity: the members of different clumps touch, momentum is kept (equal member shares M/2 and
    # symmetric members, so sum v_k = 2 (V_1 + V_2)), energy is lost, both clumps end up spinning.
    d, v0 = 1.2 * R, 0.1
    rows = [[0.6e-3, 1e-3 - 0.5 * d, 1e-3, v0, 0, 0, 0, 0, 0, R, 0], [0.6e-3, 1e-3 + 0.5 * d, 1e-3, v0, 0, 0, 0, 0, 0, R, 0],
            [0.95e-3 - 0.5 * d, 1e-3 + 0.8 * R, 1e-3, 0, 0, 0, 0, 0, 0, R, 1], [0.95e-3 + 0.5 * d, 1e-3 + 0.8 * R, 1e-3, 0, 0, 0, 0, 0, 0, R, 1]]
    path = os.path.join(tmp, "dumbbells.csv")
    write(path, rows)
    out = os.path.join(tmp, "collision")
    run_vofdem(exe, 2, BASE + ["-gravity", "0,0,0", "-dem_particles_file", path, "-dem_youngs_modulus", "1e7", "-dem_restitution", "0.5", "-max_steps", "4000",
                               "-monitor_every", "2", "-grid_ranks", "2,1,1", "-output_dir", out, "-dem_save_particles", out + "-end.csv"])
    end = read(out + "-end.csv")
    p = np.sum([[e["vx"], e["vy"], e["vz"]] for e in end], axis=0)
    check(np.linalg.norm(p - [2 * v0, 0, 0]) < 1e-12 * v0, "collision: momentum kept (sum of member velocities %s m/s)" % p)
    contacts = max(int(r["pair_contacts"]) for r in monitor(out))
    check(contacts > 0, "collision: members of different clumps touched (%d pair contacts at most)" % contacts)
    w = [np.linalg.norm([e["wx"], e["wy"], e["wz"]]) for e in end]
    check(min(w) > 1.0 and abs(end[0]["wz"] - end[1]["wz"]) < 1e-9 * w[0], "collision: both clumps spin (|w| %.1f and %.1f rad/s), each as one body" % (w[0], w[2]))
    mon = monitor(out)
    e0, e1 = float(mon[0]["kinetic_energy_J"]) + float(mon[0]["rotational_energy_J"]), float(mon[-1]["kinetic_energy_J"]) + float(mon[-1]["rotational_energy_J"])
    check(e1 < 0.95 * e0, "collision: kinetic energy falls from %.3e J to %.3e J (restitution 0.5)" % (e0, e1))


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-clumps-")
    try:
        precession(exe, tmp)
        collision(exe, tmp)
        drop(exe, tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)


if __name__ == "__main__":
    main()
