// Diffusion-based smoothing between particles and the MAC grid (docs/physics.md K1, K3; Sun & Xiao 2015,
// J. Comput. Phys. 299, "Diffusion-based coarse graining in hybrid continuum-discrete solvers"): the
// alternative to kernel sums where a kernel's support spans many cells.
//  - Deposit (K3): each particle's value goes to the 2x2x2 nearest points of the location with the
//    tent weight (KernelAverager, kernel::Shape::Linear, normalised over the points that take part,
//    as for the kernel), then the grid field is diffused over a pseudo-time T: `steps` backward-Euler
//    steps of (I - tau D_e d^2/dx_e^2) w_new = w_old, tau = T/steps, with zero flux through walls
//    and periodic where the grid is. On a uniform grid one backward-Euler step adds exactly 2 D_e tau
//    to the variance per direction e (its Fourier symbol is 1/(1 + tau D_e k^2 + O(k^4))), so the
//    smoothing adds b_e^2 = 2 D_e T whatever the number of steps (more steps: closer to a Gaussian).
//  - Average (K1, K2): the same smoothing S applied to the field (weighted: S(c f)/S(c)), then read at
//    the particle with the same tent weight: the pair is adjoint (S is symmetric), as the kernel's.
// Width matching: the tent adds on average h_e^2/6 to the variance (f (1 - f) h^2 for a particle a
// fraction f between two points, mean over f), so b_e^2 = sigma^2 - h_e^2/6, sigma^2 the kernel's
// variance per direction (Coupling sets it: 8 H^2/13 for the smooth kernel).
// Conservation (K3): the operator's columns sum to one (its Laplacian's columns sum to zero with zero
// flux), so the total changes only by the sum of the KSP residual; after each solve that defect is
// added back spread evenly over the location's points (not the wall faces), so totals hold to
// round-off whatever the solver tolerance (-<prefix>ksp_rtol, default 1e-6).
// The operator S can also be a separable discrete Gaussian with the same variance (GaussianFilter.hpp:
// explicit, 3 (2R + 1) multiply-adds per point, exact variance; Operator::Gaussian), with the same tent
// deposit and read, the same conservation and adjointness.
// The matrix lives on a DMDA of stencil width 1 with the location's ownership ranges (so its vectors
// are the location's), assembled once; the KSP (by default Chebyshev with the known spectrum bounds and a
// fixed iteration count from the tolerance: no reductions, and S a fixed symmetric polynomial of the matrix,
// so that deposit and average are adjoint to round-off) takes options from the prefix.
#pragma once

#include "vofdem/coupling/DiffusionOperator.hpp"
#include "vofdem/coupling/GaussianFilter.hpp"
#include "vofdem/coupling/KernelAverager.hpp"
#include "vofdem/grid/StaggeredGrid.hpp"

#include <petscksp.h>

#include <string>
#include <vector>

namespace vofdem {

class DiffusionSmoother {
public:
  enum class Operator { Diffusion, Gaussian };
  // spread[e]: b_e^2 (m^2) added per direction; steps >= 1 (diffusion); margin as KernelAverager::SetUp;
  // prefix: the KSP options prefix (diffusion). Collective.
  PetscErrorCode SetUp(const StaggeredGrid &sg, const PetscReal spread[3], PetscInt steps, PetscReal margin, const char *prefix, Operator op = Operator::Diffusion);
  Operator       GetOperator() const { return op_; }
  PetscInt       FilterRadius(int e) const { return filter_[3].Radius(e); }  // Gaussian: taps per side along e (cells)
  PetscErrorCode Destroy();
  PetscInt       GhostWidth() const { return compact_.GhostWidth(); }
  PetscInt       Steps() const { return steps_; }
  // KSP iterations summed over all solves since set-up (the cost measure of scripts/smoothing-cost).
  PetscInt       Iterations() const { return iterations_; }

  // The interface of KernelAverager (H is not used: one smoothing width for all particles).
  PetscErrorCode Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, const PetscReal *value, PetscInt stride, Vec out, bool walls = false);
  PetscErrorCode Average(int loc, Vec field, Vec weight, PetscInt n, const PetscReal *x, const PetscReal *H, PetscReal *out, PetscInt stride, bool walls = true);
  PetscErrorCode Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, PetscInt nf, const PetscReal *const value[], PetscInt stride, Vec out[], bool walls = false);
  PetscErrorCode Average(int loc, PetscInt nf, const Vec field[], const Vec weight[], const bool walls[], PetscInt n, const PetscReal *x, const PetscReal *H, PetscReal *const out[],
                         PetscInt stride);

  // The smoothing's solver (Chebyshev, no preconditioner, no norms, rtol 1e-6; the prefix's options applied).
  static PetscErrorCode CreateSolver(MPI_Comm comm, const char *prefix, KSP *ksp);

  // The Chebyshev iterations per pseudo-step for tolerance rtol (spectrum bounds [1, 1 + 4 sum_e a_e]).
  static PetscInt ChebyshevIterations(const PetscReal spread[3], PetscInt steps, const PetscReal h[3], PetscReal rtol);
  static constexpr PetscReal kDefaultTolerance = 1e-6;

  // v <- S v on location loc (global vector of the location), total kept. Collective.
  PetscErrorCode Smooth(int loc, Vec v);
  // The same where v is zero outside the z planes inPlanes and only the planes outPlanes are wanted
  // (GaussianFilter::Apply; the diffusion smooths all). Collective.
  PetscErrorCode Smooth(int loc, Vec v, const PetscInt inPlanes[2], const PetscInt outPlanes[2]);

private:
  // The z planes (inclusive, the same on all ranks) that the tent weights of these particles touch on location
  // loc, with a margin; first > last when there are no particles. Collective.
  PetscErrorCode TentPlanes(int loc, PetscInt n, const PetscReal *x, PetscInt planes[2]) const;
  PetscErrorCode Assemble(int loc);
  PetscErrorCode Work(int loc, size_t count);

  const StaggeredGrid *sg_ = nullptr;
  KernelAverager       compact_;  // the tent weight
  Operator             op_ = Operator::Diffusion;
  GaussianFilter       filter_[4];  // Operator::Gaussian, per location
  PetscReal            spread_[3] = {0, 0, 0};
  PetscInt             steps_ = 1, iterations_ = 0;
  std::string          prefix_;
  DM                   dm_[4]   = {nullptr, nullptr, nullptr, nullptr};  // stencil width 1, the location's layout
  Mat                  A_[4]    = {nullptr, nullptr, nullptr, nullptr};  // assembled (the preconditioner's)
  Mat                  S_[4]    = {nullptr, nullptr, nullptr, nullptr};  // the same by the stencil (the products)
  DiffusionOperator    stencil_[4];
  KSP                  ksp_[4]  = {nullptr, nullptr, nullptr, nullptr};
  Vec                  mask_[4] = {nullptr, nullptr, nullptr, nullptr};  // 1 where the smoothing acts, 0 on wall faces
  PetscReal            count_[4] = {0, 0, 0, 0};                         // points where mask is 1
  Vec                  rhs_[4]  = {nullptr, nullptr, nullptr, nullptr};
  std::vector<Vec>     work_[4];  // per location: deposits, smoothed fields and weights
};

}  // namespace vofdem
