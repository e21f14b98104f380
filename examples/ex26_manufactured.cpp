static const char help[] = "Verification F5 (docs/verification.md): a manufactured solution of the volume-averaged momentum equation (Flow.hpp)\n"
                           "with variable fluid fraction eps, density rho and viscosity mu, in the periodic box [0,1]^2 (4 periodic cells in z):\n"
                           "  eps = 0.775 + 0.175 sin(kx) cos(ky) (0.6 to 0.95), rho = 1 + 0.5 cos(k(x+y)) (ratio 3), mu = -mu (1 + 0.5 sin(k(x-y))),\n"
                           "  eps U = (d psi/dy, -d psi/dx), psi = sin(kx) sin(ky) cos(t) / k (so div(eps U) = 0 exactly), p = 0.5 cos(kx + 1) sin(ky) cos(t)^2,\n"
                           "with k = 2 pi. The forcing f = dU/dt + U.grad U - div(eps mu (grad U + grad U^T))/(eps rho) + grad p / rho is\n"
                           "evaluated exactly (forward-mode derivatives, no finite differences). Runs to -final_time with dt = -cfl h / 2 on the\n"
                           "grids of -cells_list (default 16,32,64); prints the RMS and maximum velocity errors and the RMS pressure error (mean\n"
                           "removed, against p(t - dt/2): the incremental scheme's pressure lives at half steps) and the observed orders; the\n"
                           "velocity RMS order must be >= 1.8 between the two finest grids. Flow options (-flow_advection, ...) apply.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/flow/Flow.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace {

const PetscReal kK = 2 * PETSC_PI;

// A second-order forward-mode jet in (x, y, t): value, gradient in x, y, t, Hessian in x, y. The
// forcing needs U, grad U, its second x-y derivatives and dU/dt, and grad of eps mu.
struct Jet {
  PetscReal v = 0, g[3] = {0, 0, 0}, H[2][2] = {{0, 0}, {0, 0}};
};

Jet Var(PetscReal value, int i) {
  Jet a;
  a.v    = value;
  a.g[i] = 1;
  return a;
}

Jet operator+(const Jet &a, const Jet &b) {
  Jet c;
  c.v = a.v + b.v;
  for (int i = 0; i < 3; ++i) c.g[i] = a.g[i] + b.g[i];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) c.H[i][j] = a.H[i][j] + b.H[i][j];
  return c;
}

Jet operator*(PetscReal s, const Jet &a) {
  Jet c;
  c.v = s * a.v;
  for (int i = 0; i < 3; ++i) c.g[i] = s * a.g[i];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) c.H[i][j] = s * a.H[i][j];
  return c;
}

Jet operator+(PetscReal s, const Jet &a) {
  Jet c = a;
  c.v += s;
  return c;
}

Jet operator-(const Jet &a, const Jet &b) { return a + (-1) * b; }
Jet operator+(const Jet &a, PetscReal s) { return s + a; }

Jet operator*(const Jet &a, const Jet &b) {
  Jet c;
  c.v = a.v * b.v;
  for (int i = 0; i < 3; ++i) c.g[i] = a.v * b.g[i] + b.v * a.g[i];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) c.H[i][j] = a.v * b.H[i][j] + b.v * a.H[i][j] + a.g[i] * b.g[j] + a.g[j] * b.g[i];
  return c;
}

// f(a) from f, f', f'' at a.v (the chain rule to second order).
Jet Chain(const Jet &a, PetscReal f, PetscReal df, PetscReal ddf) {
  Jet c;
  c.v = f;
  for (int i = 0; i < 3; ++i) c.g[i] = df * a.g[i];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) c.H[i][j] = df * a.H[i][j] + ddf * a.g[i] * a.g[j];
  return c;
}

Jet Sin(const Jet &a) { return Chain(a, std::sin(a.v), std::cos(a.v), -std::sin(a.v)); }
Jet Cos(const Jet &a) { return Chain(a, std::cos(a.v), -std::sin(a.v), -std::cos(a.v)); }
Jet Inv(const Jet &a) { return Chain(a, 1 / a.v, -1 / (a.v * a.v), 2 / (a.v * a.v * a.v)); }
Jet operator/(const Jet &a, const Jet &b) { return a * Inv(b); }

struct Exact {
  PetscReal mu0 = 0.02;
  Jet       eps, rho, mu, U[2], p;

  void At(PetscReal x, PetscReal y, PetscReal t) {
    const Jet X = Var(x, 0), Y = Var(y, 1), T = Cos(Var(t, 2));
    eps = 0.775 + 0.175 * (Sin(kK * X) * Cos(kK * Y));
    rho = 1 + 0.5 * Cos(kK * (X + Y));
    mu  = mu0 * (1 + 0.5 * Sin(kK * (X - Y)));
    // psi = sin(kx) sin(ky) T / k: its derivatives by hand
    const Jet psiX = Cos(kK * X) * Sin(kK * Y) * T, psiY = Sin(kK * X) * Cos(kK * Y) * T;
    U[0] = psiY / eps;
    U[1] = (-1) * psiX / eps;
    p    = 0.5 * (Cos(kK * X + 1) * Sin(kK * Y) * (T * T));
  }
  // The acceleration source that makes (U, p) solve the momentum equation of Flow.hpp (g = 0).
  PetscReal Forcing(int d) const {
    if (d == 2) return 0;
    const Jet em   = eps * mu;
    PetscReal adv = 0, visc = 0;
    for (int j = 0; j < 2; ++j) {
      adv += U[j].v * U[d].g[j];
      visc += em.g[j] * (U[d].g[j] + U[j].g[d]) + em.v * (U[d].H[j][j] + U[j].H[d][j]);
    }
    return U[d].g[2] + adv - visc / (eps.v * rho.v) + p.g[d] / rho.v;
  }
};

PetscReal ForcingFn(void *ctx, PetscReal t, const PetscReal x[3], int d) {
  if (d == 2) return 0;  // the solution is 2-D
  Exact e = *(const Exact *)ctx;
  e.At(x[0], x[1], t);
  return e.Forcing(d);
}

using vofdem::example::SetOption;

using vofdem::example::Num;

struct Errors {
  PetscReal uRms = 0, uMax = 0, pRms = 0;
  PetscInt  steps = 0;
};

// Fills velocity component d with the exact field at t, or measures its error against it.
PetscErrorCode VisitVelocity(vofdem::Flow &flow, const Exact &ex0, int d, PetscReal t, bool fill, PetscReal *sumSq, PetscReal *maxAbs, PetscInt *count) {
  vofdem::LocalField u;
  PetscInt           s[3], n[3];
  Exact              ex = ex0;

  PetscFunctionBeginUser;
  const vofdem::StaggeredGrid &sg = flow.Staggered();
  const PetscReal             *h  = sg.Base().Spacing();
  sg.Owned(d, s, n);
  PetscCall(sg.GetGlobal(d, flow.Velocity(d), &u));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscInt q[3] = {i, j, k};
        PetscReal      x[3];
        for (int c = 0; c < 3; ++c) x[c] = (c == d ? q[c] : q[c] + 0.5) * h[c];
        ex.At(x[0], x[1], t);
        const PetscReal exact = d < 2 ? ex.U[d].v : 0;
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

// Cell fields: which = 0 eps, 1 rho, 2 mu, 3 p (at t), filled into v; with `measure`, the RMS
// error of v against p with the mean removed (the pressure is defined up to a constant).
PetscErrorCode VisitCells(vofdem::Flow &flow, const Exact &ex0, int which, PetscReal t, Vec v, bool measure, PetscReal *rms) {
  vofdem::LocalField c;
  PetscInt           s[3], n[3];
  Exact              ex = ex0;
  PetscReal          sum = 0, sum2 = 0, cnt = 0;

  PetscFunctionBeginUser;
  const vofdem::StaggeredGrid &sg = flow.Staggered();
  const PetscReal             *h  = sg.Base().Spacing();
  sg.Owned(3, s, n);
  PetscCall(sg.GetGlobal(3, v, &c));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        ex.At((i + 0.5) * h[0], (j + 0.5) * h[1], t);
        const PetscReal exact = which == 0 ? ex.eps.v : which == 1 ? ex.rho.v : which == 2 ? ex.mu.v : ex.p.v;
        if (!measure) c.at(i, j, k) = exact;
        else {
          const PetscReal e = PetscRealPart(c.at(i, j, k)) - exact;
          sum += e, sum2 += e * e, cnt += 1;
        }
      }
  PetscCall(sg.RestoreGlobal(3, v, &c));
  if (measure) {
    PetscReal loc[3] = {sum, sum2, cnt}, g[3];
    PetscCallMPI(MPI_Allreduce(loc, g, 3, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
    *rms = std::sqrt(std::fmax(g[1] / g[2] - (g[0] / g[2]) * (g[0] / g[2]), 0));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RunGrid(PetscInt n, PetscReal finalTime, PetscReal cfl, const Exact &ex, Errors *err) {
  vofdem::Grid grid;
  vofdem::Flow flow;

  PetscFunctionBeginUser;
  const PetscReal h = 1.0 / n;
  PetscCall(SetOption("-grid_cells", std::to_string(n) + "," + std::to_string(n) + ",4"));
  PetscCall(SetOption("-grid_upper", "1,1," + Num(4 * h)));
  PetscCall(SetOption("-grid_periodic", "x,y,z"));
  PetscCall(grid.SetFromOptions(PETSC_COMM_WORLD));
  PetscCall(flow.SetFromOptions(grid));
  PetscCall(grid.SetUp(PETSC_FALSE));
  const PetscReal gravity[3] = {0, 0, 0};
  PetscCall(flow.SetUp(gravity));
  // dt proportional to h: the time error shrinks with h^2 too. |u| + |v| <= 1/0.6 m/s, so the Courant
  // number dt (|u| + |v|) / h stays below 0.42 at the default -cfl 0.5.
  const PetscInt  steps = (PetscInt)std::ceil(finalTime / (cfl * h / 2) - 1e-9);
  const PetscReal dt    = finalTime / steps;
  PetscCall(VisitCells(flow, ex, 0, 0, flow.FluidFraction(), false, nullptr));
  PetscCall(VisitCells(flow, ex, 1, 0, flow.Density(), false, nullptr));
  PetscCall(VisitCells(flow, ex, 2, 0, flow.Viscosity(), false, nullptr));
  PetscCall(VisitCells(flow, ex, 3, -0.5 * dt, flow.Pressure(), false, nullptr));
  PetscCall(flow.PropertiesChanged());
  // The exact U at the faces: div(eps U) = 0 holds to O(h^2) on the grid; the first projection removes the rest.
  for (int d = 0; d < 3; ++d) PetscCall(VisitVelocity(flow, ex, d, 0, true, nullptr, nullptr, nullptr));
  flow.SetForcing(ForcingFn, (void *)&ex);
  for (PetscInt s = 0; s < steps; ++s) PetscCall(flow.Step(s * dt, dt));
  PetscReal sumSq = 0, mx = 0, g[2];
  PetscInt  count = 0, gc;
  for (int d = 0; d < 2; ++d) PetscCall(VisitVelocity(flow, ex, d, finalTime, false, &sumSq, &mx, &count));
  PetscCallMPI(MPI_Allreduce(&sumSq, &g[0], 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(&mx, &g[1], 1, MPIU_REAL, MPI_MAX, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(&count, &gc, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  err->uRms  = std::sqrt(g[0] / gc);
  err->uMax  = g[1];
  err->steps = steps;
  PetscCall(VisitCells(flow, ex, 3, finalTime - 0.5 * dt, flow.Pressure(), true, &err->pRms));
  PetscCall(flow.Destroy());
  PetscCall(grid.Destroy());
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  PetscInt  list[8] = {16, 32, 64}, nlist = 8;
  PetscReal finalTime = 0.5, cfl = 0.5;
  PetscBool set;
  Exact     ex;

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
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-mu", &ex.mu0, nullptr));
  // The discretisation error is measured: the solvers' share must be negligible.
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-flow_pressure_ksp_rtol", &set));
  if (!set) PetscCall(SetOption("-flow_pressure_ksp_rtol", "1e-11"));
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-flow_viscous_ksp_rtol", &set));
  if (!set) PetscCall(SetOption("-flow_viscous_ksp_rtol", "1e-12"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Manufactured solution, variable eps, rho (ratio 3) and mu (%g to %g Pa s), t = %g s, dt = %g h / 2 m/s\n", (double)(0.5 * ex.mu0),
                        (double)(1.5 * ex.mu0), (double)finalTime, (double)cfl));
  std::vector<Errors> e(nlist);
  const PetscReal     minOrder = 1.8;
  int                 failures = 0;
  for (PetscInt g = 0; g < nlist; ++g) {
    PetscCall(RunGrid(list[g], finalTime, cfl, ex, &e[g]));
    char line[320];
    std::snprintf(line, sizeof line, "grid %3d^2: steps %4d  u RMS error %.4e  max %.4e  p RMS error %.4e", (int)list[g], (int)e[g].steps, (double)e[g].uRms,
                  (double)e[g].uMax, (double)e[g].pRms);
    std::string text = line;
    if (g) {
      const PetscReal r = std::log((PetscReal)list[g] / list[g - 1]);
      std::snprintf(line, sizeof line, "  orders u %.2f max %.2f p %.2f", (double)(std::log(e[g - 1].uRms / e[g].uRms) / r), (double)(std::log(e[g - 1].uMax / e[g].uMax) / r),
                    (double)(std::log(e[g - 1].pRms / e[g].pRms) / r));
      text += line;
    }
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s\n", text.c_str()));
  }
  if (nlist >= 2) {
    const PetscReal order = std::log(e[nlist - 2].uRms / e[nlist - 1].uRms) / std::log((PetscReal)list[nlist - 1] / list[nlist - 2]);
    failures              = !(order >= minOrder);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "F5 velocity RMS order between %d^2 and %d^2: %.2f (tolerance >= %.1f) %s\n", (int)list[nlist - 2], (int)list[nlist - 1],
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
    output_file: output/ex26_manufactured_1.out
  test:
    suffix: central
    nsize: 1
    args: -flow_advection central
TEST*/
