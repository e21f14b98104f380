static const char help[] = "Verification of the pressure Poisson solve -div(beta grad p) = f (docs/physics.md F1, F2; docs/verification.md F5 for the\n"
                           "operator): manufactured solutions with constant and smoothly variable beta and Neumann, Dirichlet and\n"
                           "periodic boundaries on 16^3 and 32^3 (and -fine 1: 64^3) cells of the unit cube. Prints the RMS error of p\n"
                           "per grid and the observed order, which must be >= 1.9. Exits non-zero on failure.\n\n";

// p = a0 + a1 z + X(x) Y(y) Z(z) with cosine factors chosen so that the exact solution satisfies the
// boundary conditions of the case exactly: dp/dn = 0 on Neumann faces (cos(pi x) at x = 0, 1),
// p constant on the Dirichlet faces z = 0, 1 (Z = sin(pi z): p = a0, a0 + a1), periodic in every
// direction for the periodic case (wave number 2 pi). beta = 1 + 0.5 cos(2 pi x) cos(2 pi y) cos(2 pi z)
// (smooth, periodic, between 0.5 and 1.5) or 1. f = -(grad beta . grad p + beta lap p) at cell centres.

#include "vofdem/base/Runtime.hpp"
#include "vofdem/flow/PressureSolver.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cmath>
#include <string>

namespace {

struct Case {
  const char *name;
  bool        variable;   // beta
  int         kind;       // 0 Neumann, 1 Dirichlet on z faces, 2 periodic
};

struct Factor {  // cos(k s + phase)
  PetscReal k, phase;
  PetscReal f(PetscReal s) const { return std::cos(k * s + phase); }
  PetscReal d(PetscReal s) const { return -k * std::sin(k * s + phase); }
  PetscReal dd(PetscReal s) const { return -k * k * std::cos(k * s + phase); }
};

struct Exact {
  Factor    X, Y, Z;
  PetscReal a0 = 0, a1 = 0;
  bool      variable;
  PetscReal p(const PetscReal x[3]) const { return a0 + a1 * x[2] + X.f(x[0]) * Y.f(x[1]) * Z.f(x[2]); }
  PetscReal beta(const PetscReal x[3], PetscReal g[3]) const {
    const PetscReal w = 2 * PETSC_PI;
    if (!variable) {
      g[0] = g[1] = g[2] = 0;
      return 1;
    }
    const PetscReal cx = std::cos(w * x[0]), cy = std::cos(w * x[1]), cz = std::cos(w * x[2]);
    g[0] = -0.5 * w * std::sin(w * x[0]) * cy * cz;
    g[1] = -0.5 * w * cx * std::sin(w * x[1]) * cz;
    g[2] = -0.5 * w * cx * cy * std::sin(w * x[2]);
    return 1 + 0.5 * cx * cy * cz;
  }
  PetscReal f(const PetscReal x[3]) const {
    PetscReal       g[3];
    const PetscReal b  = beta(x, g);
    const PetscReal px = X.d(x[0]) * Y.f(x[1]) * Z.f(x[2]), py = X.f(x[0]) * Y.d(x[1]) * Z.f(x[2]);
    const PetscReal pz = a1 + X.f(x[0]) * Y.f(x[1]) * Z.d(x[2]);
    const PetscReal lap = X.dd(x[0]) * Y.f(x[1]) * Z.f(x[2]) + X.f(x[0]) * Y.dd(x[1]) * Z.f(x[2]) + X.f(x[0]) * Y.f(x[1]) * Z.dd(x[2]);
    return -(g[0] * px + g[1] * py + g[2] * pz + b * lap);
  }
};

Exact MakeExact(const Case &c) {
  const PetscReal pi = PETSC_PI;
  Exact           e;
  e.variable = c.variable;
  if (c.kind == 2) {
    e.X = {2 * pi, 0.3};
    e.Y = {2 * pi, 0};
    e.Z = {2 * pi, -0.7};
  } else {
    e.X = {pi, 0};
    e.Y = {pi, 0};
    e.Z = c.kind == 1 ? Factor{pi, -pi / 2} : Factor{pi, 0};
    if (c.kind == 1) e.a0 = 1, e.a1 = 2;
  }
  return e;
}

using vofdem::example::SetOption;

// RMS error of the solve on n^3 cells (mean removed where p is defined up to a constant).
PetscErrorCode SolveCase(const Case &c, PetscInt n, PetscReal *error, PetscInt *iterations) {
  vofdem::Grid           grid;
  vofdem::PressureSolver solver;
  Vec                    beta, rhs, p, exact;
  PetscScalar         ***bb, ***ff, ***ee;
  PetscInt               xs, ys, zs, xm, ym, zm;

  PetscFunctionBeginUser;
  const Exact e = MakeExact(c);
  PetscCall(SetOption("-grid_cells", std::to_string(n) + "," + std::to_string(n) + "," + std::to_string(n)));
  if (c.kind == 2) PetscCall(SetOption("-grid_periodic", "x,y,z"));
  else PetscCall(PetscOptionsClearValue(nullptr, "-grid_periodic"));
  PetscCall(grid.SetFromOptions(PETSC_COMM_WORLD));
  PetscCall(grid.SetUp(PETSC_FALSE));
  PetscCall(solver.Create(grid));
  if (c.kind == 1) {
    PetscCall(solver.SetBoundary(4, vofdem::PressureBoundary::Dirichlet, e.a0));
    PetscCall(solver.SetBoundary(5, vofdem::PressureBoundary::Dirichlet, e.a0 + e.a1));
  }
  PetscCall(solver.SetFromOptions());
  PetscCall(solver.SetUp());
  DM dm = grid.CellDM();
  PetscCall(DMCreateGlobalVector(dm, &beta));
  PetscCall(VecDuplicate(beta, &rhs));
  PetscCall(VecDuplicate(beta, &p));
  PetscCall(VecDuplicate(beta, &exact));
  PetscCall(DMDAVecGetArray(dm, beta, &bb));
  PetscCall(DMDAVecGetArray(dm, rhs, &ff));
  PetscCall(DMDAVecGetArray(dm, exact, &ee));
  PetscCall(DMDAGetCorners(dm, &xs, &ys, &zs, &xm, &ym, &zm));
  const PetscReal *h = grid.Spacing();
  for (PetscInt k = zs; k < zs + zm; ++k)
    for (PetscInt j = ys; j < ys + ym; ++j)
      for (PetscInt i = xs; i < xs + xm; ++i) {
        const PetscReal x[3] = {(i + 0.5) * h[0], (j + 0.5) * h[1], (k + 0.5) * h[2]};
        PetscReal       g[3];
        bb[k][j][i] = e.beta(x, g);
        ff[k][j][i] = e.f(x);
        ee[k][j][i] = e.p(x);
      }
  PetscCall(DMDAVecRestoreArray(dm, beta, &bb));
  PetscCall(DMDAVecRestoreArray(dm, rhs, &ff));
  PetscCall(DMDAVecRestoreArray(dm, exact, &ee));
  PetscCall(solver.SetCoefficient(beta, "beta"));
  PetscCall(VecSet(p, 0));
  PetscCall(solver.Solve(rhs, p));
  *iterations = solver.Iterations();
  PetscCall(VecAXPY(p, -1, exact));
  if (solver.HasNullSpace()) {
    PetscScalar mean;
    PetscCall(VecSum(p, &mean));
    PetscCall(VecShift(p, -mean / (n * n * n)));
  }
  PetscCall(VecNorm(p, NORM_2, error));
  *error /= std::sqrt((PetscReal)(n * n * n));
  PetscCall(VecDestroy(&beta));
  PetscCall(VecDestroy(&rhs));
  PetscCall(VecDestroy(&p));
  PetscCall(VecDestroy(&exact));
  PetscCall(solver.Destroy());
  PetscCall(grid.Destroy());
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  const Case cases[] = {{"neumann, constant beta", false, 0}, {"neumann, variable beta", true, 0}, {"dirichlet z, variable beta", true, 1},
                        {"periodic, constant beta", false, 2}, {"periodic, variable beta", true, 2}};
  PetscBool  fine     = PETSC_FALSE, given;
  int        failures = 0;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-fine", &fine, nullptr));
  // The discretisation error is measured: make the solver's share negligible (and equal on any rank count).
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-flow_pressure_ksp_rtol", &given));
  if (!given) PetscCall(SetOption("-flow_pressure_ksp_rtol", "1e-11"));
  const PetscReal tolerance = 1.9;
  for (const Case &c : cases) {
    PetscReal errors[3];
    PetscInt  its[3];
    const int grids = fine ? 3 : 2;
    for (int g = 0; g < grids; ++g) PetscCall(SolveCase(c, 16 << g, &errors[g], &its[g]));
    for (int g = 0; g < grids; ++g) {
      const PetscReal order = g ? std::log2(errors[g - 1] / errors[g]) : 0;
      const bool      bad   = g && !(order >= tolerance);
      failures += bad;
      if (g)
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%-28s %3d^3: RMS error %.5e, observed order %.3f (tolerance >= %.1f) %s\n", c.name, 16 << g,
                              (double)errors[g], (double)order, (double)tolerance, bad ? "FAIL" : "ok"));
      else PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%-28s %3d^3: RMS error %.5e\n", c.name, 16 << g, (double)errors[g]));
    }
  }
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d convergence checks below order %.1f\n", failures, (double)tolerance));
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
    output_file: output/ex22_pressure_convergence_1.out
  test:
    suffix: pfmg
    nsize: 2
    args: -flow_pressure_pc pfmg
    output_file: output/ex22_pressure_convergence_1.out
TEST*/
