// The head solve of the Darcy seepage (Darcy.hpp; docs/physics.md (F11)): the coefficient from the
// permeability law, the finite-volume matrix, the KSP, and the fluxes, gradients and flows of the result.
#include "vofdem/darcy/Darcy.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace {
PetscReal Harmonic(PetscReal a, PetscReal b) { return a + b > 0 ? 2 * a * b / (a + b) : 0; }
}  // namespace

// beta = k(eps, |q|)/mu per owned cell; *change: the largest relative change from the coefficient before.
static PetscErrorCode CellCoefficient(const permeability::Row &row, const permeability::Parameters &param, PetscReal maxEps, Vec eps, Vec speed, Vec beta, Vec betaOld,
                                      PetscReal *change, MPI_Comm comm) {
  const PetscScalar *e, *u;
  PetscScalar       *b, *o;
  PetscInt           n;
  PetscReal          worst = 0;

  PetscFunctionBeginUser;
  PetscCall(VecCopy(beta, betaOld));
  PetscCall(VecGetLocalSize(beta, &n));
  PetscCall(VecGetArrayRead(eps, &e));
  PetscCall(VecGetArrayRead(speed, &u));
  PetscCall(VecGetArray(beta, &b));
  PetscCall(VecGetArray(betaOld, &o));
  for (PetscInt c = 0; c < n; ++c) {
    const PetscReal ec = std::min(PetscRealPart(e[c]), maxEps);
    b[c]               = row.k(param, ec, PetscRealPart(u[c])) / param.viscosity;
    worst              = std::max(worst, std::fabs(PetscRealPart(b[c]) - PetscRealPart(o[c])) / PetscRealPart(b[c]));
  }
  PetscCall(VecRestoreArray(betaOld, &o));
  PetscCall(VecRestoreArray(beta, &b));
  PetscCall(VecRestoreArrayRead(speed, &u));
  PetscCall(VecRestoreArrayRead(eps, &e));
  PetscCallMPI(MPI_Allreduce(&worst, change, 1, MPIU_REAL, MPI_MAX, comm));
  PetscFunctionReturn(0);
}

// -div(beta grad p) = -s by finite volumes, divided by the cell volume: per interior face beta_f (p_C - p_N)/h^2
// with the harmonic mean beta_f; a fixed-head face 2 beta_C (p_C - p_face)/h^2; a closed face nothing.
PetscErrorCode Darcy::Assemble(PetscReal pIn, PetscReal pOut, Vec source) {
  const PetscScalar ***b, ***s = nullptr;
  PetscScalar       ***r;
  PetscInt             st[3], m[3];

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing();
  const PetscInt  *N = grid_->Cells();
  const PetscReal  ih2[3] = {1 / (h[0] * h[0]), 1 / (h[1] * h[1]), 1 / (h[2] * h[2])};
  PetscCall(DMGlobalToLocal(dm_, beta_, INSERT_VALUES, betaLocal_));
  PetscCall(MatZeroEntries(A_));
  PetscCall(DMDAVecGetArrayRead(dm_, betaLocal_, &b));
  PetscCall(DMDAVecGetArray(dm_, b_, &r));
  if (source) PetscCall(DMDAVecGetArrayRead(dm_, source, &s));
  PetscCall(DMDAGetCorners(dm_, &st[0], &st[1], &st[2], &m[0], &m[1], &m[2]));
  for (PetscInt k = st[2]; k < st[2] + m[2]; ++k)
    for (PetscInt j = st[1]; j < st[1] + m[1]; ++j)
      for (PetscInt i = st[0]; i < st[0] + m[0]; ++i) {
        const PetscReal bc  = PetscRealPart(b[k][j][i]);
        MatStencil      row = {k, j, i, 0}, col[7];
        PetscScalar     val[7], diag = 0, rhs = s ? -s[k][j][i] : 0;
        PetscInt        n = 1;
        for (int d = 0; d < 3; ++d)
          for (int side = 0; side < 2; ++side) {
            PetscInt q[3] = {i, j, k};
            q[d] += side ? 1 : -1;
            if (grid_->Periodic(d) || (q[d] >= 0 && q[d] < N[d])) {
              const PetscReal bf = Harmonic(bc, PetscRealPart(b[q[2]][q[1]][q[0]])) * ih2[d];
              diag += bf;
              col[n]   = {q[2], q[1], q[0], 0};
              val[n++] = -bf;
            } else if (Open(2 * d + side)) {
              diag += 2 * bc * ih2[d];
              rhs += 2 * bc * ih2[d] * (side ? pOut : pIn);
            }
          }
        col[0] = row;
        val[0] = diag;
        PetscCall(MatSetValuesStencil(A_, 1, &row, n, col, val, ADD_VALUES));
        r[k][j][i] = rhs;
      }
  if (source) PetscCall(DMDAVecRestoreArrayRead(dm_, source, &s));
  PetscCall(DMDAVecRestoreArray(dm_, b_, &r));
  PetscCall(DMDAVecRestoreArrayRead(dm_, betaLocal_, &b));
  PetscCall(MatAssemblyBegin(A_, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A_, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

// Per cell and direction the two face fluxes q_f = -beta_f dp/dx (interior: (p_N - p_C)/h, harmonic beta_f; a
// fixed-head face: half a cell, beta_C; a closed face: 0): the cell's q is their mean (its speed |q| the nonlinear
// laws read), its -grad p is q/beta_C, the drop of the flux-continuous pressure across the cell's own two halves
// over h, and the boundary faces' fluxes are the inlet's and the outlet's flows.
PetscErrorCode Darcy::Fluxes(PetscReal pIn, PetscReal pOut) {
  const PetscScalar ***p, ***b;
  PetscScalar       ***g[3], ***u;
  PetscInt             st[3], m[3];
  PetscReal            flow[2] = {0, 0}, all[2];

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing();
  const PetscInt  *N = grid_->Cells();
  PetscCall(DMGlobalToLocal(dm_, p_, INSERT_VALUES, pLocal_));
  PetscCall(DMGlobalToLocal(dm_, beta_, INSERT_VALUES, betaLocal_));
  PetscCall(DMDAVecGetArrayRead(dm_, pLocal_, &p));
  PetscCall(DMDAVecGetArrayRead(dm_, betaLocal_, &b));
  for (int d = 0; d < 3; ++d) PetscCall(DMDAVecGetArray(dm_, gradient_[d], &g[d]));
  PetscCall(DMDAVecGetArray(dm_, speed_, &u));
  PetscCall(DMDAGetCorners(dm_, &st[0], &st[1], &st[2], &m[0], &m[1], &m[2]));
  for (PetscInt k = st[2]; k < st[2] + m[2]; ++k)
    for (PetscInt j = st[1]; j < st[1] + m[1]; ++j)
      for (PetscInt i = st[0]; i < st[0] + m[0]; ++i) {
        const PetscInt  c[3] = {i, j, k};
        const PetscReal pc = PetscRealPart(p[k][j][i]), bc = PetscRealPart(b[k][j][i]);
        PetscReal       q2 = 0;
        for (int d = 0; d < 3; ++d) {
          PetscReal grad, flux[2];
          for (int side = 0; side < 2; ++side) {
            PetscInt q[3] = {i, j, k};
            q[d] += side ? 1 : -1;
            const PetscReal sign = side ? 1 : -1;  // dp/dx = sign (p_other - p_C)/distance
            if (grid_->Periodic(d) || (q[d] >= 0 && q[d] < N[d])) {
              grad       = sign * (PetscRealPart(p[q[2]][q[1]][q[0]]) - pc) / h[d];
              flux[side] = -Harmonic(bc, PetscRealPart(b[q[2]][q[1]][q[0]])) * grad;
            } else if (Open(2 * d + side)) {
              grad       = sign * ((side ? pOut : pIn) - pc) / (0.5 * h[d]);
              flux[side] = -bc * grad;
            } else flux[side] = 0;
          }
          const PetscReal qc = 0.5 * (flux[0] + flux[1]);
          g[d][k][j][i]      = qc / bc;  // -grad p = q/beta in the cell: the drops of its two halves, q_f (h/2)/beta_C, over h
          q2 += qc * qc;
          if (d == axis_) {
            const PetscReal area = h[(d + 1) % 3] * h[(d + 2) % 3];
            if (c[d] == 0) flow[0] += flux[0] * area;
            if (c[d] == N[d] - 1) flow[1] += flux[1] * area;
          }
        }
        u[k][j][i] = std::sqrt(q2);
      }
  PetscCall(DMDAVecRestoreArray(dm_, speed_, &u));
  for (int d = 0; d < 3; ++d) PetscCall(DMDAVecRestoreArray(dm_, gradient_[d], &g[d]));
  PetscCall(DMDAVecRestoreArrayRead(dm_, betaLocal_, &b));
  PetscCall(DMDAVecRestoreArrayRead(dm_, pLocal_, &p));
  PetscCallMPI(MPI_Allreduce(flow, all, 2, MPIU_REAL, MPIU_SUM, comm_));
  last_.inflow  = all[0];
  last_.outflow = all[1];
  PetscFunctionReturn(0);
}

PetscErrorCode Darcy::Solve(PetscReal time, Vec source) {
  const permeability::Row &row = permeability::kLaws[law_];
  PetscReal                change = 0;

  PetscFunctionBeginUser;
  const PetscReal pOut = rhoG() * outletHead_, pIn = pOut + rhoG() * HeadDifference(time);
  last_.headDifference = axis_ >= 0 ? HeadDifference(time) : 0;
  last_.picard         = 0;
  PetscCall(VecMin(eps_, nullptr, &last_.minEps));
  PetscCall(VecMax(eps_, nullptr, &last_.maxEps));
  if (axis_ < 0) {  // a closed box: nothing drives a flow (a source alone would make the system singular)
    PetscCall(CellCoefficient(row, param_, maxEps_, eps_, speed_, beta_, betaOld_, &change, comm_));
    PetscCall(Fluxes(pIn, pOut));
    PetscFunctionReturn(0);
  }
  for (PetscInt it = 0;; ++it) {
    PetscCall(CellCoefficient(row, param_, maxEps_, eps_, speed_, beta_, betaOld_, &change, comm_));
    if (row.nonlinear && it > 0 && change <= picardRtol_) break;  // p, q are those of this coefficient to the tolerance
    if (it >= picardMax_) {
      PetscCall(PetscPrintf(comm_, "vofdem: warning: darcy: %d Picard iterations left k/mu changing by %.2e (-darcy_picard_rtol %g; raise -darcy_picard_max)\n", (int)it, (double)change,
                            (double)picardRtol_));
      break;
    }
    KSPConvergedReason reason;
    PetscCall(Assemble(pIn, pOut, source));
    PetscCall(KSPSolve(ksp_, b_, p_));
    PetscCall(KSPGetConvergedReason(ksp_, &reason));
    PetscCall(KSPGetIterationNumber(ksp_, &last_.iterations));
    PetscCall(KSPGetResidualNorm(ksp_, &last_.residual));
    PetscCheck(reason > 0, comm_, PETSC_ERR_NOT_CONVERGED, "darcy: the head solve did not converge (%s after %d iterations); see -darcy_ksp_converged_reason", KSPConvergedReasons[reason],
               (int)last_.iterations);
    PetscCall(Fluxes(pIn, pOut));
    last_.picard = it + 1;
    if (!row.nonlinear) break;
  }
  const PetscReal *lo = grid_->Lower(), *up = grid_->Upper();
  const int        a = axis_;
  const PetscReal  L = up[a] - lo[a], area = (up[(a + 1) % 3] - lo[(a + 1) % 3]) * (up[(a + 2) % 3] - lo[(a + 2) % 3]);
  last_.gradient     = last_.headDifference / L;
  last_.permeability = pIn != pOut ? param_.viscosity * L * last_.outflow / (area * (pIn - pOut)) : 0;
  PetscFunctionReturn(0);
}

PetscErrorCode Darcy::Summarize(DarcySummary *s) const {
  *s = last_;
  return 0;
}

}  // namespace vofdem
