#!/usr/bin/python3
"""-dem_insert_<name>_every T (ParticleSources::NeedsChange): a source inserts in batches, asking for a neighbour-list
rebuild at most once per T instead of once per particle; nothing is lost. A stream of 20000 spheres/s for 5 ms into a
box, on 2 ranks, with and without T = 1 ms. Checks: without batches the count is floor(rate t) at every monitor line;
with them it lies between floor(rate t_b) (t_b the last batch time) and floor(rate t), lags by more than one particle
somewhere (batches happen), ends at the same 100; and the rebuilds (-log_view's DEMRebuild count) fall by more than 5x.
Usage: test_insert_batches.py VOFDEM"""
import csv
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scripts", "lib"))
from testcheck import check, failures, run_vofdem  # noqa: E402

RATE, END, EVERY = 20000.0, 0.005, 1e-3
SCENE = ["-physics", "dem", "-grid_cells", "4,4,8", "-grid_upper", "0.01,0.01,0.02", "-dem_radius", "3e-4", "-dem_fill_count", "0",
         "-dem_inserts", "a", "-dem_insert_a_lower", "0.002,0.002,0.012", "-dem_insert_a_upper", "0.008,0.008,0.018",
         "-dem_insert_a_rate", str(RATE), "-dem_insert_a_end", str(END), "-final_time", "0.006", "-max_steps", "100000",
         "-monitor_every", "50", "-monitor_timing", "0"]


def run(tmp, name, extra):
    out = os.path.join(tmp, name)
    run_vofdem(sys.argv[1], 2, SCENE + ["-output_dir", out, "-log_view", ":" + out + ".log_view"] + extra)
    with open(os.path.join(out, "monitor.csv")) as f:
        rows = [(float(r["time_s"]), int(r["inserted"])) for r in csv.DictReader(f)]
    rebuilds = -1
    with open(out + ".log_view") as f:
        for line in f:
            if line.startswith("DEMRebuild"):
                rebuilds = int(line.split()[1])
    return rows, rebuilds


def main():
    tmp = tempfile.mkdtemp(prefix="vofdem-batches-")
    plain, rebuildsPlain = run(tmp, "plain", [])
    due = lambda t: int(math.floor(RATE * min(t, END) + 1e-9))
    bad = [(t, n) for t, n in plain if n != due(t)]
    check(not bad, "without batches: inserted = floor(rate t) at all %d monitor lines (first exception: %s)" % (len(plain), bad[:1]))
    batched, rebuildsBatched = run(tmp, "batched", ["-dem_insert_a_every", str(EVERY)])
    bad, lag = [], 0
    for t, n in batched:
        tb = EVERY * math.floor(t / EVERY + 1e-9)
        if not due(tb) <= n <= due(t):
            bad.append((t, n, due(tb), due(t)))
        lag = max(lag, due(t) - n)
    check(not bad, "with -dem_insert_a_every %g: floor(rate t_b) <= inserted <= floor(rate t) at all %d lines (first exception: %s)" % (EVERY, len(batched), bad[:1]))
    check(lag > 1, "batches happen: the count lags floor(rate t) by up to %d particles (one batch is %d)" % (lag, int(RATE * EVERY)))
    check(batched[-1][1] == plain[-1][1] == due(END), "both end with %d = %d particles inserted (floor(rate x end) = %d)" % (batched[-1][1], plain[-1][1], due(END)))
    check(0 < rebuildsBatched and 5 * rebuildsBatched < rebuildsPlain, "neighbour-list rebuilds: %d with batches, %d without" % (rebuildsBatched, rebuildsPlain))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
