#!/usr/bin/python3
"""Side-by-side plot of the particle-laden dam break (V7): one row per mode, one column per observation
time; the y-averaged water fraction (contour 0.5 and shading) and the beads (x, z) from the files that
examples/ex42_particle_dam_break writes with -profiles PREFIX (PREFIX_<t>_alpha.csv, PREFIX_<t>_beads.csv).

usage: plot_particle_dam_break.py OUT.png LABEL=PREFIX [LABEL=PREFIX ...]
"""
import glob
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

TANK = (0.2, 0.3)  # x, z extent (m)


def snapshots(prefix):
    """(time, alpha file, beads file) for every snapshot of a run, in time order."""
    out = []
    for fa in glob.glob(prefix + "_*_alpha.csv"):
        t = float(fa[len(prefix) + 1:-len("_alpha.csv")])
        out.append((t, fa, fa.replace("_alpha.csv", "_beads.csv")))
    if not out:
        sys.exit(f"plot_particle_dam_break: no snapshots {prefix}_<t>_alpha.csv (run ex42 with -profiles {prefix})")
    return sorted(out)


def main():
    if len(sys.argv) < 3 or any("=" not in a for a in sys.argv[2:]):
        sys.exit(__doc__)
    png, runs = sys.argv[1], [a.split("=", 1) for a in sys.argv[2:]]
    shots = [snapshots(p) for _, p in runs]
    ncol = max(len(s) for s in shots)
    fig, axes = plt.subplots(len(runs), ncol, figsize=(2.6 * ncol, 4.4 * len(runs)), squeeze=False)
    for r, ((label, _), run) in enumerate(zip(runs, shots)):
        for c in range(ncol):
            ax = axes[r][c]
            if c >= len(run):
                ax.axis("off")
                continue
            t, fa, fb = run[c]
            a = np.loadtxt(fa, delimiter=",", ndmin=2)
            nz, nx = a.shape
            x = (np.arange(nx) + 0.5) * TANK[0] / nx
            z = (np.arange(nz) + 0.5) * TANK[1] / nz
            ax.imshow(a, origin="lower", extent=(0, TANK[0], 0, TANK[1]), cmap="Blues", vmin=0, vmax=1.5, aspect="equal")
            ax.contour(x, z, a, levels=[0.5], colors="navy", linewidths=1)
            b = np.loadtxt(fb, delimiter=",", skiprows=1, ndmin=2)
            if b.size:
                ax.scatter(b[:, 0], b[:, 1], s=0.4, c="darkorange", linewidths=0)
            ax.set_xlim(0, TANK[0])
            ax.set_ylim(0, TANK[1])
            ax.set_title(f"{label}, t = {t:.3f} s", fontsize=9)
            ax.set_xlabel("x (m)")
            if c == 0:
                ax.set_ylabel("z (m)")
    fig.suptitle("Particle-laden dam break (V7): water (alpha averaged over y, contour 0.5) and glass beads")
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    print(f"plot_particle_dam_break: wrote {png}")


if __name__ == "__main__":
    main()
