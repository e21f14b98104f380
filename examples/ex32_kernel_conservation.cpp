static const char help[] = "Verification C3 (docs/verification.md) for the kernel projection (KernelAverager.hpp; docs/physics.md K1-K3): particles\n"
                           "scattered over a box of -grid_cells (default 16,12,10) cells, some within a twentieth of a cell of the walls, some\n"
                           "on and a little across the boundaries between ranks (as between migrations), deposit their volume to the cells,\n"
                           "a force to the faces of each velocity component (also with the wall faces taking part, as the coupling's force deposit\n"
                           "does: their half control volumes) and a heat to the cells. The grid totals must equal the particle\n"
                           "totals to a relative 1e-12, for the smooth kernel, the truncated Gaussian, the unresolved limit and the divided volume, with walls and\n"
                           "with a periodic direction. The kernel average of a constant field must be that constant (1e-14), and the sum of\n"
                           "the averages of a non-uniform field is printed (the same on any rank count). Exits non-zero on failure.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/coupling/KernelAverager.hpp"
#include "vofdem/grid/StaggeredGrid.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace {

const PetscReal kConserve = 1e-12, kConstant = 1e-14;
using vofdem::example::Verdict;

struct Lcg {  // the same sequence on every rank
  std::uint64_t s;
  PetscReal     Next() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (PetscReal)((s >> 11) * (1.0 / 9007199254740992.0));
  }
};

// A smooth non-uniform field at location loc (cells 3, faces 0-2).
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

// The sum of |f| over the wall faces of face location d (both ends; 0 along a periodic direction), over all ranks.
PetscErrorCode WallShare(const vofdem::StaggeredGrid &sg, int d, Vec f, PetscReal *all) {
  vofdem::LocalField F;
  PetscInt           s[3], m[3];
  PetscReal          mine = 0;

  PetscFunctionBeginUser;
  if (!sg.Base().Periodic(d)) {
    PetscCall(sg.GetGlobal(d, f, &F));
    sg.Owned(d, s, m);
    for (PetscInt k = s[2]; k < s[2] + m[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + m[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + m[0]; ++i) {
          const PetscInt q[3] = {i, j, k};
          if (q[d] == 0 || q[d] == sg.Points(d, d) - 1) mine += std::fabs(PetscRealPart(F.at(q)));
        }
    PetscCall(sg.RestoreGlobal(d, f, &F));
  }
  PetscCallMPI(MPI_Allreduce(&mine, all, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  PetscFunctionReturn(0);
}

PetscErrorCode RunCase(const char *name, vofdem::kernel::Shape shape, bool periodicX, PetscReal widthInCells, PetscInt *failures) {
  vofdem::Grid           grid;
  vofdem::StaggeredGrid  sg;
  vofdem::KernelAverager avg;
  PetscMPIInt            rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (periodicX) PetscCall(PetscOptionsSetValue(nullptr, "-grid_periodic", "x"));
  else PetscCall(PetscOptionsClearValue(nullptr, "-grid_periodic"));
  PetscCall(grid.SetFromOptions(PETSC_COMM_WORLD));
  PetscCall(grid.SetUp(PETSC_FALSE));
  PetscCall(sg.Create(grid));
  const PetscReal *h = grid.Spacing(), *lo = grid.Lower(), *up = grid.Upper();
  const PetscReal  H = widthInCells * h[0], margin = 0.4 * h[0];
  vofdem::KernelAverager::Settings set;
  set.shape = shape;
  PetscCall(avg.SetUp(sg, set, vofdem::kernel::Cutoff(shape, H, set.truncation), margin));

  // Particles: random ones, one near each corner (a twentieth of a cell from three walls), and a
  // column on the plane x = mid (a rank boundary on 2 ranks); each rank keeps those in its box, and
  // some of those then move up to 0.4 cells across it (particles stray between migrations).
  std::vector<PetscReal> x, H1, vol, force, heat;
  Lcg                    rng{12345};
  PetscReal              tot[5] = {0, 0, 0, 0, 0}, mag[5] = {0, 0, 0, 0, 0};
  auto add = [&](const PetscReal p[3]) {
    PetscReal f[3], v = 1e-9 * (0.5 + rng.Next()), q = 2 * rng.Next() - 0.5, shift = 0.8 * (rng.Next() - 0.5) * h[0];
    for (int e = 0; e < 3; ++e) f[e] = 2 * rng.Next() - 1;
    // The totals over all particles (every rank draws the same numbers).
    tot[0] += v, mag[0] += v;
    for (int e = 0; e < 3; ++e) tot[1 + e] += f[e], mag[1 + e] += std::fabs(f[e]);
    tot[4] += q, mag[4] += std::fabs(q);
    if (!grid.OwnsPoint(p)) return;
    PetscReal y[3] = {p[0] + shift, p[1], p[2]};
    if (!periodicX) y[0] = std::fmin(std::fmax(y[0], lo[0] + 0.01 * h[0]), up[0] - 0.01 * h[0]);
    else if (y[0] < lo[0]) y[0] += up[0] - lo[0];  // DEM wraps periodic positions into the box
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

  // Deposits and their totals.
  PetscReal sum[5];
  Vec       c;
  PetscCall(DMCreateGlobalVector(sg.Cells(), &c));
  PetscCall(VecSet(c, 0));
  PetscCall(avg.Deposit(3, n, x.data(), H1.data(), vol.data(), 1, c));
  PetscCall(VecSum(c, &sum[0]));
  PetscCall(VecSet(c, 0));
  PetscCall(avg.Deposit(3, n, x.data(), H1.data(), heat.data(), 1, c));
  PetscCall(VecSum(c, &sum[4]));
  PetscReal withWalls[3], onWalls[3];  // the coupling's force deposit: the wall faces' half control volumes take part
  for (int d = 0; d < 3; ++d) {
    Vec f;
    PetscCall(DMCreateGlobalVector(sg.Face(d), &f));
    PetscCall(VecSet(f, 0));
    PetscCall(avg.Deposit(d, n, x.data(), H1.data(), force.data() + d, 3, f, true));
    PetscCall(VecSum(f, &withWalls[d]));
    PetscCall(WallShare(sg, d, f, &onWalls[d]));
    PetscCall(VecSet(f, 0));
    PetscCall(avg.Deposit(d, n, x.data(), H1.data(), force.data() + d, 3, f));
    PetscCall(VecSum(f, &sum[1 + d]));
    // Without walls nothing may land on a wall face (its velocity is the boundary condition's).
    PetscReal all;
    PetscCall(WallShare(sg, d, f, &all));
    if (all != 0) {
      ++*failures;
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: force on the wall faces of component %c: %g FAIL\n", name, "xyz"[d], (double)all));
    }
    PetscCall(VecDestroy(&f));
  }
  const char *what[5] = {"volume", "force x", "force y", "force z", "heat"};
  PetscInt    total;
  PetscCallMPI(MPI_Allreduce(&n, &total, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: %d particles, kernel reach %d cells\n", name, (int)total, (int)avg.GhostWidth()));
  for (int k = 0; k < 5; ++k) {
    const PetscReal err = std::fabs(sum[k] - tot[k]) / mag[k];
    const bool      ok  = err < kConserve;
    *failures += !ok;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  %-7s grid total - particle total: %.1e of the particles' sum of magnitudes (tolerance %g) %s\n", what[k], (double)err,
                          (double)kConserve, Verdict(ok)));
  }

  {  // With the wall faces: conserved as well, and the particles next to the walls leave a share there.
    PetscReal worst = 0;
    bool      shared = true;
    for (int d = 0; d < 3; ++d) {
      worst = std::max(worst, std::fabs(withWalls[d] - tot[1 + d]) / mag[1 + d]);
      if (!grid.Periodic(d) && !(onWalls[d] > 0)) shared = false;
    }
    const bool ok = worst < kConserve && shared;
    *failures += !ok;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  force with the wall faces: grid total - particle total: %.1e at most (tolerance %g); |share| on the wall faces x, y, z %.4e, %.4e, %.4e %s\n",
                          (double)worst, (double)kConserve, (double)onWalls[0], (double)onWalls[1], (double)onWalls[2], Verdict(ok)));
  }

  // Averages: a constant field (eps-weighted like K1), and a non-uniform one.
  std::vector<PetscReal> out(n);
  Vec                    w;
  PetscCall(VecDuplicate(c, &w));
  PetscCall(FillField(sg, 3, w, false));  // a positive non-uniform weight
  for (int loc = 0; loc < 4; ++loc) {
    Vec f, wf = nullptr;
    PetscCall(DMCreateGlobalVector(sg.Location(loc), &f));
    if (loc == 3) wf = w;
    PetscCall(FillField(sg, loc, f, true));
    PetscCall(avg.Average(loc, f, wf, n, x.data(), H1.data(), out.data(), 1));
    PetscReal dev = 0, all;
    for (PetscInt p = 0; p < n; ++p) dev = std::fmax(dev, std::fabs(out[p] - 3.7) / 3.7);
    PetscCallMPI(MPI_Allreduce(&dev, &all, 1, MPIU_REAL, MPIU_MAX, PETSC_COMM_WORLD));
    PetscCall(FillField(sg, loc, f, false));
    PetscCall(avg.Average(loc, f, wf, n, x.data(), H1.data(), out.data(), 1));
    PetscReal s = 0, sAll;
    for (PetscInt p = 0; p < n; ++p) s += out[p];
    PetscCallMPI(MPI_Allreduce(&s, &sAll, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
    const bool ok = all < kConstant;
    *failures += !ok;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  average at %-7s constant field: deviation %.1e (tolerance %g) %s; non-uniform field: sum over particles %.12e\n",
                          loc == 3 ? "cells" : loc == 0 ? "x faces" : loc == 1 ? "y faces" : "z faces", (double)all, (double)kConstant, Verdict(ok), (double)sAll));
    PetscCall(VecDestroy(&f));
  }
  PetscCall(VecDestroy(&w));
  PetscCall(VecDestroy(&c));
  PetscCall(avg.Destroy());
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
  PetscBool set;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-grid_cells", &set));
  if (!set) PetscCall(PetscOptionsSetValue(nullptr, "-grid_cells", "16,12,10"));
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-grid_upper", &set));
  if (!set) PetscCall(PetscOptionsSetValue(nullptr, "-grid_upper", "1.6,1.2,1.0"));
  using vofdem::kernel::Shape;
  PetscCall(RunCase("smooth kernel, H = 1.2 cells, walls", Shape::Smooth, false, 1.2, &failures));
  PetscCall(RunCase("smooth kernel, H = 0.3 cells, walls", Shape::Smooth, false, 0.3, &failures));
  PetscCall(RunCase("truncated Gaussian, H = 1.5 cells, periodic in x", Shape::Truncated, true, 1.5, &failures));
  PetscCall(RunCase("unresolved (containing cell), walls", Shape::Unresolved, false, 1.0, &failures));
  PetscCall(RunCase("unresolved (containing cell), periodic in x", Shape::Unresolved, true, 1.0, &failures));
  PetscCall(RunCase("divided volume (radius 0.45 cells), walls", Shape::Divided, false, 0.45, &failures));
  PetscCall(RunCase("divided volume (radius 0.45 cells), periodic in x", Shape::Divided, true, 0.45, &failures));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "C3 kernel conservation: %s\n", failures ? "FAIL" : "ok"));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}
/*TEST
  rtol: 1e-10
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    output_file: output/ex32_kernel_conservation_1.out
TEST*/
