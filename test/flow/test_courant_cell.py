#!/usr/bin/python3
"""-flow_courant cell (src/flow/FlowCourant.cpp; docs/modules/flow.md): the 3-D lid-driven cavity at Re 100, 16^3 cells,
from rest to t = 3, at CFL 0.5 with the box's measure (the box's largest |u_d| summed over d) and with the cell's (per
cell the faster of its two faces per direction, summed; the largest cell):
  - the cell's measure is never larger than the box's, so its steps are never shorter and it takes fewer of them
    (here the lid's speed binds it, 0.5 h/U; the box's sum adds the v and w maxima);
  - its answer is as good: the kinetic energy at t = 3 is within 1e-4 of a run with ten times shorter steps (box CFL
    0.05), and its error is at most 1.5 times the box measure's at CFL 0.5;
  - 1 and 2 ranks (split in x: the cells at the seam need the neighbour's faces) take the same steps and agree to 1e-12.
  test_courant_cell.py VOFDEM"""
import csv
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

SCENE = os.path.join(ROOT, "config", "scenes", "cavity3d-re100.yaml")


def run(exe, tmp, measure, cfl, ranks):
    out = os.path.join(tmp, "%s-%g-%d" % (measure, cfl, ranks))
    run_vofdem(exe, ranks, ["-options_file_yaml", SCENE, "-grid_cells", "16,16,16", "-final_time", "3", "-flow_courant", measure,
                            "-flow_cfl", "%g" % cfl, "-monitor_every", "1", "-output_dir", out])
    with open(os.path.join(out, "monitor.csv")) as f:
        rows = list(csv.DictReader(f))
    return rows


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-courant-")
    try:
        fine = run(exe, tmp, "box", 0.05, 1)[-1]
        ke_fine = float(fine["flow_kinetic_energy_J"])
        box, cell = run(exe, tmp, "box", 0.5, 1), run(exe, tmp, "cell", 0.5, 1)
        nb, nc = int(box[-1]["step"]), int(cell[-1]["step"])
        check(nc < nb, "steps to t = 3: cell %d, box %d (fewer with the cell's measure)" % (nc, nb))
        first = min(len(box), len(cell)) - 1  # rows before either run's last (shortened) step
        shorter = [i for i in range(1, first) if float(cell[i]["dt_s"]) < float(box[i]["dt_s"]) * (1 - 1e-12)]
        check(not shorter, "the cell's step is never shorter than the box's at the same step number (%d shorter)" % len(shorter))
        eb = float(box[-1]["flow_kinetic_energy_J"]) / ke_fine - 1
        ec = float(cell[-1]["flow_kinetic_energy_J"]) / ke_fine - 1
        check(abs(ec) <= 1e-4, "cell: kinetic energy at t = 3 %.10e against CFL 0.05's %.10e: %.2e (tolerance 1e-4)" % (float(cell[-1]["flow_kinetic_energy_J"]), ke_fine, ec))
        check(abs(ec) <= 1.5 * abs(eb), "cell's error %.2e against the box's %.2e at CFL 0.5 (at most 1.5 times)" % (ec, eb))
        two = run(exe, tmp, "cell", 0.5, 2)
        check(int(two[-1]["step"]) == nc, "2 ranks: %s steps (1 rank: %d)" % (two[-1]["step"], nc))
        d = abs(float(two[-1]["flow_kinetic_energy_J"]) / float(cell[-1]["flow_kinetic_energy_J"]) - 1)
        check(d <= 1e-12, "2 ranks: kinetic energy agrees to %.1e (tolerance 1e-12)" % d)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
