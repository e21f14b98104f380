#!/usr/bin/python3
"""Powder-bed analysis of rigid clumps (src/analysis/SolidVolume.cpp, P10) at the end of a run and by vofdem-analyze:
a periodic lattice of two-sphere clumps (radii R and 0.8 R, centres 1.2 R apart along x; cells 3 R x 2 R x 2 R, so
each clump touches its six neighbours: end to end in x through the small and the large member, side by side in
y and z through the large ones) read by vofdem (-dem_particles_file with a clump column), analysed after zero
steps on 1 and 2 ranks, and again from its particles_000000.h5 by vofdem-analyze; checks
  - packing density of a window of whole cells starting off the lattice: the union of each clump (the lens
    of its members once) / cell volume, (V(R) + V(0.8 R) - lens) / 12 R^3, within the quadrature's error;
  - every clump is one particle with coordination 6 (coordination.csv counts clumps, not spheres); the
    cutting rings count clumps;
  - 1 and 2 ranks, and the run and vofdem-analyze (which reads the clump ids of particles_<step>.h5), give
    the same summary.csv;
  - a file without the clump dataset (written before it was) is still read, with a note, every sphere a
    particle (its packing counts the lens twice).
  test_clump_analysis.py VOFDEM VOFDEM_ANALYZE"""
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile

import h5py

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import ENV, check, failures, run_vofdem  # noqa: E402

R, N = 1e-4, 4
CELL = [3 * R, 2 * R, 2 * R]
L = [N * c for c in CELL]
BOX = ["-grid_lower", "0,0,0", "-grid_upper", ",".join("%.17g" % v for v in L), "-grid_periodic", "x,y,z"]
OFF = [0.37, 0.11, 0.59]
LO = [OFF[d] * CELL[d] for d in range(3)]
HI = [LO[d] + 2 * CELL[d] for d in range(3)]
WINDOW = ["-analysis_lower", ",".join("%.17g" % v for v in LO), "-analysis_upper", ",".join("%.17g" % v for v in HI),
          "-analysis_contact_gap", "1e-12", "-analysis_ray_spacing", "1e-5", "-analysis_rings", "2", "-analysis_ring_radius", "%g" % (2 * R),
          "-analysis_segregation_cells", "2,1,1"]


def sphere(r):
    return 4 * math.pi * r ** 3 / 3


def lens(a, b, d):
    return math.pi * (a + b - d) ** 2 * (d * d + 2 * d * (a + b) - 3 * (a - b) ** 2) / (12 * d)


def members():
    """Rows x, y, z, radius, clump: the large member first."""
    rows = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                c = [(i + 0.5) * CELL[0], (j + 0.5) * CELL[1], (k + 0.5) * CELL[2]]
                clump = (k * N + j) * N + i
                rows.append((c[0] - 0.5 * R, c[1], c[2], R, clump))
                rows.append((c[0] + 0.7 * R, c[1], c[2], 0.8 * R, clump))
    return rows


def summary(d):
    with open(os.path.join(d, "summary.csv")) as f:
        return {r["metric"]: float(r["value"]) for r in csv.DictReader(f)}


def coordination(d):
    with open(os.path.join(d, "coordination.csv")) as f:
        return {int(r["coordination"]): int(r["count"]) for r in csv.DictReader(f)}


def rings(d):
    with open(os.path.join(d, "rings.csv")) as f:
        return [int(r["particles"]) for r in csv.DictReader(f)]


def same(a, b, what):
    bad = [k for k in a if k not in b or abs(a[k] - b[k]) > 1e-12 * max(1.0, abs(a[k]))]
    check(not bad and set(a) == set(b), "%s: same summary.csv%s" % (what, (" (differ: %s)" % ", ".join(bad)) if bad else ""))


def analyze(analyze_exe, h5, out):
    p = subprocess.run(["mpiexec", "--oversubscribe", "-n", "2", analyze_exe, "-analysis_input", h5, "-analysis_metrics", "all", "-analysis_dir", out] + BOX + WINDOW,
                       env=ENV, capture_output=True, text=True, timeout=300)
    print(p.stdout, p.stderr)
    check(p.returncode == 0, "vofdem-analyze of %s exits 0" % os.path.basename(h5))
    return p


def main():
    exe, analyze_exe = sys.argv[1], sys.argv[2]
    rows = members()
    inside = sum(1 for r in rows if r[3] == R and all(LO[d] <= r[d] <= HI[d] for d in range(3)))  # clumps by their large member
    union = sphere(R) + sphere(0.8 * R) - lens(R, 0.8 * R, 1.2 * R)
    phi = union / (CELL[0] * CELL[1] * CELL[2])
    tol = 5e-4 * lens(R, 0.8 * R, 1.2 * R) / (CELL[0] * CELL[1] * CELL[2])  # the quadrature's error of the lenses cut (SolidVolume.hpp)
    # The rings (RingsAlongX): along x through the window's middle in y, radius 2 R, the window's heights.
    axes = [(LO[0] + (k + 0.5) * (HI[0] - LO[0]) / 2, 0.5 * (LO[1] + HI[1])) for k in range(2)]
    def held(r, a):
        return (r[0] - a[0]) ** 2 + (r[1] - a[1]) ** 2 <= (2 * R) ** 2 and LO[2] <= r[2] <= HI[2]
    want = [sum(1 for r in rows if r[3] == R and held(r, a)) for a in axes]
    spheres = [sum(1 for r in rows if held(r, a)) for a in axes]
    tmp = tempfile.mkdtemp(prefix="vofdem-clump-analysis-")
    try:
        path = os.path.join(tmp, "dumbbells.csv")
        with open(path, "w") as f:
            f.write("x,y,z,radius,clump\n")
            for r in rows:
                f.write("%.17g,%.17g,%.17g,%.17g,%d\n" % r)
        scene = ["-physics", "dem", "-grid_cells", "4,4,4", "-dem_radius", "%g" % R, "-dem_fill_count", "0", "-dem_particles_file", path,
                 "-gravity", "0,0,0", "-dt", "1e-8", "-max_steps", "0", "-monitor_timing", "0", "-dem_output_every", "1"] + BOX
        sums = {}
        for n in (1, 2):
            out = os.path.join(tmp, "run%d" % n)
            p = run_vofdem(exe, n, scene + WINDOW + ["-analysis_metrics", "all", "-output_dir", out])
            print(p.stdout)
            s = sums[n] = summary(os.path.join(out, "analysis"))
            z = coordination(os.path.join(out, "analysis"))
            check(abs(s["packing_density"] - phi) < tol, "%d rank(s): packing density %.9f = union of a clump / cell %.9f (+- %.1e)" % (n, s["packing_density"], phi, tol))
            check(s["mean_coordination"] == 6 and z.get(6) == inside and sum(z.values()) == inside,
                  "%d rank(s): %d clumps in the window, each one particle with coordination 6 (coordination.csv %s)" % (n, inside, z))
            check(0 < s["rings_packing_density"] < 1, "%d rank(s): cutting-ring packing %.4f in (0, 1)" % (n, s["rings_packing_density"]))
            check(rings(os.path.join(out, "analysis")) == want, "%d rank(s): the rings hold %s clumps (by their large member; %s spheres)" % (n, want, spheres))
        same(sums[1], sums[2], "1 and 2 ranks")
        h5 = os.path.join(tmp, "run2", "particles_000000.h5")
        with h5py.File(h5, "r") as f:
            check(sorted(set(f["clump"][()].astype(int))) == list(range(N ** 3)), "particles_000000.h5 has the clump id of every sphere")
        out = os.path.join(tmp, "tool")
        if analyze(analyze_exe, h5, out).returncode == 0:
            same(sums[2], summary(out), "the run and vofdem-analyze of its particles_000000.h5")
            check(coordination(out) == coordination(os.path.join(tmp, "run2", "analysis")) and rings(out) == want,
                  "vofdem-analyze: the run's coordination.csv and ring counts (clumps, not spheres)")
        # A file written before the clump ids were: read with a note, every sphere a particle.
        old = os.path.join(tmp, "old.h5")
        shutil.copy(h5, old)
        with h5py.File(old, "a") as f:
            del f["clump"]
        p = analyze(analyze_exe, old, os.path.join(tmp, "tool-old"))
        if p.returncode == 0:
            s = summary(os.path.join(tmp, "tool-old"))
            twice = (sphere(R) + sphere(0.8 * R)) / (CELL[0] * CELL[1] * CELL[2])
            check("has no clump dataset" in p.stdout and abs(s["packing_density"] - twice) < 1e-9,
                  "a file without clump ids: a note, and every sphere counted (packing %.6f = %.6f, the lens twice)" % (s["packing_density"], twice))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)


if __name__ == "__main__":
    main()
