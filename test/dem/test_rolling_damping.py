#!/usr/bin/python3
"""-dem_rolling_damping (docs/physics.md P5): the viscous part of the EPSD rolling model, -eta 2 sqrt(I_r k_r) w while
the rolling spring is below its cap. ex05's sphere (R 1 mm, rolling at 5 cm/s on the floor, mu_r 0.1) stops after
0.073 s; then only the rolling spring acts, and what is left of its motion at t = 0.15 s is what the damping took:
  - at -dem_rolling_damping 0 the model is LIGGGHTS' epsd2 (spring and cap only), bit for bit in every monitor row,
    and the sphere keeps rocking on its spring (kinetic energy above 1e-15 J);
  - at 0.3 (the default) the rocking is damped out (below 1e-25 J, on 1 and 2 ranks), at 1 (critical) faster still
    (less rotational energy left than at 0.3).
Usage: test_rolling_damping.py VOFDEM"""
import csv
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402


def run(exe, tmp, name, ranks, rolling):
    out = os.path.join(tmp, name)
    run_vofdem(exe, ranks, ["-physics", "dem", "-grid_cells", "2,2,2", "-grid_upper", "0.01,0.01,0.01", "-grid_ranks", "%d,1,1" % ranks, "-gravity", "0,0,-9.81",
                            "-dem_radius", "1e-3", "-dem_restitution", "0.1", "-dem_friction", "0.5", "-dem_particles_file", os.path.join(tmp, "sphere.csv"),
                            "-dem_rolling_friction", "0.1", "-final_time", "0.15", "-max_steps", "100000", "-monitor_every", "1000", "-monitor_timing", "0",
                            "-output_dir", out] + rolling)
    path = os.path.join(out, "monitor.csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{k: v for k, v in r.items() if k != "wall_time_s"} for r in csv.DictReader(f)]


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-rolling-damping-")
    with open(os.path.join(tmp, "sphere.csv"), "w") as f:
        f.write("x,y,z,vx,vy,vz,wx,wy,wz\n0.0035,0.005,0.001,0.05,0,0,0,50,0\n")
    none = run(exe, tmp, "eta0", 1, ["-dem_rolling", "epsd", "-dem_rolling_damping", "0"])
    epsd2 = run(exe, tmp, "epsd2", 1, ["-dem_rolling", "epsd2"])
    ke = lambda rows: float(rows[-1]["kinetic_energy_J"]) if rows else float("nan")  # noqa: E731
    rot = lambda rows: float(rows[-1]["rotational_energy_J"]) if rows else float("nan")  # noqa: E731
    check(bool(none) and none == epsd2, "epsd at -dem_rolling_damping 0 is epsd2's run in all %d monitor rows" % len(none))
    check(ke(none) > 1e-15, "undamped, the sphere still rocks on its rolling spring at t = 0.15 s: kinetic energy %.3e J (above 1e-15 J)" % ke(none))
    for ranks in (1, 2):
        d = run(exe, tmp, "eta03-%d" % ranks, ranks, ["-dem_rolling", "epsd"])
        check(ke(d) < 1e-25, "%d rank(s), default damping 0.3: kinetic energy %.3e J at t = 0.15 s (below 1e-25 J)" % (ranks, ke(d)))
    d03 = run(exe, tmp, "eta03", 1, ["-dem_rolling", "epsd", "-dem_rolling_damping", "0.3"])
    d1 = run(exe, tmp, "eta1", 1, ["-dem_rolling", "epsd", "-dem_rolling_damping", "1"])
    check(rot(d1) < rot(d03), "critical damping 1 leaves less rotational energy than 0.3: %.3e J against %.3e J" % (rot(d1), rot(d03)))
    finish()


if __name__ == "__main__":
    main()
