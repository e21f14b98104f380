#!/usr/bin/python3
"""Plots the melt pool of an energy run from its monitor table (-output_dir DIR writes DIR/monitor.csv): the peak
temperature, the beam's and the absorbed power, and the pool's length, width and depth (the monitor's
-energy_pool_isotherm, the liquidus by default) against time.
Usage: plot_melt_pool.py MONITOR_CSV [OUT.png] [--half-y] [--reference WIDTH,DEPTH]
  OUT.png          default: melt_pool.png beside MONITOR_CSV
  --half-y         the box is the half y > 0 of a track along y = 0 (config/scenes/amb2018-02-*.yaml,
                   laser-track-conduction.yaml): the width and the powers are doubled to the whole track's
  --reference W,D  measured width and depth in um, drawn as dashed lines (E2 case B: 133,91; case C: 100,60)"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

NEEDED = ("time_s", "temperature_max_K", "laser_beam_W", "laser_absorbed_W", "pool_length_m", "pool_width_m", "pool_depth_m")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("monitor")
    ap.add_argument("out", nargs="?")
    ap.add_argument("--half-y", action="store_true")
    ap.add_argument("--reference", help="measured width,depth in um")
    a = ap.parse_args()
    out = a.out or os.path.join(os.path.dirname(os.path.abspath(a.monitor)), "melt_pool.png")
    data = np.genfromtxt(a.monitor, delimiter=",", names=True)
    missing = [c for c in NEEDED if c not in data.dtype.names]
    if missing:
        raise SystemExit("plot_melt_pool.py: %s has no column(s) %s (is it an -physics energy run's monitor.csv?)" % (a.monitor, ", ".join(missing)))
    data = np.atleast_1d(data)
    t = 1e3 * data["time_s"]  # ms
    m = 2.0 if a.half_y else 1.0
    whole = " (x2: half box)" if a.half_y else ""

    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, sharex=True, figsize=(7.5, 8.5))
    ax1.plot(t, data["temperature_max_K"], color="C3")
    ax1.set_ylabel("peak temperature [K]")
    ax2.plot(t, m * data["laser_beam_W"], label="beam" + whole, color="C0")
    ax2.plot(t, m * data["laser_absorbed_W"], label="absorbed" + whole, color="C1")
    if "energy_loss_W" in data.dtype.names:
        ax2.plot(t, m * data["energy_loss_W"], label="surface losses" + whole, color="C2")
    ax2.set_ylabel("power [W]")
    ax2.legend(loc="best", fontsize=8)
    ax3.plot(t, 1e6 * data["pool_length_m"], label="length", color="C0")
    ax3.plot(t, 1e6 * m * data["pool_width_m"], label="width" + whole, color="C1")
    ax3.plot(t, 1e6 * data["pool_depth_m"], label="depth", color="C2")
    if a.reference:
        w, d = (float(x) for x in a.reference.split(","))
        ax3.axhline(w, color="C1", ls="--", lw=1, label="measured width %g um" % w)
        ax3.axhline(d, color="C2", ls="--", lw=1, label="measured depth %g um" % d)
    ax3.set_ylabel("pool extent [um]")
    ax3.set_xlabel("time [ms]")
    ax3.legend(loc="best", fontsize=8)
    last = data[-1]
    ax1.set_title("%s\nat t = %.4g ms: peak %.0f K, pool %.1f x %.1f x %.1f um (length x width x depth)"
                  % (a.monitor, t[-1], last["temperature_max_K"], 1e6 * last["pool_length_m"], 1e6 * m * last["pool_width_m"], 1e6 * last["pool_depth_m"]),
                  fontsize=9)
    for ax in (ax1, ax2, ax3):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print("plot_melt_pool.py: wrote %s" % out)


if __name__ == "__main__":
    main()
