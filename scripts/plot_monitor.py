#!/usr/bin/python3
"""Plots a vofdem monitor table (monitor.csv): kinetic energy and floor load against time.
Usage: plot_monitor.py monitor.csv out.png"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

data = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
fig, (a, b) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
a.plot(data["time_s"], data["kinetic_energy_J"])
a.set_ylabel("kinetic energy [J]")
b.plot(data["time_s"], -data["floor_force_z_N"])
b.set_ylabel("load on the floor [N]")
b.set_xlabel("time [s]")
a.set_title(sys.argv[1])
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
