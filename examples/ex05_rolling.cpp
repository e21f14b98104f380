static const char help[] = "Verification D5: rolling resistance (P5) of a sphere rolling on a plane under gravity.\n"
                           "While it rolls, the torque mu_r R F_n decelerates it at a = (5/7) mu_r g (no slip: I = 2/5 m R^2), for the\n"
                           "constant-torque model (cdt) and the elastic-plastic spring-dashpot (epsd) alike: within 2 %.\n"
                           "Once it has stopped, epsd holds it (|w| stays below 1e-6 of the initial spin) while cdt chatters around\n"
                           "w = 0, its torque flipping sign every step.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/examples/Help.hpp"

#include <cstdio>
#include <string>

struct Rolled {
  PetscReal deceleration;  // m/s^2, fitted while rolling
  PetscReal restSpin;      // largest |w| over the last quarter of the run, rad/s
};

static PetscErrorCode Roll(const char *model, PetscReal R, PetscReal v0, PetscReal muR, PetscReal tEnd, Rolled *out) {
  vofdem::Simulation sim;
  char               row[256];
  PetscReal          x[3], v[3], w[3];
  PetscBool          found;

  PetscFunctionBeginUser;
  // Rolling without slip from the start: v = (v0, 0, 0), w = (0, v0/R, 0), touching the floor; it rolls
  // about 1.8 mm, across x = 5 mm, the rank boundary with -grid_ranks 2,1,1.
  std::snprintf(row, sizeof row, "x,y,z,vx,vy,vz,wx,wy,wz\n%.17g,%.17g,%.17g,%.17g,0,0,0,%.17g,0\n", 0.0035, 0.005, R, v0, v0 / R);
  PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, "ex05_sphere.csv", row, "particle file"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_particles_file", "ex05_sphere.csv"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_rolling", model));
  std::snprintf(row, sizeof row, "%.17g", (double)muR);
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_rolling_friction", row));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  // Least-squares slope of v_x(t) over the rolling phase, after the contact has settled and before
  // the sphere stops: t in [0.1, 0.6] of the stopping time v0 / a.
  const PetscReal tStop = v0 / (5.0 / 7.0 * muR * 9.81);
  PetscReal       st = 0, sv = 0, stt = 0, stv = 0, cnt = 0;
  out->restSpin     = 0;
  while (sim.Time() < tEnd) {
    PetscCall(sim.Step());
    PetscCall(Particles(sim)->FindParticle(0, x, v, &found, w));
    const PetscReal t = sim.Time();
    if (t > 0.1 * tStop && t < 0.6 * tStop) st += t, sv += v[0], stt += t * t, stv += t * v[0], cnt += 1;
    if (t > 0.75 * tEnd) out->restSpin = PetscMax(out->restSpin, PetscSqrtReal(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
  }
  out->deceleration = -(cnt * stv - st * sv) / (cnt * stt - st * st);
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  const PetscReal R = 1e-3, v0 = 0.05, muR = 0.1, a = 5.0 / 7.0 * muR * 9.81, tStop = v0 / a, spin = v0 / R;
  PetscInt        failures = 0;
  Rolled          cdt, epsd;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsInsertString(nullptr, "-physics dem -grid_cells 2,2,2 -grid_upper 0.01,0.01,0.01 -gravity 0,0,-9.81 -dem_radius 1e-3 "
                                              "-dem_restitution 0.1 -dem_friction 0.5"));
  PetscCall(Roll("cdt", R, v0, muR, 2 * tStop, &cdt));
  PetscCall(Roll("epsd", R, v0, muR, 2 * tStop, &epsd));
  const PetscReal errC = PetscAbsReal(cdt.deceleration - a) / a, errE = PetscAbsReal(epsd.deceleration - a) / a;
  const bool      chatter = cdt.restSpin > 1e-6 * spin, held = epsd.restSpin < 1e-6 * spin;
  failures += (errC > 0.02) + (errE > 0.02) + !held;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "sphere R %g m rolling at %g m/s on a plane, mu_r %g: analytic deceleration (5/7) mu_r g = %.6f m/s^2, stops after %.4f s\n",
                        (double)R, (double)v0, (double)muR, (double)a, (double)tStop));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "cdt:  deceleration %.6f m/s^2, error %.3f %% (tolerance 2 %%) %s\n", (double)cdt.deceleration, (double)(100 * errC),
                        errC > 0.02 ? "FAIL" : "ok"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "epsd: deceleration %.6f m/s^2, error %.3f %% (tolerance 2 %%) %s\n", (double)epsd.deceleration, (double)(100 * errE),
                        errE > 0.02 ? "FAIL" : "ok"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "after stopping: cdt keeps spinning back and forth (|w| above 1e-6 of the initial spin): %s; epsd holds the sphere (|w| below 1e-6 of it): %s\n",
                        chatter ? "yes" : "no", held ? "yes" : "no"));
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d checks (rest spin: cdt %g, epsd %g rad/s)\n", (int)failures, (double)cdt.restSpin, (double)epsd.restSpin));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-4
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    args: -grid_ranks 2,1,1
    output_file: output/ex05_rolling_1.out
TEST*/
