#!/usr/bin/python3
"""Powder-bed analysis end to end (src/analysis): a periodic simple-cubic lattice of touching spheres read by
vofdem (-dem_particles_file), analysed at the end of a zero-step run on 1 and 2 ranks (-analysis_metrics all)
and again from its particles_000000.h5 by vofdem-analyze; checks
  - packing density pi/6 in a window of whole lattice cells that starts off the lattice (spheres cut by
    the window, periodic images counted), every particle with coordination 6, segregation index 1 in
    every cell, cutting-ring packing of the known value;
  - 1 and 2 ranks, and the run and vofdem-analyze, give the same summary.csv; a window with no particle
    centre is refused in one line, and with -analysis_allow_empty recorded with the packing of the spheres
    reaching into it;
  - scripts/plot_powder.py makes its PNG files.
  test_powder_analysis.py VOFDEM VOFDEM_ANALYZE"""
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import ENV, check, failures, run_vofdem  # noqa: E402

R, N = 1e-4, 6
A = 2 * R
L = N * A
BOX = ["-grid_lower", "0,0,0", "-grid_upper", "%g,%g,%g" % (L, L, L), "-grid_periodic", "x,y,z"]
# A window of 3 x 2 x 4 lattice cells starting at (0.37, 0.11, 0.59) cells: cuts spheres everywhere.
LO = [0.37 * A, 0.11 * A, 0.59 * A]
HI = [LO[0] + 3 * A, LO[1] + 2 * A, LO[2] + 4 * A]
WINDOW = ["-analysis_lower", ",".join("%.17g" % v for v in LO), "-analysis_upper", ",".join("%.17g" % v for v in HI),
          "-analysis_contact_gap", "1e-12", "-analysis_ray_spacing", "1e-5", "-analysis_rings", "3", "-analysis_ring_radius", "%g" % R,
          "-analysis_segregation_cells", "3,2,1"]


def summary(d):
    with open(os.path.join(d, "summary.csv")) as f:
        return {r["metric"]: float(r["value"]) for r in csv.DictReader(f)}


def same(a, b, what):
    bad = [k for k in a if k not in b or abs(a[k] - b[k]) > 1e-12 * max(1.0, abs(a[k]))]
    check(not bad and set(a) == set(b), "%s: same summary.csv%s" % (what, (" (differ: %s)" % ", ".join(bad)) if bad else ""))


def main():
    exe, analyze = sys.argv[1], sys.argv[2]
    tmp = tempfile.mkdtemp(prefix="vofdem-analysis-")
    try:
        lattice = os.path.join(tmp, "lattice.csv")
        with open(lattice, "w") as f:
            f.write("x,y,z,radius\n")
            for k in range(N):
                for j in range(N):
                    for i in range(N):
                        f.write("%.17g,%.17g,%.17g,%g\n" % ((i + 0.5) * A, (j + 0.5) * A, (k + 0.5) * A, R))
        scene = ["-physics", "dem", "-grid_cells", "4,4,4", "-dem_radius", "%g" % R, "-dem_fill_count", "0", "-dem_particles_file", lattice,
                 "-gravity", "0,0,0", "-dt", "1e-8", "-max_steps", "0", "-monitor_timing", "0", "-dem_output_every", "1"] + BOX
        sums = {}
        for n in (1, 2):
            out = os.path.join(tmp, "run%d" % n)
            p = run_vofdem(exe, n, scene + WINDOW + ["-analysis_metrics", "all", "-output_dir", out])
            print(p.stdout)
            s = sums[n] = summary(os.path.join(out, "analysis"))
            check(s["particles_total"] == N ** 3, "%d rank(s): %d particles analysed" % (n, N ** 3))
            check(abs(s["packing_density"] - math.pi / 6) < 1e-10, "%d rank(s): packing density %.12f = pi/6" % (n, s["packing_density"]))
            check(s["mean_coordination"] == 6, "%d rank(s): mean coordination %g = 6" % (n, s["mean_coordination"]))
            check(s["segregation_index_min"] == 1 and s["segregation_index_max"] == 1, "%d rank(s): segregation index 1 in every cell" % n)
            # The rings' axes miss the lattice columns here (exact ring values: unit tests).
            check(0 < s["rings_packing_density"] < 1, "%d rank(s): cutting-ring packing %.4f in (0, 1)" % (n, s["rings_packing_density"]))
            check(s["tetrahedra"] > 0, "%d rank(s): %d Delaunay tetrahedra" % (n, s["tetrahedra"]))
        same(sums[1], sums[2], "1 and 2 ranks")
        h5 = os.path.join(tmp, "run2", "particles_000000.h5")
        out = os.path.join(tmp, "tool")
        p = subprocess.run(["mpiexec", "--oversubscribe", "-n", "2", analyze, "-analysis_input", h5, "-analysis_metrics", "all", "-analysis_dir", out] + BOX + WINDOW,
                           env=ENV, capture_output=True, text=True, timeout=300)
        check(p.returncode == 0, "vofdem-analyze exits 0")
        print(p.stdout, p.stderr)
        if p.returncode == 0:
            same(sums[2], summary(out), "the run and vofdem-analyze of its particles_000000.h5")
            # A window that holds no particle centre (between two lattice layers) is refused in one line.
            gap = ["-analysis_lower", "0,0,%.17g" % (0.6 * A), "-analysis_upper", "%g,%g,%.17g" % (L, L, 0.9 * A)]
            p = subprocess.run(["mpiexec", "--oversubscribe", "-n", "2", analyze, "-analysis_input", h5, "-analysis_dir", out + "-empty"] + BOX + gap,
                               env=ENV, capture_output=True, text=True, timeout=300)
            msg = "vofdem: error: analysis of %s: no particle centre in the window" % h5
            errors = [x for x in (p.stdout + p.stderr).splitlines() if x.startswith("vofdem: error:")]
            check(p.returncode != 0 and not p.stdout.strip() and len(errors) == 1 and errors[0].startswith(msg),
                  "vofdem-analyze refuses a window without particles in one line: %s" % " | ".join(errors))
            # ... unless told that an empty layer is a result (a sweep's bare layer): its packing is what the spheres
            # below reach into it, here the slab 0.2 R to 0.8 R above their centres: pi (0.6 - 0.504/3) R^3 per
            # 2 R x 2 R x 0.6 R of window, 0.18 pi.
            p = subprocess.run(["mpiexec", "--oversubscribe", "-n", "2", analyze, "-analysis_input", h5, "-analysis_dir", out + "-empty", "-analysis_allow_empty"] + BOX + gap,
                               env=ENV, capture_output=True, text=True, timeout=300)
            print(p.stdout, p.stderr)
            s = summary(out + "-empty") if p.returncode == 0 else {}
            check(s.get("particles_in_window") == 0 and abs(s.get("packing_density", -1) - 0.18 * math.pi) < 1e-10 and "mean_coordination" not in s,
                  "with -analysis_allow_empty the empty window is recorded: exit %d, particles_in_window %s, packing density %s (0.18 pi = %.12f), no coordination"
                  % (p.returncode, s.get("particles_in_window"), s.get("packing_density"), 0.18 * math.pi))
            p = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "plot_powder.py"), out], capture_output=True, text=True, timeout=300)
            print(p.stdout, p.stderr)
            pngs = sorted(f for f in os.listdir(out) if f.endswith(".png"))
            want = ["coordination.png", "pores.png", "rings.png", "segregation.png", "surface.png"]
            check(p.returncode == 0 and pngs == want, "plot_powder.py makes %s (made: %s)" % (", ".join(want), ", ".join(pngs)))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)


if __name__ == "__main__":
    main()
