// The particle-grid maps of the coupling (docs/physics.md K1-K3) by one of three methods
// (-coupling_smoothing): kernel sums over the cells of each particle's support (KernelAverager.hpp), or
// a compact deposit followed by a grid smoothing with the kernel's variance (DiffusionSmoother.hpp):
// diffusion in pseudo-time, or a separable discrete Gaussian (GaussianFilter.hpp). The kernel's cost per particle grows as (cut-off/cell)^3, the diffusion's is per cell and
// the same for any width: `auto` picks by the estimate in Smoothing.cpp (scripts/smoothing-cost).
#pragma once

#include "vofdem/coupling/DiffusionSmoother.hpp"
#include "vofdem/coupling/KernelAverager.hpp"

namespace vofdem {

class Smoothing {
public:
  enum class Method { Kernel, Diffusion, Gaussian, Auto };
  struct Settings {
    Method   method = Method::Auto;
    PetscInt steps  = 2;    // backward-Euler pseudo-steps of the diffusion
    // auto: the Gaussian filter when the kernel's points summed over the particles exceed this many times
    // the grid's points times the filter's taps (sum over directions of 2R + 1), else the kernel sums. In the
    // bubbling bed the kernel took 5.8x the filter's time at a ratio of 1.7 and 6.6x at 3.3 (Smoothing.cpp).
    // The diffusion is not chosen by auto: the filter was cheaper at cell/d 0.5, 1 and 3.
    PetscReal crossover = 0.4;
  };
  // The kernel's variance per direction (m^2) for width H (quadrature of kernel::Weight; 8 H^2/13 smooth).
  static PetscReal KernelVariance(kernel::Shape s, PetscReal H, PetscReal truncation);
  static const char *Name(Method m) { return m == Method::Kernel ? "kernel" : m == Method::Diffusion ? "diffusion" : m == Method::Gaussian ? "gaussian" : "auto"; }

  // Reads the diffusion's KSP options (-coupling_smoothing_ksp_*, -coupling_smoothing_pc_*) with a
  // throw-away solver, so that they count as used at the options check before the particles are made.
  static PetscErrorCode ReadSolverOptions(MPI_Comm comm);
  // H: the width of the widest particle's kernel (the diffusion uses one width for all); particles:
  // the number of particles (auto's estimate). Collective.
  PetscErrorCode SetUp(const StaggeredGrid &sg, const KernelAverager::Settings &k, const Settings &s, PetscReal H, PetscReal margin, PetscInt particles);
  PetscErrorCode Destroy();
  bool           Diffusion() const { return diffusion_; }
  PetscInt       GhostWidth() const { return diffusion_ ? smoother_.GhostWidth() : kernel_.GhostWidth(); }
  const DiffusionSmoother &Smoother() const { return smoother_; }
  PetscReal      Spread(int e) const { return spread_[e]; }  // b_e^2 of the diffusion (m^2)

  // Excluded cells (KernelAverager::SetExcludedCells): the kernel sums only; the smoothers deposit everywhere.
  bool           CanExclude() const { return !diffusion_; }
  PetscErrorCode SetExcludedCells(Vec cells, PetscInt *count) { return kernel_.SetExcludedCells(diffusion_ ? nullptr : cells, count); }
  PetscErrorCode Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, const PetscReal *value, PetscInt stride, Vec out, bool walls = false, bool excluded = false) {
    return diffusion_ ? smoother_.Deposit(loc, n, x, H, value, stride, out, walls) : kernel_.Deposit(loc, n, x, H, value, stride, out, walls, excluded);
  }
  PetscErrorCode Average(int loc, Vec field, Vec weight, PetscInt n, const PetscReal *x, const PetscReal *H, PetscReal *out, PetscInt stride, bool walls = true) {
    return diffusion_ ? smoother_.Average(loc, field, weight, n, x, H, out, stride, walls) : kernel_.Average(loc, field, weight, n, x, H, out, stride, walls);
  }
  PetscErrorCode Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, PetscInt nf, const PetscReal *const value[], PetscInt stride, Vec out[], bool walls = false,
                         bool excluded = false) {
    return diffusion_ ? smoother_.Deposit(loc, n, x, H, nf, value, stride, out, walls) : kernel_.Deposit(loc, n, x, H, nf, value, stride, out, walls, excluded);
  }
  PetscErrorCode Average(int loc, PetscInt nf, const Vec field[], const Vec weight[], const bool walls[], PetscInt n, const PetscReal *x, const PetscReal *H, PetscReal *const out[],
                         PetscInt stride) {
    return diffusion_ ? smoother_.Average(loc, nf, field, weight, walls, n, x, H, out, stride) : kernel_.Average(loc, nf, field, weight, walls, n, x, H, out, stride);
  }

private:
  KernelAverager    kernel_;
  DiffusionSmoother smoother_;
  bool              diffusion_ = false;
  PetscReal         spread_[3] = {0, 0, 0};
};

}  // namespace vofdem
