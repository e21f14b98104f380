#!/usr/bin/python3
"""Five options of the powder-bed analysis (src/analysis), each against a value it must produce:
  - -analysis_bins B: pore_radius.csv and pore_sphericity.csv have B bins whose counts add up to the tetrahedra;
  - -analysis_surface_grid (on by default): surface_grid.csv holds surface_rays_y rows of surface_rays_x heights whose
    mean is the summary's surface_mean_height (both written to 10 digits), and -analysis_surface_grid 0 writes no such file;
  - -analysis_reference_radius: a bed of equal spheres of radius R has segregation index R / reference in every cell
    (1 by default, 0.5 at 2 R);
  - -analysis_repose_fit: a pile of small spheres laid on a cone whose flank is 30 deg below half its height and 45
    deg above fits 30 deg between 0.1 and 0.4 of the height and 45 deg between 0.6 and 0.9 (within 1.5 deg: the
    spheres' bumps);
  - -analysis_clump_resolution: a lattice of two-sphere clumps (radii R and 0.8 R, 1.2 R apart) whose union is known
    exactly (the two spheres less their lens): the packing's error falls as the quadrature's columns grow, 8 -> 64 -> 512.
Each bed is read by vofdem (-dem_particles_file, zero steps) and analysed from its particles_000000.h5 by
vofdem-analyze on 1 rank, the repose pile also on 2.
Usage: test_analysis_options.py VOFDEM VOFDEM_ANALYZE"""
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import ENV, check, finish, run_vofdem  # noqa: E402

R = 1e-4


def summary(d):
    with open(os.path.join(d, "summary.csv")) as f:
        return {r["metric"]: float(r["value"]) for r in csv.DictReader(f)}


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def write_bed(tmp, name, particles, box, clumps=False):
    """particles: (x, y, z, r[, clump]); returns the particles_000000.h5 of a zero-step vofdem run."""
    path = os.path.join(tmp, name + ".csv")
    with open(path, "w") as f:
        f.write("x,y,z,radius,clump\n" if clumps else "x,y,z,radius\n")
        for p in particles:
            f.write(",".join("%.17g" % v for v in p[:4]) + ("," + str(p[4]) if clumps else "") + "\n")
    out = os.path.join(tmp, name)
    run_vofdem(exe, 1, ["-physics", "dem", "-grid_cells", "4,4,4", "-dem_radius", "%g" % R, "-dem_fill_count", "0", "-dem_particles_file", path, "-gravity", "0,0,0",
                        "-dt", "1e-8", "-max_steps", "0", "-monitor_timing", "0", "-dem_output_every", "1", "-output_dir", out] + box)
    return os.path.join(out, "particles_000000.h5")


def analyze(h5, out, args, ranks=1):
    p = subprocess.run(["mpiexec", "--oversubscribe", "-n", str(ranks), analyze_exe, "-analysis_input", h5, "-analysis_dir", out] + args, env=ENV,
                       capture_output=True, text=True, timeout=300)
    check(p.returncode == 0, "vofdem-analyze %s exits 0" % " ".join(a for a in args if a.startswith("-analysis_") and a not in ("-analysis_lower", "-analysis_upper")))
    if p.returncode:
        print(p.stdout, p.stderr)
    return p.returncode == 0


def lattice_checks(tmp):
    n, a = 6, 2 * R
    box = ["-grid_lower", "0,0,0", "-grid_upper", "%g,%g,%g" % (n * a, n * a, n * a), "-grid_periodic", "x,y,z"]
    # A slightly jittered simple-cubic lattice (deterministic), so that the Delaunay tetrahedra are not degenerate.
    pts = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                s = (i * 7 + j * 13 + k * 29) % 11 / 11.0 - 0.5
                pts.append(((i + 0.5) * a + 0.04 * R * s, (j + 0.5) * a - 0.03 * R * s, (k + 0.5) * a + 0.02 * R * s, 0.98 * R))
    h5 = write_bed(tmp, "lattice", pts, box)
    common = box + ["-analysis_ray_spacing", "2e-5", "-analysis_segregation_cells", "2,2,1"]
    for bins in (3, 7):
        out = os.path.join(tmp, "bins%d" % bins)
        if analyze(h5, out, common + ["-analysis_metrics", "pores", "-analysis_bins", str(bins)]):
            t = summary(out)["tetrahedra"]
            for f in ("pore_radius.csv", "pore_sphericity.csv"):
                h = rows(os.path.join(out, f))
                check(len(h) == bins and sum(int(r["count"]) for r in h) == t, "-analysis_bins %d: %s has %d bins holding %d of %d tetrahedra"
                      % (bins, f, len(h), sum(int(r["count"]) for r in h), t))
    for grid in (False, True):
        out = os.path.join(tmp, "grid%d" % grid)
        if analyze(h5, out, common + ["-analysis_metrics", "surface"] + ([] if grid else ["-analysis_surface_grid", "0"])):
            path = os.path.join(out, "surface_grid.csv")
            if not grid:
                check(not os.path.exists(path), "-analysis_surface_grid 0: no surface_grid.csv")
                continue
            s = summary(out)
            g = [[float(v) for v in line.split(",")] for line in open(path)] if os.path.exists(path) else []
            heights = [v for line in g for v in line]
            mean = sum(heights) / len(heights) if heights else float("nan")
            check(len(g) == s["surface_rays_y"] and all(len(line) == s["surface_rays_x"] for line in g)
                  and abs(mean - s["surface_mean_height"]) < 1e-9 * s["surface_mean_height"],
                  "-analysis_surface_grid (default): %d x %d heights (the summary's %d x %d), mean %.12g m = surface_mean_height %.12g m"
                  % (len(g[0]) if g else 0, len(g), s["surface_rays_x"], s["surface_rays_y"], mean, s["surface_mean_height"]))
    for ref, want in ((None, 1.0), (2 * 0.98 * R, 0.5)):
        out = os.path.join(tmp, "ref%s" % ("default" if ref is None else "2R"))
        if analyze(h5, out, common + ["-analysis_metrics", "segregation"] + ([] if ref is None else ["-analysis_reference_radius", "%.17g" % ref])):
            s = summary(out)
            check(abs(s["segregation_index_min"] - want) < 1e-12 and abs(s["segregation_index_max"] - want) < 1e-12,
                  "-analysis_reference_radius %s: segregation index %.12g to %.12g in every cell (R / reference = %g)"
                  % ("not given" if ref is None else "%g m" % ref, s["segregation_index_min"], s["segregation_index_max"], want))


def repose_checks(tmp):
    # A cone of base radius B: 30 deg from the rim up to half its height hk, 45 deg above (kink at distance dk = hk).
    r, B = 1.5e-5, 1e-3
    t30 = math.tan(math.radians(30))
    dk = t30 * B / (1 + t30)
    hk = dk

    def flank(d):
        return (B - d) * t30 if d >= dk else hk + (dk - d)

    side, step = 2.4e-3, 1.6 * r
    c = side / 2
    pts = []
    m = int(side / step)
    for j in range(m):
        for i in range(m):
            x, y = (i + 0.5) * step, (j + 0.5) * step
            d = math.hypot(x - c, y - c)
            if d <= B:
                pts.append((x, y, flank(d) + r, r))
    box = ["-grid_lower", "0,0,0", "-grid_upper", "%g,%g,%g" % (side, side, 1.2e-3)]
    h5 = write_bed(tmp, "pile", pts, box)
    H = 2 * hk
    for lo, hi, want in ((0.1, 0.4, 30.0), (0.6, 0.9, 45.0)):
        for ranks in (1, 2):
            out = os.path.join(tmp, "repose-%g-%d" % (lo, ranks))
            if analyze(h5, out, box + ["-analysis_metrics", "repose", "-analysis_ray_spacing", "5e-6", "-analysis_repose_axis", "%g,%g" % (c, c),
                                       "-analysis_repose_fit", "%g,%g" % (lo, hi)], ranks):
                s = summary(out)
                check(abs(s["repose_angle"] - want) < 1.5, "%d rank(s): -analysis_repose_fit %g,%g: %.3f deg (flank %g deg; pile height %.4g m, the cone's %.4g m + 2 r)"
                      % (ranks, lo, hi, s["repose_angle"], want, s["repose_pile_height"], H))


def clump_checks(tmp):
    n, cell = 3, [3 * R, 2 * R, 2 * R]
    box = ["-grid_lower", "0,0,0", "-grid_upper", ",".join("%.17g" % (n * v) for v in cell), "-grid_periodic", "x,y,z"]
    pts = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                cx, cy, cz = (i + 0.5) * cell[0], (j + 0.5) * cell[1], (k + 0.5) * cell[2]
                pts.append((cx - 0.5 * R, cy, cz, R, (k * n + j) * n + i))
                pts.append((cx + 0.7 * R, cy, cz, 0.8 * R, (k * n + j) * n + i))
    h5 = write_bed(tmp, "clumps", pts, box, clumps=True)
    lo = [0.37 * cell[0], 0.11 * cell[1], 0.59 * cell[2]]
    win = ["-analysis_lower", ",".join("%.17g" % v for v in lo), "-analysis_upper", ",".join("%.17g" % (lo[d] + 2 * cell[d]) for d in range(3))]
    a, b, dist = R, 0.8 * R, 1.2 * R
    lens = math.pi * (a + b - dist) ** 2 * (dist * dist + 2 * dist * (a + b) - 3 * (a - b) ** 2) / (12 * dist)
    exact = (4 * math.pi / 3 * (a ** 3 + b ** 3) - lens) / (cell[0] * cell[1] * cell[2])
    err = {}
    for res in (8, 64, 512):
        out = os.path.join(tmp, "clump%d" % res)
        if analyze(h5, out, box + win + ["-analysis_metrics", "packing", "-analysis_clump_resolution", str(res)]):
            err[res] = abs(summary(out)["packing_density"] - exact)
    check(len(err) == 3 and err[8] > err[64] > err[512], "-analysis_clump_resolution 8 / 64 / 512: packing error %s against the exact union %.9f"
          % (" / ".join("%.2e" % err[k] for k in sorted(err)), exact))


def main():
    global exe, analyze_exe
    exe, analyze_exe = sys.argv[1], sys.argv[2]
    tmp = tempfile.mkdtemp(prefix="vofdem-analysis-options-")
    try:
        lattice_checks(tmp)
        repose_checks(tmp)
        clump_checks(tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
