#!/usr/bin/python3
"""The first fluid step of a coupled run whose inflow meets particles present at the start (Simulation::SetUp):
the initial velocity is made divergence-free with the particles' eps (F1) before the first step is chosen, so that
the step's limit sees the pores' speed U/eps and not the inflow's U. The bubbling-bed scene (config/scenes/
bubbling-bed.yaml: air at 0.9 m/s into a loose fill of 10,000 spheres) at cell/d 3, 2 steps, on 1 and 2 ranks.
Checks: the divergence of eps u at step 0 is round-off of the solve (before: 217 1/s, the inflow against eps), the
step-1 Courant number is the scene's -flow_cfl 0.4 (before: 0.509, the step chosen from 0.9 m/s while the pores
carried 1.13 m/s), and the speed at step 0 is above the inflow's (the pores').
Usage: test_first_step_cfl.py VOFDEM"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402


def main():
    exe = os.path.abspath(sys.argv[1])
    os.chdir(ROOT)
    for ranks in (1, 2):
        p = run_vofdem(exe, ranks, ["-options_file_yaml", os.path.join("config", "scenes", "bubbling-bed.yaml"), "-grid_cells", "12,3,33", "-max_steps", "2",
                                    "-monitor_every", "1", "-flow_output_every", "0", "-dem_output_every", "0"])
        rows = {int(m.group(1)): m.group(0) for m in re.finditer(r"^step\s+(\d+)\s.*$", p.stdout, re.M)}
        if not all(k in rows for k in (0, 1)):
            check(False, "%d rank(s): monitor lines of steps 0 and 1" % ranks)
            continue
        num = lambda row, key: float(re.search(key + r"\s+(\S+)", row).group(1))
        div0, u0, cfl1 = num(rows[0], r"div"), num(rows[0], r"max\|u_i\|"), num(rows[1], r"CFL")
        check(div0 < 1e-2, "%d rank(s): step 0 div(eps u) %.2e 1/s (below 1e-2: projected with the particles' eps)" % (ranks, div0))
        check(u0 > 0.9 * 1.1, "%d rank(s): step 0 max|u| %.4f m/s above the inflow's 0.9 m/s by 10 %% (the pores)" % (ranks, u0))
        check(cfl1 <= 0.4 * 1.005, "%d rank(s): step 1 Courant number %.3f (the scene's -flow_cfl 0.4)" % (ranks, cfl1))
    finish()


if __name__ == "__main__":
    main()
