#!/usr/bin/python3
"""A melt pool that freezes (issue 51, "the solidifying pool"): config/scenes/laser-track-conduction.yaml reduced to
40 x 12 x 8 cells (R_l/h = 1), the beam over 1 mm in 1.25 ms and then off; the run goes on to 4 ms:
  - a pool forms (melt volume above 0, pool deeper than 0 while the beam is on);
  - it freezes completely: the melt volume is exactly 0 at the end, with the step unchanged (no collapse) and at
    most 10 enthalpy iterations in any step;
  - the energy account closes: |total - accounted| below 1e-10 of the energy the laser put in (radiation included);
on 1 and 2 ranks (split in z, so the beam's column march crosses ranks). And the 3 kW spot
(config/scenes/spot-on-plate.yaml at 20 x 20 x 10 cells) passes the boiling point: the run stops on 2 ranks with one
error line naming the peak temperature and the boiling point, a non-zero exit and no PETSc trace.
  test_pool_freezes.py VOFDEM"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-pool-freezes-")
    try:
        for ranks in (1, 2):
            out = os.path.join(tmp, "r%d" % ranks)
            run_vofdem(exe, ranks, ["-options_file_yaml", os.path.join(ROOT, "config", "scenes", "laser-track-conduction.yaml"), "-grid_cells", "40,12,8",
                                    "-grid_ranks", "1,1,%d" % ranks, "-final_time", "4e-3", "-monitor_every", "1", "-monitor_timing", "0", "-output_dir", out])
            with open(os.path.join(out, "monitor.csv")) as f:
                head, *rows = [line.strip().split(",") for line in f if line.strip()]
            rows = [dict(zip(head, map(float, r))) for r in rows]
            melted = max(r["melt_volume_m3"] for r in rows)
            deepest = max(r["pool_depth_m"] for r in rows)
            check(melted > 0 and deepest > 0, "%d rank(s): a pool forms: melt volume up to %.3e m^3, depth up to %.3e m" % (ranks, melted, deepest))
            last = rows[-1]
            dts = {round(r["dt_s"], 15) for r in rows[1:]}
            its = max(r["energy_iterations"] for r in rows)
            check(last["melt_volume_m3"] == 0 and abs(last["time_s"] - 4e-3) < 1e-12 and len(dts) <= 2,
                  "%d rank(s): frozen at t = %.4g s: melt volume %.3g m^3, steps of %s s" % (ranks, last["time_s"], last["melt_volume_m3"], sorted(dts)))
            check(its <= 10, "%d rank(s): at most %d enthalpy iterations in a step (<= 10)" % (ranks, its))
            put = sum(r["laser_absorbed_W"] * r["dt_s"] for r in rows[1:])
            drift = abs(last["energy_total_J"] - last["energy_accounted_J"])
            check(drift <= 1e-10 * put, "%d rank(s): energy account: |total - accounted| %.2e J, %.1e of the %.4e J absorbed (tolerance 1e-10)" % (ranks, drift, drift / put, put))
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        p = subprocess.run(["mpiexec", "-n", "2", "--oversubscribe", exe, "-options_file_yaml", os.path.join(ROOT, "config", "scenes", "spot-on-plate.yaml"),
                            "-grid_cells", "20,20,10"], capture_output=True, text=True, env=env, timeout=120)
        errors = [l for l in (p.stdout + p.stderr).splitlines() if "error" in l.lower()]
        stop = re.compile(r"vofdem: error: energy: the metal reached ([0-9.]+) K at t = \S+ s, past its boiling point 3000\.? K")
        m = stop.search(p.stdout + p.stderr)
        check(p.returncode != 0 and len(errors) == 1 and m is not None and "PETSC ERROR" not in p.stdout + p.stderr,
              "the 3 kW spot stops at the boiling point: exit %d, %d error line(s): %s" % (p.returncode, len(errors), errors[0] if errors else "none"))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
