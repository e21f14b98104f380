#!/usr/bin/python3
"""Particles files across a periodic face (-dem_particles_file, -dem_save_particles; src/dem/DemFill.cpp):
  - a sphere whose centre lies up to a radius outside the periodic box (it crossed the face since the run that
    wrote the file last wrapped it) is read as its image in the box, and a zero-step run saves it there;
  - a dumbbell clump across the periodic face, its spheres written on either side of the box (as a run holds
    them), is read as one body: spinning in zero gravity it turns about its own centroid exactly as the same
    dumbbell in the middle of the box does (before, the clump was built from the spheres as written, a box
    length apart);
  - the saved end state (spheres in the box) reads back and gives the same state after zero steps.
  On 1 and 2 ranks.
  test_periodic_file.py VOFDEM"""
import os
import shutil
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, failures, read_particles as read, run_vofdem  # noqa: E402

R, L = 1e-4, 2e-3
BASE = ["-physics", "dem", "-grid_lower", "0,0,0", "-grid_upper", "%g,%g,%g" % (L, L, L), "-grid_cells", "4,4,4", "-grid_periodic", "x",
        "-dem_radius", "%g" % R, "-dem_density", "2500", "-dem_youngs_modulus", "1e8", "-dem_fill_count", "0", "-gravity", "0,0,0",
        "-monitor_timing", "0"]


def write(path, rows):
    with open(path, "w") as f:
        f.write("x,y,z,vx,vy,vz,wx,wy,wz,radius,clump\n")
        for r in rows:
            f.write(",".join("%.17g" % v for v in r) + "\n")


def image(dx):
    return dx - L * round(dx / L)


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-periodic-file-")
    try:
        d, w = 1.2 * R, 1000.0  # dumbbell: member centres d apart; spin about z (rad/s)
        rows = [[-0.3 * R, 1.0e-3, 0.4e-3, 0, 0, 0, 0, 0, 0, R, -1],  # a sphere 0.3 R below the lower x face
                [L + 0.5 * R, 1.0e-3, 1.6e-3, 0, 0, 0, 0, 0, 0, R, -1],  # and one 0.5 R beyond the upper one
                [L - 0.5 * d, 0.5e-3, 1.0e-3, 0, 0, 0, 0, 0, w, R, 0],  # clump 0 across the face at x = L ...
                [0.5 * d, 0.5e-3, 1.0e-3, 0, 0, 0, 0, 0, w, R, 0],  # ... its second sphere written on the other side
                [1.0e-3 - 0.5 * d, 1.5e-3, 1.0e-3, 0, 0, 0, 0, 0, w, R, 1],  # clump 1: the same in the middle
                [1.0e-3 + 0.5 * d, 1.5e-3, 1.0e-3, 0, 0, 0, 0, 0, w, R, 1]]
        path = os.path.join(tmp, "start.csv")
        write(path, rows)
        for n in (1, 2):
            out = os.path.join(tmp, "zero%d" % n)
            run_vofdem(exe, n, BASE + ["-dem_particles_file", path, "-max_steps", "0", "-grid_ranks", "%d,1,1" % n, "-output_dir", out,
                                       "-dem_save_particles", out + ".csv"])
            s = read(out + ".csv")
            check(len(s) == 6, "zero steps on %d rank(s): 6 spheres saved (%d)" % (n, len(s)))
            if len(s) != 6:
                continue
            check(abs(s[0]["x"] - (L - 0.3 * R)) < 1e-15 and abs(s[1]["x"] - 0.5 * R) < 1e-15,
                  "zero steps on %d rank(s): the spheres outside the periodic faces read and saved as their images in the box (x = %.6e, %.6e m)"
                  % (n, s[0]["x"], s[1]["x"]))
            check(all(0 <= p["x"] <= L for p in s), "zero steps on %d rank(s): every saved centre in the box along x" % n)
            # The saved state reads back: the same spheres after zero steps.
            back = out + "-back"
            run_vofdem(exe, n, BASE + ["-dem_particles_file", out + ".csv", "-max_steps", "0", "-grid_ranks", "%d,1,1" % n, "-output_dir", back,
                                       "-dem_save_particles", back + ".csv"])
            t = read(back + ".csv")
            worst = max(abs(a[k] - b[k]) for a, b in zip(s, t) for k in ("x", "y", "z", "vx", "vy", "vz")) if len(t) == 6 else float("inf")
            check(worst < 1e-15, "zero steps on %d rank(s): the saved file reads back to the same state (largest change %.1e)" % (n, worst))
        ends = {}
        for n in (1, 2):
            out = os.path.join(tmp, "spin%d" % n)
            run_vofdem(exe, n, BASE + ["-dem_particles_file", path, "-max_steps", "400", "-grid_ranks", "%d,1,1" % n, "-output_dir", out,
                                       "-dem_save_particles", out + ".csv"])
            e = ends[n] = read(out + ".csv")
            if len(e) != 6:
                check(False, "spin on %d rank(s): 6 spheres at the end (%d)" % (n, len(e)))
                continue
            # Clump 0 across the face against clump 1 in the middle: the same turn about the centroid.
            r0 = np.array([image(e[3]["x"] - e[2]["x"]), e[3]["y"] - e[2]["y"], e[3]["z"] - e[2]["z"]])
            r1 = np.array([e[5]["x"] - e[4]["x"], e[5]["y"] - e[4]["y"], e[5]["z"] - e[4]["z"]])
            c0 = np.array([image(e[2]["x"] + 0.5 * image(e[3]["x"] - e[2]["x"])), 0.5 * (e[2]["y"] + e[3]["y"]), 0.5 * (e[2]["z"] + e[3]["z"])])
            turned = np.degrees(np.arctan2(r1[1], r1[0]))
            check(turned > 5, "spin on %d rank(s): the middle dumbbell turned (%.1f deg)" % (n, turned))
            check(np.linalg.norm(r0 - r1) < 1e-12, "spin on %d rank(s): the dumbbell across the face turns as the one in the middle (difference %.1e m)"
                  % (n, np.linalg.norm(r0 - r1)))
            check(np.linalg.norm(c0 - [0, 0.5e-3, 1.0e-3]) < 1e-12, "spin on %d rank(s): ... about its own centroid on the face (moved %.1e m)"
                  % (n, np.linalg.norm(c0 - [0, 0.5e-3, 1.0e-3])))
        if len(ends.get(1, [])) == 6 and len(ends.get(2, [])) == 6:
            worst = max(abs(image(a[k] - b[k]) if k == "x" else a[k] - b[k]) for a, b in zip(ends[1], ends[2]) for k in ("x", "y", "z"))
            check(worst < 1e-12, "spin: 1 and 2 ranks agree to %.1e m" % worst)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)


if __name__ == "__main__":
    main()
