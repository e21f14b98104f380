#!/usr/bin/python3
"""A cohesive pile handed on through particle files (-dem_save_particles with -dem_save_contact_history, read back by
-dem_particles_file with -dem_contact_history_file; src/dem/ContactHistoryFile.cpp):
  - 100 JKR spheres with friction and EPSD rolling resistance (e 0.3) settle in a narrow box on 2 ranks until at
    rest (kinetic energy ~1e-34 J at t = 0.4 s), saving their particles and contacts (pairs and box faces, bonds among them);
  - read back with the contacts, on 1 and 2 ranks, the pile stays at rest: after 1000 steps no sphere has moved
    by more than 1e-8 of its radius and the kinetic energy stays below 1e-25 J;
  - read back without them (tangential and rolling springs from zero, bonds stretched past touching read as
    apart) the same pile moves: some sphere by more than 1e-4 of its radius, kinetic energy above 1e-20 J
    (the check that the first one can fail);
  - the contacts file names the pairs by rows of the particles file, i < j, faces as j = -1 - face.
  test_contact_history_file.py VOFDEM"""
import os
import shutil
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, read_particles as read, run_vofdem  # noqa: E402

R = 1e-4
SCENE = ["-physics", "dem", "-grid_upper", "1e-3,1e-3,3e-3", "-grid_cells", "2,2,6", "-dem_radius", "%g" % R, "-dem_density", "2500",
         "-dem_youngs_modulus", "1e7", "-dem_restitution", "0.3", "-dem_friction", "0.5", "-dem_rolling", "epsd", "-dem_rolling_friction", "0.1",
         # EPSD for rolling only, the model this pile settled with: resisting the twist too, the settling ends with one
         # sphere hanging from two bonds in tension, which the default load max(F_n, 0) leaves free to roll (test dem/epsd_rest).
         "-dem_rolling_twist", "0",
         "-dem_cohesion", "jkr", "-dem_surface_energy", "0.05", "-seed", "5", "-monitor_timing", "0", "-monitor_every", "1000"]


def kinetic(outdir):
    """The last monitor row's translational plus rotational kinetic energy."""
    with open(os.path.join(outdir, "monitor.csv")) as f:
        head, *rows = [line.strip().split(",") for line in f if line.strip()]
    last = rows[-1]
    return float(last[head.index("kinetic_energy_J")]) + float(last[head.index("rotational_energy_J")])


def positions(path):
    return np.array([[p["x"], p["y"], p["z"]] for p in read(path)])


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-contacts-file-")
    try:
        pile, contacts = os.path.join(tmp, "pile.csv"), os.path.join(tmp, "pile-contacts.csv")
        run_vofdem(exe, 2, SCENE + ["-grid_ranks", "1,1,2", "-dem_fill_count", "100", "-dem_fill_spacing", "2.1e-4", "-dem_fill_jitter", "0.3",
                                    "-dem_fill_velocity_spread", "0.05", "-final_time", "0.4", "-max_steps", "10000000", "-output_dir", os.path.join(tmp, "settle"),
                                    "-dem_save_particles", pile, "-dem_save_contact_history", contacts])
        x0 = positions(pile)
        check(len(x0) == 100, "the settled pile holds its 100 spheres (%d)" % len(x0))
        e0 = kinetic(os.path.join(tmp, "settle"))
        check(e0 < 1e-28, "the pile is at rest when saved: kinetic energy %.3g J < 1e-28 J" % e0)
        rows = np.loadtxt(contacts, delimiter=",", skiprows=1, ndmin=2)
        pairs, faces = rows[rows[:, 1] >= 0], rows[rows[:, 1] < 0]
        check(len(pairs) > 100 and len(faces) > 20, "contacts saved: %d pairs, %d with box faces" % (len(pairs), len(faces)))
        check(bool(np.all(pairs[:, 0] < pairs[:, 1])) and bool(np.all(pairs[:, 1] < 100)) and bool(np.all(faces[:, 1] >= -6)),
              "pairs as rows i < j of the particles file, faces as j = -1 - face")
        check(bool(np.all(rows[:, 9] == 1)), "every contact of the cohesive pile is a JKR bond (jkr_bonded 1)")
        if len(x0) != 100:
            return
        for n in (1, 2):
            for with_contacts in (True, False):
                name = "%s%d" % ("with" if with_contacts else "without", n)
                out = os.path.join(tmp, name)
                args = SCENE + ["-grid_ranks", "1,1,%d" % n, "-dem_fill_count", "0", "-dem_particles_file", pile, "-max_steps", "1000",
                                "-output_dir", out, "-dem_save_particles", out + ".csv"]
                if with_contacts:
                    args += ["-dem_contact_history_file", contacts]
                run_vofdem(exe, n, args)
                x = positions(out + ".csv")
                if len(x) != 100:
                    check(False, "%s: 100 spheres after 1000 steps (%d)" % (name, len(x)))
                    continue
                moved, e = np.abs(x - x0).max() / R, kinetic(out)
                if with_contacts:
                    check(moved < 1e-8 and e < 1e-25, "with its contacts on %d rank(s) the pile stays at rest: largest move %.2e R (< 1e-8), "
                          "kinetic energy %.2e J (< 1e-25)" % (n, moved, e))
                else:
                    check(moved > 1e-4 and e > 1e-20, "without them on %d rank(s) it moves: largest move %.2e R (> 1e-4), kinetic energy %.2e J (> 1e-20)"
                          % (n, moved, e))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
