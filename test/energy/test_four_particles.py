#!/usr/bin/python3
"""Seed 000's four-particle scenes (docs/verification.md E3) at the seed's own cell size (70 um, 0.73 d: 20 x 20 x 16
cells; the scenes' 35 um cells are the validate case e3-four-particles), on 1 and 2 ranks. The outcomes are told
apart by scripts/deposition_outcome.py's criteria:
  (a) config/scenes/four-particles-collide.yaml: two particles touch before any reaches the solidus; all four then
      melt in flight (no metal around them); four marks on the floor at the end;
  (b) config/scenes/four-particles-coalesce.yaml: all four melt before any two touch; the metal is then one body clear
      of the floor (one drop in flight);
and in both: each melted particle's energy account (absorbed = m (h - h_0) + exchanged) closes to 1e-10, the
energy account of cells and particles to 1e-12 at every monitor line, the conversions' books to 1e-12; 1 and 2
ranks melt the particles in the same step with the same accounts (1e-10) and end with the same metal (1e-12).
  test_four_particles.py VOFDEM"""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

SOLIDUS = 1533.0


def run(exe, scene, particles, ranks, out, extra):
    run_vofdem(exe, ranks, extra + ["-options_file_yaml", os.path.join(ROOT, "config", "scenes", scene), "-grid_cells", "20,20,16",
                            "-dem_particles_file", os.path.join(ROOT, "config", "scenes", particles), "-output_dir", out, "-monitor_every", "5",
                            "-monitor_timing", "0"], timeout=600)
    res = os.path.join(out, "outcome.json")
    p = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "deposition_outcome.py"), out, "--alpha", "0.1", "--json", res],
                       capture_output=True, text=True)
    print(p.stdout, p.stderr)
    check(p.returncode == 0, "deposition_outcome.py reads %s" % out)
    outcome = json.load(open(res)) if os.path.exists(res) else {}
    with open(os.path.join(out, "monitor.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    return outcome, rows


def books(label, o, rows):
    melted = o.get("melted", [])
    check(len(melted) == 4, "%s: all four particles melted (%d)" % (label, len(melted)))
    worst = max([m["account_error"] for m in melted] + [0])
    check(worst <= 1e-10, "%s: each melted particle's account closes: absorbed = m (h - h_0) + exchanged to %.1e (tolerance 1e-10)" % (label, worst))
    acc = max(abs(r["energy_total_J"] - r["energy_accounted_J"]) / r["energy_total_J"] for r in rows)
    check(acc <= 1e-12, "%s: cells and particles: |energy_total_J - energy_accounted_J| at most %.1e of the total (tolerance 1e-12)" % (label, acc))
    conv = max(max(r["melt_volume_error"], r["melt_energy_error"], r["melt_momentum_error"]) for r in rows)
    check(conv <= 1e-12, "%s: the conversions' books (volume, energy, momentum) within %.1e (tolerance 1e-12)" % (label, conv))


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-four-particles-")
    try:
        results = {}
        # (b) to 2.1 ms: the drop forms at 1.92 ms (its fall to the floor is the validate case's)
        for scene, particles, key, extra in (("four-particles-collide.yaml", "four-particles.csv", "a", []),
                                             ("four-particles-coalesce.yaml", "four-particles.csv", "b", ["-final_time", "2.1e-3"])):
            for ranks in (1, 2):
                out = os.path.join(tmp, "%s-%d" % (key, ranks))
                o, rows = run(exe, scene, particles, ranks, out, extra)
                results[(key, ranks)] = (o, rows)
                label = "(%s) %s, %d rank(s)" % (key, scene, ranks)
                books(label, o, rows)
                melted = o.get("melted", [])
                first_melt = min([m["time_s"] for m in melted] + [1e9])
                contact = o.get("first_contact_s")
                if key == "a":
                    check(contact is not None and contact < first_melt and o.get("hottest_at_contact_K", 1e9) < SOLIDUS,
                          "%s: two particles touched (t = %s s) before any melted (%.4e s), the hottest at %s K, below the solidus %g K"
                          % (label, contact, first_melt, o.get("hottest_at_contact_K"), SOLIDUS))
                    check(all(m["where"] == "in flight" for m in melted) and len(melted) == 4, "%s: all four melted in flight (no metal around them)" % label)
                    check(o.get("marks") == 4, "%s: four marks on the floor at the end (%s)" % (label, o.get("marks")))
                else:
                    last_melt = max([m["time_s"] for m in melted] + [0])
                    check(contact is None or contact > last_melt, "%s: all four melted (by %.4e s) before any two touched (%s)" % (label, last_melt, contact))
                    check(o.get("one_drop_in_flight_s") is not None, "%s: the metal is one body clear of the floor after the four melted (t = %s s)" % (label, o.get("one_drop_in_flight_s")))
            a, b = results[(key, 1)], results[(key, 2)]
            ma, mb = {m["id"]: m for m in a[0].get("melted", [])}, {m["id"]: m for m in b[0].get("melted", [])}
            same = sorted(ma) == sorted(mb) and all(ma[i]["time_s"] == mb[i]["time_s"] for i in ma)
            check(same, "(%s): 1 and 2 ranks melt the same particles at the same times" % key)
            dev = max([abs(ma[i][k] / mb[i][k] - 1) for i in ma if i in mb for k in ("absorbed_J", "sensible_J", "latent_J")] + [1.0 if not ma else 0.0])
            check(dev <= 1e-10, "(%s): 1 and 2 ranks give the melted particles' accounts alike to %.1e (tolerance 1e-10)" % (key, dev))
            va, vb = a[1][-1]["vof_volume_m3"], b[1][-1]["vof_volume_m3"]
            check(abs(va / vb - 1) <= 1e-12, "(%s): 1 and 2 ranks end with the same metal volume: %.12e, %.12e m^3" % (key, va, vb))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
