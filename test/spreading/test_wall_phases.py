#!/usr/bin/python3
"""Walls in phases (-dem_wall_<name>_start, -dem_wall_<name>_remove_time), the machinery of a spreading
scene that settles its powder first (seed 001), checked against free motion on 1 and 2 ranks:

  a shelf removed: a sphere resting on a plane wall at z = 5 mm falls when the wall is removed at
  t_r = 0.05 s; at T = 0.08 s its centre is at z_rest - g (T - t_r)^2/2 (to g T dt + 1e-7 m: the step
  at which the removal is seen, the rest overlap);
  a piston that waits: a plane wall at x = 2 mm moving at V = 0.1 m/s from t_s = 0.02 s meets a sphere
  at rest whose surface is d = 0.5 mm away at t_s + d/V and sends it off at (1 + e) V (an infinitely
  massive wall, e = 1 here); at T = 0.04 s the sphere has moved (1 + e) V (T - t_s - d/V) (to 2e-5 m:
  the contact lasts some microseconds). A wall that ignored its start time would have met the sphere
  20 ms earlier (4 mm further on);
  a belt that waits: a plane wall with velocity 0.1 m/s along its surface from t = 1 s carries a sphere
  resting on it under gravity with friction; until then the surface is at rest and the sphere stays put.
Usage: test_wall_phases.py VOFDEM"""
import csv
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, failures, run_vofdem  # noqa: E402

BASE = ["-physics", "dem", "-grid_cells", "4,4,4", "-grid_upper", "0.01,0.01,0.01", "-dem_radius", "5e-4", "-dem_density", "2500",
        "-dem_youngs_modulus", "1e8", "-max_steps", "10000000", "-monitor_every", "1000000", "-monitor_timing", "0"]


def particles(path):
    return sorted((int(float(r["id"])) if "id" in r else i, [float(r[k]) for k in ("x", "y", "z", "vx", "vy", "vz")])
                  for i, r in enumerate(csv.DictReader(open(path))))


def main():
    exe = os.path.abspath(sys.argv[1])
    tmp = tempfile.mkdtemp(prefix="vofdem-phases-")
    r, g = 5e-4, 9.81
    shelf = os.path.join(tmp, "shelf.csv")
    open(shelf, "w").write("x,y,z\n0.005,0.005,%.17g\n" % (0.005 + r))
    piston = os.path.join(tmp, "piston.csv")
    open(piston, "w").write("x,y,z\n0.003,0.005,0.005\n")
    for ranks in (1, 2):
        out = os.path.join(tmp, "shelf-%d.csv" % ranks)
        tr, T = 0.05, 0.08
        p = run_vofdem(exe, ranks, BASE + ["-gravity", "0,0,-9.81", "-dem_particles_file", shelf, "-dem_walls", "shelf", "-dem_wall_shelf_type", "plane",
                                           "-dem_wall_shelf_point", "0,0,0.005", "-dem_wall_shelf_normal", "0,0,1", "-dem_wall_shelf_remove_time", str(tr),
                                           "-final_time", str(T), "-dem_save_particles", out])
        check("removed at t = 0.05 s" in p.stdout, "%d rank(s): the set-up names the removal time" % ranks)
        rows = particles(out)
        z, want = rows[0][1][2], 0.005 + r - 0.5 * g * (T - tr) ** 2
        check(abs(z - want) < 2e-6, "%d rank(s): shelf removed at %g s: z(%g s) = %.8f m, free fall from rest on it %.8f m (|diff| %.1e < 2e-6)"
              % (ranks, tr, T, z, want, abs(z - want)))
        out = os.path.join(tmp, "piston-%d.csv" % ranks)
        ts, T, V, d = 0.02, 0.04, 0.1, 0.0005
        run_vofdem(exe, ranks, BASE + ["-gravity", "0,0,0", "-dem_restitution", "1", "-dem_friction", "0.5", "-dem_particles_file", piston,
                                       "-dem_walls", "piston", "-dem_wall_piston_type", "plane", "-dem_wall_piston_point", "0.002,0,0",
                                       "-dem_wall_piston_normal", "1,0,0", "-dem_wall_piston_velocity", "%g,0,0" % V, "-dem_wall_piston_start", str(ts),
                                       "-final_time", str(T), "-dem_save_particles", out])
        x, vx = particles(out)[0][1][0], particles(out)[0][1][3]
        want = 0.003 + 2 * V * (T - ts - d / V)
        check(abs(x - want) < 2e-5 and abs(vx / (2 * V) - 1) < 1e-3,
              "%d rank(s): piston from %g s: x(%g s) = %.7f m against %.7f m, v = %.6f m/s against 2V = %.3f" % (ranks, ts, T, x, want, vx, 2 * V))
        # A waiting wall's surface is at rest: a sphere pressed on it by gravity with friction is not dragged.
        out = os.path.join(tmp, "waiting-%d.csv" % ranks)
        run_vofdem(exe, ranks, BASE + ["-gravity", "0,0,-9.81", "-dem_friction", "0.5", "-dem_particles_file", shelf, "-dem_walls", "belt",
                                       "-dem_wall_belt_type", "plane", "-dem_wall_belt_point", "0,0,0.005", "-dem_wall_belt_normal", "0,0,1",
                                       "-dem_wall_belt_velocity", "0.1,0,0", "-dem_wall_belt_start", "1", "-final_time", "0.02", "-dem_save_particles", out])
        x, vx = particles(out)[0][1][0], particles(out)[0][1][3]
        check(abs(x - 0.005) < 1e-12 and abs(vx) < 1e-12, "%d rank(s): a sphere on a belt that waits stays put: x - 0.005 = %.1e m, vx = %.1e m/s" % (ranks, x - 0.005, vx))
    if failures:
        print("FAIL: %d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
