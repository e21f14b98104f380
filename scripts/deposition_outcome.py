#!/usr/bin/python3
"""What happened in a deposition scene (docs/verification.md E3): reads a run's output folder (-output_dir with the
particles' and the flow's ParaView series, monitor.csv and melted_particles.csv) and prints, on lines starting
"outcome:", the criteria that tell seed 000's outcomes apart:
  - contacts: the first time two particles touched (between two particle frames: closest approach overlapping, approach turned into separation) and
    the hottest particle's temperature then, against the liquidus: "contact before melting" or not;
  - melting: per particle when, where (the bottom's height above the floor) and whether it touched metal
    (melted_particles.csv: metal_around), and its energy account (absorbed, exchanged, sensible, latent; closure);
  - drops: the connected bodies of metal (alpha >= ALPHA, 26-connected cells) in each flow frame after the first melt:
    the first frame, once all the particles have melted, in which the metal is one body clear of the floor ("one drop in flight"), and at the end the
    bodies that touch the floor ("marks") with their volumes.
  deposition_outcome.py OUT [--alpha 0.5] [--liquidus 1609] [--floor 0] [--particles 4] [--json FILE]"""
import argparse
import csv
import glob
import json
import os
import re
import sys

import h5py
import numpy as np
from scipy import ndimage


def frames(out, kind):
    """(time, file) of each frame of a series, from its .xmf index."""
    xmf = os.path.join(out, kind + ".xmf")
    text = open(xmf).read()
    times = [float(t) for t in re.findall(r'<Time Value="([^"]+)"', text)]
    files = re.findall(r'(%s_\d+\.h5):' % kind, text)
    seen, result = set(), []
    for t, f in zip(times, [f for f in files if not (f in seen or seen.add(f))]):
        result.append((t, os.path.join(out, f)))
    return result


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--alpha", type=float, default=0.5)
    ap.add_argument("--liquidus", type=float, default=1609.0)
    ap.add_argument("--floor", type=float, default=0.0)
    ap.add_argument("--json")
    ap.add_argument("--particles", type=int, default=4, help="particles in the scene (one drop in flight: all of them melted)")
    o = ap.parse_args()
    res = {}
    # 1. contacts between particles: in each interval between two particle frames, a pair whose closest approach on
    # straight lines from the first frame overlaps and whose normal approach speed has turned into separation
    # (a Hertz contact of these spheres lasts a few us, shorter than the frames' interval)
    first_contact, t_hot = None, None
    prev = None
    for t, f in frames(o.out, "particles"):
        with h5py.File(f, "r") as h:
            x, v, r, T, ids = h["position"][...], h["velocity"][...], h["radius"][...], h["temperature"][...], h["id"][...]
        order = np.argsort(ids)
        x, v, r, T, ids = x[order], v[order], r[order], T[order], ids[order]
        if prev is not None and len(r) > 1 and np.array_equal(prev[4], ids):
            t0, x0, v0, T0 = prev[0], prev[1], prev[2], prev[5]
            dt = t - t0
            for i in range(len(r)):
                for j in range(i + 1, len(r)):
                    dx, dv = x0[j] - x0[i], v0[j] - v0[i]
                    s = np.clip(-np.dot(dx, dv) / max(np.dot(dv, dv), 1e-300), 0, dt)
                    closest = np.linalg.norm(dx + s * dv) - r[i] - r[j]
                    n0 = np.dot(dx, dv)                       # < 0: approaching
                    n1 = np.dot(x[j] - x[i], v[j] - v[i])     # > 0: separating
                    if closest <= 0 and n0 < 0 and n1 > 0 and first_contact is None:
                        first_contact, t_hot = t0 + s, float(max(T0.max(), T.max()))
        if first_contact is not None:
            break
        prev = (t, x, v, r, ids, T)
    res["first_contact_s"] = first_contact
    res["hottest_at_contact_K"] = t_hot
    if first_contact is None:
        print("outcome: contact: no two particles touched in any particle frame")
    else:
        print("outcome: contact: first at t = %.4e s, hottest particle then %.1f K (liquidus %.0f K): %s"
              % (first_contact, t_hot, o.liquidus, "contact before melting" if t_hot < o.liquidus else "contact after melting"))
    # 2. melting, from the melt log (the last row of each id)
    log = {}
    path = os.path.join(o.out, "melted_particles.csv")
    if os.path.exists(path):
        for row in csv.DictReader(open(path)):
            log[int(row["id"])] = {k: float(v) for k, v in row.items()}
    melts = sorted(log.values(), key=lambda m: (m["time_s"], m["id"]))
    res["melted"] = []
    worst = 0.0
    for m in melts:
        height = m["z_m"] - m["radius_m"] - o.floor
        where = "on or in metal" if m["metal_around"] > 1e-6 else ("in flight" if height > 0.05 * m["radius_m"] else "on the floor")
        worst = max(worst, m["account_error"])
        res["melted"].append({"id": int(m["id"]), "time_s": m["time_s"], "height_m": height, "where": where, "metal_around": m["metal_around"],
                              "absorbed_J": m["absorbed_J"], "exchanged_J": m["exchanged_J"], "sensible_J": m["sensible_J"], "latent_J": m["latent_J"],
                              "account_error": m["account_error"]})
        print("outcome: melted: particle %d at t = %.4e s, %s (bottom %.1f um above the floor, metal around %.3f), v = (%.3f, %.3f, %.3f) m/s; "
              "absorbed %.4e J, to the fluid %.4e J, sensible %.4e J, latent %.4e J, account closes to %.1e"
              % (m["id"], m["time_s"], where, height * 1e6, m["metal_around"], m["vx_m_s"], m["vy_m_s"], m["vz_m_s"], m["absorbed_J"], m["exchanged_J"],
                 m["sensible_J"], m["latent_J"], m["account_error"]))
    res["account_error_max"] = worst
    # 3. drops and marks
    flow = frames(o.out, "flow")
    t_melt = melts[0]["time_s"] if melts else None
    one_in_flight = None
    last = None
    timeline = []
    for t, f in flow:
        if t_melt is None or t < t_melt:
            continue
        with h5py.File(f, "r") as h:
            a = h["vof_alpha"][...]  # (z, y, x) as written
        lab, n = ndimage.label(a >= o.alpha, structure=np.ones((3, 3, 3)))
        bodies = []
        for k in range(1, n + 1):
            cells = lab == k
            bodies.append({"cells": int(cells.sum()), "volume_cells": float(a[cells].sum()), "on_floor": bool(cells[0].any())})
        last = (t, bodies, a)
        timeline.append("%.3f:%d%s" % (t * 1e3, n, "f" * sum(b["on_floor"] for b in bodies)))
        if one_in_flight is None and n == 1 and not bodies[0]["on_floor"] and len(log) == o.particles:
            one_in_flight = t
    res["one_drop_in_flight_s"] = one_in_flight
    print("outcome: bodies per flow frame (t in ms: bodies, one f per body on the floor): " + " ".join(timeline))
    if last is None:
        print("outcome: drops: no metal")
    else:
        t, bodies, a = last
        marks = [b for b in bodies if b["on_floor"]]
        res["end_time_s"] = t
        res["bodies_at_end"] = len(bodies)
        res["marks"] = len(marks)
        res["mark_volumes_cells"] = [b["volume_cells"] for b in marks]
        print("outcome: drops: %s" % ("all the metal one body clear of the floor at t = %.4e s (one drop in flight)" % one_in_flight
                                       if one_in_flight is not None else "the metal was never one body clear of the floor"))
        print("outcome: marks: at t = %.4e s %d bod%s of metal (alpha >= %g), %d on the floor (volumes in cells: %s)"
              % (t, len(bodies), "y" if len(bodies) == 1 else "ies", o.alpha, len(marks), ", ".join("%.2f" % b["volume_cells"] for b in marks)))
    if o.json:
        json.dump(res, open(o.json, "w"), indent=1)


if __name__ == "__main__":
    main()
