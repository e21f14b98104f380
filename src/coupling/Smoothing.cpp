#include "vofdem/coupling/Smoothing.hpp"

#include "vofdem/core/Runtime.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

// sigma^2 = (1/3) int r^4 k dr / int r^2 k dr (the 3-D second moment shared by three directions), by
// Simpson's rule over the support (the smooth kernel: rc^2/13 = 8 H^2/13 in closed form).
PetscReal Smoothing::KernelVariance(kernel::Shape s, PetscReal H, PetscReal truncation) {
  if (s == kernel::Shape::Unresolved || s == kernel::Shape::Linear) return 0;
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
  bool             fits   = k.shape != kernel::Shape::Unresolved;
  for (int e = 0; e < 3; ++e) {
    spread_[e] = sigma2 - h[e] * h[e] / 6;  // the tent's own variance, h^2/6 on average, comes on top
    if (!(spread_[e] > 0)) fits = false;
  }
  if (s.method == Method::Diffusion) {
    if (k.shape == kernel::Shape::Unresolved)
      VofdemInputError(grid.Comm(), "option -coupling_smoothing: diffusion smooths to a kernel's width; -coupling_kernel unresolved has none (use smooth or truncated, or -coupling_smoothing kernel)");
    for (int e = 0; e < 3; ++e)
      if (!(spread_[e] > 0))
        VofdemInputError(grid.Comm(),
                         "option -coupling_smoothing: diffusion needs a kernel wider than the cell: the kernel's spread (standard deviation %g m) is below the tent deposit's own (h/sqrt(6) = %g m in %c); use -coupling_smoothing kernel or a wider -coupling_kernel_width / -coupling_kernel_min_width",
                         (double)std::sqrt(sigma2), (double)(h[e] / std::sqrt(6.0)), "xyz"[e]);
  }
  diffusion_ = s.method == Method::Diffusion;
  if (s.method == Method::Auto && fits) {
    // The kernel visits about (4/3) pi (rc/h)^3 points per particle and location; the diffusion does
    // steps x n Chebyshev sweeps over every point (n from the spectrum, DiffusionSmoother). Diffusion when
    // the first exceeds crossover times the second (scripts/smoothing-cost, results/smoothing-cost.md).
    const PetscReal rc      = kernel::Cutoff(k.shape, H, k.truncation);
    const PetscReal support = 4.0 / 3.0 * PETSC_PI * rc * rc * rc / (h[0] * h[1] * h[2]);
    const PetscReal points  = (PetscReal)grid.Cells()[0] * grid.Cells()[1] * grid.Cells()[2];
    const PetscReal sweeps  = (PetscReal)s.steps * DiffusionSmoother::ChebyshevIterations(spread_, s.steps, h, DiffusionSmoother::kDefaultTolerance);
    diffusion_ = particles * support > s.crossover * points * sweeps;
    PetscCall(PetscInfo(nullptr, "coupling: kernel points over all particles / (cells x diffusion sweeps) = %g (crossover %g): %s\n", (double)(particles * support / (points * sweeps)),
                        (double)s.crossover, diffusion_ ? "diffusion" : "kernel"));
  }
  if (diffusion_) PetscCall(smoother_.SetUp(sg, spread_, s.steps, margin, "coupling_smoothing_"));
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
