#!/usr/bin/python3
"""Seed 001's speed trend in the quick tier: config/scenes/tungsten-spreading-reduced.yaml (settle in the
hopper, hopper walls removed and the blade started at 6 ms) at a slow and a fast blade, 2 ranks, the
powder-bed analysis on the final state; the two runs are a 2 x 1 grid of scripts/sweep. Checks:
  the layer's packing density in the analysed window falls when the speed rises (V = 0.05 -> 0.1 m/s),
  and both layers hold particles (at 0.2 m/s the reduced layer is all but bare, 0-2 centres in the window:
  'falls' would then compare a layer with nothing);
  and what would make that comparison wrong for another reason:
  the powder had settled before the blade started (kinetic energy at 5.4 ms below 1e-10 J; the 700
  particles falling in at 0.3 m/s carry ~2e-8 J);
  the particle count is conserved: particles left + deleted past the substrate's end = 700 filled;
  the layer in the window (particles reaching into 0 <= z <= delta) is not in flight (|vz| < 1 cm/s; the
  seed analyses a layer at rest, but lone grains rolling on the bare substrate after a fast blade stop
  only after ~0.2 s under mu_r = 0.0315, too long for the quick tier: their speed is printed; grains
  in flight above the slab are counted, and the packing counts only sphere volume inside it), and its thickness is respected: no particle of it
  reaches above delta = 100 um (z + r <= delta + 1 %, the blade's elastic overlap), after the blade
  passed the window.
Usage: test_spreading_speed.py VOFDEM"""
import csv
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, failures  # noqa: E402

FILLED, DELTA, START, WINDOW = 700, 1.0e-4, 0.006, (6.0e-4, 1.2e-3)
SLOW, FAST = 0.05, 0.1  # m/s
REST = 0.015  # s after the blade's travel, for the grains the blade throws up to land


def main():
    exe = os.path.abspath(sys.argv[1])
    tmp = tempfile.mkdtemp(prefix="vofdem-spread-")
    packing = {}
    os.chdir(ROOT)  # the scene names its STL file relative to the source root
    # The runs go through scripts/sweep (its quick-tier use: a 2 x 1 grid of the reduced scene), which
    # also writes the sweep's table and plot.
    p = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "sweep"), "--scene", "reduced", "--speeds", "%g,%g" % (SLOW, FAST), "--layers", "%g" % DELTA,
                        "--out", tmp, "--build-dir", os.path.dirname(exe), "--vofdem-args", "-monitor_every 400"], capture_output=True, text=True, timeout=1200)
    print(p.stdout, p.stderr)
    check(p.returncode == 0, "scripts/sweep --scene reduced exits 0")
    table = list(csv.DictReader(open(os.path.join(tmp, "sweep.csv")))) if os.path.exists(os.path.join(tmp, "sweep.csv")) else []
    check(len(table) == 2 and os.path.exists(os.path.join(tmp, "sweep.png")), "the sweep's table has both runs (%d rows) and its plot is there" % len(table))
    for V in (SLOW, FAST):
        out = os.path.join(tmp, "V%g_d%g" % (V, DELTA * 1e6))
        final = START + 1.5e-3 / V + REST
        summary = {r["metric"]: float(r["value"]) for r in csv.DictReader(open(os.path.join(out, "analysis", "summary.csv")))}
        packing[V] = summary["packing_density"]
        rows = list(csv.DictReader(open(os.path.join(out, "monitor.csv"))))
        before = [r for r in rows if float(r["time_s"]) <= START - 4e-4][-1]
        ke = float(before["kinetic_energy_J"])
        check(ke < 1e-10, "V = %g m/s: settled before the blade starts: kinetic energy %.3e J at t = %.4f s (< 1e-10 J)" % (V, ke, float(before["time_s"])))
        last = rows[-1]
        left, deleted = int(float(last["particles"])), int(float(last["deleted"]))
        check(left + deleted == FILLED, "V = %g m/s: particles conserved: %d left + %d deleted = %d (filled %d)" % (V, left, deleted, left + deleted, FILLED))
        parts = list(csv.DictReader(open(os.path.join(out, "end.csv"))))
        check(len(parts) == left, "V = %g m/s: the saved particles (%d) are the monitor's (%d)" % (V, len(parts), left))
        speed = lambda p: sum(float(p[k]) ** 2 for k in ("vx", "vy", "vz")) ** 0.5  # noqa: E731
        inwin = [p for p in parts if WINDOW[0] <= float(p["x"]) <= WINDOW[1]]
        layer = [p for p in inwin if float(p["z"]) - float(p["radius"]) < DELTA]  # touches the analysed slab 0 <= z <= delta
        flying = [p for p in inwin if p not in layer]
        vz = max((abs(float(p["vz"])) for p in layer), default=0.0)
        vmax = max((speed(p) for p in layer), default=0.0)
        check(vz < 1e-2, "V = %g m/s: nothing of the layer in the window is in flight at the end: largest |vz| of its %d particles %.2e m/s (< 1e-2 m/s); "
              "fastest %.2e m/s (grains rolling on the bare substrate: rolling friction stops them only slowly); %d grain(s) in flight above the slab"
              % (V, len(layer), vz, vmax, len(flying)))
        top = max((float(p["z"]) + float(p["radius"]) for p in layer), default=0.0)
        edge = -1e-4 + V * (final - START)  # the blade's back face started at x = -0.1 mm
        check(edge > WINDOW[1] and top <= DELTA * 1.01,
              "V = %g m/s: layer thickness respected: highest particle top of the layer in the window %.2f um (delta %.0f um), blade's back face at %.2f mm past the window's end %.2f mm"
              % (V, top * 1e6, DELTA * 1e6, edge * 1e3, WINDOW[1] * 1e3))
        print("V = %g m/s: packing density %.4f with %d particle centres in the window, mean coordination %.3f"
              % (V, packing[V], int(summary["particles_in_window"]), summary.get("mean_coordination", 0.0)))
    check(packing[SLOW] > 0.1 and packing[FAST] > 0.03, "neither layer is bare: packing %.4f > 0.1 at %g m/s, %.4f > 0.03 at %g m/s" % (packing[SLOW], SLOW, packing[FAST], FAST))
    check(packing[FAST] < packing[SLOW], "packing falls as the speed rises: %.4f at %g m/s -> %.4f at %g m/s" % (packing[SLOW], SLOW, packing[FAST], FAST))
    if failures:
        print("FAIL: %d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
