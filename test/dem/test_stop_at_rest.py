#!/usr/bin/python3
"""-stop_kinetic_energy E -stop_kinetic_energy_after T (Simulation.cpp): a run ends at the first monitor line at or after T
whose particle kinetic energy (translational + rotational) is below E, like a run that reached its -final_time (last
checkpoint, analysis of the end state); before T a low energy (the spheres just released) does not end it. A run stopped
by a signal writes no analysis (its state is not the run's result). Usage: test_stop_at_rest.py VOFDEM"""
import csv
import os
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scripts", "lib"))
from testcheck import ENV, check, failures, run_vofdem  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# 400 glass spheres of 0.5 mm dropped ~1 cm in config/scenes/box-drop.yaml: they land at ~0.045 s and are at rest by ~0.13 s.
SCENE = ["-options_file_yaml", os.path.join(ROOT, "config", "scenes", "box-drop.yaml"), "-dem_fill_count", "400", "-monitor_timing", "0",
         "-monitor_every", "200", "-analysis_metrics", "packing"]
BOUND, AFTER = 1e-9, 0.05


def energies(out):
    with open(os.path.join(out, "monitor.csv")) as f:
        return [(float(r["time_s"]), float(r["kinetic_energy_J"]) + float(r["rotational_energy_J"])) for r in csv.DictReader(f)]


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-rest-")
    # Without -stop_kinetic_energy_after the spheres, released at rest, end the run at the first monitor line.
    out = os.path.join(tmp, "early")
    p = run_vofdem(exe, 2, SCENE + ["-stop_kinetic_energy", str(BOUND), "-output_dir", out])
    rows = energies(out)
    check(len(rows) == 2 and rows[-1][1] < BOUND, "without -stop_kinetic_energy_after: ends at the first monitor line (t = %g s, %g J)" % rows[-1])
    # With it: on past the fall, at the first line at or after AFTER below the bound.
    out = os.path.join(tmp, "rest")
    p = run_vofdem(exe, 2, SCENE + ["-stop_kinetic_energy", str(BOUND), "-stop_kinetic_energy_after", str(AFTER), "-output_dir", out])
    rows = energies(out)
    t_end, e_end = rows[-1]
    check("below -stop_kinetic_energy" in p.stdout, "the run says why it ended")
    check(t_end >= AFTER and e_end < BOUND, "ends at rest after %g s: t = %g s, %g J" % (AFTER, t_end, e_end))
    check(all(e >= BOUND for t, e in rows[1:-1] if t >= AFTER), "no earlier line after %g s was below %g J" % (AFTER, BOUND))
    check(any(e < BOUND for t, e in rows[1:] if t < AFTER), "a line before %g s was below %g J and did not end it" % (AFTER, BOUND))
    check(max(e for t, e in rows) > 100 * BOUND, "the spheres moved (largest energy %g J)" % max(e for t, e in rows))
    check(os.path.exists(os.path.join(out, "analysis", "summary.csv")), "the end state is analysed")
    # A signal mid-run: a checkpoint, exit 0, and no analysis of the unfinished state.
    out = os.path.join(tmp, "signal")
    cmd = ["mpiexec", "-n", "2", "--oversubscribe", exe] + SCENE + ["-stop_kinetic_energy", str(BOUND), "-stop_kinetic_energy_after", str(AFTER), "-output_dir", out,
                                                           "-checkpoint_minutes", "60"]  # checkpoints on: the signal handlers are installed
    q = subprocess.Popen(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    deadline = time.time() + 120
    while time.time() < deadline and q.poll() is None:
        try:
            if len(open(os.path.join(out, "monitor.csv")).readlines()) > 20:
                break
        except OSError:
            pass
        time.sleep(0.05)
    q.send_signal(signal.SIGUSR1)  # mpiexec forwards it to the ranks (test/checkpoint: signal_usr1_2)
    text = q.communicate(timeout=120)[0]
    check(q.returncode == 0, "a signal: exit 0 (%d)" % q.returncode)
    check("no analysis" in text and not os.path.exists(os.path.join(out, "analysis", "summary.csv")), "a signal: no analysis of the unfinished state")
    if failures:
        print(text[-3000:])
    print("all checks passed" if not failures else "FAILED: %d check(s)" % len(failures))
    sys.exit(1 if failures else 0)


main()
