static const char help[] = "Verification D1 (sphere-wall variant): normal impact of a sphere on a wall with Hertz contact and damping.\n"
                           "Measures the coefficient of restitution for e = 0.3, 0.6, 0.9 (within 2 %) and the elastic contact time\n"
                           "for e = 1 against Hertz' t_c = 2.87 (m*^2/(R* E*^2 v))^(1/5) (within 1 %). Exits non-zero on failure.\n\n";

// A wall is a sphere of infinite radius and mass (docs/physics.md P3): R* = R, m* = m. The contact
// starts and ends where the gap crosses zero, found by linear interpolation between steps.

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cstdio>
#include <string>

struct Impact {
  PetscReal restitution;  // measured
  PetscReal contactTime;  // s
};

// Full precision: std::to_string would print 5.4e-8 as "0.000000".
using vofdem::example::Num;

using vofdem::example::SetOption;

// One impact: radius R, falling onto the floor at speed v0, no gravity, time step t_c / stepsPerContact.
static PetscErrorCode RunImpact(PetscReal e, PetscReal v0, PetscReal tc, PetscInt stepsPerContact, Impact *out) {
  vofdem::Simulation sim;
  PetscReal          x[3], v[3], gapOld = 0, tStart = -1, tEnd = -1, vAfter = 0;
  PetscBool          found;

  PetscFunctionBeginUser;
  PetscCall(SetOption("-dem_restitution", Num(e)));
  PetscCall(SetOption("-dem_fill_velocity", "0,0," + Num(-v0)));
  PetscCall(SetOption("-dt", Num(tc / stepsPerContact)));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem    *dem = Particles(sim);
  const PetscReal R   = dem->Radius();
  PetscCall(dem->FindParticle(0, x, v, &found));
  PetscCheck(found, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "particle 0 missing");
  gapOld = x[2] - R;
  for (PetscInt k = 0; k < 100 * stepsPerContact && tEnd < 0; ++k) {
    const PetscReal t0 = sim.Time();
    PetscCall(sim.Step());
    PetscCall(dem->FindParticle(0, x, v, &found));
    const PetscReal gap = x[2] - R, t1 = sim.Time();
    if (tStart < 0 && gapOld > 0 && gap <= 0) tStart = t0 + (t1 - t0) * gapOld / (gapOld - gap);
    if (tStart >= 0 && gapOld <= 0 && gap > 0) {
      tEnd   = t0 + (t1 - t0) * gapOld / (gapOld - gap);
      vAfter = v[2];
    }
    gapOld = gap;
  }
  PetscCheck(tEnd > 0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the sphere never left the wall");
  out->restitution = vAfter / v0;
  out->contactTime = tEnd - tStart;
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  const PetscReal R = 1e-3, rho = 2500, E = 1e8, nu = 0.28, v0 = 0.5;
  PetscInt        stepsPerContact = 200, failures = 0;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-steps_per_contact", &stepsPerContact, nullptr));
  // One particle a gap of R/100 above the floor of a 10 R box, the same material for the wall.
  PetscCall(SetOption("-physics", "dem"));
  PetscCall(SetOption("-grid_cells", "2,2,2"));
  PetscCall(SetOption("-grid_upper", "0.01,0.01,0.01"));
  PetscCall(SetOption("-gravity", "0,0,0"));
  PetscCall(SetOption("-dem_radius", Num(R)));
  PetscCall(SetOption("-dem_density", Num(rho)));
  PetscCall(SetOption("-dem_youngs_modulus", Num(E)));
  PetscCall(SetOption("-dem_poisson_ratio", Num(nu)));
  PetscCall(SetOption("-dem_fill_count", "1"));
  PetscCall(SetOption("-dem_fill_lower", "0.004,0.004,0.00001"));
  PetscCall(SetOption("-dem_fill_upper", "0.006,0.006,0.00203"));

  const PetscReal m = rho * 4.0 / 3.0 * PETSC_PI * R * R * R;
  const PetscReal Estar = vofdem::hertz::EffectiveModulus(E, nu, E, nu);
  const PetscReal tc    = vofdem::hertz::HertzContactTime(m, R, Estar, v0);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "sphere R %g m on a wall at %g m/s; Hertz contact time %.6e s; %d steps per contact\n", (double)R, (double)v0,
                        (double)tc, (int)stepsPerContact));
  for (PetscReal e : {0.3, 0.6, 0.9}) {
    Impact i;
    PetscCall(RunImpact(e, v0, tc, stepsPerContact, &i));
    const PetscReal err = PetscAbsReal(i.restitution - e) / e;
    failures += err > 0.02;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "e %.1f: measured %.6f, error %.3f %% (tolerance 2 %%) %s\n", (double)e, (double)i.restitution,
                          (double)(100 * err), err > 0.02 ? "FAIL" : "ok"));
  }
  Impact i;
  PetscCall(RunImpact(1.0, v0, tc, stepsPerContact, &i));
  const PetscReal err = PetscAbsReal(i.contactTime - tc) / tc;
  failures += err > 0.01;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "e 1.0: restitution %.6f, contact time %.6e s, error %.3f %% (tolerance 1 %%) %s\n", (double)i.restitution,
                        (double)i.contactTime, (double)(100 * err), err > 0.01 ? "FAIL" : "ok"));
  // A failed check is a result, not a crash: say so and exit non-zero on every rank.
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d of 4 impact checks out of tolerance\n", (int)failures));
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
    output_file: output/ex02_wall_impact_1.out
TEST*/
