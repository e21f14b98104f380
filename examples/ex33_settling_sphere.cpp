static const char help[] = "Verification C1 (docs/verification.md): a single sphere settling to its terminal velocity through a fluid at rest,\n"
                           "coupled by the semi-resolved kernel (-physics dem,flow; docs/physics.md K1-K3, K1b). Sphere d = 1 mm, 2500 kg/m^3, fluid\n"
                           "1000 kg/m^3 and 0.01 Pa s, Schiller-Naumann drag: the drag law's terminal velocity 0.05508 m/s (Re 5.5), from the force\n"
                           "balance solved here. For each cell/diameter ratio of -ratios (default 0.5,1,2,4,10) a closed box of max(16 d, 8 cells)\n"
                           "across and max(30 d, 6 cells) high, the sphere released at rest on the axis, max(5 d, 1.5 cells) below the lid,\n"
                           "dt = -dt (default 2e-3 s) to -final_time (default 0.3 s, about 20 response times and 16 diameters of fall). The velocity\n"
                           "at the end must be within 2 %% of the law's at every ratio with one setting (the defaults of -coupling_*), and steady\n"
                           "(changed by less than 0.2 %% over the last 0.05 s). Each ratio runs again with -coupling_self_correction 0: that\n"
                           "error is printed beside (K1b), not checked. Other -coupling_* options apply to both runs. Exits non-zero on failure.\n"
                           "-timing: also one line per run with its error and wall time; -runs corrected|uncorrected: only that run, nothing\n"
                           "checked (scripts/work-precision C1).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/examples/Help.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

const PetscReal kD = 1e-3, kRhoP = 2500, kRhoF = 1000, kMu = 0.01, kG = 9.81;
const PetscReal kTolerance = 0.02, kSteady = 0.002;

// The Schiller-Naumann terminal velocity: (rho_p - rho_f) V g = (pi/8) Cd rho_f d^2 W^2 (bisection).
PetscReal TerminalVelocity() {
  const PetscReal weight = (kRhoP - kRhoF) * PETSC_PI * kD * kD * kD / 6 * kG;
  PetscReal       lo = 0, hi = 10;
  for (int i = 0; i < 200; ++i) {
    const PetscReal W = 0.5 * (lo + hi), Re = kRhoF * kD * W / kMu;
    const PetscReal Cd = 24 / Re * (1 + 0.15 * std::pow(Re, 0.687));
    (PETSC_PI / 8 * Cd * kRhoF * kD * kD * W * W > weight ? hi : lo) = W;
  }
  return 0.5 * (lo + hi);
}

PetscErrorCode Set(const char *name, PetscReal v) {
  char buf[64];
  PetscFunctionBeginUser;
  std::snprintf(buf, sizeof buf, "%.17g", (double)v);
  PetscCall(PetscOptionsSetValue(nullptr, name, buf));
  PetscFunctionReturn(0);
}

struct Outcome {
  PetscReal velocity = 0, change = 0, seconds = 0;
  PetscInt  cells[3] = {0, 0, 0};
};

// One settling run at cell/d = ratio; the sphere's vertical velocity at the end and its change over the last 0.05 s.
PetscErrorCode Settle(PetscReal ratio, bool correct, PetscReal dt, PetscReal tEnd, Outcome *out) {
  const PetscReal h = ratio * kD;
  const PetscInt  nx = std::max((PetscInt)std::lround(16 * kD / h), (PetscInt)8), nz = std::max((PetscInt)std::lround(30 * kD / h), (PetscInt)6);
  const PetscReal L = nx * h, Z = nz * h, z0 = Z - std::max(5 * kD, 1.5 * h);
  char            buf[256];
  PetscLogDouble  t0, t1;

  PetscFunctionBeginUser;
  std::snprintf(buf, sizeof buf, "%d,%d,%d", (int)nx, (int)nx, (int)nz);
  PetscCall(PetscOptionsSetValue(nullptr, "-grid_cells", buf));
  std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", (double)L, (double)L, (double)Z);
  PetscCall(PetscOptionsSetValue(nullptr, "-grid_upper", buf));
  PetscCall(PetscOptionsSetValue(nullptr, "-physics", "dem,flow"));
  PetscCall(Set("-dem_radius", kD / 2));
  PetscCall(Set("-dem_density", kRhoP));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_count", "1"));
  std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", (double)(L / 2 - kD / 2), (double)(L / 2 - kD / 2), (double)(z0 - kD / 2));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_lower", buf));
  std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", (double)(L / 2 + kD / 2), (double)(L / 2 + kD / 2), (double)(z0 + kD / 2));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_upper", buf));
  PetscCall(Set("-flow_density", kRhoF));
  PetscCall(Set("-flow_viscosity", kMu));
  PetscCall(PetscOptionsSetValue(nullptr, "-coupling_drag", "schillernaumann"));
  PetscCall(PetscOptionsSetValue(nullptr, "-coupling_self_correction", correct ? "1" : "0"));
  PetscCall(Set("-dt", dt));
  PetscCall(PetscOptionsSetValue(nullptr, "-max_steps", "1000000"));
  out->cells[0] = out->cells[1] = nx, out->cells[2] = nz;

  vofdem::Simulation sim;
  PetscCall(PetscTime(&t0));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  PetscReal x[3], v[3], before = 0;
  PetscBool found;
  while (sim.Time() < tEnd * (1 - 1e-12)) {
    PetscCall(sim.Step());
    if (before == 0 && sim.Time() >= tEnd - 0.05 - 1e-12) {
      PetscCall(Particles(sim)->FindParticle(0, x, v, &found));
      before = v[2];
    }
  }
  PetscCall(Particles(sim)->FindParticle(0, x, v, &found));
  PetscCheck(found, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the sphere was lost");
  out->velocity = -v[2];
  out->change   = std::fabs(v[2] - before) / std::fabs(v[2]);
  PetscCall(sim.Destroy());
  PetscCall(PetscTime(&t1));
  out->seconds = t1 - t0;
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  PetscReal ratios[16] = {0.5, 1, 2, 4, 10}, dt = 2e-3, tEnd = 0.3;
  PetscInt  n = 5, failures = 0;
  PetscBool timing = PETSC_FALSE;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetRealArray(nullptr, nullptr, "-ratios", ratios, &n, nullptr));
  if (n == 0) n = 5;
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-dt", &dt, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-final_time", &tEnd, nullptr));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-timing", &timing, nullptr));
  char which[32] = "both";
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-runs", which, sizeof which, nullptr));
  const std::string runs = which;
  if (runs != "both" && runs != "corrected" && runs != "uncorrected") VofdemInputError(PETSC_COMM_WORLD, "option -runs: give both, corrected or uncorrected (found %s)", which);
  const PetscReal W = TerminalVelocity();
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "C1 settling sphere: d %g m, rho_p %g, rho_f %g kg/m^3, mu %g Pa s; Schiller-Naumann terminal velocity %.6f m/s (Re %.3f)\n",
                        (double)kD, (double)kRhoP, (double)kRhoF, (double)kMu, (double)W, (double)(kRhoF * kD * W / kMu)));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "cell/d  grid        velocity (m/s)  error    steady  | uncorrected (K1b off): velocity  error%s\n", timing ? "  | wall s (corrected, uncorrected)" : ""));
  for (PetscInt k = 0; k < n; ++k) {
    Outcome on, off;
    if (runs != "uncorrected") PetscCall(Settle(ratios[k], true, dt, tEnd, &on));
    if (runs != "corrected") PetscCall(Settle(ratios[k], false, dt, tEnd, &off));
    // one line per run for scripts/work-precision C1 (error against wall time)
    if (timing && runs != "uncorrected") PetscCall(PetscPrintf(PETSC_COMM_WORLD, "timing: ratio %g corrected error %.6e wall %.3f s\n", (double)ratios[k], (double)(on.velocity / W - 1), (double)on.seconds));
    if (timing && runs != "corrected") PetscCall(PetscPrintf(PETSC_COMM_WORLD, "timing: ratio %g uncorrected error %.6e wall %.3f s\n", (double)ratios[k], (double)(off.velocity / W - 1), (double)off.seconds));
    if (runs != "both") continue;
    const PetscReal err = on.velocity / W - 1, errOff = off.velocity / W - 1;
    const bool      ok  = std::fabs(err) <= kTolerance && on.change < kSteady;
    failures += !ok;
    char grid[64], tim[64] = "";
    std::snprintf(grid, sizeof grid, "%dx%dx%d", (int)on.cells[0], (int)on.cells[1], (int)on.cells[2]);
    if (timing) std::snprintf(tim, sizeof tim, "  | %.1f %.1f", on.seconds, off.seconds);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%-6g  %-10s  %.6f        %+6.2f %%  %-6s  |                        %.6f  %+6.2f %%%s  %s\n", (double)ratios[k], grid, (double)on.velocity,
                          (double)(100 * err), on.change < kSteady ? "yes" : "no", (double)off.velocity, (double)(100 * errOff), tim, ok ? "ok" : "FAIL"));
  }
  if (runs != "both") PetscFunctionReturn(0);  // timing runs (-runs corrected|uncorrected) check nothing
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "C1 terminal velocity within %g %% of the drag law at every ratio with one setting: %s\n", (double)(100 * kTolerance), failures ? "FAIL" : "ok"));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}
/*TEST
  rtol: 1e-3
  atol: 2e-3
  timeout: 900
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    output_file: output/ex33_settling_sphere_1.out
TEST*/
