#!/usr/bin/python3
"""Reads build/scaling/<scene>/log_view.<n>.txt (PETSc -log_view) for each rank count and writes
scaling.md (time, speed-up and efficiency per stage, and the whole run) and scaling.png.
Usage: scaling_table.py OUTDIR CORES RANKS..."""
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out, cores, ranks = sys.argv[1], int(sys.argv[2]), [int(r) for r in sys.argv[3:]]
STAGE = re.compile(r"^\s*\d+:\s+(.+?):\s+([0-9.eE+-]+)\s+[0-9.]+%")
TOTAL = re.compile(r"^Time \(sec\):\s+([0-9.eE+-]+)")

times = {}  # stage -> {ranks: seconds}
for n in ranks:
    path = os.path.join(out, "log_view.%d.txt" % n)
    in_stages = False
    with open(path) as f:
        for line in f:
            m = TOTAL.match(line)
            if m:
                times.setdefault("total", {})[n] = float(m.group(1))
            if line.startswith("Summary of Stages"):
                in_stages = True
                continue
            if in_stages:
                m = STAGE.match(line)
                if m:
                    times.setdefault(m.group(1).strip(), {})[n] = float(m.group(2))
                elif line.startswith("---"):
                    in_stages = False
if "total" not in times:
    sys.exit("scaling_table: no -log_view summary found in %s" % out)

base = ranks[0]
rows = ["| stage | ranks | time [s] | speed-up | efficiency |", "| --- | --- | --- | --- | --- |"]
for stage, by_n in times.items():
    for n in ranks:
        if n not in by_n:
            continue
        t, t0 = by_n[n], by_n.get(base, float("nan"))
        speedup = t0 / t if t > 0 else float("nan")
        note = " (oversubscribed)" if n > cores else ""
        rows.append("| %s | %d%s | %.4g | %.2f | %.0f %% |" % (stage, n, note, t, speedup, 100 * speedup * base / n))
table = "\n".join(rows)
with open(os.path.join(out, "scaling.md"), "w") as f:
    f.write(table + "\n")
print(table)

fig, ax = plt.subplots(figsize=(6, 4))
for stage, by_n in times.items():
    ns = [n for n in ranks if n in by_n]
    ax.plot(ns, [by_n[base] / by_n[n] for n in ns], "o-", label=stage)
ax.plot(ranks, [n / base for n in ranks], "k--", label="ideal")
ax.set_xlabel("ranks")
ax.set_ylabel("speed-up over %d rank%s" % (base, "s" if base > 1 else ""))
ax.legend()
ax.set_title("strong scaling: %s" % os.path.basename(out))
fig.tight_layout()
fig.savefig(os.path.join(out, "scaling.png"), dpi=100)
print("strong-scaling: table %s, plot %s" % (os.path.join(out, "scaling.md"), os.path.join(out, "scaling.png")))
