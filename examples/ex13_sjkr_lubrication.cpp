static const char help[] = "SJKR cohesion (P6, LIGGGHTS' definition) and lubrication (P8), each against its analytic answer.\n"
                           "SJKR: two touching spheres, and a sphere touching the floor, pulled together by F = k A with no gravity, come to\n"
                           "rest at the overlap where Hertz' force equals k A (within 1 %). Lubrication: two spheres approaching head on\n"
                           "through a liquid, and a sphere approaching the floor, stop at the gap h0 exp(-m* u0 / (6 pi mu R*^2)) (within 1 %).\n"
                           "Reduced modulus: a surface energy measured at E is scaled by (E'/E)^(2/5) (P9) once, and only on request.\n"
                           "Exits non-zero on failure.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

static const PetscReal R = 1e-3, rho = 2500, E = 1e8, nu = 0.28;

using vofdem::example::Num;

static PetscErrorCode UseParticles(const std::string &rows) {
  PetscFunctionBeginUser;
  PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, "ex13_particles.csv", "x,y,z,vx,vy,vz\n" + rows, "particle file"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_particles_file", "ex13_particles.csv"));
  PetscFunctionReturn(0);
}

// Runs `steps` steps with the given extra options and returns the gap (pair: centre distance - 2R,
// wall: z - R) at the end and its smallest value.
static PetscErrorCode Gap(bool pair, const char *options, PetscInt steps, PetscReal *gapEnd, PetscReal *gapMin) {
  vofdem::Simulation sim;
  PetscReal          xa[3], va[3], xb[3], vb[3];
  PetscBool          found;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsInsertString(nullptr, options));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  auto         gap = [&](PetscReal *g) {
    PetscFunctionBeginUser;
    PetscCall(dem->FindParticle(0, xa, va, &found));
    if (pair) PetscCall(dem->FindParticle(1, xb, vb, &found));
    *g = pair ? xb[2] - xa[2] - 2 * R : xa[2] - R;
    PetscFunctionReturn(0);
  };
  *gapMin = PETSC_MAX_REAL;
  for (PetscInt k = 0; k < steps; ++k) {
    PetscCall(sim.Step());
    if (k % 10 == 0) {
      PetscCall(gap(gapEnd));
      *gapMin = PetscMin(*gapMin, *gapEnd);
    }
  }
  PetscCall(gap(gapEnd));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

static PetscErrorCode Check(const char *what, PetscReal value, PetscReal exact, PetscReal tol, PetscInt *failures) {
  const PetscReal err = PetscAbsReal(value - exact) / PetscAbsReal(exact);

  PetscFunctionBeginUser;
  *failures += !(err <= tol);
  char line[256];
  std::snprintf(line, sizeof line, "%s: measured %.6e, expected %.6e, error %.4f %% (tolerance %g %%) %s\n", what, (double)value, (double)exact, (double)(100 * err),
                (double)(100 * tol), err <= tol ? "ok" : "FAIL");
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", line));
  PetscFunctionReturn(0);
}

// Root of f on [a, b] by bisection (f(a), f(b) of opposite signs).
static PetscReal Bisect(const std::function<PetscReal(PetscReal)> &f, PetscReal a, PetscReal b) {
  for (int it = 0; it < 200; ++it) {
    const PetscReal m = 0.5 * (a + b);
    if ((f(a) < 0) == (f(m) < 0)) a = m;
    else b = m;
  }
  return 0.5 * (a + b);
}

static PetscErrorCode Run() {
  PetscInt        failures = 0;
  const PetscReal Estar = vofdem::hertz::EffectiveModulus(E, nu, E, nu), m = rho * 4.0 / 3.0 * PETSC_PI * R * R * R;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsInsertString(nullptr, "-physics dem -grid_cells 2,2,2 -grid_upper 0.01,0.01,0.01 -gravity 0,0,0 -dem_radius 1e-3 "
                                              "-dem_density 2500 -dem_youngs_modulus 1e8 -dem_poisson_ratio 0.28 -monitor_every 1000000"));
  // SJKR: equilibrium (4/3) E* sqrt(R*) delta^1.5 = k A(delta); two spheres: R* = R/2, A = pi (R delta - delta^2/4)
  // (the circle where spheres of radius R at distance 2R - delta meet); floor: R* = R, A = pi (2 R delta - delta^2).
  const PetscReal k = 1.6e6;
  {
    auto pairF = [&](PetscReal d) { return 4.0 / 3.0 * Estar * std::sqrt(R / 2) * std::pow(d, 1.5) - k * PETSC_PI * (R * d - d * d / 4); };
    auto wallF = [&](PetscReal d) { return 4.0 / 3.0 * Estar * std::sqrt(R) * std::pow(d, 1.5) - k * PETSC_PI * (2 * R * d - d * d); };
    const PetscReal dPair = Bisect(pairF, 1e-9 * R, 0.5 * R), dWall = Bisect(wallF, 1e-9 * R, 0.5 * R);
    PetscReal       gEnd, gMin;
    const std::string sjkr = " -dem_cohesion sjkr -dem_cohesion_energy_density " + Num(k) + " -dem_restitution 0.3 -max_steps 100000";
    PetscCall(UseParticles("0.005,0.005,0.004,0,0,0\n0.005,0.005," + Num(0.006 - 1e-9) + ",0,0,0\n"));
    PetscCall(Gap(true, sjkr.c_str(), 4000, &gEnd, &gMin));
    PetscCall(Check("SJKR two spheres, overlap at rest", -gEnd, dPair, 0.01, &failures));
    PetscCall(UseParticles("0.005,0.005," + Num(R - 1e-9) + ",0,0,0\n"));
    PetscCall(Gap(false, sjkr.c_str(), 4000, &gEnd, &gMin));
    PetscCall(Check("SJKR sphere on the floor, overlap at rest", -gEnd, dWall, 0.01, &failures));
    PetscCall(PetscOptionsClearValue(nullptr, "-dem_cohesion"));
    PetscCall(PetscOptionsClearValue(nullptr, "-dem_cohesion_energy_density"));
    PetscCall(PetscOptionsClearValue(nullptr, "-dem_restitution"));
  }
  // Lubrication: m* du/dt = -6 pi mu R*^2 u / h with u = -dh/dt gives u(h) = u0 - K ln(h0/h),
  // K = 6 pi mu R*^2 / m*, so the approach stops at h0 exp(-u0/K) (above the inner cut-off).
  {
    const PetscReal mu = 1e-3, h0 = 0.19 * R, u0 = 1.5e-3;  // water; inside the default outer cut-off 0.2 R
    const std::string lub = " -dem_lubrication_viscosity " + Num(mu);
    PetscReal         gEnd, gMin;
    const PetscReal   Kpair = 6 * PETSC_PI * mu * (R / 2) * (R / 2) / (m / 2), Kwall = 6 * PETSC_PI * mu * R * R / m;
    PetscCall(UseParticles("0.005,0.005,0.004,0,0," + Num(u0 / 2) + "\n0.005,0.005," + Num(0.006 + h0) + ",0,0," + Num(-u0 / 2) + "\n"));
    PetscCall(Gap(true, lub.c_str(), 60000, &gEnd, &gMin));
    PetscCall(Check("lubrication two spheres, gap where they stop", gEnd, h0 * std::exp(-u0 / Kpair), 0.01, &failures));
    PetscCall(UseParticles("0.005,0.005," + Num(R + h0) + ",0,0," + Num(-u0) + "\n"));
    PetscCall(Gap(false, lub.c_str(), 60000, &gEnd, &gMin));
    PetscCall(Check("lubrication sphere and floor, gap where it stops", gEnd, h0 * std::exp(-u0 / Kwall), 0.01, &failures));
    PetscCall(PetscOptionsClearValue(nullptr, "-dem_lubrication_viscosity"));
  }
  // Reduced modulus (P9): gamma measured at 340 GPa, run at E' = 3.4 GPa: gamma' = gamma (E'/E)^(2/5).
  {
    vofdem::Simulation sim;
    PetscCall(UseParticles("0.005,0.005,0.004,0,0,0\n"));
    PetscCall(PetscOptionsInsertString(nullptr, "-dem_youngs_modulus 3.4e9 -dem_cohesion jkr -dem_surface_energy 1 -dem_surface_energy_modulus 3.4e11"));
    PetscCall(sim.Create(PETSC_COMM_WORLD));
    PetscCall(sim.SetFromOptions());
    PetscCall(Check("surface energy scaled once from 340 GPa to 3.4 GPa", Particles(sim)->TypeMaterial(0).surfaceEnergy, std::pow(0.01, 0.4), 1e-12, &failures));
    PetscCall(sim.Destroy());
  }
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d checks out of tolerance\n", (int)failures));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
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
    args: -grid_ranks 1,1,2
    output_file: output/ex13_sjkr_lubrication_1.out
TEST*/
