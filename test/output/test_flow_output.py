#!/usr/bin/python3
"""Flow output test: runs the quasi-2-D lid-driven cavity with a solid block (below the middle: on one rank of two) and -flow_output_every
on 1 and 2 ranks and checks
  - the structure of flow.xmf (scripts/check-xdmf): one uniform grid per output, every dataset shaped
    z, y, x as the index says;
  - the contents: cell velocity = mean of the cell's two faces, so cells inside the solid (all faces
    held at 0) are exactly 0; the lid drags the top row along +x (mean u > 0.2 of the lid speed)
    while w stays 0 (quasi-2-D), which fails if the axes are mixed up; density is the scene's;
  - the velocity at the centre of the box against the run's own -flow_profile_output (the profile
    samples the faces: the cell-centred value is the mean of the two faces around x = 0.5 on line y);
  - 1 and 2 ranks write the same fields (within 1e-12 of the lid speed);
  - ParaView reads flow.xmf (scripts/check-paraview), when pvpython is installed.
  test_flow_output.py VOFDEM_EXECUTABLE"""
import csv
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scripts", "lib"))
from testcheck import check, failures, run_vofdem  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = ["-options_file_yaml", os.path.join(ROOT, "config", "scenes", "cavity-re100.yaml"), "-grid_cells", "32,32,4",
         "-grid_upper", "1,1,0.125", "-max_steps", "20", "-monitor_every", "10", "-monitor_timing", "0", "-flow_output_every", "10",
         "-flow_solid_boxes", "0.35,0.15,-1,0.65,0.45,1", "-flow_pressure_ksp_rtol", "1e-12", "-flow_viscous_ksp_rtol", "1e-12"]


def run(exe, n, out):
    run_vofdem(exe, n, SCENE + ["-output_dir", out, "-flow_profile_output", os.path.join(out, "profile.csv")])


def fields(out, step):
    with h5py.File(os.path.join(out, "flow_%08d.h5" % step), "r") as f:
        return {k: f[k][()] for k in f}


def main():
    exe = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        outs = {}
        for n in (1, 2):
            outs[n] = os.path.join(tmp, "r%d" % n)
            run(exe, n, outs[n])
        if failures:
            return 1
        out = outs[2]
        names = sorted(x for x in os.listdir(out) if x.startswith("flow_"))
        check(names == ["flow_%08d.h5" % s for s in (0, 10, 20)], "files at steps 0, 10, 20: %s" % names)
        p = subprocess.run([os.path.join(ROOT, "scripts", "check-xdmf"), os.path.join(out, "flow.xmf")], capture_output=True, text=True)
        print(p.stdout.strip())
        check(p.returncode == 0, "check-xdmf accepts flow.xmf")
        f = fields(out, 20)
        vel, solid = f["velocity"], f["flow_solid"]
        check(vel.shape == (4, 32, 32, 3) and solid.shape == (4, 32, 32), "velocity is z, y, x, 3 and solid z, y, x: %s %s" % (vel.shape, solid.shape))
        inside = solid > 0.5
        # cells all of whose neighbours are solid too: every face blocked
        core = np.zeros_like(inside)
        core[:, 1:-1, 1:-1] = inside[:, 1:-1, 1:-1] & inside[:, :-2, 1:-1] & inside[:, 2:, 1:-1] & inside[:, 1:-1, :-2] & inside[:, 1:-1, 2:]
        check(core.sum() > 0 and np.abs(vel[core]).max() == 0.0, "velocity exactly 0 in the %d cells deep inside the block" % core.sum())
        top = vel[:, -1, :, 0].mean()
        check(top > 0.2, "the top row moves with the lid along +x: mean u %.3f" % top)
        check(np.abs(vel[..., 2]).max() < 1e-10, "w stays 0: max |w| %.1e" % np.abs(vel[..., 2]).max())
        check(np.allclose(f["flow_density"], 1.0), "density 1 everywhere")
        with open(os.path.join(out, "profile.csv")) as fp:
            rows = [r for r in csv.DictReader(fp) if r["line"] == "y"]
        # line y runs through x = 0.5 (a u-face plane between cells 15 and 16): rows at the cell centres
        prof = {round(float(r["y"]) * 32 - 0.5): float(r["u"]) for r in rows if abs(float(r["y"]) * 32 - 0.5 - round(float(r["y"]) * 32 - 0.5)) < 1e-9}
        j = 24
        check(j in prof and abs(prof[j] - vel[1, j, 15, 0]) < 0.05 and abs(prof[j] - vel[1, j, 16, 0]) < 0.05,
              "cell velocity next to the centre line matches the profile within 0.05 (row %d: profile %.4f, cells %.4f %.4f)"
              % (j, prof.get(j, float("nan")), vel[1, j, 15, 0], vel[1, j, 16, 0]))
        one = fields(outs[1], 20)
        diff = max(np.abs(one[k] - f[k]).max() for k in f)
        check(diff < 1e-12, "1 and 2 ranks write the same fields: max difference %.1e" % diff)
        p = subprocess.run([os.path.join(ROOT, "scripts", "check-paraview"), os.path.join(out, "flow.xmf")], capture_output=True, text=True)
        print(p.stdout.strip())
        check(p.returncode in (0, 77), "ParaView reads flow.xmf (or pvpython is not installed)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
