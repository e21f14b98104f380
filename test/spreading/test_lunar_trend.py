#!/usr/bin/python3
"""Seed 002's trend on the reduced lunar-regolith scene (config/scenes/lunar-spreading-reduced.yaml), 2 ranks:
the three settings of seed 002 section 3, earth without van der Waals, earth with it, moon with it. Seed
002 reports packing 0.588 > 0.463 > 0.395, coordination 5.456 > 4.993 > 3.27 and Ra 10.7 < 30.5 < 48.8 um
in that order (full size). Checks what the reduced run can honestly check: each run ends with a bed in
the window (particles in every cutting ring, packing > 0.1) and all clumps whole; the ordering is PRINTED
and checked only with --check-trend (the reduced scene's springs are 10^4 x softer and its bond numbers
differ; results/lunar-speed.md says what it showed). Prints packing, coordination and Ra beside the seed's.
Usage: test_lunar_trend.py VOFDEM [--check-trend]"""
import csv
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, failures, run_vofdem  # noqa: E402

SETTINGS = [("earth, no van der Waals", ["-dem_hamaker", "0"], (0.588, 5.456, 10.686)),
            ("earth, van der Waals", [], (0.463, 4.993, 30.461)),
            ("moon, van der Waals", ["-gravity", "0,0,-1.63"], (0.395, 3.27, 48.783))]


def summary(path):
    out = {}
    with open(path) as f:
        for r in csv.DictReader(f):  # metric,value,unit
            try:
                out[r["metric"]] = float(r["value"])
            except ValueError:
                pass
    return out


def main():
    exe = os.path.abspath(sys.argv[1])
    strict = "--check-trend" in sys.argv
    os.chdir(ROOT)
    tmp = tempfile.mkdtemp(prefix="vofdem-lunar-")
    res = []
    for name, extra, seed in SETTINGS:
        out = os.path.join(tmp, name.replace(",", "").replace(" ", "-"))
        run_vofdem(exe, 2, ["-options_file_yaml", os.path.join("config", "scenes", "lunar-spreading-reduced.yaml"), "-output_dir", out,
                            "-dem_save_particles", out + "-end.csv"] + extra, timeout=3600)
        s = summary(os.path.join(out, "analysis", "summary.csv"))
        phi, z, ra = s.get("rings_packing_density", 0), s.get("rings_mean_coordination", 0), s.get("Ra_line", 0)
        with open(os.path.join(out, "analysis", "rings.csv")) as f:
            rings = [int(r["particles"]) for r in csv.DictReader(f)]
        with open(out + "-end.csv") as f:
            rows = list(csv.DictReader(f))
        members = {}
        for r in rows:
            members.setdefault(r["clump"], 0)
            members[r["clump"]] += 1
        check(min(rings) > 0 and phi > 0.1, "%s: a bed in the window (particles per ring %s, packing %.3f)" % (name, rings, phi))
        check(all(1 < n <= 5 for n in members.values()), "%s: %d clumps at the end, all whole (2-5 members)" % (name, len(members)))
        print("%s: packing %.4f (seed %.3f), coordination %.3f (seed %.3f), Ra %.2f um (seed %.3f um)" % (name, phi, seed[0], z, seed[1], ra * 1e6, seed[2]))
        res.append((phi, z, ra))
    order = res[0][0] > res[1][0] > res[2][0], res[0][1] > res[1][1] > res[2][1], res[0][2] < res[1][2] < res[2][2]
    text = "seed 002's ordering on the reduced scene: packing falling %s, coordination falling %s, Ra rising %s" % tuple("yes" if o else "NO" for o in order)
    if strict:
        check(all(order), text)
    else:
        print("reported, not checked: " + text)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
