static const char help[] = "Verification G2: a cantilever of N + 1 = 11 bonded spheres (parallel bonds, P13) under a small tip load P.\n"
                           "Each bond turns as a rotational spring, M = k_n I dtheta, between spheres L_b = 2 r + gap apart: the chain\n"
                           "bends as a beam of EI = k_n I L_b (I = pi R^4/4, R = lambda r), clamped at sphere 0 and loaded at sphere N,\n"
                           "L = N L_b. Its static tip deflection is Euler-Bernoulli's P L^3 / (3 EI) within 2 %. Sphere 0 is the clamp:\n"
                           "a sphere of density 1e30 kg/m^3 (it neither moves nor turns). The example adds the tip load as its impulse P dt\n"
                           "after every step, and damps all velocities and spins at a rate of twice the first bending frequency\n"
                           "(the damping moves no equilibrium; without it the beam rings for ever: bonds have no damping of their own).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/sim/ModuleAccess.hpp"

#include <petscdmswarm.h>

#include <cmath>
#include <cstdio>
#include <string>

static const PetscInt  N = 10;  // bonds; spheres 0 .. N
static const PetscReal r = 1e-3, gap = 1e-6, Lb = 2 * r + gap, rho = 2500, kn = 1e13, ks = 1e13, lambda = 1, yBeam = 0.003, zBeam = 0.003, xBeam = 0.001;
static const PetscReal deflection = 1e-4;  // P is chosen so that Euler-Bernoulli's tip deflection is this fraction of L (small load)

// The tip pushed by P dt in -z, every velocity and spin times 1/(1 + c dt).
static PetscErrorCode Constrain(DM swarm, PetscReal dt, PetscReal P, PetscReal m, PetscReal c) {
  PetscInt    n, bs;
  PetscReal  *v, *w;
  PetscInt64 *id;

  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetLocalSize(swarm, &n));
  PetscCall(DMSwarmGetField(swarm, vofdem::field::velocity, &bs, nullptr, (void **)&v));
  PetscCall(DMSwarmGetField(swarm, vofdem::field::omega, &bs, nullptr, (void **)&w));
  PetscCall(DMSwarmGetField(swarm, vofdem::field::id, &bs, nullptr, (void **)&id));
  const PetscReal damp = 1 / (1 + c * dt);
  for (PetscInt p = 0; p < n; ++p) {
    if (id[p] == N) v[3 * p + 2] -= P * dt / m;
    for (int d = 0; d < 3; ++d) v[3 * p + d] *= damp, w[3 * p + d] *= damp;
  }
  PetscCall(DMSwarmRestoreField(swarm, vofdem::field::id, &bs, nullptr, (void **)&id));
  PetscCall(DMSwarmRestoreField(swarm, vofdem::field::omega, &bs, nullptr, (void **)&w));
  PetscCall(DMSwarmRestoreField(swarm, vofdem::field::velocity, &bs, nullptr, (void **)&v));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  vofdem::Simulation sim;
  std::string        rows = "x,y,z,type\n";
  char               line[256], opts[1024];
  PetscReal          x[3], v[3];
  PetscBool          found;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  // The beam's constants: bond section, EI = k_n I L_b, the load for the chosen deflection, the first bending mode
  // omega_1 = 1.875^2 sqrt(EI / (mu L^4)) with mu = m / L_b.
  const PetscReal R = lambda * r, I = PETSC_PI * R * R * R * R / 4, EI = kn * I * Lb, L = N * Lb, m = rho * 4.0 / 3.0 * PETSC_PI * r * r * r;
  const PetscReal P = 3 * EI * deflection * L / (L * L * L), omega1 = 1.875 * 1.875 * std::sqrt(EI / (m / Lb * L * L * L * L));
  std::snprintf(opts, sizeof opts,
                "-physics dem -grid_cells 4,2,2 -grid_upper 0.024,0.006,0.006 -gravity 0,0,0 -dem_radius %.17g -dem_types beam,clamp -dem_type_beam_density %.17g "
                "-dem_type_clamp_density 1e30 -dem_cohesion bond "
                "-dem_bond_radius_ratio %.17g -dem_bond_normal_stiffness %.17g -dem_bond_shear_stiffness %.17g -dem_bond_tensile_strength 1e30 "
                "-dem_bond_shear_strength 1e30 -dem_bond_gap 1e-5 -final_time 1 -max_steps 100000000 -monitor_every 100000000",
                (double)r, (double)rho, (double)lambda, (double)kn, (double)ks);
  PetscCall(PetscOptionsInsertString(nullptr, opts));
  for (PetscInt k = 0; k <= N; ++k) {
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%d\n", (double)(xBeam + k * Lb), (double)yBeam, (double)zBeam, k == 0 ? 1 : 0);  // sphere 0: the clamp
    rows += line;
  }
  PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, "ex56_beam.csv", rows, "particle file"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_particles_file", "ex56_beam.csv"));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem    *dem = Particles(sim);
  // All modes decay at least as exp(-c t / 2), the first critically damped; 24 time constants (12 leave 0.2 % of the
  // deflection to come: the rotational inertia makes the first mode slower than omega_1).
  const PetscReal c = 2 * omega1, settle = 24 / omega1;
  PetscInt        steps = 0;
  while (sim.Time() < settle) {
    PetscCall(sim.Step());
    PetscCall(Constrain(dem->Swarm(), sim.Dt(), P, m, c));
    ++steps;
  }
  PetscCall(dem->FindParticle(N, x, v, &found));
  PetscCheck(found, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the tip sphere is lost");
  vofdem::DemSummary s;
  PetscCall(dem->Summarize(&s));
  const PetscReal tip = zBeam - x[2], eb = P * L * L * L / (3 * EI), err = std::abs(tip - eb) / eb;
  // The chain's own answer: joint j at (j + 1/2) L_b turns by M_j / (k_n I), M_j = P (L - (j + 1/2) L_b), plus the bonds'
  // shear, P / (k_s A) each: (4 N^2 - 1) / (4 N^2) of Euler-Bernoulli's and (3 k_n R^2 / (4 k_s L_b^2 N^2)) more.
  const PetscReal chain = eb * (4.0 * N * N - 1) / (4.0 * N * N) + N * P / (ks * PETSC_PI * R * R);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "beam of %d bonds, L = %.6e m, EI = k_n I L_b = %.6e N m^2, tip load %.6e N; %d steps of %.3e s, %lld bonds intact\n", (int)N,
                        (double)L, (double)EI, (double)P, (int)steps, (double)sim.Dt(), (long long)s.bondsIntact));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "tip deflection %.6e m (Euler-Bernoulli P L^3/(3 EI) = %.6e m, error %.3f %%, tolerance 2 %%) %s\n", (double)tip, (double)eb,
                        (double)(100 * err), err > 0.02 ? "FAIL" : "ok"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "the discrete chain's own answer (joints and bond shear) %.6e m: %.4f of Euler-Bernoulli's\n", (double)chain, (double)(chain / eb)));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(err > 0.02 || s.bondsIntact != N ? PETSC_ERR_NOT_CONVERGED : 0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-6
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    args: -grid_ranks 2,1,1
    output_file: output/ex56_bonded_beam_1.out
TEST*/
