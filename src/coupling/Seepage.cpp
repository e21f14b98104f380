// The seepage coupling (Seepage.hpp; docs/physics.md (F11)): options, set-up, the particles' eps and the
// seepage force on them.
#include "vofdem/coupling/Seepage.hpp"

#include "vofdem/base/NamedTable.hpp"
#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

PetscErrorCode Seepage::SetFromOptions(MPI_Comm comm) {
  PetscFunctionBeginUser;
  comm_ = comm;
  PetscOptionsBegin(comm, "seepage_", "Seepage coupling: particles in the Darcy head equation, its seepage force on them (-physics dem,darcy; docs/physics.md F11)", "Seepage");
  {
    OptionReader             opt(PetscOptionsObject);
    std::vector<std::string> k    = {kernelName_};
    const std::string        help = "Kernel of the particles' volume deposit and of their share of the force: " + table::Help(kernel::kKernels);
    PetscCall(opt.NameList("-kernel", help.c_str(), table::Names(kernel::kKernels), &k));
    if (k.size() != 1) VofdemInputError(comm, "option -seepage_kernel: give one kernel (%s)", table::Choices(kernel::kKernels).c_str());
    kernelName_   = k[0];
    kernel_.shape = kernel::kKernels[table::Find(kernel::kKernels, kernelName_)].shape;
    PetscCall(opt.Real("-kernel_width", "Kernel width H in particle diameters (H = kappa d, K1)", "-", &kappa_, RealRange::Positive()));
    PetscCall(opt.Real("-kernel_min_width", "Smallest kernel width in cells: H = max(kappa d, this x the largest cell spacing)", "cells", &minWidthCells_, RealRange::Closed(0.5, 1e6)));
    PetscCall(opt.Real("-kernel_truncation", "Cut-off of the truncated Gaussian kernel, in widths H", "-", &kernel_.truncation, RealRange::LeftOpen(0, 10)));
    PetscCall(opt.Real("-min_fluid_fraction", "Floor of eps in the head equation (cells below it are counted in the monitor)", "-", &minEps_, RealRange::LeftOpen(0, 1)));
    PetscCall(opt.Bool("-buoyancy", "The hydrostatic pore pressure's buoyancy -rho_w V g on each particle (the head equation holds the excess pressure only)", &buoyancy_));
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscReal Seepage::KernelWidth(PetscReal d) const {
  if (kernel_.shape == kernel::Shape::Divided) return d / 2;  // the divided volume reaches the sphere's radius (Kernel.hpp)
  const PetscReal *h = grid_->Spacing();
  return std::max(kappa_ * d, minWidthCells_ * std::max(h[0], std::max(h[1], h[2])));
}

PetscErrorCode Seepage::SetUp(const Grid &grid, Darcy &darcy, Dem &dem, const PetscReal gravity[3]) {
  PetscFunctionBeginUser;
  grid_  = &grid;
  darcy_ = &darcy;
  dem_   = &dem;
  for (int d = 0; d < 3; ++d) g_[d] = gravity ? gravity[d] : 0;
  for (int e = 0; e < 3; ++e)
    if (2 * dem.MaxRadius() > grid.Upper()[e] - grid.Lower()[e])
      VofdemInputError(comm_, "seepage: particles of diameter %g m are larger than the box (%g m in %c)", (double)(2 * dem.MaxRadius()), (double)(grid.Upper()[e] - grid.Lower()[e]), "xyz"[e]);
  PetscCall(sg_.Create(grid));
  const PetscReal Hmax = KernelWidth(2 * dem.MaxRadius());
  PetscCall(avg_.SetUp(sg_, kernel_, kernel::Cutoff(kernel_.shape, Hmax, kernel_.truncation), 0.5 * dem.Skin() + 1e-12));
  PetscCall(DMCreateGlobalVector(sg_.Cells(), &solid_));
  for (Vec &f : field_) PetscCall(VecDuplicate(solid_, &f));
  PetscInt a, b;
  PetscCall(VecGetLocalSize(solid_, &a));
  PetscCall(VecGetLocalSize(darcy.FluidFraction(), &b));
  PetscCheck(a == b, comm_, PETSC_ERR_PLIB, "seepage: the kernel's cells (%d) and the head equation's (%d) differ on this rank", (int)a, (int)b);
  dem.SetFluidCoupled(true);
  PetscFunctionReturn(0);
}

PetscErrorCode Seepage::Project() {
  ParticleArrays     a;
  const PetscScalar *s;
  PetscScalar       *e;
  PetscInt           m, clipped = 0;
  PetscReal          local = 0, lo = 1, sums[2], all[2];

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing();
  const PetscReal  Vc = h[0] * h[1] * h[2];
  PetscCall(dem_->Particles().GetArrays(&a));
  H_.resize(a.n);
  volume_.resize(a.n);
  for (PetscInt p = 0; p < a.n; ++p) {
    H_[p]      = KernelWidth(2 * a.radius[p]);
    volume_[p] = 4.0 / 3.0 * PETSC_PI * a.radius[p] * a.radius[p] * a.radius[p];
    local += volume_[p];
  }
  PetscCall(VecSet(solid_, 0));
  PetscCall(avg_.Deposit(3, a.n, a.x, H_.data(), volume_.data(), 1, solid_));
  PetscCall(dem_->Particles().RestoreArrays(&a));
  PetscCall(VecGetLocalSize(solid_, &m));
  PetscCall(VecGetArrayRead(solid_, &s));
  PetscCall(VecGetArray(darcy_->FluidFraction(), &e));
  for (PetscInt c = 0; c < m; ++c) {
    PetscReal v = 1 - PetscRealPart(s[c]) / Vc;
    if (v < minEps_) v = minEps_, ++clipped;
    lo   = std::min(lo, v);
    e[c] = v;
  }
  PetscCall(VecRestoreArray(darcy_->FluidFraction(), &e));
  PetscCall(VecRestoreArrayRead(solid_, &s));
  sums[0] = local;
  PetscCall(VecSum(solid_, &sums[1]));
  PetscCallMPI(MPI_Allreduce(sums, all, 1, MPIU_REAL, MPIU_SUM, comm_));
  last_.particleVolume  = all[0];
  last_.projectedVolume = sums[1];
  PetscCallMPI(MPI_Allreduce(&clipped, &last_.clipped, 1, MPIU_INT, MPI_SUM, comm_));
  PetscCallMPI(MPI_Allreduce(&lo, &last_.minEps, 1, MPIU_REAL, MPIU_MIN, comm_));
  PetscFunctionReturn(0);
}

PetscErrorCode Seepage::Forces() {
  ParticleArrays a;
  PetscInt       m;
  PetscReal      grid[3] = {0, 0, 0}, sums[6] = {0, 0, 0, 0, 0, 0}, all[6];

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing();
  const PetscReal  Vc = h[0] * h[1] * h[2];
  const Vec       *gradient = darcy_->PressureGradient();  // -grad p at the cells
  PetscCall(VecGetLocalSize(solid_, &m));
  {
    const PetscScalar *s, *g[3];
    PetscScalar       *f[3];
    PetscCall(VecGetArrayRead(solid_, &s));
    for (int d = 0; d < 3; ++d) PetscCall(VecGetArrayRead(gradient[d], &g[d]));
    for (int d = 0; d < 3; ++d) PetscCall(VecGetArray(field_[d], &f[d]));
    for (PetscInt c = 0; c < m; ++c) {
      const PetscReal solid = PetscRealPart(s[c]);
      for (int d = 0; d < 3; ++d) {
        f[d][c] = solid > 0 ? PetscRealPart(g[d][c]) * Vc / solid : 0;
        if (solid > 0) grid[d] += PetscRealPart(g[d][c]) * Vc;
      }
    }
    for (int d = 0; d < 3; ++d) PetscCall(VecRestoreArray(field_[d], &f[d]));
    for (int d = 0; d < 3; ++d) PetscCall(VecRestoreArrayRead(gradient[d], &g[d]));
    PetscCall(VecRestoreArrayRead(solid_, &s));
  }
  PetscCall(dem_->Particles().GetArrays(&a));
  H_.resize(a.n);
  volume_.resize(a.n);
  share_.assign(3 * (size_t)a.n, 0);
  for (PetscInt p = 0; p < a.n; ++p) {
    H_[p]      = KernelWidth(2 * a.radius[p]);
    volume_[p] = 4.0 / 3.0 * PETSC_PI * a.radius[p] * a.radius[p] * a.radius[p];
  }
  // The kernel average with the deposit's normalised weights (cells take part alike in both: no wall faces).
  const Vec        weights[3] = {nullptr, nullptr, nullptr};
  const bool       walls[3]   = {true, true, true};
  PetscReal *const out[3]     = {share_.data(), share_.data() + 1, share_.data() + 2};
  PetscCall(avg_.Average(3, 3, field_, weights, walls, a.n, a.x, H_.data(), out, 3));
  const PetscReal rhoW = darcy_->Density();
  for (PetscInt p = 0; p < a.n; ++p) {
    a.fluidDrag[p] = 0;
    if (a.fluidAddedMass) a.fluidAddedMass[p] = 0;
    if (a.fluidRotationalDrag) a.fluidRotationalDrag[p] = 0;
    if (a.fluidSurfacePlane)
      for (int k = 0; k < 4; ++k) a.fluidSurfacePlane[4 * p + k] = 0;
    for (int d = 0; d < 3; ++d) {
      const PetscReal F = volume_[p] * share_[3 * p + d];
      sums[d] += F;
      a.fluidVelocity[3 * p + d] = 0;
      a.fluidForce[3 * p + d]    = F - (buoyancy_ ? rhoW * volume_[p] * g_[d] : 0);
    }
  }
  PetscCall(dem_->Particles().RestoreArrays(&a));
  for (int d = 0; d < 3; ++d) sums[3 + d] = grid[d];
  PetscCallMPI(MPI_Allreduce(sums, all, 6, MPIU_REAL, MPIU_SUM, comm_));
  for (int d = 0; d < 3; ++d) last_.force[d] = all[d], last_.gridForce[d] = all[3 + d];
  PetscFunctionReturn(0);
}

PetscErrorCode Seepage::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "seepage: kernel %s, H = max(%g d, %g cells); eps floor %g; each particle's share of its cells' -grad p V_c%s (docs/physics.md F11)\n",
                                   kernelName_.c_str(), (double)kappa_, (double)minWidthCells_, (double)minEps_, buoyancy_ ? " plus the buoyancy -rho_w V g" : ""));
  PetscFunctionReturn(0);
}

PetscErrorCode Seepage::Destroy() {
  PetscFunctionBeginUser;
  for (Vec *v : {&solid_, &field_[0], &field_[1], &field_[2]}) PetscCall(VecDestroy(v));
  PetscCall(avg_.Destroy());
  PetscCall(sg_.Destroy());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
