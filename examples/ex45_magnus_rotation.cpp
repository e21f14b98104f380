static const char help[] = "Rotation and lubrication in the CFD-DEM coupling (-physics dem,flow; docs/physics.md P1 f_Magnus, P8, F5; RotationLaws.hpp).\n"
                           "Fluid 1000 kg/m^3, 0.01 Pa s, at rest in a closed box of 1 mm cells; spheres d = 1 mm; no gravity.\n"
                           "(a) Magnus lift: a heavy sphere (1e7 kg/m^3, so that it keeps its speed) moves along +x at 0.05 m/s spinning at\n"
                           "    20 rad/s about +z (Re_p 5, Re_r 2) for 0.2 s, once with -coupling_lift rubinowkeller and once with oesterle\n"
                           "    (-coupling_pressure_force 0, -coupling_added_mass 0). The lift measured from its motion over the second\n"
                           "    0.1 s (the fluid's disturbance formed: H/V = 0.03 s), (m dv_y - drag impulse_y)/T, against the law evaluated\n"
                           "    with the exact rotation (omega: the fluid is at rest) and the exact slip (the sphere's mean velocity): within\n"
                           "    2 %%, the error of the kernel's estimate of the undisturbed slip (K1b: C1, ex33, holds the drag law's settling\n"
                           "    velocity to 2 %%; here the sphere is 5 d from the side walls); its direction +y = Omega x (v - u) (the z\n"
                           "    component below 1 %% of it); the lift the DEM applied equal to the measured one (round-off); the fluid's source\n"
                           "    equal to minus the particles' force, lift included, to 1e-12 at every step (C3, F5).\n"
                           "(b) Rotational drag: a sphere (2500 kg/m^3) at rest spinning at 100 rad/s in fluid of 0.001 Pa s with\n"
                           "    -coupling_rotational_drag (the fluid's reaction torque is neglected, so it stays at rest):\n"
                           "    omega decays as exp(-t/tau), tau = I/(pi mu d^3) = rho_p d^2/(60 mu); tau measured from omega(t) at 0.1 s\n"
                           "    within 1 %%. With -coupling_rotational_drag_correction the decay follows the ODE I domega/dt = -pi mu d^3\n"
                           "    (1 + 5/(64 pi) Re_r^0.6) omega (Re_r = rho d^2 omega/mu, 100 at the start), integrated here: within 1 %%.\n"
                           "(c) Lubrication from the fluid: two heavy spheres 0.09 mm apart approaching at 2 x 1 mm/s, across the boundary\n"
                           "    between the ranks on 2 ranks, with -coupling_lubrication (and -dem_lubrication_viscosity 0): the force on\n"
                           "    each, 6 pi mu R_eff^2 v_n/h with mu the flow's 0.01 Pa s and R_eff = R/2, within 1e-6 at the first five gaps\n"
                           "    (0.086 to 0.070 mm); again with -physics dem,flow,vof, the box full of the VOF's liquid of 0.01 Pa s and the\n"
                           "    flow's phase 0 a gas of 1.8e-5 Pa s: the mixture viscosity the particles read, the liquid's.\n"
                           "(d) The fluid rotation read: a linear shear u_x = 10 (y - y0) s^-1 (and u_y in z, u_z in x) set on the grid, a\n"
                           "    sphere at rest at its centre: after one step of 1e-4 s it reads curl(u)/2 = -5 rad/s along z (x, y) to 1e-5 (the kernel average of the grid's\n"
                           "    central differences of a linear field is exact; the sphere's eps bends the shear by 2e-6 in the step).\n"
                           "-parts abcd: the parts to run. Exits non-zero on failure.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/grid/StaggeredGrid.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

const PetscReal kD = 1e-3, kRhoF = 1000;
const PetscReal kLiftTol = 0.02, kDirectionTol = 0.01, kConserveTol = 1e-12, kTauTol = 0.01, kLubTol = 1e-6;
using vofdem::example::Verdict;

PetscErrorCode Set(const char *name, const char *value) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsSetValue(nullptr, name, value));
  PetscFunctionReturn(0);
}
PetscErrorCode SetReal(const char *name, PetscReal v) {
  char buf[64];
  PetscFunctionBeginUser;
  std::snprintf(buf, sizeof buf, "%.17g", (double)v);
  PetscCall(PetscOptionsSetValue(nullptr, name, buf));
  PetscFunctionReturn(0);
}

// The particles (x,y,z,vx,vy,vz,wx,wy,wz per row) through -dem_particles_file, written by rank 0.
PetscErrorCode Particles(const std::string &rows, const char *tag) {
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  const std::string path = std::string("ex45_") + tag + "_" + std::to_string(size) + ".csv";
  if (rank == 0) {
    std::ofstream f(path);
    f << "x,y,z,vx,vy,vz,wx,wy,wz\n" << rows;
  }
  PetscCallMPI(MPI_Barrier(PETSC_COMM_WORLD));
  PetscCall(Set("-dem_particles_file", path.c_str()));
  PetscFunctionReturn(0);
}

// The particles file is read by SetUp: remove it then.
PetscErrorCode SetUp(vofdem::Simulation &sim) {
  char        path[PETSC_MAX_PATH_LEN];
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-dem_particles_file", path, sizeof path, nullptr));
  PetscCallMPI(MPI_Barrier(PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (rank == 0) std::remove(path);
  PetscFunctionReturn(0);
}

// The scene common to the three parts: box of cells x 1 mm, fluid at rest, no gravity, spheres of 1 mm.
PetscErrorCode Scene(PetscInt nx, PetscInt ny, PetscInt nz, PetscReal rhoP, PetscReal mu, PetscReal dt) {
  char buf[128];
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsClear(nullptr));
  std::snprintf(buf, sizeof buf, "%d,%d,%d", (int)nx, (int)ny, (int)nz);
  PetscCall(Set("-grid_cells", buf));
  std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", (double)(nx * kD), (double)(ny * kD), (double)(nz * kD));
  PetscCall(Set("-grid_upper", buf));
  PetscCall(Set("-physics", "dem,flow"));
  PetscCall(Set("-gravity", "0,0,0"));
  PetscCall(SetReal("-dem_radius", kD / 2));
  PetscCall(SetReal("-dem_density", rhoP));
  PetscCall(SetReal("-flow_density", kRhoF));
  PetscCall(SetReal("-flow_viscosity", mu));
  PetscCall(Set("-coupling_drag", "schillernaumann"));
  PetscCall(Set("-coupling_added_mass", "0"));
  PetscCall(SetReal("-dt", dt));
  PetscCall(Set("-max_steps", "1000000"));
  PetscFunctionReturn(0);
}

// Sums over the local particles, over all ranks: the y and z drag impulse and explicit (lift) impulse of the last step.
PetscErrorCode StepImpulses(vofdem::Simulation &sim, PetscReal drag[3], PetscReal lift[3]) {
  vofdem::ParticleArrays a;
  PetscReal              loc[6] = {0, 0, 0, 0, 0, 0}, all[6];
  PetscFunctionBeginUser;
  PetscCall(Particles(sim)->Particles().GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p)
    for (int c = 0; c < 3; ++c) loc[c] += a.fluidImpulse[3 * p + c], loc[3 + c] += a.fluidExplicitImpulse[3 * p + c];
  PetscCall(Particles(sim)->Particles().RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(loc, all, 6, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  for (int c = 0; c < 3; ++c) drag[c] = all[c], lift[c] = all[3 + c];
  PetscFunctionReturn(0);
}

// (a) The Magnus lift on a heavy sphere moving through fluid at rest.
PetscErrorCode Lift(const char *law, PetscInt *failures) {
  const PetscReal V = 0.05, omega = 20, rhoP = 1e7, mu = 0.01, dt = 4e-3, T = 0.2;
  const PetscReal m = rhoP * PETSC_PI * kD * kD * kD / 6;
  char            row[256];
  PetscFunctionBeginUser;
  PetscCall(Scene(20, 12, 12, rhoP, mu, dt));
  PetscCall(Set("-coupling_pressure_force", "0"));  // the y impulse below is then the drag's and the lift's only
  std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,%.17g,0,0,0,0,%.17g\n", 5 * kD, 6 * kD, 6 * kD, (double)V, (double)omega);
  PetscCall(Particles(row, "lift"));
  PetscCall(Set("-coupling_lift", law));
  vofdem::Simulation sim;
  PetscCall(SetUp(sim));
  PetscReal x[3], v[3], w[3], vSum = 0, drag[3] = {0, 0, 0}, lift[3] = {0, 0, 0}, dragY = 0, dragZ = 0, applied[3] = {0, 0, 0}, worst = 0, t0 = 0, vy0 = 0, vz0 = 0;
  PetscBool found;
  PetscInt  steps = 0;
  while (sim.Time() < T * (1 - 1e-12)) {
    PetscCall(sim.Step());
    PetscCall(StepImpulses(sim, drag, lift));
    PetscCall(Particles(sim)->FindParticle(0, x, v, &found, w));
    if (sim.Time() <= T / 2 + 1e-12) {  // the second half only: the fluid's disturbance has formed (H/V = 0.03 s)
      t0 = sim.Time(), vy0 = v[1], vz0 = v[2];
      continue;
    }
    dragY += drag[1], dragZ += drag[2];
    for (int c = 0; c < 3; ++c) applied[c] += lift[c];
    vSum += v[0], ++steps;
    vofdem::CouplingSummary cs;
    PetscCall(Coupled(sim)->Summarize(&cs));
    const PetscReal f = std::sqrt(cs.dragSum[0] * cs.dragSum[0] + cs.dragSum[1] * cs.dragSum[1] + cs.dragSum[2] * cs.dragSum[2]);
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(cs.sourceSum[c] + cs.dragSum[c]) / f);
  }
  PetscCheck(found, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the sphere was lost");
  const PetscReal tEnd = sim.Time() - t0, vMean = vSum / steps;
  // Measured: the sphere's y and z momentum change less what the drag gave it.
  const PetscReal Ly = (m * (v[1] - vy0) - dragY) / tEnd, Lz = (m * (v[2] - vz0) - dragZ) / tEnd;
  const PetscReal Om[3] = {0, 0, omega}, slip[3] = {vMean, 0, 0};
  PetscReal       F[3];
  vofdem::rotation::Lift which;
  vofdem::rotation::ParseLift(law, &which);
  vofdem::rotation::LiftForce(which, kD, kRhoF, mu, Om, slip, F);
  const PetscReal err = Ly / F[1] - 1, side = std::fabs(Lz / Ly), appliedErr = std::fabs(applied[1] / tEnd - Ly) / std::fabs(Ly);
  const bool      ok = std::fabs(err) <= kLiftTol && Ly > 0 && side <= kDirectionTol && worst <= kConserveTol;
  *failures += !ok;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(a) lift %-13s Re_p %.3f Re_r %.3f: law %.5e N (+y), measured (%.5e, %.5e) N (y, z): error %+.2f %% (tolerance %g %%), |z/y| %.1e (%g); "
                                          "lift the DEM applied vs measured %.1e; fluid source + particle force %.1e (%g) %s\n",
                        law, (double)(kRhoF * kD * vMean / mu), (double)(kRhoF * kD * kD * omega / mu), (double)F[1], (double)Ly, (double)Lz, (double)(100 * err), (double)(100 * kLiftTol),
                        (double)side, (double)kDirectionTol, (double)appliedErr, (double)worst, (double)kConserveTol, Verdict(ok)));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

// (b) A sphere spinning in fluid at rest slows down by the rotational drag.
PetscErrorCode SpinDown(bool correction, PetscInt *failures) {
  const PetscReal rhoP = 2500, mu = 1e-3, omega0 = 100, dt = 1e-3, T = 0.1;
  const PetscReal I = rhoP * PETSC_PI * kD * kD * kD / 6 * kD * kD / 10, K = PETSC_PI * mu * kD * kD * kD, tau = I / K;
  char            row[256];
  PetscFunctionBeginUser;
  PetscCall(Scene(14, 8, 8, rhoP, mu, dt));  // on 2 ranks split in x at the sphere
  std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,0,0,0,0,0,%.17g\n", 7 * kD, 4 * kD, 4 * kD, (double)omega0);
  PetscCall(Particles(row, correction ? "spin_dennis" : "spin"));
  PetscCall(Set("-coupling_rotational_drag", "1"));
  if (correction) PetscCall(Set("-coupling_rotational_drag_correction", "1"));
  vofdem::Simulation sim;
  PetscCall(SetUp(sim));
  PetscReal x[3], v[3], w[3];
  PetscBool found;
  while (sim.Time() < T * (1 - 1e-12)) PetscCall(sim.Step());
  PetscCall(Particles(sim)->FindParticle(0, x, v, &found, w));
  PetscCheck(found, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the sphere was lost");
  const PetscReal t = sim.Time();
  if (!correction) {
    const PetscReal tauMeasured = t / std::log(omega0 / w[2]), err = tauMeasured / tau - 1;
    const bool      ok = std::fabs(err) <= kTauTol;
    *failures += !ok;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(b) spin-down, Stokes torque: omega %.6g rad/s after %g s, tau measured %.6e s, I/(pi mu d^3) %.6e s: error %+.3f %% (tolerance %g %%) %s\n",
                          (double)w[2], (double)t, (double)tauMeasured, (double)tau, (double)(100 * err), (double)(100 * kTauTol), Verdict(ok)));
  } else {
    // I dw/dt = -K (1 + 5/(64 pi) (rho d^2 w/mu)^0.6) w, classical RK4 with 1e5 steps.
    PetscReal       y = omega0;
    const PetscInt  N = 100000;
    const PetscReal hh = t / N;
    auto            f = [&](PetscReal o) { return -K / I * (1 + 5 / (64 * PETSC_PI) * std::pow(kRhoF * kD * kD * o / mu, 0.6)) * o; };
    for (PetscInt k = 0; k < N; ++k) {
      const PetscReal k1 = f(y), k2 = f(y + 0.5 * hh * k1), k3 = f(y + 0.5 * hh * k2), k4 = f(y + hh * k3);
      y += hh / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    const PetscReal err = w[2] / y - 1;
    const bool      ok  = std::fabs(err) <= kTauTol;
    *failures += !ok;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(b) spin-down, Dennis et al. factor (Re_r %.3g at the start): omega %.6g rad/s after %g s, the ODE's %.6g: error %+.3f %% (tolerance %g %%) %s\n",
                          (double)(kRhoF * kD * kD * omega0 / mu), (double)w[2], (double)t, (double)y, (double)(100 * err), (double)(100 * kTauTol), Verdict(ok)));
  }
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

// (c) Two spheres approaching: the DEM's lubrication with the flow's viscosity. The force of the last DEM
// evaluation (FindParticle's force: contacts, gaps and gravity, here the lubrication alone) against P8 at the
// pair's gap and approach speed then (positions are those of the evaluation; velocities change by the heavy
// spheres' last half kick only, below 1e-9).
// vof: the box full of the VOF's liquid (phase 1, 0.01 Pa s) and the flow's phase 0 a gas of 1.8e-5 Pa s: the
// lubrication takes the mixture viscosity the particles read (carried to the ghosts on 2 ranks), the liquid's.
PetscErrorCode Lubrication(bool vof, PetscInt *failures) {
  const PetscReal rhoP = 1e7, mu = 0.01, v0 = 1e-3, gap0 = 0.09e-3, dt = 2e-3, R = kD / 2, Reff = R / 2;
  char            rows[512];
  PetscFunctionBeginUser;
  PetscCall(Scene(16, 8, 8, rhoP, mu, dt));
  PetscCall(Set("-dem_dt_factor", "0.003"));  // short DEM steps: the velocity of the force's evaluation (mid-step) is the one printed to 1e-7
  // Around x = 8 mm, the boundary between the ranks on 2 ranks: the pair sees its partner as a ghost there.
  const PetscReal xa = 8 * kD - R - gap0 / 2, xb = 8 * kD + R + gap0 / 2;
  std::snprintf(rows, sizeof rows, "%.17g,%.17g,%.17g,%.17g,0,0,0,0,0\n%.17g,%.17g,%.17g,%.17g,0,0,0,0,0\n", (double)xa, 4 * kD, 4 * kD, (double)v0, (double)xb, 4 * kD, 4 * kD, (double)-v0);
  PetscCall(Particles(rows, "lub"));
  PetscCall(Set("-coupling_lubrication", "1"));
  if (vof) {
    PetscCall(Set("-physics", "dem,flow,vof"));
    PetscCall(Set("-flow_density", "1.2"));
    PetscCall(Set("-flow_viscosity", "1.8e-5"));
    PetscCall(SetReal("-vof_density", kRhoF));
    PetscCall(SetReal("-vof_viscosity", mu));
    PetscCall(Set("-vof_boxes", "0,0,0,0.016,0.008,0.008"));
  }
  vofdem::Simulation sim;
  PetscCall(SetUp(sim));
  PetscReal worst = 0;
  PetscInt  checked = 0;
  for (int k = 0; k < 20 && checked < 5; ++k) {
    PetscCall(sim.Step());
    PetscReal xA[3], vA[3], fA[3], xB[3], vB[3], fB[3], w[3];
    PetscBool fa, fb;
    PetscCall(Particles(sim)->FindParticle(0, xA, vA, &fa, w, fA));
    PetscCall(Particles(sim)->FindParticle(1, xB, vB, &fb, w, fB));
    PetscCheck(fa && fb, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "a sphere was lost");
    const PetscReal h = xB[0] - xA[0] - 2 * R, vn = vA[0] - vB[0];  // approach speed > 0
    if (!(h > 0.01 * R && h < 0.2 * R)) continue;  // inside the default range of -dem_lubrication_*_gap, above its floor
    const PetscReal expected = 6 * PETSC_PI * mu * Reff * Reff * vn / h;  // pushes A back along -x, B along +x
    const PetscReal err = std::max(std::fabs(-fA[0] / expected - 1), std::fabs(fB[0] / expected - 1));
    worst = std::max(worst, err);
    ++checked;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(c)%s gap %.4e m, approach %.6e m/s: lubrication %.6e N, 6 pi mu R_eff^2 v/h %.6e N (mu %g Pa s): error %.1e\n", vof ? " liquid" : "", (double)h, (double)vn,
                          (double)fB[0], (double)expected, (double)mu, (double)err));
  }
  const bool ok = checked == 5 && worst <= kLubTol;
  *failures += !ok;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(c) lubrication with the %s viscosity at %d gaps: worst error %.1e (tolerance %g) %s\n", vof ? "VOF liquid's (mixture read)" : "flow's", (int)checked, (double)worst, (double)kLubTol, Verdict(ok)));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

// (d) The fluid's rotation the particles read: a linear shear u_c = gamma (x_e - x_e0) set on the grid (c = x, y, z,
// e the next direction), a sphere at rest at x_e0 (no slip there, no drag) with -coupling_rotational_drag, x periodic, one short step (the walls' no-slip reaches
// sqrt(nu dt) = 0.03 cells in it): the kernel average of the grid's central differences of a linear field is exact
// (the points are symmetric about the sphere), so Omega_f = curl(u)/2 = (0, 0, -gamma/2) up to what the step changed:
// the sphere's eps < 1 makes the projection bend the shear around it (2.3e-6 with d = 1 mm; 4e-8 with d = 0.1 mm).
// Tolerance 1e-5: a wrong component, sign, spacing or factor is off by order 1.
PetscErrorCode Shear(int c, PetscInt *failures) {
  const PetscReal gamma = 10, rhoP = 2500, mu = 0.01, dt = 1e-4;
  const int       e = (c + 1) % 3, f = (c + 2) % 3;  // u_c = gamma (x_e - centre): curl(u)_f = -gamma
  PetscInt        cells[3] = {8, 8, 8};
  PetscReal       centre[3] = {4 * kD, 4 * kD, 4 * kD};
  char            row[256], periodic[2] = {"xyz"[c], 0};
  PetscFunctionBeginUser;
  cells[e] = 16, centre[e] = 8 * kD;  // on 2 ranks split along e at the sphere
  PetscCall(Scene(cells[0], cells[1], cells[2], rhoP, mu, dt));
  PetscCall(Set("-grid_periodic", periodic));  // the shear is then divergence-free up to the walls: the projection keeps it
  std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,0,0,0,0,0,0\n", (double)centre[0], (double)centre[1], (double)centre[2]);
  PetscCall(Particles(row, "shear"));
  PetscCall(Set("-coupling_rotational_drag", "1"));
  vofdem::Simulation sim;
  PetscCall(SetUp(sim));
  {
    const vofdem::StaggeredGrid &sg = Fluid(sim)->Staggered();
    vofdem::LocalField           U;
    PetscInt                     st[3], n[3];
    const PetscReal             *h = sg.Base().Spacing(), *lo = sg.Base().Lower();
    PetscCall(sg.GetGlobal(c, Fluid(sim)->Velocity(c), &U));
    sg.Owned(c, st, n);
    for (PetscInt k = st[2]; k < st[2] + n[2]; ++k)
      for (PetscInt j = st[1]; j < st[1] + n[1]; ++j)
        for (PetscInt i = st[0]; i < st[0] + n[0]; ++i) {
          const PetscInt q[3] = {i, j, k};
          U.at(q)             = gamma * (lo[e] + (q[e] + 0.5) * h[e] - centre[e]);  // faces of c sit at cell centres along e
        }
    PetscCall(sg.RestoreGlobal(c, Fluid(sim)->Velocity(c), &U));
  }
  PetscCall(sim.Step());
  vofdem::ParticleArrays a;
  PetscReal              loc[4] = {0, 0, 0, 0}, all[4], expect[3] = {0, 0, 0};
  PetscCall(Particles(sim)->Particles().GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p) loc[0] += a.fluidRotation[3 * p], loc[1] += a.fluidRotation[3 * p + 1], loc[2] += a.fluidRotation[3 * p + 2], loc[3] += 1;
  PetscCall(Particles(sim)->Particles().RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(loc, all, 4, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  PetscCheck(all[3] == 1, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the sphere was lost");
  expect[f] = -gamma / 2;
  PetscReal err = 0;
  for (int d = 0; d < 3; ++d) err += (all[d] - expect[d]) * (all[d] - expect[d]);
  err = std::sqrt(err) / (gamma / 2);
  const bool ok = err <= 1e-5;
  *failures += !ok;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(d) u_%c = %g (%c - %c0): the fluid rotation read (%.7f, %.7f, %.7f) rad/s, curl(u)/2 = (%g, %g, %g): error %.1e (tolerance 1e-05) %s\n", "xyz"[c],
                        (double)gamma, "xyz"[e], "xyz"[e], (double)all[0], (double)all[1], (double)all[2], (double)expect[0], (double)expect[1], (double)expect[2], (double)err, Verdict(ok)));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  PetscInt failures = 0;
  char     part[16] = "abcd";
  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-parts", part, sizeof part, nullptr));  // read before the scenes clear the options
  const std::string parts = part;
  if (parts.find('a') != std::string::npos) PetscCall(Lift("rubinowkeller", &failures));
  if (parts.find('a') != std::string::npos) PetscCall(Lift("oesterle", &failures));
  if (parts.find('b') != std::string::npos) PetscCall(SpinDown(false, &failures));
  if (parts.find('b') != std::string::npos) PetscCall(SpinDown(true, &failures));
  if (parts.find('c') != std::string::npos) PetscCall(Lubrication(false, &failures));
  if (parts.find('c') != std::string::npos) PetscCall(Lubrication(true, &failures));
  for (int c = 0; c < 3 && parts.find('d') != std::string::npos; ++c) PetscCall(Shear(c, &failures));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "rotation and lubrication in the coupling: %s\n", failures ? "FAIL" : "ok"));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}
/*TEST
  rtol: 1e-3
  atol: 1e-9
  timeout: 300
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    output_file: output/ex45_magnus_rotation_1.out
TEST*/
