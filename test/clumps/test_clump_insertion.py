#!/usr/bin/python3
"""Clump insertion (P10; src/dem/ClumpInsertion.cpp, ClumpLibrary.cpp) in vofdem runs:
  - fractions: 600 clumps of the four built-in regolith shapes at number fractions 0.1/0.2/0.3/0.4 (told
    apart by their member counts 2..5): each count within 4 binomial standard deviations of its share;
    every clump whole (all members, the base sphere the largest and lowest-id one); no two members of
    different clumps overlap; sizes: the base radius over the volume-equivalent radius is the template's;
  - ranks: the same clumps, falling and colliding, on 1 and 2 ranks (the same ids, positions to 1e-9 m: the
    round-off of sums in another order, grown by collisions); the fractions case on 2 ranks is placed by
    the same keyed draws;
  - deletion: clumps of five spheres thrown through a deletion box leave whole: every remaining clump
    has its five members, the deleted count is a multiple of five, no remaining centre is in the box.
  test_clump_insertion.py VOFDEM"""
import csv
import math
import os
import shutil
import sys
import tempfile
from collections import defaultdict

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, failures, run_vofdem  # noqa: E402

BOX = ["-physics", "dem", "-grid_lower", "0,0,0", "-grid_upper", "4e-3,4e-3,4e-3", "-grid_cells", "4,4,4", "-dem_radius", "5e-5", "-dem_density", "2770",
       "-dem_youngs_modulus", "1e7", "-dem_fill_count", "0", "-monitor_timing", "0", "-monitor_every", "1000000", "-seed", "11"]
REGOLITH = "regolith1,regolith2,regolith3,regolith4"


def read(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def clumps_of(rows):
    by = defaultdict(list)
    for r in rows:  # in id order
        if r["clump"] >= 0:
            by[int(r["clump"])].append(r)
    return by


def fractions(exe, tmp):
    out = os.path.join(tmp, "fractions")
    fr = [0.1, 0.2, 0.3, 0.4]
    n = 600
    # dt 1e-6 s: 6 steps of 100 clumps into a 3.6 mm cube, at rest without gravity.
    run_vofdem(exe, 2, BOX + ["-gravity", "0,0,0", "-dt", "1e-6", "-dt_force", "-max_steps", "6", "-dem_inserts", "a", "-dem_insert_a_lower", "2e-4,2e-4,2e-4",
                              "-dem_insert_a_upper", "3.8e-3,3.8e-3,3.8e-3", "-dem_insert_a_rate", "1.00001e8", "-dem_insert_a_clumps", REGOLITH,
                              "-dem_insert_a_clump_fractions", ",".join(map(str, fr)), "-dem_insert_a_size_distribution", "uniform",
                              "-dem_insert_a_radius_min", "3.5e-5", "-dem_insert_a_radius_max", "6e-5", "-dem_save_particles", out + ".csv"])
    rows = read(out + ".csv")
    by = clumps_of(rows)
    check(len(by) == n and all(r["clump"] >= 0 for r in rows), "fractions: %d clumps inserted (expected %d), %d spheres, none loose" % (len(by), n, len(rows)))
    counts = defaultdict(int)
    whole = True
    for c, m in by.items():
        counts[len(m)] += 1
        base = max(m, key=lambda r: r["radius"])
        whole = whole and base is m[0] and 2 <= len(m) <= 5
    for k, f in enumerate(fr):
        got, mean = counts[k + 2], n * f
        sd = math.sqrt(n * f * (1 - f))
        check(abs(got - mean) < 4 * sd, "fractions: regolith%d %d of %d clumps (expected %.0f +- %.1f)" % (k + 1, got, n, mean, sd))
    check(whole, "fractions: every clump has 2-5 members, its base sphere (the largest) first in id order")
    # No overlap between members of different clumps (within a clump they overlap by design).
    pts = [(r["x"], r["y"], r["z"], r["radius"], r["clump"]) for r in rows]
    cell = 2 * max(p[3] for p in pts)
    grid = defaultdict(list)
    for i, p in enumerate(pts):
        grid[(int(p[0] / cell), int(p[1] / cell), int(p[2] / cell))].append(i)
    worst = 0.0
    for i, p in enumerate(pts):
        key = (int(p[0] / cell), int(p[1] / cell), int(p[2] / cell))
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for j in grid.get((key[0] + dx, key[1] + dy, key[2] + dz), []):
                        q = pts[j]
                        if j <= i or q[4] == p[4]:
                            continue
                        d = math.dist(p[:3], q[:3])
                        worst = max(worst, (p[3] + q[3] - d) / (p[3] + q[3]))
    check(worst <= 0, "fractions: no overlap between clumps (largest relative overlap %.2e)" % worst)
    # The base radius ranges over the template's share of [35, 60] um: s = r_eq / r_eq,unit, base radius s.
    bases = [max(r["radius"] for r in m) for m in by.values()]
    check(min(bases) > 0.6 * 3.5e-5 and max(bases) < 6e-5, "fractions: base radii %.3g..%.3g m, below the volume-equivalent 35..60 um" % (min(bases), max(bases)))


def ranks(exe, tmp):
    res = {}
    for n in (1, 2):
        out = os.path.join(tmp, "ranks%d" % n)
        run_vofdem(exe, n, BOX + ["-grid_ranks", "%d,1,1" % n, "-gravity", "0,0,-9.81", "-dem_restitution", "0.3", "-dem_friction", "0.3", "-final_time", "4e-3", "-monitor_every", "500",
                                  "-max_steps", "100000", "-dem_inserts", "a", "-dem_insert_a_lower", "1.5e-3,1.5e-3,1.5e-4", "-dem_insert_a_upper", "2.5e-3,2.5e-3,6e-4",
                                  "-dem_insert_a_rate", "7.5e4", "-dem_insert_a_velocity", "0,0,-0.3", "-dem_insert_a_velocity_spread", "0.2", "-dem_insert_a_clumps", REGOLITH,
                                  "-dem_insert_a_size_distribution", "uniform", "-dem_insert_a_radius_min", "3.5e-5", "-dem_insert_a_radius_max", "6e-5",
                                  "-output_dir", out, "-dem_save_particles", out + ".csv"])
        res[n] = read(out + ".csv")
        with open(os.path.join(out, "monitor.csv")) as f:
            mon = list(csv.DictReader(f))
        pairs, walls = max(int(r["pair_contacts"]) for r in mon), max(int(r["wall_contacts"]) for r in mon)
        check(pairs > 5 and walls > 2, "ranks: %d rank(s): %d spheres; up to %d clump-clump and %d floor contacts (monitor every 500 steps)" % (n, len(res[n]), pairs, walls))
    a, b = res[1], res[2]
    same = len(a) == len(b) and all(p["clump"] == q["clump"] for p, q in zip(a, b))
    dx = max((abs(p[k] - q[k]) for p, q in zip(a, b) for k in ("x", "y", "z")), default=1)
    # Insertion is decided identically on every rank; contact forces are summed in another order on 2
    # ranks, and collisions amplify that round-off: 1e-9 m is 2e-5 of the smallest grain's diameter.
    check(same and dx < 1e-9, "ranks: 1 and 2 ranks insert the same %d clumps (%d spheres); after 4 ms of collisions positions agree to %.1e m" % (len(clumps_of(a)), len(a), dx))


def deletion(exe, tmp):
    out = os.path.join(tmp, "deletion")
    run_vofdem(exe, 2, BOX + ["-grid_ranks", "2,1,1", "-gravity", "0,0,0", "-final_time", "3e-3", "-max_steps", "100000",
                              "-dem_inserts", "a", "-dem_insert_a_lower", "3e-4,3e-4,3e-4", "-dem_insert_a_upper", "1e-3,3.7e-3,3.7e-3", "-dem_insert_a_rate", "1e5",
                              "-dem_insert_a_end", "2e-3", "-dem_insert_a_velocity", "1.5,0,0", "-dem_insert_a_clumps", "regolith4",
                              "-dem_insert_a_size_distribution", "uniform", "-dem_insert_a_radius_min", "3.5e-5", "-dem_insert_a_radius_max", "6e-5",
                              "-dem_delete_boxes", "3e-3,0,0,4e-3,4e-3,4e-3", "-output_dir", out, "-dem_save_particles", out + ".csv"])
    rows = read(out + ".csv")
    with open(os.path.join(out, "monitor.csv")) as f:
        last = list(csv.DictReader(f))[-1]
    ins, dele = int(last["inserted"]), int(last["deleted"])
    sizes = [len(m) for m in clumps_of(rows).values()]
    check(dele > 0 and dele % 5 == 0 and ins - dele == len(rows), "deletion: %d spheres inserted, %d deleted (%d clumps), %d remain" % (ins, dele, dele // 5, len(rows)))
    check(all(s == 5 for s in sizes), "deletion: all %d remaining clumps whole (member counts %s)" % (len(sizes), sorted(set(sizes))))
    inside = sum(1 for r in rows if r["x"] >= 3e-3)
    check(inside == 0, "deletion: no remaining centre in the box (%d)" % inside)


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-clumpins-")
    try:
        fractions(exe, tmp)
        ranks(exe, tmp)
        deletion(exe, tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
