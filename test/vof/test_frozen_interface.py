#!/usr/bin/python3
"""-vof_advect 0 (Vof.cpp, docs/verification.md V3): the interface stays where it is while the flow steps. The dam
break (config/scenes/dam-break.yaml, 40x20x2 cells) on 2 ranks for 20 steps with checkpoints at steps 10 and 20:
frozen, alpha at step 20 equals alpha at step 10 bit for bit while the flow moves (max |v| > 0.01 m/s and changing);
moving (the default, the control), alpha changes between the two. Usage: test_frozen_interface.py VOFDEM"""
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from checkpointtools import path, read  # noqa: E402
from testcheck import check, failures, run_vofdem  # noqa: E402

import numpy as np  # noqa: E402


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-frozen-")
    scene = ["-options_file_yaml", os.path.join(ROOT, "config", "scenes", "dam-break.yaml"), "-grid_cells", "40,20,2", "-max_steps", "20",
             "-checkpoint_every", "10", "-checkpoint_keep", "5", "-monitor_timing", "0"]
    states = {}
    for name, extra in (("frozen", ["-vof_advect", "0"]), ("moving", [])):
        folder = os.path.join(tmp, name)
        run_vofdem(exe, 2, scene + ["-checkpoint_dir", folder, "-output_dir", folder + "-out"] + extra)
        states[name] = [read(path(folder, s)) for s in (10, 20)]
    f10, f20 = states["frozen"]
    m10, m20 = states["moving"]
    same = f10["vof/vof_alpha"].tobytes() == f20["vof/vof_alpha"].tobytes()
    check(same, "-vof_advect 0: alpha at step 20 equals alpha at step 10 bit for bit")
    speed = float(np.max(np.abs(f20["flow/flow_v"])))
    moved = f10["flow/flow_v"].tobytes() != f20["flow/flow_v"].tobytes()
    check(speed > 0.01 and moved, "-vof_advect 0: the flow still steps (max |v| %.3e m/s at step 20, changed since step 10: %s)" % (speed, moved))
    change = float(np.max(np.abs(m20["vof/vof_alpha"] - m10["vof/vof_alpha"])))
    check(change > 1e-3, "control, the default: alpha moves between steps 10 and 20 (max change %.3e)" % change)
    print("FAIL: %d check(s) failed" % len(failures) if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
