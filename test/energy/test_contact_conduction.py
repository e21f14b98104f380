#!/usr/bin/python3
"""Contact conduction (docs/physics.md P11's contact term, Q_ij = 4 k_i k_j/(k_i + k_j) sqrt(pi a^2) (T_j - T_i)): two
IN718 spheres (d 96 um, k 29 W/(m K), cp 650 J/(kg K)) of two types, one at 700 K and one at 300 K, touching, in argon
whose conductivity is 1e-15 W/(m K) and with radiation off (their exchange with the gas is 1e-14 of the contact's), -physics
dem,flow,vof,energy, 12^3 cells of 125 um:
  jkr:   no gravity, -dem_cohesion jkr with w = 2 gamma = 1 J/m^2, E 2e9 Pa: they pull together and rest at JKR's zero-load
         contact radius a_0 = (9 pi w R*^2 / (2 E*))^(1/3) = 1.95 um; on 2 ranks (-grid_ranks 2,1,1) the contact lies on the
         rank boundary x = 0.75 mm, one sphere on each rank;
  hertz: under gravity, one sphere on the floor and one on top of it: Hertz's static overlap under the top sphere's
         weight, delta = (3 m g / (4 E* sqrt(R*)))^(2/3), a = sqrt(R* delta) = 0.85 um.
Checked:
  (a) the pair's temperature difference decays as exp(-2 G t / (m cp)) with G = 2 k sqrt(pi) a: the rate fitted from the
      monitor's T_max - T_min after the contact has settled (t >= 5 ms) within 1 % of the rate from a;
  (b) the heat one sphere gains the other loses: the particles' enthalpy stays at its start (less the 1e-16 J the gas
      takes, particle_heat_exchanged_J) to 1e-12 of the heat conducted, and the energy account closes (|energy_total_J - energy_accounted_J| within 1e-12 of it);
  (c) the monitor counts one conducting pair once the contact has settled, and its power equals the enthalpy change of the hot sphere per step;
  (d) 1 and 2 ranks agree to 1e-10 (the pair across the rank boundary is evaluated by both ranks from the same numbers);
  (e) with -coupling_heat_contact_conduction 0 the difference stays (to 1e-9): the decay is the contacts'.
  test_contact_conduction.py VOFDEM"""
import math
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, monitor_rows as rows, run_vofdem  # noqa: E402

R, RHO, CP, K = 48e-6, 8380.0, 650.0, 29.0  # in718.yaml
E, NU, W = 2e9, 0.28, 1.0
ESTAR = E / (2 * (1 - NU * NU))
RSTAR = R / 2
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
G_EARTH = 9.81
T_HOT, T_COLD = 700.0, 300.0
DT = 1e-3
C = 0.75e-3  # the box's centre


def contact_radius(case):
    if case == "jkr":
        return (9 * math.pi * W * RSTAR ** 2 / (2 * ESTAR)) ** (1.0 / 3.0)
    delta = (3 * MASS * G_EARTH / (4 * ESTAR * math.sqrt(RSTAR))) ** (2.0 / 3.0)
    return math.sqrt(RSTAR * delta)


def particles(path, case):
    """The hot sphere is type 0, the cold one type 1; both at rest."""
    if case == "jkr":  # touching across x = 0.75 mm
        rows = [(C - R, C, C, 0), (C + R, C, C, 1)]
    else:  # on the floor, and on top of it
        rows = [(C, C, R, 0), (C, C, 3 * R, 1)]
    with open(path, "w") as f:
        f.write("x,y,z,radius,vx,vy,vz,type\n")
        for x, y, z, t in rows:
            f.write("%.10g,%.10g,%.10g,%.10g,0,0,0,%d\n" % (x, y, z, R, t))


def arguments(out, case, t_end):
    csvfile = os.path.join(out + "-particles.csv")
    particles(csvfile, case)
    args = ["-physics", "dem,flow,vof,energy", "-grid_upper", "1.5e-3,1.5e-3,1.5e-3", "-grid_cells", "12,12,12",
            "-gravity", "0,0,0" if case == "jkr" else "0,0,-%g" % G_EARTH,
            "-flow_density", "1.6", "-flow_viscosity", "2.1e-5", "-vof_density", "%g" % RHO, "-vof_viscosity", "6e-3",
            "-energy_metal", "in718", "-energy_gas_conductivity", "1e-15", "-energy_gas_specific_heat", "2e8",
            "-energy_initial_temperature", "500", "-energy_reference_temperature", "500", "-energy_interface_radiation", "0",
            "-coupling_heat_radiation", "0", "-coupling_heat_material", "in718",
            "-dem_types", "hot,cold", "-coupling_heat_type_hot_initial_temperature", "%g" % T_HOT,
            "-coupling_heat_type_cold_initial_temperature", "%g" % T_COLD,
            "-dem_radius", "%g" % R, "-dem_density", "%g" % RHO, "-dem_youngs_modulus", "%g" % E, "-dem_poisson_ratio", "%g" % NU,
            "-dem_restitution", "0.3"]
    for t in ("hot", "cold"):
        args += ["-dem_type_%s_density" % t, "%g" % RHO, "-dem_type_%s_youngs_modulus" % t, "%g" % E, "-dem_type_%s_poisson_ratio" % t, "%g" % NU,
                 "-dem_type_%s_restitution" % t, "0.3"]
    if case == "jkr":
        args += ["-dem_cohesion", "jkr", "-dem_surface_energy", "%g" % (W / 2)]
        for t in ("hot", "cold"):
            args += ["-dem_type_%s_surface_energy" % t, "%g" % (W / 2)]
    args += ["-dem_particles_file", csvfile, "-dem_output_every", "0", "-flow_output_every", "0",
             "-dt", "%g" % DT, "-final_time", "%g" % t_end, "-max_steps", "100000", "-monitor_every", "1", "-monitor_timing", "0", "-output_dir", out]
    return args


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-contact-conduction-")
    try:
        for case, t_end, rank_counts in (("jkr", 0.04, (1, 2)), ("hertz", 0.06, (1,))):
            a = contact_radius(case)
            G = 2 * K * math.sqrt(math.pi) * a  # 4 k k/(k + k) sqrt(pi a^2)
            rate = 2 * G / (MASS * CP)
            runs = {}
            for ranks in rank_counts:
                out = os.path.join(tmp, "%s-%d" % (case, ranks))
                run_vofdem(exe, ranks, arguments(out, case, t_end) + (["-grid_ranks", "2,1,1"] if ranks == 2 else []))
                r = rows(out)
                runs[ranks] = r
                label = "%s, %d rank(s)" % (case, ranks)
                check(abs(r[-1]["time_s"] - t_end) < 1e-9 and abs(r[0]["particle_temperature_max_K"] - T_HOT) < 1e-9 and abs(r[0]["particle_temperature_min_K"] - T_COLD) < 1e-9,
                      "%s: ran to t = %g s from %g K and %g K" % (label, r[-1]["time_s"], r[0]["particle_temperature_max_K"], r[0]["particle_temperature_min_K"]))
                late = [x for x in r if x["time_s"] >= 5e-3 - 1e-12]
                ts = [x["time_s"] for x in late]
                ys = [math.log(x["particle_temperature_max_K"] - x["particle_temperature_min_K"]) for x in late]
                tm, ym = sum(ts) / len(ts), sum(ys) / len(ys)
                fitted = -sum((t - tm) * (y - ym) for t, y in zip(ts, ys)) / sum((t - tm) ** 2 for t in ts)
                check(abs(fitted / rate - 1) <= 0.01, "%s: the difference decays at %.4f 1/s against 2 G/(m cp) = %.4f 1/s from a = %.4e m (error %.2e, tolerance 1e-2; %g K left of %g K)"
                      % (label, fitted, rate, a, abs(fitted / rate - 1), r[-1]["particle_temperature_max_K"] - r[-1]["particle_temperature_min_K"], T_HOT - T_COLD))
                conducted = MASS * CP * (T_HOT - r[-1]["particle_temperature_max_K"])
                # what the gas takes (particle_heat_exchanged_J, 1e-16 J) is not the contacts'
                drift = max(abs(x["particle_enthalpy_J"] - r[0]["particle_enthalpy_J"] + x["particle_heat_exchanged_J"]) for x in r) / conducted
                account = max(abs(x["energy_total_J"] - x["energy_accounted_J"]) for x in r) / conducted
                check(drift <= 1e-12 and account <= 1e-12, "%s: the particles' enthalpy less the gas's share stays to %.2e of the %.4e J conducted, the account closes to %.2e (tolerance 1e-12)"
                      % (label, drift, conducted, account))
                pairs = set(int(x["particle_conducting_pairs"]) for x in late)  # the top sphere lands in the first steps
                power = max(abs(x["particle_conduction_W"] * DT - MASS * CP * (p["particle_temperature_max_K"] - x["particle_temperature_max_K"])) for p, x in zip(r, r[1:])) / (MASS * CP * (T_HOT - T_COLD) * rate * DT)
                check(pairs == {1} and power <= 1e-6, "%s: the monitor counts %s conducting pair(s); its power is the hot sphere's loss per step to %.2e of the first step's (tolerance 1e-6)"
                      % (label, sorted(pairs), power))
            if 2 in runs:
                p, q = runs[1], runs[2]
                diff = max(max(abs(x["particle_temperature_max_K"] / y["particle_temperature_max_K"] - 1), abs(x["particle_temperature_min_K"] / y["particle_temperature_min_K"] - 1)) for x, y in zip(p, q))
                check(len(p) == len(q) and diff <= 1e-10, "%s: 1 and 2 ranks agree: both temperatures to %.2e (tolerance 1e-10)" % (case, diff))
        out = os.path.join(tmp, "off")
        run_vofdem(exe, 1, arguments(out, "jkr", 0.01) + ["-coupling_heat_contact_conduction", "0"])
        r = rows(out)
        kept = (r[-1]["particle_temperature_max_K"] - r[-1]["particle_temperature_min_K"]) / (T_HOT - T_COLD)
        check(abs(kept - 1) <= 1e-9 and int(r[-1]["particle_conducting_pairs"]) == 0, "off: -coupling_heat_contact_conduction 0 keeps %.12f of the difference (tolerance 1e-9)" % kept)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
