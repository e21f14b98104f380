#!/usr/bin/python3
"""Verification G1 (docs/physics.md P13, eqs 18-19): two spheres in one parallel bond, pulled apart, sheared, bent,
twisted, and pulled and bent at once, each to just below and just above its break load.
  Two spheres of radius r = 1 mm, 1 um apart across z = 5 mm (the rank boundary with -grid_ranks 1,1,2), are bonded
  at t = 0 (bond radius R = lambda r, lambda = 0.8); in the one step that follows they move apart, across, or turn,
  so that the bond's increment is the whole load: a relative displacement s = v dt gives F = k_n A s, a relative
  turn theta = w dt gives M = k_n I theta (bending) or k_s J theta (twist). The break loads from eqs 18-19:
    tension F* = sigma_t A, shear F* = tau_s A, bending M* = sigma_t I / R, twist M* = tau_s J / R,
    with A = pi R^2, I = pi R^4/4, J = pi R^4/2; and pulled and bent at once -F_n/A + |M_s| R/I = sigma_t.
  At (1 - 1e-10) of the load the bond holds and carries exactly that load: the force and torque on sphere 0,
  read back from its velocity change over the step's last half kick, 2 m dv/dt and 2 (0.4 m r^2) dw/dt, equal
  (1 - 1e-10) F* (M*) to 1e-12, and the monitor's sigma/sigma_t (tau/tau_s) is 1 - 1e-10 to 1e-12; at
  (1 + 1e-10) it breaks (1 broken, 0 intact) and gives no force. So the break load is F* (M*) to 1e-10.
  The contact bond (-dem_bond_model contact: no moments, strengths as forces) alike in tension and shear, its break
  loads the strengths themselves; bent 10 times past the parallel bond's break rotation it holds and gives no torque.
  On 1 and 2 ranks (on 2 the bond is between spheres of different ranks).
  test_bond_break.py VOFDEM"""
import math
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, read_particles, run_vofdem  # noqa: E402

r, rho, gap, lam = 1e-3, 2500.0, 1e-6, 0.8
kn, ks, sigma_t, tau_s, dt = 2e16, 1e16, 2e6, 1.5e6, 1e-6
R = lam * r
A, I, J = math.pi * R**2, math.pi * R**4 / 4, math.pi * R**4 / 2
m = rho * 4.0 / 3.0 * math.pi * r**3
Isphere = 0.4 * m * r * r
EPS = 1e-10
F_t, F_s = 3.0, 2.0  # the contact bond's strengths, N
CONTACT = ["-dem_bond_model", "contact", "-dem_bond_tensile_strength", "%.17g" % F_t, "-dem_bond_shear_strength", "%.17g" % F_s]
SCENE = ["-physics", "dem", "-grid_upper", "0.01,0.01,0.01", "-grid_cells", "2,2,2", "-gravity", "0,0,0", "-dem_radius", "%.17g" % r,
         "-dem_density", "%.17g" % rho, "-dem_cohesion", "bond", "-dem_bond_radius_ratio", "%.17g" % lam, "-dem_bond_normal_stiffness", "%.17g" % kn,
         "-dem_bond_shear_stiffness", "%.17g" % ks, "-dem_bond_tensile_strength", "%.17g" % sigma_t, "-dem_bond_shear_strength", "%.17g" % tau_s,
         "-dem_bond_gap", "1e-5", "-dt", "%.17g" % dt, "-dt_force", "-max_steps", "1", "-final_time", "1", "-monitor_every", "1", "-monitor_timing", "0"]

# Each case: the load's break value from eqs 18-19, and how a fraction f of it is applied in one step (the relative
# velocity and spin of sphere 0 against sphere 1, split half and half; n points from sphere 1 to sphere 0, -z).
# measure: the load on sphere 0 read back from its change of velocity (force) or spin (torque); column: the monitor's.
CASES = {
    "tension": dict(load=sigma_t * A, unit="N", column="bond_sigma_per_strength",
                    motion=lambda f: dict(v=(0, 0, -f * sigma_t / kn / dt)), measure=lambda dv, dw: 2 * m * dv[2] / dt),
    "shear": dict(load=tau_s * A, unit="N", column="bond_tau_per_strength",
                  motion=lambda f: dict(v=(f * tau_s / ks / dt, 0, 0)), measure=lambda dv, dw: -2 * m * dv[0] / dt),
    "bending": dict(load=sigma_t * I / R, unit="N m", column="bond_sigma_per_strength",
                    motion=lambda f: dict(w=(0, f * sigma_t / (kn * R) / dt, 0)), measure=lambda dv, dw: -2 * Isphere * dw[1] / dt),
    "twist": dict(load=tau_s * J / R, unit="N m", column="bond_tau_per_strength",
                  motion=lambda f: dict(w=(0, 0, f * tau_s / (ks * R) / dt)), measure=lambda dv, dw: -2 * Isphere * dw[2] / dt),
    # Half the tensile strength from the pull, half from the bending: sigma = k_n s + k_n R theta.
    "tension+bending": dict(load=sigma_t, unit="Pa", column="bond_sigma_per_strength",
                            motion=lambda f: dict(v=(0, 0, -0.5 * f * sigma_t / kn / dt), w=(0, 0.5 * f * sigma_t / (kn * R) / dt, 0)),
                            measure=lambda dv, dw: 2 * m * dv[2] / dt / A - 2 * Isphere * dw[1] / dt * R / I),
    # The contact bond (-dem_bond_model contact): the same springs, no moments, strengths as forces (N).
    "contact tension": dict(load=F_t, unit="N", column="bond_sigma_per_strength", args=CONTACT,
                            motion=lambda f: dict(v=(0, 0, -f * F_t / (kn * A) / dt)), measure=lambda dv, dw: 2 * m * dv[2] / dt),
    "contact shear": dict(load=F_s, unit="N", column="bond_tau_per_strength", args=CONTACT,
                          motion=lambda f: dict(v=(f * F_s / (ks * A) / dt, 0, 0)), measure=lambda dv, dw: -2 * m * dv[0] / dt),
}


def run(exe, ranks, tmp, name, f):
    """One step of the bonded pair at fraction f of the case's break load: monitor row, sphere 0 before and after."""
    motion = CASES[name]["motion"](f)
    v, w = motion.get("v", (0, 0, 0)), motion.get("w", (0, 0, 0))
    z0, z1 = 0.005 - r - gap / 2, 0.005 + r + gap / 2
    rows = [(0.005, 0.005, z0) + tuple(0.5 * c for c in v) + tuple(0.5 * c for c in w),
            (0.005, 0.005, z1) + tuple(-0.5 * c for c in v) + tuple(-0.5 * c for c in w)]
    out = os.path.join(tmp, "%s-%s-%d" % (name.replace("+", "_").replace(" ", "_"), "below" if f < 1 else "above" if f < 2 else "far", ranks))
    os.makedirs(out)
    path = os.path.join(out, "pair.csv")
    with open(path, "w") as fh:
        fh.write("x,y,z,vx,vy,vz,wx,wy,wz\n")
        for row in rows:
            fh.write(",".join("%.17g" % c for c in row) + "\n")
    args = SCENE + CASES[name].get("args", []) + ["-dem_particles_file", path, "-dem_save_particles", os.path.join(out, "after.csv"), "-output_dir", out]
    if ranks == 2:
        args += ["-grid_ranks", "1,1,2"]
    run_vofdem(exe, ranks, args)
    with open(os.path.join(out, "monitor.csv")) as fh:
        head, *table = [line.strip().split(",") for line in fh if line.strip()]
    last = dict(zip(head, table[-1])) if table else {}
    after = read_particles(os.path.join(out, "after.csv"))
    if not after or not last:
        return None, None, None
    a = after[0]
    dv = [a["vx"] - rows[0][3], a["vy"] - rows[0][4], a["vz"] - rows[0][5]]
    dw = [a["wx"] - rows[0][6], a["wy"] - rows[0][7], a["wz"] - rows[0][8]]
    return last, dv, dw


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-bond-break-")
    print("bond radius R = %.6g m, A = %.6e m^2, I = %.6e m^4, J = %.6e m^4" % (R, A, I, J))
    try:
        for ranks in (1, 2):
            for name, case in [(k, c) for k, c in CASES.items() if k != "contact bending"]:
                last, dv, dw = run(exe, ranks, tmp, name, 1 - EPS)
                if last is None:
                    check(False, "%s on %d rank(s): the run wrote its monitor and particles" % (name, ranks))
                    continue
                load = case["measure"](dv, dw)
                rel = load / case["load"] - (1 - EPS)
                ratio = float(last[case["column"]]) - (1 - EPS)
                check(int(last["bonds_intact"]) == 1 and int(last["bonds_broken"]) == 0,
                      "%s, %d rank(s), at (1 - 1e-10) of the break load: the bond holds (intact %s, broken %s)" % (name, ranks, last["bonds_intact"], last["bonds_broken"]))
                check(abs(rel) < 1e-12, "%s, %d rank(s): it carries %.15e %s, break load %.15e %s (%s) times (1 - 1e-10) to %.1e (tolerance 1e-12)"
                      % (name, ranks, load, case["unit"], case["load"], case["unit"], "the strength" if "args" in case else "eqs 18-19", abs(rel)))
                check(abs(ratio) < 1e-12, "%s, %d rank(s): the monitor's %s is %s, 1 - 1e-10 to %.1e" % (name, ranks, case["column"], last[case["column"]], abs(ratio)))
                last, dv, dw = run(exe, ranks, tmp, name, 1 + EPS)
                if last is None:
                    check(False, "%s on %d rank(s): the run wrote its monitor and particles" % (name, ranks))
                    continue
                check(int(last["bonds_intact"]) == 0 and int(last["bonds_broken"]) == 1 and max(abs(c) for c in dv + dw) == 0,
                      "%s, %d rank(s), at (1 + 1e-10) of it: the bond breaks (intact %s, broken %s) and gives no force (|dv|, |dw| <= %.1e)"
                      % (name, ranks, last["bonds_intact"], last["bonds_broken"], max(abs(c) for c in dv + dw)))
            # A contact bond has no moments: turned 10 times past the parallel bond's break rotation it holds and
            # gives no torque (the check that the contact bond is not the parallel one).
            CASES["contact bending"] = dict(CASES["bending"], args=CONTACT)
            last, dv, dw = run(exe, ranks, tmp, "contact bending", 10)
            if last is not None:
                check(int(last["bonds_intact"]) == 1 and max(abs(c) for c in dw) == 0,
                      "contact bending, %d rank(s), 10 times the parallel bond's break rotation: the contact bond holds (intact %s) with no torque (|dw| %.1e)"
                      % (ranks, last["bonds_intact"], max(abs(c) for c in dw)))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
