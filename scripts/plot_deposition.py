#!/usr/bin/python3
"""A picture of a deposition run (the four-particle scenes, docs/verification.md E3) from its saved fields:
four moments side by side, seen from the side (x-z): the metal of the VOF field (alpha's largest value along y,
grey) and the particles (circles coloured by their temperature), and the floor seen from above (x-y) at the end.
  plot_deposition.py OUT PICTURE.png [--times t1,t2,t3,t4]   (default: start, first melt, halfway, end)"""
import argparse
import csv
import os
import re

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402


def frames(out, kind):
    text = open(os.path.join(out, kind + ".xmf")).read()
    times = [float(t) for t in re.findall(r'<Time Value="([^"]+)"', text)]
    seen, files = set(), []
    for f in re.findall(r'(%s_\d+\.h5):' % kind, text):
        if f not in seen:
            seen.add(f)
            files.append(os.path.join(out, f))
    return list(zip(times, files))


def nearest(series, t):
    return min(series, key=lambda s: abs(s[0] - t))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("png")
    ap.add_argument("--times")
    o = ap.parse_args()
    flow, parts = frames(o.out, "flow"), frames(o.out, "particles")
    grid = open(os.path.join(o.out, "flow.xmf")).read()
    geo = re.search(r'ORIGIN_DXDYDZ">\s*<DataItem[^>]*>([^<]+)</DataItem>\s*<DataItem[^>]*>([^<]+)</DataItem>', grid)
    origin = [float(v) for v in geo.group(1).split()][::-1]  # z y x -> x y z
    spacing = [float(v) for v in geo.group(2).split()][::-1]
    with h5py.File(flow[0][1], "r") as h:
        nz, ny, nx = h["vof_alpha"].shape
    ext_xz = [origin[0], origin[0] + nx * spacing[0], origin[2], origin[2] + nz * spacing[2]]
    ext_xy = [origin[0], origin[0] + nx * spacing[0], origin[1], origin[1] + ny * spacing[1]]
    if o.times:
        times = [float(t) for t in o.times.split(",")]
    else:
        melt = None
        log = os.path.join(o.out, "melted_particles.csv")
        if os.path.exists(log):
            rows = list(csv.DictReader(open(log)))
            melt = min(float(r["time_s"]) for r in rows) if rows else None
        end = flow[-1][0]
        times = [0.0, melt if melt else 0.5 * end, 0.5 * ((melt or 0.5 * end) + end), end]
    gap = max(np.diff([p[0] for p in parts]).max() if len(parts) > 1 else 0, np.diff([f[0] for f in flow]).max() if len(flow) > 1 else 0)
    fig, axes = plt.subplots(1, len(times) + 1, figsize=(3.2 * (len(times) + 1), 3.4))
    for ax, t in zip(axes, times):
        tf, ff = nearest(flow, t)
        with h5py.File(ff, "r") as h:
            a = h["vof_alpha"][...]
        ax.imshow(a.max(axis=1), origin="lower", extent=ext_xz, cmap="Greys", vmin=0, vmax=1)
        tp, fp = nearest(parts, tf)
        with h5py.File(fp, "r") as h:
            x, r, T = h["position"][...], h["radius"][...], h["temperature"][...]
        if abs(tp - tf) > 2 * gap:  # no particle frame then: the swarm was empty (every particle melted)
            x, r, T = np.zeros((0, 3)), np.zeros(0), np.zeros(0)
        cmap = plt.get_cmap("inferno")
        for k in range(len(r)):
            ax.add_patch(Circle((x[k, 0], x[k, 2]), r[k], color=cmap(np.clip((T[k] - 500) / 1200, 0, 1)), ec="k", lw=0.5))
        ax.set_title("t = %.2f ms: %d particle%s" % (tf * 1e3, len(r), "" if len(r) == 1 else "s"), fontsize=9)
        ax.set_xlabel("x (m)", fontsize=8)
        ax.tick_params(labelsize=6)
        ax.set_aspect("equal")
    axes[0].set_ylabel("z (m)", fontsize=8)
    with h5py.File(flow[-1][1], "r") as h:
        a = h["vof_alpha"][...]
    top = axes[-1]
    top.imshow(a.sum(axis=0) * spacing[2], origin="lower", extent=ext_xy, cmap="Greys")
    top.set_title("floor from above, t = %.2f ms:\nmetal thickness" % (flow[-1][0] * 1e3), fontsize=9)
    top.set_xlabel("x (m)", fontsize=8)
    top.set_ylabel("y (m)", fontsize=8)
    top.tick_params(labelsize=6)
    sm = plt.cm.ScalarMappable(cmap="inferno", norm=plt.Normalize(500, 1700))
    fig.colorbar(sm, ax=list(axes), shrink=0.6, pad=0.02, label="particle temperature (K)")
    fig.suptitle("%s: metal (grey, VOF) and particles (DEM)" % os.path.basename(os.path.normpath(o.out)), fontsize=10)
    fig.savefig(o.png, dpi=110)
    print("plot_deposition: wrote %s" % o.png)


if __name__ == "__main__":
    main()
