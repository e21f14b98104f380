#!/usr/bin/python3
"""-coupling_kernel truncated -coupling_kernel_truncation rc (docs/physics.md K1, K3): the seed's Gaussian cut at rc H
is normalised over its support, so whatever the cut the particles' volume and their drag reach the grid exactly
(C3: the monitor's coupling_volume_error and coupling_exchange_error at round-off, below 1e-12), while the cut
changes the fluid fraction the bed makes (coupling_min_eps differs between rc = 1.2 and rc = 3). The bubbling bed
(config/scenes/bubbling-bed.yaml, 1000 particles, 12x3x33 cells) for 5 steps on 2 ranks.
Usage: test_kernel_truncation.py VOFDEM"""
import csv
import os
import re
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, failures, run_vofdem  # noqa: E402


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-truncation-")
    min_eps = {}
    for rc in ("1.2", "3"):
        out = os.path.join(tmp, rc)
        p = run_vofdem(exe, 2, ["-options_file_yaml", os.path.join(ROOT, "config", "scenes", "bubbling-bed.yaml"), "-grid_cells", "12,3,33", "-dem_fill_count", "1000",
                                "-max_steps", "5", "-monitor_every", "1", "-monitor_timing", "0", "-output_dir", out, "-coupling_kernel", "truncated",
                                "-coupling_kernel_truncation", rc])
        check(re.search(r"kernel truncated, .*cut at %s0* H" % re.escape(rc if "." in rc else rc + "."), p.stdout) is not None,
              "rc %s: the banner names the cut" % rc)
        with open(os.path.join(out, "monitor.csv")) as f:
            rows = list(csv.DictReader(f))[1:]  # after the set-up line, every step
        worst = max(max(float(r["coupling_volume_error"]), float(r["coupling_exchange_error"])) for r in rows)
        check(worst < 1e-12, "rc %s: projected volume and drag reach the grid exactly over %d steps (worst %.1e)" % (rc, len(rows), worst))
        min_eps[rc] = float(rows[-1]["coupling_min_eps"])
    check(min_eps["1.2"] != min_eps["3"], "the cut changes the bed's fluid fraction (min eps %.4f at rc 1.2, %.4f at rc 3)" % (min_eps["1.2"], min_eps["3"]))
    print("FAIL: %d check(s) failed" % len(failures) if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
