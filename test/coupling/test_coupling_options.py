#!/usr/bin/python3
"""Four coupling options that change what a coupled run computes, each shown to take effect against a run that
must agree with it bit for bit and one that must not (the bubbling bed, config/scenes/bubbling-bed.yaml, 1000
particles on 12x3x33 cells, 6 fluid steps on 2 ranks; the monitor's coupling columns compared row by row):
  - -coupling_drag_switch (docs/physics.md F6): Gidaspow's law is Wen-Yu at eps >= the switch and Ergun below, so a
    switch of 0.01 gives -coupling_drag wenyu's run and a switch of 1 gives -coupling_drag ergun's, and the two differ;
  - -coupling_min_fluid_fraction: the floor of eps; at 0.99 (above the loose bed's eps) the monitor's min eps is the
    floor and cells are counted as clipped, at the default none is;
  - -coupling_self_correction_min_eps (K1b): at 1 no particle qualifies (its eps is below 1), the run is that with
    -coupling_self_correction 0; at the default 0.9 the correction acts and the drag differs;
  - -coupling_smoothing_crossover: -coupling_smoothing auto picks the Gaussian filter when the kernel's work exceeds the
    crossover times the filter's, so at 1e-6 auto is -coupling_smoothing gaussian's run, at 1e6 -coupling_smoothing
    kernel's, and those two differ.
Usage: test_coupling_options.py VOFDEM"""
import csv
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

COLUMNS = ["coupling_min_eps", "coupling_eps_clipped_cells", "coupling_drag_x_N", "coupling_drag_y_N", "coupling_drag_z_N"]


def run(exe, tmp, name, extra):
    out = os.path.join(tmp, name)
    run_vofdem(exe, 2, ["-options_file_yaml", os.path.join(ROOT, "config", "scenes", "bubbling-bed.yaml"), "-grid_cells", "12,3,33", "-dem_fill_count", "1000",
                        "-max_steps", "6", "-monitor_every", "1", "-monitor_timing", "0", "-output_dir", out] + extra)
    path = os.path.join(out, "monitor.csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{c: r[c] for c in COLUMNS} for r in list(csv.DictReader(f))[1:]]  # every step after the set-up line


def same(a, b):
    return bool(a) and a == b


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-coupling-options-")
    r = lambda name, extra: run(exe, tmp, name, extra)  # noqa: E731

    wenyu, ergun = r("wenyu", ["-coupling_drag", "wenyu"]), r("ergun", ["-coupling_drag", "ergun"])
    low, high = r("switch-low", ["-coupling_drag", "gidaspow", "-coupling_drag_switch", "0.01"]), r("switch-high", ["-coupling_drag", "gidaspow", "-coupling_drag_switch", "1"])
    check(same(low, wenyu), "gidaspow with -coupling_drag_switch 0.01 is wenyu's run, row by row (last drag z %s N)" % (low[-1]["coupling_drag_z_N"] if low else "-"))
    check(same(high, ergun), "gidaspow with -coupling_drag_switch 1 is ergun's run, row by row (last drag z %s N)" % (high[-1]["coupling_drag_z_N"] if high else "-"))
    check(bool(wenyu) and bool(ergun) and wenyu[-1]["coupling_drag_z_N"] != ergun[-1]["coupling_drag_z_N"], "wenyu and ergun differ, so the switch decided")

    base = r("default", [])
    floor = r("floor", ["-coupling_min_fluid_fraction", "0.99"])
    check(bool(base) and all(int(x["coupling_eps_clipped_cells"]) == 0 for x in base) and float(base[-1]["coupling_min_eps"]) < 0.99,
          "default floor 0.1: no cell clipped, min eps %s" % (base[-1]["coupling_min_eps"] if base else "-"))
    check(bool(floor) and all(float(x["coupling_min_eps"]) == 0.99 and int(x["coupling_eps_clipped_cells"]) > 0 for x in floor),
          "-coupling_min_fluid_fraction 0.99: min eps at the floor, %s cells clipped at the last step" % (floor[-1]["coupling_eps_clipped_cells"] if floor else "-"))

    off = r("self-off", ["-coupling_self_correction", "0"])
    none = r("self-min-1", ["-coupling_self_correction_min_eps", "1"])
    check(same(none, off), "-coupling_self_correction_min_eps 1 (no particle at eps 1) is the run without the correction, row by row")
    check(bool(base) and bool(off) and base[-1]["coupling_drag_z_N"] != off[-1]["coupling_drag_z_N"],
          "at the default 0.9 the correction acts: drag z %s N against %s N without it" % (base[-1]["coupling_drag_z_N"] if base else "-", off[-1]["coupling_drag_z_N"] if off else "-"))

    gauss, kern = r("gaussian", ["-coupling_smoothing", "gaussian"]), r("kernel", ["-coupling_smoothing", "kernel"])
    a_lo = r("auto-lo", ["-coupling_smoothing", "auto", "-coupling_smoothing_crossover", "1e-6"])
    a_hi = r("auto-hi", ["-coupling_smoothing", "auto", "-coupling_smoothing_crossover", "1e6"])
    check(same(a_lo, gauss), "auto with -coupling_smoothing_crossover 1e-6 is the Gaussian filter's run, row by row")
    check(same(a_hi, kern), "auto with -coupling_smoothing_crossover 1e6 is the kernel sums' run, row by row")
    check(bool(gauss) and bool(kern) and gauss != kern, "the Gaussian filter and the kernel sums differ (last drag z %s / %s N), so the crossover decided"
          % (gauss[-1]["coupling_drag_z_N"] if gauss else "-", kern[-1]["coupling_drag_z_N"] if kern else "-"))
    finish()


if __name__ == "__main__":
    main()
