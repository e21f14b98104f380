// The time-step limit of the flow's explicit viscous terms (Flow.hpp), from the current mu, rho and eps.
//
// AB2 is stable for a term whose eigenvalues lie in [-1/dt, 0]; the full viscous operator
// (1/(eps rho)_f) div(eps mu (grad U + grad U^T)) has real non-positive eigenvalues (it is symmetric in the
// mass-weighted inner product), and Gershgorin's theorem bounds their size by each face row's sum of
// absolute coefficients divided by the face's (eps rho)_f. Per d-face of MomentumTerms (FlowMomentum.cpp):
//   L (explicit only):  2 (em_C + em_M)/h_d^2 + sum_e 2 (em_P,e + em_N,e)/h_e^2
//   T (mu not uniform): 2 (|em_C - m| + |em_M - m|)/h_d^2 + sum_e 2 (|em_P,e - m| + |em_N,e - m|)/(h_d h_e)
// with em = eps mu at the two cells (C, M) and on the four edges (P, N per tangential e). T is the
// transpose term div(eps mu grad U^T): with a uniform em it is em grad(div U), zero on the projected
// velocity, so only the deviation from a reference m (the middle of the row's em values) acts. This
// replaces a bound from the phases alone (min(rho)/(4 |mu_1 - mu_0| sum 1/h^2)), which assumed the whole
// viscosity jump at a face of the lighter phase; here a face of pure gas sees at most half of it (the
// edge values average four cells) and faces inside the denser phase are weighted by their own density.
// Like the phase bound it is an estimate, not a proof: the operator with the shifted T is not
// symmetric, and the properties are those at the start of the step (the interface moves less than half a
// cell in it). In a uniform fluid with explicit viscosity it is the classical nu dt sum(4/h^2) <= 1.
// T is bounded only where the viscosity itself is not uniform (two phases): with one fluid and particles
// (eps varying, div U not zero) the term was never limited and runs such as ex34's packed bed are stable
// at steps this estimate would cut by about 1.5x; no bound is claimed there.
#include "vofdem/flow/Flow.hpp"
#include "vofdem/grid/FaceProperties.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace {

// The largest row rate of component d over the owned interior faces [s, s+n).
PetscReal FaceRates(int d, const LocalField &em, const LocalField &beta, const LocalField &eps, const PetscInt s[3], const PetscInt n[3], const PetscReal h[3],
                    bool laplacian, bool transpose) {
  const int      te[2] = {(d + 1) % 3, (d + 2) % 3};
  const PetscInt cs_d = em.stride[d], cs_e[2] = {em.stride[te[0]], em.stride[te[1]]};
  const PetscReal ihd2 = 1 / (h[d] * h[d]);
  const PetscReal ihe2[2] = {1 / (h[te[0]] * h[te[0]]), 1 / (h[te[1]] * h[te[1]])};
  const PetscReal ihde[2] = {1 / (h[d] * h[te[0]]), 1 / (h[d] * h[te[1]])};
  PetscReal       worst = 0;
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
      const PetscScalar *c0 = &em.at(s[0], j, k), *b0 = &beta.at(s[0], j, k), *e0 = &eps.at(s[0], j, k);
      for (PetscInt i = 0; i < n[0]; ++i) {
        const PetscScalar *c = c0 + i;
        const PetscReal    emC = c[0], emM = c[-cs_d];
        PetscReal          emP[2], emN[2];
        PetscReal          lo = std::min(emC, emM), hi = std::max(emC, emM);
        for (int a = 0; a < 2; ++a) {  // the edge values of MomentumTerms
          emP[a] = 0.25 * (emC + emM + c[cs_e[a]] + c[cs_e[a] - cs_d]);
          emN[a] = 0.25 * (emC + emM + c[-cs_e[a]] + c[-cs_e[a] - cs_d]);
          lo     = std::min(lo, std::min(emP[a], emN[a]));
          hi     = std::max(hi, std::max(emP[a], emN[a]));
        }
        const PetscReal m = 0.5 * (lo + hi);
        PetscReal       row = 0;
        if (transpose) {
          row = 2 * (std::fabs(emC - m) + std::fabs(emM - m)) * ihd2;
          for (int a = 0; a < 2; ++a) row += 2 * (std::fabs(emP[a] - m) + std::fabs(emN[a] - m)) * ihde[a];
        }
        if (laplacian) {
          row += 2 * (emC + emM) * ihd2;
          for (int a = 0; a < 2; ++a) row += 2 * (emP[a] + emN[a]) * ihe2[a];
        }
        const PetscReal bL = b0[i - cs_d], bR = b0[i];
        const FaceProperties face = FaceAverage(e0[i - cs_d], e0[i], bL, bR);
        const PetscReal eF = face.eps, bF = face.beta;
        worst = std::max(worst, row * bF / (eF * eF));  // / (eps rho)_f
      }
    }
  return worst;
}

}  // namespace

PetscErrorCode Flow::ViscousRate(PetscReal *rate) {
  LocalField em, beta, eps;
  PetscInt   s[3], n[3];
  PetscReal  worst = 0;

  PetscFunctionBeginUser;
  if (propertiesDirty_) PetscCall(UpdatePropertyLocals());
  if (implicitViscosity_ && (!viscosityJump_ || CoupledNow())) {  // nothing explicit to bound
    *rate = 0;
    PetscFunctionReturn(0);
  }
  const PetscReal *h = grid_->Spacing();
  PetscCall(sg_.GetLocal(3, emLocal_, &em));
  PetscCall(sg_.GetLocal(3, betaLocal_, &beta));
  PetscCall(sg_.GetLocal(3, epsLocal_, &eps));
  for (int d = 0; d < 3; ++d) {
    sg_.Owned(d, s, n);
    if (!grid_->Periodic(d)) {  // boundary faces are set by the boundary conditions, not advanced
      const PetscInt last = sg_.Points(d, d) - 1, a = std::max(s[d], (PetscInt)1), b = std::min(s[d] + n[d], last);
      s[d] = a;
      n[d] = std::max(b - a, (PetscInt)0);
    }
    worst = std::max(worst, FaceRates(d, em, beta, eps, s, n, h, !implicitViscosity_, viscosityJump_));
  }
  PetscCall(sg_.RestoreLocal(3, epsLocal_, &eps));
  PetscCall(sg_.RestoreLocal(3, betaLocal_, &beta));
  PetscCall(sg_.RestoreLocal(3, emLocal_, &em));
  PetscCall(MPIU_Allreduce(&worst, rate, 1, MPIU_REAL, MPIU_MAX, grid_->Comm()));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
