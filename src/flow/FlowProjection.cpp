// The projection of Flow (Flow.hpp): -div((eps/rho) G phi) = -div(eps u*)/dt with PressureSolver,
// then u = u* - dt (1/rho)_f G phi and p += phi. docs/physics.md (F1): div(eps U) = -d(eps)/dt, the rate
// from the coupling's change of eps over the step (SetFluidFractionChange; 0 without particles).
#include "vofdem/flow/Flow.hpp"
#include "vofdem/grid/FaceProperties.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

// rhsOut = scale * div(eps u) per cell (needs uLocal_ current); maxAbs = max |div(eps u)|.
PetscErrorCode Flow::Divergence(Vec rhsOut, PetscReal scale, PetscReal *maxAbs) const {
  LocalField u[3], eps, out, chg;
  PetscInt   s[3], n[3];
  PetscReal  mx = 0;

  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) PetscCall(sg_.GetLocal(d, uLocal_[d], &u[d]));
  PetscCall(sg_.GetLocal(3, epsLocal_, &eps));
  if (rhsOut) PetscCall(sg_.GetGlobal(3, rhsOut, &out));
  // The particles' displacement (F1): div(eps U) + d(eps)/dt is what must vanish.
  const bool      moving = epsChange_ && epsChangeDt_ > 0;
  const PetscReal idt    = moving ? 1 / epsChangeDt_ : 0;
  if (moving) PetscCall(sg_.GetGlobal(3, epsChange_, &chg));
  sg_.Owned(3, s, n);
  const PetscReal *h = grid_->Spacing();
  const PetscReal  ih[3] = {1 / h[0], 1 / h[1], 1 / h[2]};
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
      // neighbours as offsets from the row's first point in each array (Flow.hpp: arrays differ in size)
      const PetscScalar *e = &eps.at(s[0], j, k), *uc[3];
      for (int d = 0; d < 3; ++d) uc[d] = &u[d].at(s[0], j, k);
      PetscScalar       *o = rhsOut ? &out.at(s[0], j, k) : nullptr;
      const PetscScalar *c = moving ? &chg.at(s[0], j, k) : nullptr;
      for (PetscInt i = 0; i < n[0]; ++i) {
        PetscReal div = c ? PetscRealPart(c[i]) * idt : 0;
        for (int d = 0; d < 3; ++d) {
          // eps at the faces: mean of the two cells (the mirror ghost makes it the cell's own at the box)
          const PetscInt  es = eps.stride[d], us = u[d].stride[d];
          const PetscReal eC = e[i], eM = 0.5 * (eC + e[i - es]), eP = 0.5 * (eC + e[i + es]);
          div += (eP * uc[d][i + us] - eM * uc[d][i]) * ih[d];
        }
        mx = std::fmax(mx, std::fabs(div));
        if (o) o[i] = scale * div;
      }
    }
  if (moving) PetscCall(sg_.RestoreGlobal(3, epsChange_, &chg));
  if (rhsOut) PetscCall(sg_.RestoreGlobal(3, rhsOut, &out));
  PetscCall(sg_.RestoreLocal(3, epsLocal_, &eps));
  for (int d = 0; d < 3; ++d) PetscCall(sg_.RestoreLocal(d, uLocal_[d], &u[d]));
  PetscCallMPI(MPI_Allreduce(&mx, maxAbs, 1, MPIU_REAL, MPI_MAX, grid_->Comm()));
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::Project(PetscReal dt, Vec *) {
  LocalField u, phi, beta, eps;
  PetscInt   s[3], n[3], gs[3], gm[3];
  PetscReal  dummy;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evProject_, 0, 0, 0, 0));
  for (int d = 0; d < 3; ++d) PetscCall(DMGlobalToLocal(sg_.Face(d), u_[d], INSERT_VALUES, uLocal_[d]));
  epsChangeDt_ = dt;
  PetscCall(Divergence(divRhs_, -1 / dt, &dummy));
  if (Relaxing()) PetscCall(DragProjectionCoefficient(dt));  // the drag acts on the correction too
  else if (coefficientPending_) {
    PetscCall(pressure_.SetCoefficient(beta_, "flow: eps/rho"));
    coefficientPending_ = false;
  }
  const Vec coefficient = Relaxing() ? dragBetaLocal_ : betaLocal_;
  if (!userPressureAtol_) {
    // The rhs is an imbalance of much larger terms (a still tank: gravity against the pressure), so a
    // reduction relative to it alone would chase round-off. The absolute floor is the relative
    // tolerance times the rhs those terms would make on their own: sqrt(N) (max|u*|/(h dt) + |g|/h)
    // (u* of the order of |g| dt in a still tank).
    KSP       ksp = pressure_.Solver();
    PetscReal rtol, divtol, umax = 0, m;
    PetscInt  maxit;
    for (int d = 0; d < 3; ++d) {
      PetscCall(VecNorm(u_[d], NORM_INFINITY, &m));
      umax = std::fmax(umax, m);
    }
    const PetscReal *h = grid_->Spacing(), hmin = std::fmin(h[0], std::fmin(h[1], h[2]));
    const PetscReal  g = std::sqrt(gravity_[0] * gravity_[0] + gravity_[1] * gravity_[1] + gravity_[2] * gravity_[2]);
    const PetscReal  N = (PetscReal)grid_->Cells()[0] * grid_->Cells()[1] * grid_->Cells()[2];
    PetscCall(KSPGetTolerances(ksp, &rtol, nullptr, &divtol, &maxit));
    PetscCall(KSPSetTolerances(ksp, rtol, rtol * std::sqrt(N) * (umax / (hmin * dt) + g / hmin), divtol, maxit));
  }
  PetscCall(pressure_.Solve(divRhs_, phi_));  // the previous increment is the initial guess
  PetscCall(DMGlobalToLocal(sg_.Cells(), phi_, INSERT_VALUES, phiLocal_));
  // Ghosts of phi at outflow faces: phi = 0 on the face (Dirichlet), odd reflection; the flux then
  // equals PressureSolver's 2 beta_C (phi_C - 0)/h. Other non-periodic faces are not corrected.
  PetscCall(DMDAGetGhostCorners(sg_.Cells(), &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  PetscCall(sg_.GetLocal(3, phiLocal_, &phi));
  for (int e = 0; e < 3; ++e)
    for (int side = 0; side < 2; ++side) {
      if (bc_.Face(2 * e + side).type != FlowBoundaryType::Outflow) continue;
      const PetscInt g = side ? grid_->Cells()[e] : -1, inner = side ? g - 1 : 0;
      if (g < gs[e] || g >= gs[e] + gm[e]) continue;
      PetscInt q[3];
      for (q[(e + 1) % 3] = gs[(e + 1) % 3]; q[(e + 1) % 3] < gs[(e + 1) % 3] + gm[(e + 1) % 3]; ++q[(e + 1) % 3])
        for (q[(e + 2) % 3] = gs[(e + 2) % 3]; q[(e + 2) % 3] < gs[(e + 2) % 3] + gm[(e + 2) % 3]; ++q[(e + 2) % 3]) {
          PetscInt r[3] = {q[0], q[1], q[2]};
          q[e] = g;
          r[e] = inner;
          phi.at(q) = -phi.at(r);
        }
    }
  PetscCall(sg_.GetLocal(3, coefficient, &beta));
  PetscCall(sg_.GetLocal(3, epsLocal_, &eps));
  const PetscReal *h = grid_->Spacing();
  for (int d = 0; d < 3; ++d) {
    PetscCall(sg_.GetGlobal(d, u_[d], &u));
    sg_.Owned(d, s, n);
    const PetscInt last = sg_.Points(d, d) - 1;
    // Faces on the box that keep their prescribed velocity (all but outflow) are left out of the range.
    if (!grid_->Periodic(d)) {
      const bool lo = bc_.Face(2 * d).type != FlowBoundaryType::Outflow, hi = bc_.Face(2 * d + 1).type != FlowBoundaryType::Outflow;
      const PetscInt a = std::max(s[d], lo ? (PetscInt)1 : (PetscInt)0), b = std::min(s[d] + n[d], hi ? last : last + 1);
      s[d] = a;
      n[d] = std::max(b - a, (PetscInt)0);
    }
    const PetscInt cs = beta.stride[d];
    const PetscReal c = dt / h[d];
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
        PetscScalar       *uu = &u.at(s[0], j, k);
        const PetscScalar *bb = &beta.at(s[0], j, k), *ee = &eps.at(s[0], j, k), *ph = &phi.at(s[0], j, k);
        for (PetscInt i = 0; i < n[0]; ++i) {
          const PetscReal bL = bb[i - cs], bR = bb[i];
          const FaceProperties face = FaceAverage(ee[i - cs], ee[i], bL, bR);
          const PetscReal eF = face.eps, bF = bL > 0 && bR > 0 ? face.beta : 0;  // 0: a held cell (SetFaceDamping)
          uu[i] -= c * bF / eF * (ph[i] - ph[i - cs]);
        }
      }
    PetscCall(sg_.RestoreGlobal(d, u_[d], &u));
    PetscCall(ZeroBlocked(d, u_[d]));  // the correction crossed solid faces too
  }
  PetscCall(sg_.RestoreLocal(3, epsLocal_, &eps));
  PetscCall(sg_.RestoreLocal(3, coefficient, &beta));
  PetscCall(sg_.RestoreLocal(3, phiLocal_, &phi));
  PetscCall(VecAXPY(p_, 1, phi_));
  PetscCall(PetscLogEventEnd(evProject_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::ZeroBlocked(int d, Vec v) const {
  PetscScalar *a;

  PetscFunctionBeginUser;
  // On every rank when there are solids anywhere, even with no blocked face here: VecRestoreArray
  // changes the vector's state, and VecNorm communicates only where the state changed (its cached
  // norm is used elsewhere), so a rank-dependent skip deadlocks the next norm.
  if (!solid_.Any()) PetscFunctionReturn(0);
  PetscCall(VecGetArray(v, &a));
  for (PetscInt o : solid_.Blocked(d)) a[o] = 0;
  PetscCall(VecRestoreArray(v, &a));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
