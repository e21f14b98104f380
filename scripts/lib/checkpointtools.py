"""Helpers for vofdem checkpoints (src/sim/Checkpoint.cpp, CheckpointFile.cpp), used by
test/checkpoint/test_checkpoint.py and scripts/kill-restart-test: file names, the comparison of two
checkpoints (every dataset and the Simulation's clock, bit for bit), the rank processes of a run."""
import os
import subprocess

import h5py
import numpy as np

CLOCK = ("simulation_step", "simulation_time", "simulation_dt")


def read(path):
    """Every dataset of the file by path, and the clock attributes as "@name"."""
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: out.__setitem__(name, obj[()]) if isinstance(obj, h5py.Dataset) else None)
        for a in CLOCK:
            out["@" + a] = np.array(f.attrs[a])
    return out


def bitwise_diff(a, b):
    """Names of the datasets (and clock attributes) of files a and b that differ in any bit or exist
    in one only; empty when the states are identical."""
    A, B = read(a), read(b)
    diff = sorted(set(A) ^ set(B))
    for k in sorted(set(A) & set(B)):
        if A[k].dtype != B[k].dtype or A[k].shape != B[k].shape or A[k].tobytes() != B[k].tobytes():
            diff.append(k)
    return diff


def path(folder, step):
    """The checkpoint of `step` in `folder`."""
    return os.path.join(folder, "checkpoint_%08d.h5" % step)


def newest_step(folder):
    """Step of the newest checkpoint in `folder`, or 0."""
    steps = [int(n[11:19]) for n in os.listdir(folder) if n.startswith("checkpoint_") and n.endswith(".h5")] if os.path.isdir(folder) else []
    return max(steps, default=0)


def rank_pids(launcher, name="vofdem"):
    """The processes called `name` among the descendants of process `launcher` (mpiexec)."""
    out = subprocess.run(["ps", "-eo", "pid,ppid,comm"], capture_output=True, text=True).stdout.split("\n")[1:]
    rows = [line.split() for line in out if line.strip()]
    kids, frontier = [], {launcher}
    while frontier:
        kids += [int(r[0]) for r in rows if int(r[1]) in frontier and r[2] == name]
        frontier = {int(r[0]) for r in rows if int(r[1]) in frontier}
    return sorted(kids)
