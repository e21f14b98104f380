#!/usr/bin/python3
"""Filling and inserting across periodic directions (src/dem/RandomFill.cpp, ParticleSources.cpp; SphereHash.hpp):
a random fill and an insertion region that span the periodic x and y of the box place centres right up to the
faces (no gap a radius wide at the seam, which a hopper or feed slot a few tens of diameters wide would show)
and never overlap a sphere across a face (minimum-image distances, all pairs). Zero gravity and zero
velocities, so the saved state after a few steps is where the spheres were placed. Before 2026-11-27 the
insertion region had to keep the largest radius from a periodic face (an input error here) and the fill
kept that margin. Clumps (regolith1, 2) inserted across the faces arrive whole, none lost: a clump whose first
member lay past a face belonged to no rank (the lunar feed slot across its periodic width lost 2 of 3,606
spheres in 185 steps). On 1 and 2 ranks.
  test_periodic_seam.py VOFDEM"""
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, read_particles as read, run_vofdem  # noqa: E402

L, R0, R1 = 2e-3, 0.8e-4, 1.2e-4
BASE = ["-physics", "dem", "-grid_lower", "0,0,0", "-grid_upper", "%g,%g,%g" % (L, L, L), "-grid_cells", "4,4,4", "-grid_periodic", "x,y",
        "-dem_fill_size_distribution", "uniform", "-dem_fill_radius_min", "%g" % R0, "-dem_fill_radius_max", "%g" % R1,
        "-dem_density", "2500", "-dem_youngs_modulus", "1e8", "-gravity", "0,0,0", "-monitor_timing", "0", "-seed", "11"]
FILL = ["-dem_fill_mode", "random", "-dem_fill_count", "200", "-dem_fill_lower", "0,0,0", "-dem_fill_upper", "%g,%g,%g" % (L, L, 0.8e-3)]
INSERT = ["-dem_fill_count", "0", "-dem_inserts", "a", "-dem_insert_a_lower", "0,0,1.0e-3", "-dem_insert_a_upper", "%g,%g,1.8e-3" % (L, L),
          "-dem_insert_a_rate", "1e9", "-dem_insert_a_end", "1e-5", "-dem_insert_a_size_distribution", "uniform",
          "-dem_insert_a_radius_min", "%g" % R0, "-dem_insert_a_radius_max", "%g" % R1]
# regolith1 and a lopsided dumbbell (a small satellite 1.5 base radii out: the centroid sits well off the base
# sphere, so near a face the base sphere, the clump's first member, often lies past it)
CLUMPS = INSERT + ["-dem_clump_templates", "lop", "-dem_clump_lop_spheres", "0,0,0,1,0,1.5,0,0.9", "-dem_insert_a_clumps", "regolith1,lop"]


def worst_overlap(s):
    """The largest overlap of any pair, minimum image along x and y, relative to the pair's radius sum."""
    worst = 0.0
    for i in range(len(s)):
        for j in range(i):
            d2 = 0.0
            for k, periodic in (("x", True), ("y", True), ("z", False)):
                dx = s[i][k] - s[j][k]
                if periodic:
                    dx -= L * round(dx / L)
                d2 += dx * dx
            if s[i].get("clump", -1) >= 0 and s[i]["clump"] == s[j].get("clump", -2):
                continue  # members of one clump overlap by design
            rs = s[i]["radius"] + s[j]["radius"]
            worst = max(worst, 1 - d2 ** 0.5 / rs)
    return worst


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-periodic-seam-")
    try:
        for what, args, lo, hi in (("fill", FILL, 0.0, 0.8e-3), ("insertion", INSERT, 1.0e-3, 1.8e-3), ("clump insertion", CLUMPS, 0.9e-3, 1.9e-3)):
            for n in (1, 2):
                out = os.path.join(tmp, "%s%d" % (what, n))
                p = run_vofdem(exe, n, BASE + args + ["-max_steps", "5", "-grid_ranks", "%d,1,1" % n, "-output_dir", out, "-dem_save_particles", out + ".csv"])
                s = read(out + ".csv")
                last = [l for l in p.stdout.splitlines() if l.startswith("step")]
                if what != "fill" and last:
                    ins = int(last[-1].split("inserted ")[1].split()[0])
                    check(ins == len(s), "%s on %d rank(s): %d spheres inserted, %d present" % (what, n, ins, len(s)))
                if what == "clump insertion":
                    members = {}
                    for q in s:
                        members[q["clump"]] = members.get(q["clump"], 0) + 1
                    check(all(2 <= m <= 5 for m in members.values()), "%s on %d rank(s): %d clumps, all whole" % (what, n, len(members)))
                check(len(s) >= 150, "%s on %d rank(s): %d spheres placed (>= 150)" % (what, n, len(s)))
                if not s:
                    continue
                over = worst_overlap(s)
                check(over <= 1e-9, "%s on %d rank(s): no two spheres overlap, across the periodic faces included (largest overlap %.2e of the radius sum)"
                      % (what, n, over))
                gap = min(min(p[k], L - p[k]) / p["radius"] for p in s for k in ("x", "y"))
                check(gap < 0.25, "%s on %d rank(s): centres up to the periodic faces (the closest %.3f radii from one; a seam gap would be >= 1)" % (what, n, gap))
                inside = all(0 <= p["x"] <= L and 0 <= p["y"] <= L and lo <= p["z"] <= hi for p in s)
                check(inside, "%s on %d rank(s): every centre in the region" % (what, n))
    finally:
        shutil.rmtree(tmp)
    finish()


if __name__ == "__main__":
    main()
