#!/usr/bin/python3
"""scripts/make-stl (the meshes of spreading and funnel scenes): every shape's surface is what it says,
and vofdem uses the blade as a wall.

  closed shapes (super-ellipse blade, whole and half; a box): every edge is shared by exactly two
  triangles, in opposite directions (watertight, consistently oriented), the enclosed volume is
  positive (normals outward) and within 1e-4 of the exact super-ellipse prism 4ab G(1+1/n)^2/G(1+2/n) W
  at the default 256 segments; open shapes (hopper box without top, bottom and one side; funnel cone;
  cup cylinder): each edge is used once or twice, the area within 5e-4 of the exact one, normals away
  from the axis;
  a sphere dropped on the blade (a = 3 mm, b = 1 mm, n = 5, top at z = 5 mm) comes to rest on it:
  centre at z = 5 mm + r less the Hertz overlap the monitor reports (1e-9 m), the wall force equal
  to its weight (1e-6), on 1 and 2 ranks.
Usage: test_make_stl.py VOFDEM"""
import collections
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, failures, run_vofdem  # noqa: E402
MAKE = os.path.join(ROOT, "scripts", "make-stl")


def read_stl(path):
    tris, cur = [], []
    for line in open(path):
        w = line.split()
        if w and w[0] == "vertex":
            cur.append(tuple(float(x) for x in w[1:4]))
            if len(cur) == 3:
                tris.append(cur)
                cur = []
    return tris


def edges(tris):
    count = collections.Counter()
    for t in tris:
        for k in range(3):
            count[(t[k], t[(k + 1) % 3])] += 1
    return count


def closed(tris):
    e = edges(tris)
    return all(n == 1 and e.get((b, a), 0) == 1 for (a, b), n in e.items())


def volume(tris):
    v = 0.0
    for a, b, c in tris:
        v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])
    return v / 6


def make(tmp, *args):
    out = os.path.join(tmp, args[0] + ".stl")
    p = subprocess.run([sys.executable, MAKE, args[0], out] + list(args[1:]), capture_output=True, text=True)
    check(p.returncode == 0, "make-stl %s: %s" % (" ".join(args), (p.stdout + p.stderr).strip()))
    return read_stl(out), p.stdout, out


def main():
    exe = os.path.abspath(sys.argv[1])
    tmp = tempfile.mkdtemp(prefix="vofdem-stl-")
    a, b, n, w = 0.003, 0.001, 5.0, 0.01
    exact = 4 * a * b * math.gamma(1 + 1 / n) ** 2 / math.gamma(1 + 2 / n) * w
    for half in (False, True):
        args = ["superellipse-blade", "--a", str(a), "--b", str(b), "--n", str(n), "--width", str(w)] + (["--half"] if half else [])
        tris, _, _ = make(tmp, *args)
        v, want = volume(tris), exact * (0.5 if half else 1)
        check(closed(tris), "blade%s: watertight, every edge twice in opposite directions (%d triangles)" % (" (half)" if half else "", len(tris)))
        check(v > 0 and abs(v / want - 1) < 1e-4, "blade%s: volume %.6e against the exact %.6e (relative %.1e < 1e-4)" % (" (half)" if half else "", v, want, v / want - 1))
    tris, _, _ = make(tmp, "box", "--lower", "0,0,0", "--upper", "1,2,3")
    check(closed(tris) and abs(volume(tris) - 6) < 1e-12, "box: watertight, volume %.15g (6)" % volume(tris))
    tris, out, _ = make(tmp, "box", "--lower", "0,0,0", "--upper", "6e-4,4e-4,1e-3", "--open", "zlo,zhi,xhi")
    check(len(tris) == 6 and abs(float(re.search(r"area (\S+)", out).group(1)) - (2 * 6e-4 * 1e-3 + 4e-4 * 1e-3)) < 1e-15, "hopper box: 3 faces, area %s" % out.strip())
    for shape, args, r0, r1, h in (("cone", ["--r-bottom", "1.34e-3", "--r-top", "25.375e-3", "--height", "0.02"], 1.34e-3, 25.375e-3, 0.02),
                                   ("cylinder", ["--radius", "0.015", "--height", "0.035"], 0.015, 0.015, 0.035)):
        tris, out, _ = make(tmp, shape, *args)
        area = float(re.search(r"area (\S+)", out).group(1))
        want = math.pi * (r0 + r1) * math.hypot(h, r1 - r0)
        e = edges(tris)
        outward = all((t[0][0] * nx + t[0][1] * ny) > 0 for t in tris
                      for nx, ny in [((t[1][1] - t[0][1]) * (t[2][2] - t[0][2]) - (t[1][2] - t[0][2]) * (t[2][1] - t[0][1]),
                                      (t[1][2] - t[0][2]) * (t[2][0] - t[0][0]) - (t[1][0] - t[0][0]) * (t[2][2] - t[0][2]))])
        check(max(e.values()) == 1 and abs(area / want - 1) < 5e-4 and outward, "%s: open shell, area %.6e against %.6e, normals away from the axis" % (shape, area, want))
    tris, _, _ = make(tmp, "cylinder", "--radius", "7.5e-4", "--height", "1.748e-3", "--segments", "96", "--closed")
    want = 48 * 7.5e-4 ** 2 * math.sin(2 * math.pi / 96) * 1.748e-3
    check(closed(tris) and abs(volume(tris) / want - 1) < 1e-12, "closed cylinder (a cup): watertight, volume %.9e against the 96-gon prism %.9e" % (volume(tris), want))
    p = subprocess.run([sys.executable, MAKE, "box", os.path.join(tmp, "x.stl"), "--lower", "0,0,0", "--upper", "1,1,1", "--open", "top"], capture_output=True, text=True)
    check(p.returncode != 0 and "make-stl: error: --open takes" in p.stderr, "a bad --open is one error line: %s" % p.stderr.strip())
    # A sphere on the blade, 1 and 2 ranks.
    _, _, blade = make(tmp, "superellipse-blade", "--a", str(a), "--b", str(b), "--n", str(n), "--width", str(w))
    start = os.path.join(tmp, "one.csv")
    open(start, "w").write("x,y,z\n0.005,0.005,0.008\n")
    r, rho, g = 5e-4, 2500.0, 9.81
    weight = rho * 4 / 3 * math.pi * r ** 3 * g
    for ranks in (1, 2):
        out = os.path.join(tmp, "rest-%d.csv" % ranks)
        p = run_vofdem(exe, ranks, ["-physics", "dem", "-grid_cells", "4,4,4", "-grid_upper", "0.01,0.01,0.01", "-dem_radius", str(r),
                                    "-dem_particles_file", start, "-dem_walls", "blade", "-dem_wall_blade_type", "stl", "-dem_wall_blade_file", blade,
                                    "-dem_wall_blade_offset", "0.005,0,0.004", "-final_time", "0.1", "-max_steps", "1000000", "-monitor_every", "100000",
                                    "-monitor_timing", "0", "-dem_save_particles", out])
        last = [l for l in p.stdout.splitlines() if l.startswith("step")][-1]
        overlap = float(re.search(r"overlap (\S+) d", last).group(1)) * 2 * r
        fz = float(re.search(r"blade F \(\S+, \S+, (\S+)\) N", last).group(1))
        z = float(next(csv.DictReader(open(out)))["z"])
        want = 0.004 + b + r - overlap
        check(abs(z - want) < 1e-9 and abs(-fz / weight - 1) < 1e-6,
              "%d rank(s): the sphere rests on the blade at z = %.10f m (top + r - overlap = %.10f), wall force %.6e N (weight %.6e N)" % (ranks, z, want, -fz, weight))
    if failures:
        print("FAIL: %d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
