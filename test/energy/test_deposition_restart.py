#!/usr/bin/python3
"""Long deposition runs across restarts (docs/modules/checkpoint.md): seed 000's four-particle scene (a)
(config/scenes/four-particles-collide.yaml at 20 x 20 x 16 cells; its particles melt at step 183 of 320) checkpointed
at step 150, while the particles are hot and the laser on, then:
  (a) continued on the other rank count (2 -> 1 and 1 -> 2): the particles melt in the same step as in the
      uninterrupted run, with the same energy accounts (1e-10), the same metal volume (1e-12) and energy (1e-10);
  (b) continued with another laser power (-laser_power 400 instead of 300) and another path (the beam moved 0.1 mm in
      x): the restart names both changes; from the restart on the beam carries 400 W (laser_beam_W, 1e-12), before it
      300 W; the first particle melts earlier than at 300 W;
  (c) continued with another laser radius: refused, with one line naming -laser_radius.
  test_deposition_restart.py VOFDEM"""
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import ENV, check, finish, run_vofdem  # noqa: E402

SCENE = ["-options_file_yaml", os.path.join(ROOT, "config", "scenes", "four-particles-collide.yaml"), "-grid_cells", "20,20,16",
         "-dem_particles_file", os.path.join(ROOT, "config", "scenes", "four-particles.csv"), "-monitor_every", "1", "-monitor_timing", "0",
         "-dem_output_every", "0", "-flow_output_every", "0"]
STOP = 150
BOX, RL = 1.4e-3, 270e-6  # the box's side in x and y, the beam's radius


def in_box(cx, cy):
    """The share of a Gaussian beam centred at (cx, cy) that enters the box (the columns' exact sum)."""
    s = math.sqrt(2) / RL
    return 0.25 * (math.erf(s * (BOX - cx)) + math.erf(s * cx)) * (math.erf(s * (BOX - cy)) + math.erf(s * cy))


def monitor(out):
    with open(os.path.join(out, "monitor.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def melts(out):
    with open(os.path.join(out, "melted_particles.csv")) as f:
        rows = {}
        for r in csv.DictReader(f):
            rows[int(r["id"])] = {k: float(v) for k, v in r.items()}  # the last row of an id counts
    return rows


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-deposition-restart-")
    try:
        ref = {}
        for ranks in (1, 2):
            out = os.path.join(tmp, "whole-%d" % ranks)
            run_vofdem(exe, ranks, SCENE + ["-output_dir", out, "-checkpoint_every", str(STOP), "-checkpoint_keep", "10", "-checkpoint_dir", os.path.join(out, "ck")], timeout=600)
            ref[ranks] = (monitor(out), melts(out), os.path.join(out, "ck", "checkpoint_%08d.h5" % STOP))
        m1 = ref[1][1]
        check(len(m1) == 4 and min(m["time_s"] for m in m1.values()) > ref[1][0][STOP]["time_s"],
              "the uninterrupted run melts its four particles after the checkpoint at step %d" % STOP)
        # (a) the other rank count
        for saved, cont in ((2, 1), (1, 2)):
            out = os.path.join(tmp, "from%d-on%d" % (saved, cont))
            p = run_vofdem(exe, cont, SCENE + ["-output_dir", out, "-restart", ref[saved][2]], timeout=600)
            check(("written on %d rank" % saved) in p.stdout, "(a) the restart on %d rank(s) says the file was written on %d" % (cont, saved))
            mine, want = melts(out), ref[cont][1]
            same = sorted(mine) == sorted(want) and all(mine[i]["time_s"] == want[i]["time_s"] for i in want)
            check(same, "(a) written on %d, continued on %d rank(s): the particles melt in the same steps as uninterrupted" % (saved, cont))
            dev = max([abs(mine[i][k] / want[i][k] - 1) for i in want if i in mine for k in ("absorbed_J", "exchanged_J", "sensible_J", "latent_J")] + [0.0 if want else 1.0])
            check(dev <= 1e-10, "(a) %d -> %d ranks: the melted particles' accounts within %.1e of the uninterrupted run's (tolerance 1e-10)" % (saved, cont, dev))
            a, b = monitor(out)[-1], ref[cont][0][-1]
            dv, de = abs(a["vof_volume_m3"] / b["vof_volume_m3"] - 1), abs(a["energy_total_J"] / b["energy_total_J"] - 1)
            check(dv <= 1e-12 and de <= 1e-10, "(a) %d -> %d ranks at the end: metal volume within %.1e (1e-12), energy within %.1e (1e-10)" % (saved, cont, dv, de))
        # (b) another power and path from the checkpoint
        out = os.path.join(tmp, "changed")
        p = run_vofdem(exe, 2, SCENE + ["-output_dir", out, "-restart", ref[2][2], "-laser_power", "400", "-laser_path", "0.8e-3,0.7e-3",
                                        "-final_time", "2.1e-3"], timeout=600)  # past the melt, short of boiling at 400 W
        line = [l for l in p.stdout.splitlines() if "the restart changes" in l]
        check(len(line) == 1 and "-laser_power 300 -> 400" in line[0] and "-laser_path" in line[0], "(b) the restart names the changes: %s" % (line[0] if line else "(no line)"))
        rows = monitor(out)
        beam = [r["laser_beam_W"] for r in rows]
        want = 400 * in_box(0.8e-3, 0.7e-3)
        check(len(beam) > 0 and all(abs(b / want - 1) <= 1e-12 for b in beam),
              "(b) after the restart the beam brings 400 W x its share in the box = %.10f W in every step (%.10f .. %.10f W)" % (want, min(beam or [0]), max(beam or [0])))
        before, was = [r["laser_beam_W"] for r in ref[2][0][1:STOP + 1]], 300 * in_box(0.7e-3, 0.7e-3)
        check(all(abs(b / was - 1) <= 1e-12 for b in before), "(b) before it 300 W x its share = %.10f W (%.10f .. %.10f W)" % (was, min(before), max(before)))
        changed = melts(out)
        first, base = min([m["time_s"] for m in changed.values()] + [1e9]), min(m["time_s"] for m in ref[2][1].values())
        check(len(changed) >= 1 and first < base, "(b) at 400 W the first particle melts earlier: %.4e s against %.4e s at 300 W (%d melted by 2.1 ms)" % (first, base, len(changed)))
        # (c) a change that is not allowed
        q = subprocess.run(["mpiexec", "--oversubscribe", "-n", "2", exe] + SCENE + ["-output_dir", os.path.join(tmp, "refused"), "-restart", ref[2][2], "-laser_radius", "3e-4"],
                           env=ENV, capture_output=True, text=True, timeout=300)
        err = [l for l in (q.stdout + q.stderr).splitlines() if "vofdem: error" in l]
        check(q.returncode != 0 and len(err) >= 1 and "-laser_radius" in err[0], "(c) -laser_radius changed at the restart is refused: %s" % (err[0] if err else "(no error line)"))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
