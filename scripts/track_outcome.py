#!/usr/bin/python3
"""What a powder-fed deposition track gave (config/scenes/nozzle-track-reduced.yaml; docs/verification.md, reduced
track): reads a run's output folder (monitor.csv, melted_particles.csv, the flow's last frame, and the particles left
at the end, -dem_save_particles) and prints, on lines starting "track:":
  - the powder: inserted (number, mass), melted in flight (the sphere touched no metal when it melted:
    metal_around < 1e-3) and on the pool (it did), left as particles at the end (bounced, or still on their way);
  - the metal: what the melted particles brought against the interface's volume change (the VOF's own account);
  - the track: the metal above the plate's top in the last frame, per column h(x, y) = sum of alpha dz above it; its
    height (the largest h, and the median over y of each row's largest h along the part of the path behind the
    pool) and its width (per row the extent in x where h > 10 % of that row's largest, median over the same rows);
  - the cost: wall time, steps, wall time per simulated ms.
  - with --png, a picture: the metal above the plate seen from above (h(x, y)) and from the side (alpha's largest
    value across x, y-z) with the particles left, coloured by temperature.
  track_outcome.py OUT [--plate 0.8e-3] [--density 8380] [--path-y 0.6e-3,2.6e-3] [--json FILE] [--png FILE]"""
import argparse
import csv
import json
import os
import re
import sys

import h5py
import numpy as np


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--plate", type=float, default=0.8e-3, help="height of the plate's top (m)")
    ap.add_argument("--density", type=float, default=8380.0, help="the metal's density (kg/m^3)")
    ap.add_argument("--path-y", default="0.6e-3,2.6e-3", help="the beam's path along y: start,end (m)")
    ap.add_argument("--json")
    ap.add_argument("--png")
    a = ap.parse_args()
    mon = read_csv(os.path.join(a.out, "monitor.csv"))
    if not mon:
        sys.exit("track_outcome: no monitor.csv in %s" % a.out)
    last = mon[-1]
    melted = {}
    for m in read_csv(os.path.join(a.out, "melted_particles.csv")):
        melted[int(m["id"])] = m  # a restart may repeat a row: the last counts
    left = read_csv(os.path.join(a.out, "end.csv"))
    inflight = [m for m in melted.values() if m["metal_around"] < 1e-3]
    onpool = [m for m in melted.values() if m["metal_around"] >= 1e-3]
    mass = lambda rows: sum(r["mass_kg"] for r in rows)
    inserted = int(last["inserted"])
    particle_mass = (inserted and (mass(melted.values()) / len(melted))) if melted else 0.0
    res = {"inserted": inserted, "inserted_kg": inserted * particle_mass, "melted_in_flight": len(inflight), "melted_on_pool": len(onpool),
           "left": len(left), "melted_kg": mass(melted.values()), "time_s": last["time_s"], "steps": int(last["step"])}
    print("track: powder inserted %d (%.4e kg), melted in flight %d, melted on the pool %d, left as particles %d (bounced or still on their way)"
          % (inserted, res["inserted_kg"], len(inflight), len(onpool), len(left)))
    v0, v1 = mon[0]["vof_volume_m3"], last["vof_volume_m3"]
    brought = res["melted_kg"] / a.density
    res["metal_brought_m3"], res["vof_change_m3"] = brought, v1 - v0
    res["metal_book_error"] = abs((v1 - v0) - brought) / brought if brought > 0 else 0.0
    print("track: metal brought by the melted particles %.6e m^3, the interface's volume change %.6e m^3 (differ by %.2e of it); "
          "each conversion's books to %.1e (volume), %.1e (energy), %.1e (momentum)"
          % (brought, v1 - v0, res["metal_book_error"], max(r["melt_volume_error"] for r in mon), max(r["melt_energy_error"] for r in mon),
             max(r["melt_momentum_error"] for r in mon)))
    xmf = open(os.path.join(a.out, "flow.xmf")).read()
    files = re.findall(r'(flow_\d+\.h5):', xmf)
    with h5py.File(os.path.join(a.out, files[-1])) as f:
        alpha = np.array(f["vof_alpha"])  # z, y, x
    nz, ny, nx = alpha.shape
    times = [float(t) for t in re.findall(r'<Time Value="([^"]+)"', xmf)]
    # the grid from the scene's box: the monitor does not carry it; the flow frame's geometry is on the .xmf
    m = re.search(r'<DataItem[^>]*Dimensions="3"[^>]*>\s*([^<]+)</DataItem>\s*<DataItem[^>]*Dimensions="3"[^>]*>\s*([^<]+)</DataItem>', xmf)
    origin = [float(v) for v in m.group(1).split()][::-1] if m else [0, 0, 0]  # x, y, z
    spacing = [float(v) for v in m.group(2).split()][::-1] if m else [0, 0, 0]
    hx, hy, hz = spacing
    z = origin[2] + (np.arange(nz) + 0.5) * hz
    above = alpha[z > a.plate]
    h = above.sum(axis=0) * hz  # y, x
    y = origin[1] + (np.arange(ny) + 0.5) * hy
    y0, y1 = [float(v) for v in a.path_y.split(",")]
    rows = [j for j in range(ny) if y0 <= y[j] <= y1 and h[j].max() > 0]
    heights = [h[j].max() for j in rows]
    widths = [(np.count_nonzero(h[j] > 0.1 * h[j].max())) * hx for j in rows]
    res["height_max_m"] = float(h.max())
    res["height_median_m"] = float(np.median(heights)) if heights else 0.0
    res["width_median_m"] = float(np.median(widths)) if widths else 0.0
    print("track: at t = %.4g s (frame %s) the metal above the plate: height at most %.1f um, median over %d rows along the path %.1f um; width (h > 10 %% of the row's) median %.1f um"
          % (times[-1] if times else 0, files[-1], 1e6 * res["height_max_m"], len(rows), 1e6 * res["height_median_m"], 1e6 * res["width_median_m"]))
    print("track: pool at the end %.1f x %.1f x %.1f um (length x width x depth, the liquidus), peak %.0f K"
          % (1e6 * last["pool_length_m"], 1e6 * last["pool_width_m"], 1e6 * last["pool_depth_m"], last["temperature_max_K"]))
    wall = last.get("wall_time_s", 0.0)
    res["wall_s"], res["wall_per_ms_s"] = wall, wall / (1e3 * last["time_s"]) if last["time_s"] > 0 else 0.0
    print("track: %d steps to t = %.4g s in %.1f s of wall time: %.2f s per simulated ms" % (res["steps"], last["time_s"], wall, res["wall_per_ms_s"]))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(res, f, indent=1)
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw={"width_ratios": [1, 1.6]})
        ext = [origin[0], origin[0] + nx * hx, origin[1], origin[1] + ny * hy]
        im = ax[0].imshow(1e6 * h, origin="lower", extent=[1e3 * v for v in ext], cmap="viridis")
        fig.colorbar(im, ax=ax[0], label="metal above the plate (um)")
        ax[0].set_xlabel("x (mm)"), ax[0].set_ylabel("y (mm)"), ax[0].set_title("from above, t = %.2f ms" % (1e3 * (times[-1] if times else 0)))
        side = alpha.max(axis=2)  # z, y
        ax[1].imshow(side, origin="lower", extent=[1e3 * ext[2], 1e3 * ext[3], 1e3 * origin[2], 1e3 * (origin[2] + nz * hz)], cmap="Greys", vmin=0, vmax=1, aspect="auto")
        if left:
            sc = ax[1].scatter([1e3 * p["y"] for p in left], [1e3 * p["z"] for p in left], s=12, c="C1", edgecolors="k", linewidths=0.3, label="particles left")
            ax[1].legend(loc="upper right", fontsize=8)
        ax[1].axhline(1e3 * a.plate, color="C0", lw=0.8, ls="--")
        ax[1].set_xlabel("y (mm), the beam moves to +y"), ax[1].set_ylabel("z (mm)"), ax[1].set_title("side (alpha's largest across x); plate top dashed")
        fig.tight_layout()
        fig.savefig(a.png, dpi=120)
        print("track: picture %s" % a.png)


if __name__ == "__main__":
    main()
