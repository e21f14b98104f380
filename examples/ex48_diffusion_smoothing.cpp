static const char help[] = "Verification of the diffusion-based smoothing (DiffusionSmoother.hpp, Smoothing.hpp; docs/physics.md K1, K3; Sun & Xiao\n"
                           "2015), the alternative to kernel sums. (1) Conservation (C3): particles scattered over a 16 x 12 x 10 box, some a\n"
                           "twentieth of a cell from the walls and some straying across rank boundaries, deposit volume and heat to the cells\n"
                           "and a force to the faces; the grid totals must equal the particle totals to a relative 1e-12, with walls and with\n"
                           "a periodic direction; nothing may land on a wall face. (2) Adjointness: the average (fluid -> particle) is the\n"
                           "transpose of the deposit: sum_p a_p <f>_p = sum_J f_J (deposit of a)_J to 1e-12 (the default\n"
                           "Chebyshev solve is a fixed symmetric polynomial of the matrix).\n"
                           "(3) Constant fields average to the constant (1e-12). (4) Gaussian test: one particle deep in a 48^3 box; the\n"
                           "deposit's first moment must be the particle's position and its second moment per direction b^2 + f(1 - f) h^2\n"
                           "(b^2 = sigma^2 - h^2/6 the diffusion's spread, f the particle's offset between points, sigma^2 = 8 H^2/13 the smooth\n"
                           "kernel's variance), to 1e-6 relative (solved to 1e-10 here; the walls 24 cells away cut tails below that); the kernel's own discrete\n"
                           "second moment is printed beside it. -method gaussian runs the same checks on the separable discrete Gaussian\n"
                           "(GaussianFilter.hpp) instead of the diffusion (its variance is exact: the moments to round-off). Exits non-zero on failure.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/coupling/Smoothing.hpp"
#include "vofdem/grid/StaggeredGrid.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace {

const PetscReal kConserve = 1e-12, kAdjoint = 1e-12, kConstant = 1e-12, kMoment = 1e-6;
// -method: the grid smoothing under test.
vofdem::Smoothing::Method g_method = vofdem::Smoothing::Method::Diffusion;
using vofdem::example::Verdict;

struct Lcg {  // the same sequence on every rank
  std::uint64_t s;
  PetscReal     Next() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (PetscReal)((s >> 11) * (1.0 / 9007199254740992.0));
  }
};

PetscErrorCode FillField(const vofdem::StaggeredGrid &sg, int loc, Vec v, bool constant) {
  vofdem::LocalField f;
  PetscInt           s[3], n[3];

  PetscFunctionBeginUser;
  const PetscReal *h = sg.Base().Spacing(), *lo = sg.Base().Lower();
  PetscCall(sg.GetGlobal(loc, v, &f));
  sg.Owned(loc, s, n);
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscInt q[3] = {i, j, k};
        PetscReal      x[3];
        for (int e = 0; e < 3; ++e) x[e] = lo[e] + (q[e] + (loc == e ? 0 : 0.5)) * h[e];
        f.at(q) = constant ? 3.7 : 1 + std::sin(3 * x[0]) * std::cos(2 * x[1]) + x[2] * x[2];
      }
  PetscCall(sg.RestoreGlobal(loc, v, &f));
  PetscFunctionReturn(0);
}

PetscErrorCode SetGrid(bool periodicX, const char *cells, const char *upper, vofdem::Grid &grid, vofdem::StaggeredGrid &sg) {
  PetscFunctionBeginUser;
  if (periodicX) PetscCall(PetscOptionsSetValue(nullptr, "-grid_periodic", "x"));
  else PetscCall(PetscOptionsClearValue(nullptr, "-grid_periodic"));
  PetscCall(PetscOptionsSetValue(nullptr, "-grid_cells", cells));
  PetscCall(PetscOptionsSetValue(nullptr, "-grid_upper", upper));
  PetscCall(grid.SetFromOptions(PETSC_COMM_WORLD));
  PetscCall(grid.SetUp(PETSC_FALSE));
  PetscCall(sg.Create(grid));
  PetscFunctionReturn(0);
}

PetscErrorCode Conservation(const char *name, bool periodicX, PetscReal widthInCells, PetscInt steps, PetscInt *failures) {
  vofdem::Grid          grid;
  vofdem::StaggeredGrid sg;
  vofdem::Smoothing     sm;

  PetscFunctionBeginUser;
  PetscCall(SetGrid(periodicX, "16,12,10", "1.6,1.2,1.0", grid, sg));
  const PetscReal *h = grid.Spacing(), *lo = grid.Lower(), *up = grid.Upper();
  const PetscReal  H = widthInCells * h[0], margin = 0.4 * h[0];
  vofdem::KernelAverager::Settings k;
  vofdem::Smoothing::Settings      set;
  set.method = g_method;
  set.steps  = steps;
  PetscCall(sm.SetUp(sg, k, set, H, margin, 0));

  std::vector<PetscReal> x, H1, vol, force, heat;
  Lcg                    rng{12345};
  PetscReal              tot[5] = {0, 0, 0, 0, 0}, mag[5] = {0, 0, 0, 0, 0};
  auto add = [&](const PetscReal p[3]) {
    PetscReal f[3], v = 1e-9 * (0.5 + rng.Next()), q = 2 * rng.Next() - 0.5, shift = 0.8 * (rng.Next() - 0.5) * h[0];
    for (int e = 0; e < 3; ++e) f[e] = 2 * rng.Next() - 1;
    tot[0] += v, mag[0] += v;
    for (int e = 0; e < 3; ++e) tot[1 + e] += f[e], mag[1 + e] += std::fabs(f[e]);
    tot[4] += q, mag[4] += std::fabs(q);
    if (!grid.OwnsPoint(p)) return;
    PetscReal y[3] = {p[0] + shift, p[1], p[2]};
    if (!periodicX) y[0] = std::fmin(std::fmax(y[0], lo[0] + 0.01 * h[0]), up[0] - 0.01 * h[0]);
    else if (y[0] < lo[0]) y[0] += up[0] - lo[0];
    else if (y[0] >= up[0]) y[0] -= up[0] - lo[0];
    for (int e = 0; e < 3; ++e) x.push_back(y[e]), force.push_back(f[e]);
    H1.push_back(H), vol.push_back(v), heat.push_back(q);
  };
  for (int p = 0; p < 300; ++p) {
    PetscReal y[3];
    for (int e = 0; e < 3; ++e) y[e] = lo[e] + rng.Next() * (up[e] - lo[e]);
    add(y);
  }
  for (int c = 0; c < 8; ++c) {
    PetscReal y[3];
    for (int e = 0; e < 3; ++e) y[e] = (c >> e) & 1 ? up[e] - 0.05 * h[e] : lo[e] + 0.05 * h[e];
    add(y);
  }
  for (int j = 0; j < 10; ++j) {
    const PetscReal y[3] = {0.5 * (lo[0] + up[0]), lo[1] + (j + 0.3) * (up[1] - lo[1]) / 10, lo[2] + (0.37 + 0.05 * j) * (up[2] - lo[2])};
    add(y);
  }
  const PetscInt n = (PetscInt)H1.size();

  PetscReal sum[5];
  Vec       c, f;
  PetscCall(DMCreateGlobalVector(sg.Cells(), &c));
  PetscCall(VecSet(c, 0));
  PetscCall(sm.Deposit(3, n, x.data(), H1.data(), vol.data(), 1, c));
  PetscCall(VecSum(c, &sum[0]));
  PetscCall(VecSet(c, 0));
  PetscCall(sm.Deposit(3, n, x.data(), H1.data(), heat.data(), 1, c));
  PetscCall(VecSum(c, &sum[4]));
  // Adjointness on the cells: sum_p heat_p <f>_p against f . (deposit of heat).
  std::vector<PetscReal> out(n);
  PetscReal              adj[2] = {0, 0}, adjAll[2];
  PetscCall(VecDuplicate(c, &f));
  PetscCall(FillField(sg, 3, f, false));
  PetscCall(VecDot(f, c, &adj[1]));
  PetscCall(sm.Average(3, f, nullptr, n, x.data(), H1.data(), out.data(), 1));
  for (PetscInt p = 0; p < n; ++p) adj[0] += heat[p] * out[p];
  PetscCallMPI(MPI_Allreduce(adj, adjAll, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  adjAll[1] = adj[1];
  PetscCall(VecDestroy(&f));
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMCreateGlobalVector(sg.Face(d), &f));
    PetscCall(VecSet(f, 0));
    PetscCall(sm.Deposit(d, n, x.data(), H1.data(), force.data() + d, 3, f));
    PetscCall(VecSum(f, &sum[1 + d]));
    if (!grid.Periodic(d)) {
      vofdem::LocalField F;
      PetscInt           s[3], m[3];
      PetscReal          onWall = 0, all;
      PetscCall(sg.GetGlobal(d, f, &F));
      sg.Owned(d, s, m);
      for (PetscInt kk = s[2]; kk < s[2] + m[2]; ++kk)
        for (PetscInt j = s[1]; j < s[1] + m[1]; ++j)
          for (PetscInt i = s[0]; i < s[0] + m[0]; ++i) {
            const PetscInt q[3] = {i, j, kk};
            if (q[d] == 0 || q[d] == sg.Points(d, d) - 1) onWall += std::fabs(PetscRealPart(F.at(q)));
          }
      PetscCall(sg.RestoreGlobal(d, f, &F));
      PetscCallMPI(MPI_Allreduce(&onWall, &all, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
      if (all != 0) {
        ++*failures;
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: force on the wall faces of component %c: %g FAIL\n", name, "xyz"[d], (double)all));
      }
    }
    PetscCall(VecDestroy(&f));
  }
  const char *what[5] = {"volume", "force x", "force y", "force z", "heat"};
  PetscInt    total;
  PetscCallMPI(MPI_Allreduce(&n, &total, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s %s: %d particles, spread b = %.4f cells in x, %d %s\n", vofdem::Smoothing::Name(g_method), name, (int)total, (double)(std::sqrt(sm.Spread(0)) / h[0]),
                        (int)(g_method == vofdem::Smoothing::Method::Gaussian ? sm.Smoother().FilterRadius(0) : steps), g_method == vofdem::Smoothing::Method::Gaussian ? "taps per side" : "pseudo-steps"));
  for (int q = 0; q < 5; ++q) {
    const PetscReal err = std::fabs(sum[q] - tot[q]) / mag[q];
    const bool      ok  = err < kConserve;
    *failures += !ok;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  %-7s grid total - particle total: %.1e of the particles' sum of magnitudes (tolerance %g) %s\n", what[q], (double)err, (double)kConserve, Verdict(ok)));
  }
  {
    const PetscReal err = std::fabs(adjAll[0] - adjAll[1]) / std::fabs(adjAll[1]);
    const bool      ok  = err < kAdjoint;
    *failures += !ok;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  adjoint: sum_p a_p <f>_p = %.10e, f . deposit(a) = %.10e: relative difference %.1e (tolerance %g) %s\n", (double)adjAll[0], (double)adjAll[1],
                          (double)err, (double)kAdjoint, Verdict(ok)));
  }
  Vec w;
  PetscCall(VecDuplicate(c, &w));
  PetscCall(FillField(sg, 3, w, false));
  for (int loc = 0; loc < 4; ++loc) {
    Vec g, wf = loc == 3 ? w : nullptr;
    PetscCall(DMCreateGlobalVector(sg.Location(loc), &g));
    PetscCall(FillField(sg, loc, g, true));
    PetscCall(sm.Average(loc, g, wf, n, x.data(), H1.data(), out.data(), 1));
    PetscReal dev = 0, all;
    for (PetscInt p = 0; p < n; ++p) dev = std::fmax(dev, std::fabs(out[p] - 3.7) / 3.7);
    PetscCallMPI(MPI_Allreduce(&dev, &all, 1, MPIU_REAL, MPIU_MAX, PETSC_COMM_WORLD));
    PetscCall(FillField(sg, loc, g, false));
    PetscCall(sm.Average(loc, g, wf, n, x.data(), H1.data(), out.data(), 1));
    PetscReal s = 0, sAll;
    for (PetscInt p = 0; p < n; ++p) s += out[p];
    PetscCallMPI(MPI_Allreduce(&s, &sAll, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
    const bool ok = all < kConstant;
    *failures += !ok;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  average at %-7s constant field%s: deviation %.1e (tolerance %g) %s; non-uniform field: sum over particles %.10e\n",
                          loc == 3 ? "cells" : loc == 0 ? "x faces" : loc == 1 ? "y faces" : "z faces", wf ? " (weighted)" : "", (double)all, (double)kConstant, Verdict(ok), (double)sAll));
    PetscCall(VecDestroy(&g));
  }
  PetscCall(VecDestroy(&w));
  PetscCall(VecDestroy(&c));
  PetscCall(sm.Destroy());
  PetscCall(sg.Destroy());
  PetscCall(grid.Destroy());
  PetscFunctionReturn(0);
}

// The first and second moments of one particle's deposit per direction, about its position.
PetscErrorCode Moments(const vofdem::StaggeredGrid &sg, Vec c, const PetscReal xp[3], PetscReal m1[3], PetscReal m2[3]) {
  vofdem::LocalField F;
  PetscInt           s[3], n[3];
  PetscReal          loc[6] = {0, 0, 0, 0, 0, 0}, all[6];

  PetscFunctionBeginUser;
  const PetscReal *h = sg.Base().Spacing(), *lo = sg.Base().Lower();
  PetscCall(sg.GetGlobal(3, c, &F));
  sg.Owned(3, s, n);
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscInt  q[3] = {i, j, k};
        const PetscReal v    = PetscRealPart(F.at(q));
        for (int e = 0; e < 3; ++e) {
          const PetscReal dx = lo[e] + (q[e] + 0.5) * h[e] - xp[e];
          loc[e] += v * dx, loc[3 + e] += v * dx * dx;
        }
      }
  PetscCall(sg.RestoreGlobal(3, c, &F));
  PetscCallMPI(MPI_Allreduce(loc, all, 6, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  for (int e = 0; e < 3; ++e) m1[e] = all[e], m2[e] = all[3 + e];
  PetscFunctionReturn(0);
}

PetscErrorCode Gaussian(PetscReal widthInCells, PetscInt steps, PetscInt *failures) {
  vofdem::Grid          grid;
  vofdem::StaggeredGrid sg;
  vofdem::Smoothing     sm, kern;

  PetscFunctionBeginUser;
  PetscCall(SetGrid(false, "48,48,48", "1,1,1", grid, sg));
  const PetscReal *h = grid.Spacing();
  const PetscReal  H = widthInCells * h[0];
  vofdem::KernelAverager::Settings k;
  vofdem::Smoothing::Settings      set;
  set.method = g_method;
  set.steps  = steps;
  // The operator's identity, so the solves are pinned to a tolerance of 1e-10 (the default 1e-6 only shapes the
  // smoothing). In a 32^3 box the zero-flux walls, 16 cells away, cut the 4-step kernel's tails by 2e-5 at
  // H = 3 cells: hence 48^3.
  PetscBool given;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-coupling_smoothing_ksp_rtol", &given));
  if (!given) PetscCall(PetscOptionsSetValue(nullptr, "-coupling_smoothing_ksp_rtol", "1e-10"));
  PetscCall(sm.SetUp(sg, k, set, H, 0, 1));
  if (!given) PetscCall(PetscOptionsClearValue(nullptr, "-coupling_smoothing_ksp_rtol"));
  set.method = vofdem::Smoothing::Method::Kernel;
  PetscCall(kern.SetUp(sg, k, set, H, 0, 1));
  const PetscReal xp[3] = {0.5 + 0.3 * h[0], 0.47 + 0.05 * h[1], 0.52 - 0.41 * h[2]}, one = 1;
  const PetscInt  n     = grid.OwnsPoint(xp) ? 1 : 0;
  Vec             c;
  PetscReal       m1[3], m2[3], k1[3], k2[3];
  PetscCall(DMCreateGlobalVector(sg.Cells(), &c));
  PetscCall(VecSet(c, 0));
  PetscCall(sm.Deposit(3, n, xp, &H, &one, 1, c));
  PetscCall(Moments(sg, c, xp, m1, m2));
  PetscCall(VecSet(c, 0));
  PetscCall(kern.Deposit(3, n, xp, &H, &one, 1, c));
  PetscCall(Moments(sg, c, xp, k1, k2));
  const PetscReal sigma2 = vofdem::Smoothing::KernelVariance(k.shape, H, k.truncation);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Gaussian test (%s): H = %g cells, %d pseudo-steps: kernel variance sigma^2 = %.6f cells^2 (8 H^2/13 = %.6f)\n", vofdem::Smoothing::Name(g_method), (double)widthInCells, (int)steps,
                        (double)(sigma2 / (h[0] * h[0])), (double)(8 * widthInCells * widthInCells / 13)));
  for (int e = 0; e < 3; ++e) {
    const PetscReal cell = (xp[e] - grid.Lower()[e]) / h[e] - 0.5, f = cell - std::floor(cell);
    const PetscReal expect = sm.Spread(e) + f * (1 - f) * h[e] * h[e];
    const PetscReal err = std::fabs(m2[e] - expect) / expect, shift = std::fabs(m1[e]) / h[e];
    const bool      ok  = err < kMoment && shift < kMoment;
    *failures += !ok;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  %c: centroid offset %.1e cells; second moment %.8f cells^2, expected b^2 + f(1-f) h^2 = %.8f: relative error %.1e (tolerance %g) %s; smooth kernel's own %.6f\n",
                          "xyz"[e], (double)shift, (double)(m2[e] / (h[e] * h[e])), (double)(expect / (h[e] * h[e])), (double)err, (double)kMoment, Verdict(ok),
                          (double)(k2[e] / (h[e] * h[e]))));
  }
  PetscCall(VecDestroy(&c));
  PetscCall(kern.Destroy());
  PetscCall(sm.Destroy());
  PetscCall(sg.Destroy());
  PetscCall(grid.Destroy());
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  PetscInt failures = 0;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscBool gaussian = PETSC_FALSE;
  {
    char      method[32] = "diffusion";
    PetscBool set;
    PetscCall(PetscOptionsGetString(nullptr, nullptr, "-method", method, sizeof method, &set));
    if (std::string(method) != "diffusion" && std::string(method) != "gaussian") VofdemInputError(PETSC_COMM_WORLD, "option -method: diffusion or gaussian, not '%s'", method);
    gaussian = std::string(method) == "gaussian" ? PETSC_TRUE : PETSC_FALSE;
  }
  g_method = gaussian ? vofdem::Smoothing::Method::Gaussian : vofdem::Smoothing::Method::Diffusion;
  PetscCall(Conservation("H = 2 cells, walls", false, 2.0, 2, &failures));
  PetscCall(Conservation("H = 1.2 cells, periodic in x", true, 1.2, 1, &failures));
  PetscCall(Gaussian(2.0, 2, &failures));
  PetscCall(Gaussian(3.0, 4, &failures));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s smoothing: %s\n", vofdem::Smoothing::Name(g_method), failures ? "FAIL" : "ok"));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}
/*TEST
  rtol: 1e-8
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    output_file: output/ex48_diffusion_smoothing_1.out
  test:
    suffix: gaussian_1
    nsize: 1
    args: -method gaussian
  test:
    suffix: gaussian_2
    nsize: 2
    args: -method gaussian
    output_file: output/ex48_diffusion_smoothing_gaussian_1.out
TEST*/
