static const char help[] = "Verification of the linear spring-dashpot (P4): two spheres meeting head on.\n"
                           "With F = k_n delta - gamma v_n and gamma = -2 beta sqrt(k_n m*), the restitution equals the input e and\n"
                           "the contact lasts pi / omega_d, omega_d = sqrt(k_n/m*) sqrt(1 - beta^2) (exact for the damped oscillator);\n"
                           "at -steps_per_contact 200 within D1's tolerances, 2 %% and 1 %%. The dashpot acts on the half-step\n"
                           "velocity (velocity Verlet, as in LIGGGHTS), an error of first order in dt that grows with the damping.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/examples/Help.hpp"

#include <cstdio>

static const PetscReal R = 1e-3, rho = 2500, kn = 1e5, v0 = 0.5;

// Spheres at z = 3 and 7 mm approach at +-v0/2 and meet at z = 5 mm (the rank boundary with
// -grid_ranks 1,1,2); returns the restitution and the contact duration (gap crossings interpolated).
static PetscErrorCode Collide(PetscReal e, PetscReal dt, PetscReal *restitution, PetscReal *duration) {
  vofdem::Simulation sim;
  PetscReal          xa[3], va[3], xb[3], vb[3], g0 = 0, tStart = -1, tEnd = -1;
  PetscBool          found;
  char               buf[256];

  PetscFunctionBeginUser;
  std::snprintf(buf, sizeof buf, "x,y,z,vz\n0.005,0.005,0.003,%.17g\n0.005,0.005,0.007,%.17g\n", v0 / 2, -v0 / 2);
  PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, "ex08_particles.csv", buf, "particle file"));
  std::snprintf(buf, sizeof buf, "%.17g", (double)e);
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_restitution", buf));
  std::snprintf(buf, sizeof buf, "%.17g", (double)dt);
  PetscCall(PetscOptionsSetValue(nullptr, "-dt", buf));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  auto gap = [&](PetscReal *g) {
    PetscFunctionBeginUser;
    PetscCall(dem->FindParticle(0, xa, va, &found));
    PetscCall(dem->FindParticle(1, xb, vb, &found));
    *g = xb[2] - xa[2] - 2 * R;
    PetscFunctionReturn(0);
  };
  PetscCall(gap(&g0));
  for (int k = 0; k < 1000000 && tEnd < 0; ++k) {
    const PetscReal t0 = sim.Time();
    PetscReal       g1 = 0;
    PetscCall(sim.Step());
    PetscCall(gap(&g1));
    const PetscReal t1 = sim.Time();
    if (tStart < 0 && g0 > 0 && g1 <= 0) tStart = t0 + (t1 - t0) * g0 / (g0 - g1);
    if (tStart >= 0 && g0 <= 0 && g1 > 0) tEnd = t0 + (t1 - t0) * g0 / (g0 - g1);
    g0 = g1;
  }
  PetscCheck(tEnd > 0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the contact never ended");
  *restitution = (vb[2] - va[2]) / v0;
  *duration    = tEnd - tStart;
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  PetscInt        failures = 0, stepsPerContact = 200;
  const PetscReal m = rho * 4.0 / 3.0 * PETSC_PI * R * R * R, mstar = m / 2, w0 = PetscSqrtReal(kn / mstar);

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsInsertString(nullptr, "-physics dem -grid_cells 2,2,2 -grid_upper 0.01,0.01,0.01 -gravity 0,0,0 -dem_radius 1e-3 -dem_density 2500 "
                                              "-dem_contact linear -dem_linear_stiffness 1e5 -dem_particles_file ex08_particles.csv"));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-steps_per_contact", &stepsPerContact, nullptr));
  for (PetscReal e : {0.3, 0.7, 0.9}) {
    PetscReal       en, tc;
    const PetscReal beta = vofdem::hertz::DampingRatio(e), tExact = PETSC_PI / (w0 * PetscSqrtReal(1 - beta * beta));
    PetscCall(Collide(e, tExact / stepsPerContact, &en, &tc));
    const PetscReal errE = PetscAbsReal(en - e) / e, errT = PetscAbsReal(tc - tExact) / tExact;
    failures += (errE > 0.02) + (errT > 0.01);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "e %.1f: restitution %.6f (error %.3f %%, tolerance 2 %%), contact time %.6e s against pi/omega_d %.6e s (error %.3f %%, tolerance 1 %%) %s\n",
                          (double)e, (double)en, (double)(100 * errE), (double)tc, (double)tExact, (double)(100 * errT),
                          errE > 0.02 || errT > 0.01 ? "FAIL" : "ok"));
  }
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d checks\n", (int)failures));
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
    output_file: output/ex08_linear_contact_1.out
TEST*/
