#include "vofdem/coupling/Smoothing.hpp"

#include "vofdem/base/Runtime.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

// sigma^2 = (1/3) int r^4 k dr / int r^2 k dr (the 3-D second moment shared by three directions), by
// Simpson's rule over the support (the smooth kernel: rc^2/13 = 8 H^2/13 in closed form).
PetscReal Smoothing::KernelVariance(kernel::Shape s, PetscReal H, PetscReal truncation) {
  if (kernel::CellBased(s) || s == kernel::Shape::Linear) return 0;
  const PetscReal rc = kernel::Cutoff(s, H, truncation);
  const int       M  = 2000;
  PetscReal       m2 = 0, m4 = 0;
  for (int i = 0; i <= M; ++i) {
    const PetscReal r = rc * i / M, w = (i == 0 || i == M) ? 1 : (i % 2 ? 4 : 2);
    const PetscReal k = kernel::Weight(s, r * r, H, rc * (1 + 1e-15));
    m2 += w * k * r * r;
    m4 += w * k * r * r * r * r;
  }
  return m4 / m2 / 3;
}

PetscErrorCode Smoothing::SetUp(const StaggeredGrid &sg, const KernelAverager::Settings &k, const Settings &s, PetscReal H, PetscReal margin, PetscInt particles) {
  const Grid &grid = sg.Base();

  PetscFunctionBeginUser;
  const PetscReal *h     = grid.Spacing();
  const PetscReal  sigma2 = KernelVariance(k.shape, H, k.truncation);
  bool             fits   = !kernel::CellBased(k.shape);
  for (int e = 0; e < 3; ++e) {
    spread_[e] = sigma2 - h[e] * h[e] / 6;  // the tent's own variance, h^2/6 on average, comes on top
    if (!(spread_[e] > 0)) fits = false;
  }
  if (s.method == Method::Diffusion || s.method == Method::Gaussian) {
    const char *name = Name(s.method);
    if (kernel::CellBased(k.shape))
      VofdemInputError(grid.Comm(), "option -coupling_smoothing: %s smooths to a kernel's width; -coupling_kernel %s has none (use smooth or truncated, or -coupling_smoothing kernel)", name,
                       k.shape == kernel::Shape::Divided ? "divided" : "unresolved");
    for (int e = 0; e < 3; ++e)
      if (!(spread_[e] > 0))
        VofdemInputError(grid.Comm(),
                         "option -coupling_smoothing: %s needs a kernel wider than the cell: the kernel's spread (standard deviation %g m) is below the tent deposit's own (h/sqrt(6) = %g m in %c); use -coupling_smoothing kernel or a wider -coupling_kernel_width / -coupling_kernel_min_width",
                         name, (double)std::sqrt(sigma2), (double)(h[e] / std::sqrt(6.0)), "xyz"[e]);
  }
  diffusion_ = s.method == Method::Diffusion || s.method == Method::Gaussian;
  // auto: the Gaussian filter where a grid smoothing wins. In the bubbling bed (10,000 spheres, 3 fluid steps,
  // coupling stage) it took 1.8 / 0.37 / 0.16 s at cell/d 0.5 / 1 / 3 against the diffusion's 7.2 / 0.64 / 0.22 s
  // and the kernel's 13.6 / 2.4 / 0.74 s.
  DiffusionSmoother::Operator op = s.method == Method::Diffusion ? DiffusionSmoother::Operator::Diffusion : DiffusionSmoother::Operator::Gaussian;
  if (s.method == Method::Auto && fits) {
    // The kernel visits about (4/3) pi (rc/h)^3 points per particle and location; the Gaussian filter does
    // sum_e (2 R_e + 1) multiply-adds per point. The filter when the first exceeds crossover times the second.
    // Measured in the bubbling bed (10,000 spheres, 1 rank): the kernel took 5.8x the filter's time at a ratio
    // of 1.7 (cell/d 0.5) and 6.6x at 3.3 (cell/d 1): break-even near 0.3-0.5.
    const PetscReal rc      = kernel::Cutoff(k.shape, H, k.truncation);
    const PetscReal support = 4.0 / 3.0 * PETSC_PI * rc * rc * rc / (h[0] * h[1] * h[2]);
    const PetscReal points  = (PetscReal)grid.Cells()[0] * grid.Cells()[1] * grid.Cells()[2];
    PetscReal       taps    = 0;
    for (int e = 0; e < 3; ++e) taps += (PetscReal)GaussianFilter::Taps(h[e], spread_[e]).size();
    diffusion_ = particles * support > s.crossover * points * taps;
    PetscCall(PetscInfo(nullptr, "coupling: kernel points over all particles / (cells x filter taps) = %g (crossover %g): %s\n", (double)(particles * support / (points * taps)),
                        (double)s.crossover, diffusion_ ? "gaussian" : "kernel"));
  }
  if (diffusion_ && op == DiffusionSmoother::Operator::Gaussian && s.method == Method::Auto) {
    // The filter's ghosts must fit in every rank's share (GaussianFilter.hpp); else the diffusion.
    bool periodic[3];
    for (int e = 0; e < 3; ++e) periodic[e] = grid.Periodic(e);
    for (int loc = 0; loc < 4; ++loc)
      if (!GaussianFilter::Fits(sg.Location(loc), h, spread_, periodic)) op = DiffusionSmoother::Operator::Diffusion;
  }
  if (diffusion_) PetscCall(smoother_.SetUp(sg, spread_, s.steps, margin, "coupling_smoothing_", op));
  else PetscCall(kernel_.SetUp(sg, k, kernel::Cutoff(k.shape, H, k.truncation), margin));
  PetscFunctionReturn(0);
}

PetscErrorCode Smoothing::ReadSolverOptions(MPI_Comm comm) {
  KSP ksp;

  PetscFunctionBeginUser;
  PetscCall(DiffusionSmoother::CreateSolver(comm, "coupling_smoothing_", &ksp));
  PetscCall(KSPDestroy(&ksp));
  PetscFunctionReturn(0);
}

PetscErrorCode Smoothing::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(smoother_.Destroy());
  PetscCall(kernel_.Destroy());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
