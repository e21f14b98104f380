#!/usr/bin/python3
"""Particle heat (docs/physics.md P11, F9, F10; docs/verification.md E6 part 1): one IN718 particle (d 96 um, seed 000)
at rest in still, hot argon, -physics dem,flow,vof,energy (no metal in the box), 12^3 cells of 125 um, the particle 10 um
off the box's centre in x (on 2 ranks, split in x, its kernel straddles the rank boundary at x = 0.75 mm). The gas's specific heat is
raised to 2e8 J/(kg K) so that the gas is a reservoir (its capacity within the kernel about 1e4 times the particle's);
in still fluid Re = 0 and Nu = 2 whatever Pr (F10). Checked at every monitor row:
  (a) the particle's temperature against the ODE with the same laws, m dh/dt = pi d^2 [2 k_g/d (T_g - T) + e sigma
      (T_g^4 - T^4)], h(T) = cp (T - T_ref) + f_l(T) L (RK4, 200 sub-steps per step), within 1 % of the rise T_g - T0:
      (i) 573 K in gas at 1400 K (sensible heat only), (ii) 1400 K in gas at 1800 K through the melting range
      (solidus 1533 K, liquidus 1609 K, L 2.1e5 J/kg: the plateau of latent heat), (iii) a 5 um particle, whose time
      constant is a third of the 2 ms step (the step is stable and does not overshoot the gas);
  (b) the kernel's deposit: the cells receive what the particles give, per step, to 1e-12 (F9, K3);
  (c) the particles' loss is the fluid's gain: the change of the fluid's energy (energy_total_J minus the particles'
      enthalpy) against the change of the particles' enthalpy, to 1e-12 of the heat exchanged;
  (d) the energy account with the particles: |energy_total_J - energy_accounted_J| within 1e-10 of the heat exchanged;
  (e) 1 and 2 ranks: the particle's temperature and the fluid's energy agree to 1e-10 (relative);
  (f) the particle's temperature in the ParaView output (particles.xmf) is the monitor's;
  (g) particles that move (20 IN718 spheres at 573 K falling 20 steps through argon at 1400 K above a plate, the scene of
      checkpoint/bitwise_coupled_heat): the cells count the fluid's share eps of their volume and move it with d(eps)/dt,
      so |energy_total_J - energy_accounted_J| stays within 1e-10 of the heat exchanged on 1 and 2 ranks, and the two
      agree to 1e-10 (cells counting their whole volume left 1.2e-3 J of 0.07 J exchanged: the gas's div u = -d(eps)/dt/eps
      moved energy through the dilatation term); -energy_tolerance 1e-10 so that the ranks compare at round-off (at the
      default 1e-6 the iteration stops where the solve's decomposition leaves T_p 8e-10 apart);
  (h) particles landing on solid metal (the same scene run on to 90 steps with the plate's top as a DEM wall): the
      deposits leave the cells held at rest out (-coupling_heat_exclude_held), so the 20 spheres come to rest on the
      plate (lowest centre within 1e-3 r of r above it), the held plate's eps stays exactly 1 while the layer above
      takes their volume, the projected volume is theirs to 1e-12, the energy account closes within 1e-10 of the heat
      exchanged, and 1 and 2 ranks agree to 1e-10; without the wall a sphere passing into the plate is stopped with one
      line (falling on, above);
a wrong sign or factor of the exchange fails (a) or (c).
  test_particle_heat.py VOFDEM"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

SIGMA = 5.670374419e-8
D, RHO, CP, EMISSIVITY = 96e-6, 8380.0, 650.0, 0.4           # in718.yaml
TS, TL, L = 1533.0, 1609.0, 2.1e5
K_GAS = 0.018                                                # argon.yaml
CP_GAS = 2e8
DT, T_END = 2e-3, 0.3
CENTRE = (0.74e-3, 0.75e-3, 0.75e-3)


def arguments(out, t_gas, t0, d=D, t_end=T_END, every=5):
    r = d / 2
    lo = ",".join("%.10g" % (c - r - 1e-9) for c in CENTRE)
    hi = ",".join("%.10g" % (c + r + 1e-9) for c in CENTRE)
    return ["-physics", "dem,flow,vof,energy", "-grid_upper", "1.5e-3,1.5e-3,1.5e-3", "-grid_cells", "12,12,12", "-gravity", "0,0,0",
            "-flow_density", "1.6", "-flow_viscosity", "2.1e-5", "-vof_density", "%g" % RHO, "-vof_viscosity", "6e-3",
            "-energy_gas_specific_heat", "%g" % CP_GAS, "-energy_initial_temperature", "%g" % t_gas, "-energy_reference_temperature", "%g" % t_gas,
            "-energy_interface_radiation", "0",
            "-dem_radius", "%g" % r, "-dem_density", "%g" % RHO, "-dem_youngs_modulus", "1e4", "-dem_fill_count", "1",
            "-dem_fill_lower", lo, "-dem_fill_upper", hi, "-coupling_heat_initial_temperature", "%g" % t0,
            "-dt", "%g" % DT, "-final_time", "%g" % t_end, "-max_steps", "100000", "-monitor_every", "%d" % every, "-monitor_timing", "0", "-output_dir", out]


def rows(out):
    with open(os.path.join(out, "monitor.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def enthalpy(T, tref):
    f = min(1.0, max(0.0, (T - TS) / (TL - TS)))
    return CP * (T - tref) + f * L


def temperature(h, tref):
    """The inverse of enthalpy(): piecewise linear in T."""
    hs, hl = enthalpy(TS, tref), enthalpy(TL, tref)
    if h <= hs:
        return tref + h / CP
    if h >= hl:
        return TL + (h - hl) / CP
    return TS + (h - hs) / (hl - hs) * (TL - TS)


def ode(t_gas, t0, times, D=D):
    """T(t) of m dh/dt = A [h_c (T_g - T) + e sigma (T_g^4 - T^4)] by RK4 on h (200 sub-steps per step)."""
    m, A, hc = RHO * math.pi * D ** 3 / 6, math.pi * D * D, 2 * K_GAS / D
    rate = lambda h: A * (hc * (t_gas - temperature(h, t_gas)) + EMISSIVITY * SIGMA * (t_gas ** 4 - temperature(h, t_gas) ** 4)) / m
    h, t, out, dt = enthalpy(t0, t_gas), 0.0, [], DT / 200
    for want in times:
        while t < want - 1e-12:
            k1 = rate(h)
            k2 = rate(h + 0.5 * dt * k1)
            k3 = rate(h + 0.5 * dt * k2)
            k4 = rate(h + dt * k3)
            h += dt * (k1 + 2 * k2 + 2 * k3 + k4) / 6
            t += dt
        out.append(temperature(h, t_gas))
    return out


FALLING = ("-physics dem,flow,vof,energy -grid_cells 8,8,12 -grid_upper 0.008,0.008,0.012 -gravity 0,0,-9.81 -flow_density 1.6 "
           "-flow_viscosity 2.1e-5 -flow_pressure_pc boomeramg -flow_pressure_ksp_rtol 1e-12 -vof_density 8380 -vof_viscosity 6e-3 "
           "-vof_boxes 0,0,0,0.008,0.008,0.002 -energy_initial_temperature 1400 -energy_interface_radiation 0 -energy_pc boomeramg "
           "-coupling_heat_initial_temperature 573 -dem_radius 5e-4 -dem_density 8380 -dem_fill_count 20 -dem_fill_lower 0,0,0.0075 "
           "-dem_fill_upper 0.008,0.008,0.012 -dem_fill_jitter 0.5 -coupling_fluid_drag implicit -dt 1e-3 -dt_force -seed 7 -max_steps 20 "
           "-monitor_every 2 -monitor_timing 0 -energy_tolerance 1e-10").split()


def falling(exe, tmp):
    """(g): moving particles, eps in the cells' energy."""
    runs = {}
    for ranks in (1, 2):
        out = os.path.join(tmp, "falling-%d" % ranks)
        run_vofdem(exe, ranks, FALLING + ["-output_dir", out])
        r = rows(out)
        runs[ranks] = r
        label = "falling, %d rank(s)" % ranks
        exchanged = r[-1]["particle_enthalpy_J"] - r[0]["particle_enthalpy_J"]
        check(r[-1]["step"] == 20 and r[-1]["kinetic_energy_J"] > 1e-6 and exchanged > 0.05,
              "%s: 20 steps, the spheres fall (KE %.3e J) and take %.4e J" % (label, r[-1]["kinetic_energy_J"], exchanged))
        worst = max(abs(x["energy_total_J"] - x["energy_accounted_J"]) for x in r) / exchanged
        check(worst <= 1e-10, "%s: |energy_total_J - energy_accounted_J| at most %.2e of the heat exchanged (tolerance 1e-10)" % (label, worst))
    # Run on, the spheres' kernels reach the solid plate, which the flow holds at rest: the run stops with one line
    # naming a particle, a non-zero exit and no trace, before the divergence it cannot remove grows (it reached 20 1/s
    # and the plate 2e4 K when nothing stopped it).
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    args = FALLING[:FALLING.index("-max_steps")] + ["-max_steps", "40"] + FALLING[FALLING.index("-max_steps") + 2:]
    p = subprocess.run(["mpiexec", "-n", "2", "--oversubscribe", exe] + args + ["-output_dir", os.path.join(tmp, "falling-on")], capture_output=True, text=True, env=env, timeout=120)
    out = p.stdout + p.stderr
    errors = [l for l in out.splitlines() if l.startswith("vofdem: error")]
    ok = p.returncode != 0 and len(errors) == 1 and re.search(r"coupling: particle \d+ at .* (moves its volume into|has passed into) solid metal", errors[0]) and "PETSC ERROR" not in out
    check(bool(ok), "falling on: the kernels reach the held plate: exit %d, %s" % (p.returncode, errors[0] if errors else "no error line"))
    a, b = runs[1], runs[2]
    dE = max(abs(x["energy_total_J"] - y["energy_total_J"]) for x, y in zip(a, b)) / (a[-1]["particle_enthalpy_J"] - a[0]["particle_enthalpy_J"])
    dT = max(abs(x["particle_temperature_max_K"] / y["particle_temperature_max_K"] - 1) for x, y in zip(a, b))
    check(len(a) == len(b) and dE <= 1e-10 and dT <= 1e-10, "falling: 1 and 2 ranks agree: the energy to %.2e of the heat exchanged, T_p to %.2e (tolerance 1e-10)" % (dE, dT))


def landing(exe, tmp):
    """(h): particles resting on the held plate."""
    runs = {}
    args = FALLING[:FALLING.index("-max_steps")] + ["-max_steps", "90"] + FALLING[FALLING.index("-max_steps") + 2:] + ["-monitor_every", "10", "-flow_output_every", "90"]
    args += ["-dem_walls", "plate", "-dem_wall_plate_type", "plane", "-dem_wall_plate_point", "0,0,0.002", "-dem_wall_plate_normal", "0,0,1"]
    for ranks in (1, 2):
        out = os.path.join(tmp, "landing-%d" % ranks)
        run_vofdem(exe, ranks, args + ["-output_dir", out, "-dem_save_particles", os.path.join(out, "end.csv")])
        r = rows(out)
        runs[ranks] = r
        label = "landing, %d rank(s)" % ranks
        with open(os.path.join(out, "end.csv")) as f:
            ps = [{k: float(v) for k, v in x.items()} for x in csv.DictReader(f)]
        low = min(p["z"] for p in ps) if ps else 0.0
        check(len(ps) == 20 and abs(low - 0.0025) <= 1e-3 * 5e-4 and r[-1]["step"] == 90,
              "%s: 90 steps, %d spheres, the lowest centre %.7f m (on the plate: 0.0025 m)" % (label, len(ps), low))
        with h5py.File(os.path.join(out, "flow_00000090.h5")) as f:
            eps = np.array(f["flow_fluid_fraction"])  # z, y, x
        check(np.all(eps[:2] == 1.0) and eps[2].min() < 0.95, "%s: the held plate's eps is exactly 1 (min %.17g), the layer above takes the spheres' volume (min eps %.4f)"
              % (label, eps[:2].min(), eps[2].min()))
        verr = max(x["coupling_volume_error"] for x in r)
        exchanged = r[-1]["particle_enthalpy_J"] - r[0]["particle_enthalpy_J"]
        worst = max(abs(x["energy_total_J"] - x["energy_accounted_J"]) for x in r) / exchanged
        check(verr <= 1e-12 and worst <= 1e-10, "%s: projected volume to %.1e of the spheres' (tolerance 1e-12), the energy account to %.2e of the %.4e J exchanged (tolerance 1e-10)"
              % (label, verr, worst, exchanged))
    a, b = runs[1], runs[2]
    dE = max(abs(x["energy_total_J"] - y["energy_total_J"]) for x, y in zip(a, b)) / (a[-1]["particle_enthalpy_J"] - a[0]["particle_enthalpy_J"])
    dT = max(abs(x["particle_temperature_max_K"] / y["particle_temperature_max_K"] - 1) for x, y in zip(a, b))
    check(len(a) == len(b) and dE <= 1e-10 and dT <= 1e-10, "landing: 1 and 2 ranks agree: the energy to %.2e of the heat exchanged, T_p to %.2e (tolerance 1e-10)" % (dE, dT))


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-particle-heat-")
    try:
        falling(exe, tmp)
        landing(exe, tmp)
        # (name, gas and initial temperature, ranks, diameter, end time, monitor rows every so many steps)
        for name, t_gas, t0, rank_counts, d, t_end, every in (("sensible", 1400.0, 573.0, (1, 2), D, T_END, 5), ("melting", 1800.0, 1400.0, (1,), D, T_END, 5),
                                                              ("small", 1400.0, 573.0, (1,), 5e-6, 0.02, 1)):
            runs = {}
            for ranks in rank_counts:
                out = os.path.join(tmp, "%s-%d" % (name, ranks))
                extra = (["-grid_ranks", "2,1,1"] if ranks == 2 else []) + (["-dem_output_every", "75"] if name == "sensible" else [])
                extra += ["-coupling_heat_melt", "0"] if name == "melting" else []  # a particle through its melting range (P12 would take it at the liquidus)
                run_vofdem(exe, ranks, arguments(out, t_gas, t0, d, t_end, every) + extra)
                r = rows(out)
                runs[ranks] = r
                label = "%s, %d rank(s)" % (name, ranks)
                check(abs(r[-1]["time_s"] - t_end) < 1e-9, "%s: ran to t = %g s" % (label, r[-1]["time_s"]))
                ref = ode(t_gas, t0, [x["time_s"] for x in r], d)
                err = max(abs(x["particle_temperature_max_K"] - w) for x, w in zip(r, ref)) / (t_gas - t0)
                k = max(range(len(r)), key=lambda i: abs(r[i]["particle_temperature_max_K"] - ref[i]))
                check(err <= 0.01, "%s: T_p against the ODE: largest error %.3e of the rise %g K (tolerance 1e-2; at t = %.3f s %.4f K against %.4f K; at the end %.4f K)"
                      % (label, err, t_gas - t0, r[k]["time_s"], r[k]["particle_temperature_max_K"], ref[k], r[-1]["particle_temperature_max_K"]))
                if name == "sensible":  # ParaView: the particle's temperature in particles.xmf
                    xmf = open(os.path.join(out, "particles.xmf")).read()
                    last = sorted(f for f in os.listdir(out) if f.startswith("particles_") and f.endswith(".h5"))[-1]  # the last fluid step's
                    with h5py.File(os.path.join(out, last)) as f:
                        tp = float(np.array(f["temperature"]).ravel()[0])
                    check('Name="temperature"' in xmf and abs(tp - r[-1]["particle_temperature_max_K"]) <= 1e-12 * tp,
                          "%s: particles.xmf names the temperature; %s holds %.12g K (the monitor's %.12g K)" % (label, last, tp, r[-1]["particle_temperature_max_K"]))
                if name == "small":  # its time constant is a third of the step: explicit Euler would oscillate and grow
                    tau = RHO * CP * d * d / (6 * 2 * K_GAS)
                    over = max(x["particle_temperature_max_K"] for x in r) - t_gas
                    check(DT > 3 * tau and over <= 1e-9 * t_gas, "%s: step %.1f time constants (conduction alone), no overshoot past the gas (by %.2e K)" % (label, DT / tau, over))
                if name == "melting":
                    melted = [x for x in r if TS < x["particle_temperature_max_K"] < TL]
                    check(len(melted) >= 3, "%s: %d monitor rows inside the melting range (the latent heat's plateau)" % (label, len(melted)))
                dep = max(abs(x["particle_heat_deposited_W"] - x["particle_heat_to_fluid_W"]) / max(abs(x["particle_heat_to_fluid_W"]), 1e-300) for x in r[1:])
                check(dep <= 1e-12, "%s: the cells receive what the particle gives, per step: largest relative difference %.2e (tolerance 1e-12)" % (label, dep))
                worst_gain = worst_account = 0.0
                fluid0, part0 = r[0]["energy_total_J"] - r[0]["particle_enthalpy_J"], r[0]["particle_enthalpy_J"]
                for x in r[1:]:
                    lost = part0 - x["particle_enthalpy_J"]  # < 0: the particle gains
                    gained = x["energy_total_J"] - x["particle_enthalpy_J"] - fluid0
                    worst_gain = max(worst_gain, abs(gained - lost) / abs(lost))
                    worst_account = max(worst_account, abs(x["energy_total_J"] - x["energy_accounted_J"]) / abs(lost))
                check(r[1]["particle_heat_to_fluid_W"] < 0 and part0 < r[-1]["particle_enthalpy_J"], "%s: the particle takes heat (%.4e W in the first row's step; enthalpy %.6e -> %.6e J)"
                      % (label, r[1]["particle_heat_to_fluid_W"], part0, r[-1]["particle_enthalpy_J"]))
                check(worst_gain <= 1e-12, "%s: the fluid's gain against the particle's loss: largest relative difference %.2e (tolerance 1e-12; %.6e J exchanged)"
                      % (label, worst_gain, part0 - r[-1]["particle_enthalpy_J"]))
                check(worst_account <= 1e-10, "%s: |energy_total_J - energy_accounted_J| at most %.2e of the heat exchanged (tolerance 1e-10)" % (label, worst_account))
            if 2 in runs:
                a, b = runs[1], runs[2]
                dT = max(abs(x["particle_temperature_max_K"] / y["particle_temperature_max_K"] - 1) for x, y in zip(a, b))
                dE = max(abs((x["energy_total_J"] - x["particle_enthalpy_J"]) - (y["energy_total_J"] - y["particle_enthalpy_J"])) / abs(x["particle_enthalpy_J"] - a[0]["particle_enthalpy_J"])
                         for x, y in zip(a[1:], b[1:]))
                check(len(a) == len(b) and dT <= 1e-10 and dE <= 1e-10, "%s: 1 and 2 ranks agree: T_p to %.2e, the fluid's energy to %.2e of the heat exchanged (tolerance 1e-10)"
                      % (name, dT, dE))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
