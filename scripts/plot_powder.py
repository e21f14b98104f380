#!/usr/bin/python3
"""Plots of a powder-bed analysis folder (the CSV files of -analysis_metrics or vofdem-analyze, src/analysis):
coordination.png, pores.png (Delaunay equivalent radius and sphericity), surface.png (ray-cast height map
and centre line), segregation.png, rings.png, repose.png; each only when its CSV is there.
  plot_powder.py DIR [DIR ...]     (Debian's /usr/bin/python3: numpy and matplotlib)"""
import csv
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def table(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def col(rows, key):
    return np.array([float(r[key]) for r in rows])


def summary(d):
    p = os.path.join(d, "summary.csv")
    return {r["metric"]: float(r["value"]) for r in table(p)} if os.path.exists(p) else {}


def save(fig, d, name, made):
    fig.tight_layout()
    fig.savefig(os.path.join(d, name), dpi=120)
    plt.close(fig)
    made.append(name)


def plot(d):
    s, made = summary(d), []
    p = os.path.join(d, "coordination.csv")
    if os.path.exists(p):
        r = table(p)
        fig, ax = plt.subplots(figsize=(5, 3.5))
        ax.bar(col(r, "coordination"), col(r, "fraction"), color="tab:blue")
        ax.set_xlabel("coordination number")
        ax.set_ylabel("fraction of particles")
        ax.set_title("mean %.3f" % s.get("mean_coordination", float("nan")))
        save(fig, d, "coordination.png", made)
    pr, ps = os.path.join(d, "pore_radius.csv"), os.path.join(d, "pore_sphericity.csv")
    if os.path.exists(pr) and os.path.exists(ps):
        fig, axes = plt.subplots(1, 2, figsize=(9, 3.5))
        for ax, path, label, scale in ((axes[0], pr, "equivalent radius (um)", 1e6), (axes[1], ps, "sphericity", 1.0)):
            r = table(path)
            key = [k for k in r[0] if k.startswith("bin_lo")][0]
            lo, hi = col(r, key) * scale, col(r, key.replace("lo", "hi")) * scale
            ax.plot(0.5 * (lo + hi), col(r, "fraction"), "o-", ms=3)
            ax.set_xlabel(label)
            ax.set_ylabel("fraction of tetrahedra")
        axes[1].axvline(0.671, color="gray", ls="--", lw=1)
        axes[0].set_title("Delaunay tetrahedra: %d" % s.get("tetrahedra", 0))
        save(fig, d, "pores.png", made)
    p = os.path.join(d, "surface_line.csv")
    if os.path.exists(p):
        grid = os.path.join(d, "surface_grid.csv")
        fig, axes = plt.subplots(2 if os.path.exists(grid) else 1, 1, figsize=(8, 6 if os.path.exists(grid) else 3), squeeze=False)
        r = table(p)
        ax = axes[-1][0]
        ax.plot(col(r, "x_m") * 1e3, col(r, "z_m") * 1e6, lw=1)
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("height (um)")
        ax.set_title("centre line: Ra %.3g um" % (s.get("Ra_line", float("nan")) * 1e6))
        if os.path.exists(grid):
            z = np.loadtxt(grid, delimiter=",", ndmin=2) * 1e6
            x0, y0, h = s.get("surface_x0", 0), s.get("surface_y0", 0), s.get("surface_ray_spacing", 1)
            ext = [x0 * 1e3, (x0 + h * z.shape[1]) * 1e3, y0 * 1e3, (y0 + h * z.shape[0]) * 1e3]
            im = axes[0][0].imshow(z, origin="lower", extent=ext, aspect="auto", cmap="viridis")
            fig.colorbar(im, ax=axes[0][0], label="height (um)")
            axes[0][0].set_xlabel("x (mm)")
            axes[0][0].set_ylabel("y (mm)")
            axes[0][0].set_title("ray-cast surface: Sa %.3g um (std. dev.)" % (s.get("Sa_std", float("nan")) * 1e6))
        save(fig, d, "surface.png", made)
    p = os.path.join(d, "segregation.csv")
    if os.path.exists(p):
        r = [x for x in table(p) if int(x["particles"]) > 0]
        fig, ax = plt.subplots(figsize=(6, 3.5))
        xc = 0.5 * (col(r, "x_lo_m") + col(r, "x_hi_m")) * 1e3
        ax.plot(xc, col(r, "segregation_index"), "o-")
        ax.axhline(1, color="gray", ls="--", lw=1)
        ax.set_xlabel("cell centre x (mm)")
        ax.set_ylabel("segregation index")
        save(fig, d, "segregation.png", made)
    p = os.path.join(d, "rings.csv")
    if os.path.exists(p):
        r = table(p)
        fig, ax = plt.subplots(figsize=(6, 3.5))
        ax.plot(col(r, "x_m") * 1e3, col(r, "packing_density"), "o-", label="packing density")
        ax2 = ax.twinx()
        ax2.plot(col(r, "x_m") * 1e3, col(r, "mean_coordination"), "s--", color="tab:red", label="coordination")
        ax.set_xlabel("ring centre x (mm)")
        ax.set_ylabel("packing density")
        ax2.set_ylabel("mean coordination", color="tab:red")
        save(fig, d, "rings.png", made)
    p = os.path.join(d, "repose.csv")
    if os.path.exists(p) and "repose_angle" in s:
        r = table(p)
        fig, ax = plt.subplots(figsize=(6, 3.5))
        dist = col(r, "distance_m")
        ax.plot(dist * 1e3, col(r, "z_m") * 1e3, ".", ms=1, alpha=0.4)
        xs = np.array([0, dist.max()])
        slope = -np.tan(np.radians(s["repose_angle"]))
        label = "fitted %.2f deg" % s["repose_angle"]
        if "repose_angle_height" in s:  # seed 001's measure, atan(2 H/D)
            label += "; atan(2H/D) %.2f deg" % s["repose_angle_height"]
        ax.plot(xs * 1e3, (s["repose_intercept"] + slope * xs) * 1e3, "r-", label=label)
        ax.set_xlabel("distance from the pile axis (mm)")
        ax.set_ylabel("height (mm)")
        ax.legend()
        save(fig, d, "repose.png", made)
    return made


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for d in sys.argv[1:]:
        if not os.path.isdir(d):
            sys.exit("plot_powder.py: %s is not a folder" % d)
        made = plot(d)
        print("plot_powder.py: %s: %s" % (d, ", ".join(made) if made else "no analysis CSV files"))
