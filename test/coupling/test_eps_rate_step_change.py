#!/usr/bin/python3
"""d(eps)/dt when the fluid step changes (issue 55, F1): a sphere (d 0.5 mm, 2500 kg/m^3) settling in water with
Schiller-Naumann at cell/d 0.6, the adaptive step near 3.5 ms. Three runs on 1 and 2 ranks:
  A  to a time on a step boundary of the adaptive run (read from its own monitor), less 1e-9 s;
  B  to 0.2 of a step later: the last step is shortened 5x to land on -final_time;
  C  at a fixed -dt near 2e-4 s that ends on the time of B (the scheme near dt -> 0).
A shorter step brings the solution toward the finer step's, never past it: B's velocity must lie between A's and
C's. Before the fix, the eps change of the last (long) step was divided by the short step, a 5x too fast
displacement: B's velocity fell 0.66 % in 0.7 ms, five times past C's; and a run to 1e-9 s past a step's end (D, a
final time rounded up) took a step of 2e-9 s that divided a whole step's displacement by it and threw the sphere at
1e5 m/s: D may move it by no more than B (less than A's distance from C). What D still moves (5e-4 of the velocity
here, where the sphere crosses about a cell per step) is the added mass's Du/Dt, the change of the velocity read over a
step that mixes the particle's last displacement with this step's fluid, and the projection taking up the change of
d(eps)/dt at once. Also: monitor.csv's dt of the last step is
the step taken, not the nominal one. Usage: test_eps_rate_step_change.py VOFDEM"""
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, read_particles, run_vofdem  # noqa: E402

SCENE = ("-physics dem,flow -grid_upper 0.0048,0.0048,0.018 -grid_cells 16,16,60 -gravity 0,0,-9.81 -flow_density 1000 -flow_viscosity 1e-3 "
         "-dem_radius 2.5e-4 -dem_density 2500 -dem_fill_count 1 -dem_fill_lower 0.00212,0.00212,0.01572 -dem_fill_upper 0.00268,0.00268,0.01628 "
         "-coupling_drag schillernaumann -max_steps 100000 -monitor_every 1000000 -monitor_timing 0").split()


def settle(exe, ranks, tmp, name, args):
    out = os.path.join(tmp, name)
    run_vofdem(exe, ranks, SCENE + ["-output_dir", out, "-dem_save_particles", os.path.join(out, "p.csv")] + args)
    p = read_particles(os.path.join(out, "p.csv"))
    rows = [l.split(",") for l in open(os.path.join(out, "monitor.csv"))][1:] if os.path.exists(os.path.join(out, "monitor.csv")) else []
    return (p[0]["vz"] if p else float("nan")), rows


def main():
    exe = os.path.abspath(sys.argv[1])
    tmp = tempfile.mkdtemp(prefix="vofdem-epsrate-")
    for ranks in (1, 2):
        _, rows = settle(exe, ranks, tmp, "probe%d" % ranks, ["-final_time", "0.15", "-monitor_every", "1"])
        if len(rows) < 35:
            check(False, "%d rank(s): the probe run's monitor has its steps" % ranks)
            continue
        t30, dt = float(rows[30][1]), float(rows[31][2])  # step 30's end (to 1e-11 s as printed); step 31 is a full step
        tA, tB, tD = t30 - 1e-9, t30 - 1e-9 + 0.2 * dt, t30 + 1e-9
        vA, _ = settle(exe, ranks, tmp, "a%d" % ranks, ["-final_time", repr(tA)])
        vD, _ = settle(exe, ranks, tmp, "d%d" % ranks, ["-final_time", repr(tD)])
        vB, rowsB = settle(exe, ranks, tmp, "b%d" % ranks, ["-final_time", repr(tB)])
        vC, _ = settle(exe, ranks, tmp, "c%d" % ranks, ["-final_time", repr(tB), "-dt", repr(tB / round(tB / 2e-4))])  # steps that end on tB
        lo, hi = min(vA, vC), max(vA, vC)
        check(abs(vD - vA) <= hi - lo, "%d rank(s): a final time 1e-9 s past a step's end (a step of 2e-9 s more) moves the sphere by %.1e m/s, less than "
              "the step's own error %.1e m/s (A against C)" % (ranks, abs(vD - vA), hi - lo))
        check(lo - 1e-12 <= vB <= hi + 1e-12,
              "%d rank(s): a last step shortened to %.3g s (nominal %.3g s) moves the sphere from %.7f to %.7f m/s (%+.3f %%), toward the "
              "fine step's %.7f m/s and not past it" % (ranks, tB - tA, dt, vA, vB, 100 * (vB / vA - 1), vC))
        last = float(rowsB[-1][2]) if rowsB else float("nan")
        check(abs(last - (tB - tA)) <= 1e-6 * dt, "%d rank(s): monitor.csv gives the last step as taken, %.6e s (the step was %.6e s)" % (ranks, last, tB - tA))
    finish()


if __name__ == "__main__":
    main()
