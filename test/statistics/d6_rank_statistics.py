#!/usr/bin/python3
"""D6, long horizon (docs/verification.md): the same scene on 1, 2 and 4 ranks, run long enough that the
trajectories have decorrelated, must give the same bulk statistics within 3 sigma of a 1-rank
ensemble of seeds.

Runs examples/ex20_rank_statistics (which prints lines "stat: <name> | <value> | <unit>"):
  - a 1-rank ensemble: the reference seed and K-1 further seeds (-seed changes the fill jitter);
  - the reference seed on each rank count of --ranks (decomposition given by --grid-ranks-N).
Checks, each printed next to its tolerance:
  - particle counts equal to the 1-rank count exactly;
  - the trajectories did decorrelate: the RMS distance between the 1-rank and N-rank positions of the
    reference seed exceeds --min-rms (otherwise agreement in the statistics proves nothing);
  - every statistic of every N-rank run lies within mean +- 3 sigma of the ensemble, sigma being the
    spread of one new draw around the estimated mean, s * sqrt(1 + 1/K).
Also prints "result: quantity | value | reference | ok|FAIL" lines for scripts/validate.

  d6_rank_statistics.py --exe build/examples/ex20_rank_statistics [--seeds K] [--ranks 2,4] [-- scene options]
  --parallel-extra "-dem_friction 0.2": a deliberately different N-rank scene, which must fail.
"""
import argparse
import csv
import math
import os
import re
import shlex
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

# A granular gas of 400 spheres (random fill, velocities spread 0.3 m/s, e = 0.8) that collides, falls
# and settles in a box: 30000 steps (~0.13 s), the last 2000 averaged. Measured: the 1- and 2-rank
# final positions differ by ~0.8 R RMS; each 1-rank run takes ~3-7 s.
SCENE = ("-physics dem -grid_cells 4,4,6 -grid_upper 0.02,0.02,0.03 -dem_radius 1e-3 -dem_fill_mode random -dem_fill_count 400 "
         "-dem_fill_lower 0,0,0.004 -dem_fill_upper 0.02,0.02,0.03 -dem_fill_velocity_spread 0.3 -dem_restitution 0.8 "
         "-dem_friction 0.5 -steps 30000 -average_steps 2000 -slab 0.002,0.005").split()
GRID_RANKS = {2: "2,1,1", 4: "2,2,1"}


def run(exe, nsize, args, workdir, name):
    cmd = ["mpiexec", "-n", str(nsize)]
    if nsize > (os.cpu_count() or 1):
        cmd += ["--oversubscribe", "--bind-to", "none"]
    save = os.path.join(workdir, name + ".csv")
    cmd += [exe] + args + ["-dem_save_particles", save]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="1")
    p = subprocess.run(cmd, env=env, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError("%s failed (exit %d):\n%s%s" % (" ".join(shlex.quote(c) for c in cmd), p.returncode, p.stdout, p.stderr))
    stats = {m.group(1).strip(): float(m.group(2)) for m in re.finditer(r"^stat: ([^|]*)\| *(\S+) *\|", p.stdout, re.M)}
    m = re.search(r"^after \d+ steps: particles (\d+) of (\d+)$", p.stdout, re.M)
    if not stats or not m:
        raise RuntimeError("%s: no statistics in the output:\n%s" % (name, p.stdout))
    with open(save) as f:
        positions = [(float(r["x"]), float(r["y"]), float(r["z"])) for r in csv.DictReader(f)]
    return {"stats": stats, "particles": int(m.group(1)), "initial": int(m.group(2)), "positions": positions}


def rms_distance(a, b):
    return math.sqrt(sum((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 + (p[2] - q[2]) ** 2 for p, q in zip(a, b)) / len(a))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True, help="path of ex20_rank_statistics")
    ap.add_argument("--seeds", type=int, default=8, help="ensemble size K (>= 3)")
    ap.add_argument("--reference-seed", type=int, default=7)
    ap.add_argument("--ranks", default="2,4", help="rank counts to compare with the ensemble")
    ap.add_argument("--jobs", type=int, default=2, help="1-rank runs at once")
    ap.add_argument("--min-rms", type=float, default=1e-4, help="smallest RMS position difference (m) that shows decorrelation")
    ap.add_argument("--parallel-extra", default="", help="options added to the N-rank runs only (to show that the check can fail)")
    ap.add_argument("scene", nargs=argparse.REMAINDER, help="options replacing the default scene (after --)")
    a = ap.parse_args()
    scene = a.scene[1:] if a.scene[:1] == ["--"] else a.scene
    scene = scene or SCENE
    if a.seeds < 3:
        print("d6_rank_statistics: error: --seeds %d: an ensemble needs at least 3 seeds for a spread" % a.seeds, file=sys.stderr)
        return 2
    ranks = [int(r) for r in a.ranks.split(",")]
    bad = [r for r in ranks if r not in GRID_RANKS]
    if bad:
        print("d6_rank_statistics: error: --ranks: no decomposition for %s ranks (known: %s)" % (bad, sorted(GRID_RANKS)), file=sys.stderr)
        return 2
    seeds = [a.reference_seed] + [a.reference_seed + 1000 * (k + 1) for k in range(a.seeds - 1)]
    print("# scene: %s" % " ".join(scene))
    if a.parallel_extra:
        print("# added to the N-rank runs only: %s" % a.parallel_extra)
    with tempfile.TemporaryDirectory(prefix="vofdem-d6-") as work:
        with ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
            ens = list(pool.map(lambda s: run(a.exe, 1, scene + ["-seed", str(s)], work, "seed%d" % s), seeds))
        par = {n: run(a.exe, n, scene + a.parallel_extra.split() + ["-seed", str(a.reference_seed), "-grid_ranks", GRID_RANKS[n]], work, "ranks%d" % n) for n in ranks}

    failures = 0

    def result(quantity, value, reference, ok):
        nonlocal failures
        failures += not ok
        print("result: %s | %s | %s | %s" % (quantity, value, reference, "ok" if ok else "FAIL"))

    ref = ens[0]
    print("1-rank ensemble: %d seeds %s; reference seed %d" % (len(seeds), ",".join(map(str, seeds)), a.reference_seed))
    for n, r in par.items():
        result("particles on %d ranks" % n, "%d" % r["particles"], "1 rank: %d, exact" % ref["particles"],
               r["particles"] == ref["particles"] and r["initial"] == ref["initial"])
    for n, r in par.items():
        d = rms_distance(ref["positions"], r["positions"])
        result("RMS position difference 1 vs %d ranks" % n, "%.3e m" % d, "> %.1e m (decorrelated)" % a.min_rms, d > a.min_rms)
    k = len(ens)
    # The kinetic energy of a nearly settled bed is positive with multiplicative, heavy-tailed
    # fluctuations (one late rattler moves it by an order of magnitude: 1.9e-10 to 2.1e-8 J across
    # seeds), so a normal 3-sigma band is compared on its logarithm.
    logged = {"kinetic energy"}
    for e in ens + list(par.values()):
        for name in logged & set(e["stats"]):
            e["stats"]["log10 " + name] = math.log10(max(e["stats"].pop(name), 1e-300))
    for name in ref["stats"]:
        values = [e["stats"][name] for e in ens]
        mean = sum(values) / k
        s = math.sqrt(sum((v - mean) ** 2 for v in values) / (k - 1))
        sigma = s * math.sqrt(1 + 1 / k)
        print("%s: ensemble mean %.6e, s %.3e (values %s)" % (name, mean, s, " ".join("%.6e" % v for v in values)))
        for n, r in par.items():
            v = r["stats"][name]
            ok = abs(v - mean) <= 3 * sigma if sigma > 0 else v == mean
            result("%s on %d ranks" % (name, n), "%.6e (%.2f sigma)" % (v, (v - mean) / sigma if sigma > 0 else 0.0),
                   "ensemble %.6e +- %.3e (3 sigma, K = %d)" % (mean, 3 * sigma, k), ok)
    print("D6 long horizon: %s" % ("FAILED (%d checks)" % failures if failures else "all checks passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except RuntimeError as e:
        print("d6_rank_statistics: error: %s" % e, file=sys.stderr)
        sys.exit(1)
