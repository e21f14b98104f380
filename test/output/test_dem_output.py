#!/usr/bin/python3
"""DEM output test: runs vofdem with -dem_output_every / -dem_contacts_every on 1 and 2 ranks and checks
  - the structure of particles.xmf and contacts.xmf (scripts/check-xdmf), and that the checker
    rejects an index whose dimensions are wrong;
  - the contents against the monitor table of the same run: per-particle contact counts sum to
    2 x pair contacts + wall contacts, segments = pair contacts, ids 0..N-1 in order, type 0,
    |F| = |F_n + F_t|, F_n along the line of centres, F_t normal to it;
  - 1 and 2 ranks give the same files (ids and counts exactly, reals within 1e-10 relative);
  - ParaView reads both indices (scripts/check-paraview), when pvpython is installed;
  - -dem_save_particles may name a file inside the run's own new -output_dir (it was refused as
    unwritable: the folder was made after the check), and the CSV holds the last step's particles.
  test_dem_output.py VOFDEM_EXECUTABLE"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scripts", "lib"))
from testcheck import check, failures, run_vofdem  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = ("-physics dem -grid_cells 4,4,4 -grid_upper 0.01,0.01,0.01 -dem_radius 5e-4 -dem_fill_count 200 -dem_fill_jitter 0.5 "
         "-dem_fill_velocity_spread 0.3 -max_steps 200 -monitor_every 50 -monitor_timing 0 -dem_output_every 100 -dem_contacts_every 50").split()


def run(exe, n, out):
    cut = ["-grid_ranks", "2,1,1"] if n == 2 else []  # the particles lie at the bottom: cut across x
    run_vofdem(exe, n, SCENE + cut + ["-output_dir", out, "-dem_save_particles", os.path.join(out, "final.csv")])


def monitor(out):
    with open(os.path.join(out, "monitor.csv")) as f:
        return {int(r["step"]): r for r in csv.DictReader(f)}


def contents(out):
    mon = monitor(out)
    for name in sorted(os.listdir(out)):
        step = int(name.split("_")[1].split(".")[0]) if name.endswith(".h5") else None
        if name.startswith("particles_"):
            with h5py.File(os.path.join(out, name), "r") as f:
                n = f["id"].shape[0]
                expect = 2 * int(mon[step]["pair_contacts"]) + int(mon[step]["wall_contacts"])
                check(int(f["contacts"][()].sum()) == expect, "%s: contacts sum to 2 x pairs + walls = %d" % (name, expect))
                check(np.array_equal(f["id"][()], np.arange(n)), "%s: ids 0..%d in order" % (name, n - 1))
                check(not f["type"][()].any(), "%s: type 0 for every particle" % name)
        if name.startswith("contacts_"):
            with h5py.File(os.path.join(out, name), "r") as f:
                m = f["ids"].shape[0]
                check(m == int(mon[step]["pair_contacts"]), "%s: %d segments = pair contacts of monitor.csv" % (name, m))
                x = f["position"][()].reshape(m, 2, 3)
                u = x[:, 0] - x[:, 1]
                u /= np.linalg.norm(u, axis=1)[:, None]
                fn, ft = f["normal_force"][()], f["tangential_force"][()]
                scale = np.abs(f["force_magnitude"][()]).max()
                check(np.allclose(f["force_magnitude"][()], np.linalg.norm(fn + ft, axis=1), rtol=1e-12), "%s: |F| = |F_n + F_t|" % name)
                check(np.abs(np.cross(fn, u)).max() <= 1e-9 * scale, "%s: F_n along the line of centres" % name)
                check(np.abs((ft * u).sum(axis=1)).max() <= 1e-9 * scale, "%s: F_t normal to it" % name)


def saved(out):
    """The CSV of -dem_save_particles against the particle file of the last step (200)."""
    with open(os.path.join(out, "final.csv")) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == 200, "final.csv: %d particles (200)" % len(rows))
    with h5py.File(os.path.join(out, "particles_000200.h5"), "r") as f:
        h5 = np.sort(f["position"][()].reshape(-1, 3)[:, 0])
    x = np.sort([float(r["x"]) for r in rows])
    check(len(x) == len(h5) and np.allclose(x, h5, rtol=0, atol=1e-15), "final.csv: x of the particles as in particles_000200.h5")


def compare(a, b):
    for name in sorted(os.listdir(a)):
        if not name.endswith(".h5"):
            continue
        with h5py.File(os.path.join(a, name), "r") as fa, h5py.File(os.path.join(b, name), "r") as fb:
            order = lambda f: np.lexsort(f["ids"][()].T[::-1]) if "ids" in f else slice(None)  # contacts come in rank order
            oa, ob = order(fa), order(fb)
            worst = 0.0
            for key in fa:
                va, vb = fa[key][()], fb[key][()]
                if key == "position" and "ids" in fa:
                    va, vb = va.reshape(-1, 6)[oa], vb.reshape(-1, 6)[ob]
                elif key == "connectivity":
                    continue
                else:
                    va, vb = va[oa], vb[ob]
                if va.shape != vb.shape:
                    worst = np.inf
                    break
                scale = max(np.abs(va).max(), 1e-300)
                worst = max(worst, np.abs(va - vb).max() / scale)
            check(worst <= 1e-10, "%s: 1 and 2 ranks agree, max relative difference %.1e (tolerance 1e-10)" % (name, worst))


def main():
    exe = sys.argv[1]
    work = tempfile.mkdtemp(prefix="vofdem-output-")
    try:
        outs = {n: os.path.join(work, "r%d" % n) for n in (1, 2)}
        for n, out in outs.items():
            run(exe, n, out)
        for out in outs.values():
            for index in ("particles.xmf", "contacts.xmf"):
                p = subprocess.run([os.path.join(ROOT, "scripts", "check-xdmf"), os.path.join(out, index)], capture_output=True, text=True)
                print(p.stdout, end="")
                check(p.returncode == 0, "check-xdmf %s" % index)
            contents(out)
            saved(out)
        compare(outs[1], outs[2])
        # The checker must be able to fail: a wrong dimension in a copy of the index.
        bad = os.path.join(outs[1], "bad.xmf")
        with open(os.path.join(outs[1], "particles.xmf")) as f:
            text = f.read()
        with open(bad, "w") as f:
            f.write(text.replace('Dimensions="200 3"', 'Dimensions="201 3"', 1))
        p = subprocess.run([os.path.join(ROOT, "scripts", "check-xdmf"), bad], capture_output=True, text=True)
        check(p.returncode == 1, "check-xdmf rejects a wrong dimension")
        os.remove(bad)
        pv = os.path.join(ROOT, "scripts", "check-paraview")
        p = subprocess.run([pv, os.path.join(outs[2], "particles.xmf"), os.path.join(outs[2], "contacts.xmf")], capture_output=True, text=True, timeout=600)
        print(p.stdout, end="")
        if p.returncode == 77:
            print("skip: ParaView check (pvpython not installed)")
        else:
            check(p.returncode == 0, "ParaView reads particles.xmf and contacts.xmf")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if failures:
        print("FAILED: %d checks" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
