static const char help[] = "Verification F1 (docs/verification.md): the 2-D Taylor-Green vortex in a periodic box [0, 2 pi]^2 (a few periodic cells in z),\n"
                           "u = sin x cos y F, v = -cos x sin y F, p = rho/4 (cos 2x + cos 2y) F^2, F = exp(-2 nu t), run to -final_time with\n"
                           "dt = -cfl h / U (so that the time error shrinks with h^2 too) on the grids of -cells_list (default 16,32,64). Prints the\n"
                           "RMS and maximum velocity errors and the RMS pressure error per grid, and the observed orders; the velocity RMS\n"
                           "order must be >= 1.8 between the two finest grids. Flow options (-flow_advection, -flow_viscous, ...) apply.\n"
                           "Also prints the wall time per grid (for scripts/work-precision; the test output does not compare it).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/flow/Flow.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <petsctime.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

const PetscReal kPi = PETSC_PI;

using vofdem::example::SetOption;

struct Errors {
  PetscReal uRms = 0, uMax = 0, pRms = 0, wall = 0;
  PetscInt  steps = 0;
};

PetscReal ExactVelocity(int d, const PetscReal x[3], PetscReal F) {
  return d == 0 ? std::sin(x[0]) * std::cos(x[1]) * F : d == 1 ? -std::cos(x[0]) * std::sin(x[1]) * F : 0;
}

// Fills component d with the exact field at F, or measures the error against it.
PetscErrorCode VisitVelocity(vofdem::Flow &flow, int d, PetscReal F, bool fill, PetscReal *sumSq, PetscReal *maxAbs, PetscInt *count) {
  vofdem::LocalField u;
  PetscInt           s[3], n[3];

  PetscFunctionBeginUser;
  const vofdem::StaggeredGrid &sg = flow.Staggered();
  const PetscReal             *h  = sg.Base().Spacing();
  sg.Owned(d, s, n);
  PetscCall(sg.GetGlobal(d, flow.Velocity(d), &u));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscInt  q[3] = {i, j, k};
        PetscReal       x[3];
        for (int c = 0; c < 3; ++c) x[c] = (c == d ? q[c] : q[c] + 0.5) * h[c];
        const PetscReal exact = ExactVelocity(d, x, F);
        if (fill) u.at(q) = exact;
        else {
          const PetscReal e = PetscRealPart(u.at(q)) - exact;
          *sumSq += e * e;
          *maxAbs = std::fmax(*maxAbs, std::fabs(e));
          ++*count;
        }
      }
  PetscCall(sg.RestoreGlobal(d, flow.Velocity(d), &u));
  PetscFunctionReturn(0);
}

PetscErrorCode RunGrid(PetscInt n, PetscReal finalTime, PetscReal cfl, PetscReal nu, Errors *err) {
  vofdem::Grid grid;
  vofdem::Flow flow;
  PetscLogDouble t0, t1;

  PetscFunctionBeginUser;
  const std::string L = std::to_string((double)(2 * kPi));
  PetscCall(SetOption("-grid_cells", std::to_string(n) + "," + std::to_string(n) + ",4"));
  PetscCall(SetOption("-grid_upper", L + "," + L + "," + std::to_string((double)(8 * kPi / n))));
  PetscCall(SetOption("-grid_periodic", "x,y,z"));
  PetscCall(SetOption("-flow_density", "1"));
  PetscCall(SetOption("-flow_viscosity", std::to_string((double)nu)));
  PetscCall(grid.SetFromOptions(PETSC_COMM_WORLD));
  PetscCall(flow.SetFromOptions(grid));
  PetscCall(grid.SetUp(PETSC_FALSE));
  const PetscReal gravity[3] = {0, 0, 0};
  PetscCall(flow.SetUp(gravity));
  for (int d = 0; d < 3; ++d) PetscCall(VisitVelocity(flow, d, 1, true, nullptr, nullptr, nullptr));
  const PetscReal h     = grid.Spacing()[0];
  const PetscInt  steps = (PetscInt)std::ceil(finalTime / (cfl * h));
  const PetscReal dt    = finalTime / steps;
  PetscCall(PetscTime(&t0));
  for (PetscInt s = 0; s < steps; ++s) PetscCall(flow.Step(s * dt, dt));
  PetscCall(PetscTime(&t1));
  const PetscReal F = std::exp(-2 * nu * finalTime);
  PetscReal       sumSq = 0, mx = 0, g[2];
  PetscInt        count = 0, gc;
  for (int d = 0; d < 2; ++d) PetscCall(VisitVelocity(flow, d, F, false, &sumSq, &mx, &count));
  PetscCallMPI(MPI_Allreduce(&sumSq, &g[0], 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(&mx, &g[1], 1, MPIU_REAL, MPI_MAX, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(&count, &gc, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  err->uRms = std::sqrt(g[0] / gc);
  err->uMax = g[1];
  // Pressure: the incremental scheme's p approximates p(t - dt/2); compared with the mean removed.
  {
    vofdem::LocalField p;
    PetscInt           s[3], c[3];
    const PetscReal    Fp = std::exp(-2 * nu * (finalTime - 0.5 * dt));
    PetscReal          sum = 0, sum2 = 0, gs[2];
    const vofdem::StaggeredGrid &sg = flow.Staggered();
    sg.Owned(3, s, c);
    PetscCall(sg.GetGlobal(3, flow.Pressure(), &p));
    for (PetscInt k = s[2]; k < s[2] + c[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + c[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + c[0]; ++i) {
          const PetscReal x = (i + 0.5) * h, y = (j + 0.5) * h;
          const PetscReal e = PetscRealPart(p.at(i, j, k)) - 0.25 * (std::cos(2 * x) + std::cos(2 * y)) * Fp * Fp;
          sum += e;
          sum2 += e * e;
        }
    PetscCall(sg.RestoreGlobal(3, flow.Pressure(), &p));
    PetscReal loc[2] = {sum, sum2};
    PetscCallMPI(MPI_Allreduce(loc, gs, 2, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
    const PetscReal N = (PetscReal)(n * n * 4);
    err->pRms         = std::sqrt(std::fmax(gs[1] / N - (gs[0] / N) * (gs[0] / N), 0));
  }
  err->wall  = t1 - t0;
  err->steps = steps;
  PetscCall(flow.Destroy());
  PetscCall(grid.Destroy());
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  PetscInt  list[8] = {16, 32, 64}, nlist = 8;
  PetscReal finalTime = 1, cfl = 0.5, nu = 0.05;
  PetscBool set, showTime = PETSC_FALSE;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetIntArray(nullptr, nullptr, "-cells_list", list, &nlist, &set));
  if (!set) nlist = 3;
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-final_time", &finalTime, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-cfl", &cfl, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-nu", &nu, nullptr));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-show_time", &showTime, nullptr));
  // The discretisation error is measured: the solvers' share must be negligible.
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-flow_pressure_ksp_rtol", &set));
  if (!set) PetscCall(SetOption("-flow_pressure_ksp_rtol", "1e-11"));
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-flow_viscous_ksp_rtol", &set));
  if (!set) PetscCall(SetOption("-flow_viscous_ksp_rtol", "1e-12"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Taylor-Green vortex, nu %g m^2/s, t = %g s, dt = %g h/U\n", (double)nu, (double)finalTime, (double)cfl));
  std::vector<Errors> e(nlist);
  const PetscReal     minOrder = 1.8;
  int                 failures = 0;
  for (PetscInt g = 0; g < nlist; ++g) {
    PetscCall(RunGrid(list[g], finalTime, cfl, nu, &e[g]));
    std::string line = "grid " + std::to_string(list[g]) + "^2: steps " + std::to_string(e[g].steps);
    char        buf[256];
    std::snprintf(buf, sizeof buf, "  u RMS error %.4e  max %.4e  p RMS error %.4e", (double)e[g].uRms, (double)e[g].uMax, (double)e[g].pRms);
    line += buf;
    if (g) {
      const PetscReal r = std::log((PetscReal)list[g] / list[g - 1]);
      std::snprintf(buf, sizeof buf, "  orders u %.2f max %.2f p %.2f", (double)(std::log(e[g - 1].uRms / e[g].uRms) / r), (double)(std::log(e[g - 1].uMax / e[g].uMax) / r),
                    (double)(std::log(e[g - 1].pRms / e[g].pRms) / r));
      line += buf;
    }
    if (showTime) {
      std::snprintf(buf, sizeof buf, "  wall %.3f s", (double)e[g].wall);
      line += buf;
    }
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s\n", line.c_str()));
  }
  if (nlist >= 2) {
    const PetscReal order = std::log(e[nlist - 2].uRms / e[nlist - 1].uRms) / std::log((PetscReal)list[nlist - 1] / list[nlist - 2]);
    failures              = !(order >= minOrder);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "F1 velocity RMS order between %d^2 and %d^2: %.2f (tolerance >= %.1f) %s\n", (int)list[nlist - 2], (int)list[nlist - 1],
                          (double)order, (double)minOrder, failures ? "FAIL" : "ok"));
  }
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-5
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    output_file: output/ex24_taylor_green_1.out
  test:
    suffix: central
    nsize: 2
    args: -flow_advection central -flow_pressure_pc boomeramg
TEST*/
