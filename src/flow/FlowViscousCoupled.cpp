// -flow_viscous_transpose implicit (and auto while mu varies): the whole viscous stress div(eps mu (grad U + grad U^T)) in the Crank-Nicolson
// solve (Flow.hpp, docs/physics.md F2). The transpose part couples the three velocity components, so they are solved
// together: per component d the rows of ViscousSolver's matrix A_d = (eps rho)_f/dt - 1/2 div(eps mu grad u_d) (its
// boundary and blocked rows included), less 1/2 T_d(U), T_d = div(eps mu grad U^T)_d at the interior faces, applied
// without a matrix. Why: explicit, T limits the step by its Gershgorin bound (FlowViscousLimit.cpp), which for metal in
// gas (rho 8000 / 1, mu 300 / 1) lies ~200x below the capillary limit (results/hard-cases.md).
// T is affine in the ghosted velocities (boundary values enter through the ghosts): T_lin(U) = T(U) - T(0), T(0)
// holding the boundary part, which goes to the right-hand side.
#include "vofdem/flow/Flow.hpp"

namespace vofdem {

namespace {

// T_d = div(eps mu grad U^T)_d at the owned interior d-faces [s, s+n) (N/m^3), the discretisation of MomentumTerms
// (FlowMomentum.cpp): along d the cell values em_C, em_M; across, the edge means of four cells.
void TransposeFaces(int d, const LocalField u[3], const LocalField &em, LocalField &out, const PetscInt s[3], const PetscInt n[3], const PetscReal h[3]) {
  const int       te[2] = {(d + 1) % 3, (d + 2) % 3};
  const PetscInt  ds = u[d].stride[d], cs_d = em.stride[d];
  PetscInt        ues_e[2], ues_d[2], cs_e[2];
  for (int a = 0; a < 2; ++a) ues_e[a] = u[te[a]].stride[te[a]], ues_d[a] = u[te[a]].stride[d], cs_e[a] = em.stride[te[a]];
  const PetscReal ihd = 1 / h[d], ihe[2] = {1 / h[te[0]], 1 / h[te[1]]};
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
      const PetscScalar *ud = &u[d].at(s[0], j, k), *c0 = &em.at(s[0], j, k);
      const PetscScalar *ut[2] = {&u[te[0]].at(s[0], j, k), &u[te[1]].at(s[0], j, k)};
      PetscScalar       *o = &out.at(s[0], j, k);
      for (PetscInt i = 0; i < n[0]; ++i) {
        const PetscScalar *c = c0 + i;
        const PetscReal    emC = c[0], emM = c[-cs_d], uP = ud[i];
        PetscReal          t = (emC * (ud[i + ds] - uP) - emM * (uP - ud[i - ds])) * ihd * ihd;
        for (int a = 0; a < 2; ++a) {
          const PetscScalar *ue = ut[a] + i;
          const PetscReal    emP = 0.25 * (emC + emM + c[cs_e[a]] + c[cs_e[a] - cs_d]);
          const PetscReal    emN = 0.25 * (emC + emM + c[-cs_e[a]] + c[-cs_e[a] - cs_d]);
          t += (emP * (ue[ues_e[a]] - ue[ues_e[a] - ues_d[a]]) - emN * (ue[0] - ue[-ues_d[a]])) * ihd * ihe[a];
        }
        o[i] = t;
      }
    }
}

}  // namespace

// out[d] = T_d of the ghost-filled locals (zero on boundary and blocked faces, which are not advanced).
PetscErrorCode Flow::TransposeTerm(Vec local[3], Vec out[3]) {
  LocalField u[3], em, o;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing();
  for (int d = 0; d < 3; ++d) PetscCall(sg_.GetLocal(d, local[d], &u[d]));
  PetscCall(sg_.GetLocal(3, emLocal_, &em));
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecSet(out[d], 0));
    PetscCall(sg_.GetGlobal(d, out[d], &o));
    sg_.Owned(d, s, n);
    if (!grid_->Periodic(d)) {
      const PetscInt last = sg_.Points(d, d) - 1, a = std::max(s[d], (PetscInt)1), b = std::min(s[d] + n[d], last);
      s[d] = a;
      n[d] = std::max(b - a, (PetscInt)0);
    }
    TransposeFaces(d, u, em, o, s, n, h);
    PetscCall(sg_.RestoreGlobal(d, out[d], &o));
    PetscCall(ZeroBlocked(d, out[d]));
  }
  PetscCall(sg_.RestoreLocal(3, emLocal_, &em));
  for (int d = 0; d < 3; ++d) PetscCall(sg_.RestoreLocal(d, local[d], &u[d]));
  PetscFunctionReturn(0);
}

// T of face velocities (global vectors), their outflow faces taken as ApplyNormal leaves them and their ghosts filled.
PetscErrorCode Flow::TransposeOf(Vec u[3], Vec out[3]) {
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecCopy(u[d], transIn_[d]));
    // A Krylov vector's outflow faces as ApplyNormal leaves them after the solve (the inner face's value): the solve
    // holds them at their old values (identity rows), and T reading those saw a jump (ex46's accelerating plug flow
    // between two outflow faces lost its uniformity to 8e-9).
    PetscCall(bc_.CopyOutflowNormal(sg_, d, transIn_[d]));
    PetscCall(DMGlobalToLocal(sg_.Face(d), transIn_[d], INSERT_VALUES, transLocal_[d]));
    PetscCall(bc_.FillVelocityGhosts(sg_, d, transLocal_[d]));
  }
  PetscCall(TransposeTerm(transLocal_, out));
  PetscFunctionReturn(0);
}

// The coupled operator on one vector holding the three components in turn: y = A_d x_d - 1/2 T_lin,d(x).
PetscErrorCode Flow::CoupledMult(Mat A, Vec x, Vec y) {
  Flow *f;

  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &f));
  PetscCall(f->PlaceCoupled(x, f->coupledX_, true));
  PetscCall(f->PlaceCoupled(y, f->coupledY_));
  for (int d = 0; d < 3; ++d) PetscCall(MatMult(f->viscous_.Operator(d), f->coupledX_[d], f->coupledY_[d]));
  PetscCall(f->TransposeOf(f->coupledX_, f->transOut_));
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecAXPY(f->coupledY_[d], -0.5, f->transOut_[d]));
    PetscCall(VecAXPY(f->coupledY_[d], 0.5, f->transZero_[d]));  // T(x) - T(0): the linear part
  }
  PetscCall(f->ResetCoupled(x, f->coupledX_, true));
  PetscCall(f->ResetCoupled(y, f->coupledY_));
  PetscFunctionReturn(0);
}

// Jacobi: the diagonals of A_d (the transpose part's own diagonal, (em_C + em_M)/(2 h_d^2), is left out: A_d's
// mass and shear terms dominate it).
PetscErrorCode Flow::CoupledDiagonal(Mat A, Vec diag) {
  Flow *f;

  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &f));
  PetscCall(f->PlaceCoupled(diag, f->coupledY_));
  for (int d = 0; d < 3; ++d) PetscCall(MatGetDiagonal(f->viscous_.Operator(d), f->coupledY_[d]));
  PetscCall(f->ResetCoupled(diag, f->coupledY_));
  PetscFunctionReturn(0);
}

// Views of the three components in one vector (read: a vector the KSP locked, as MatMult's input).
PetscErrorCode Flow::PlaceCoupled(Vec whole, Vec part[3], bool read) {
  PetscScalar *a;
  PetscInt     offset = 0;

  PetscFunctionBeginUser;
  if (read) PetscCall(VecGetArrayRead(whole, (const PetscScalar **)&a));
  else PetscCall(VecGetArray(whole, &a));
  for (int d = 0; d < 3; ++d) {
    PetscInt m;
    PetscCall(VecGetLocalSize(u_[d], &m));
    PetscCall(VecPlaceArray(part[d], a + offset));
    offset += m;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::ResetCoupled(Vec whole, Vec part[3], bool read) {
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) PetscCall(VecResetArray(part[d]));
  if (read) PetscCall(VecRestoreArrayRead(whole, nullptr));
  else PetscCall(VecRestoreArray(whole, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::CoupledSetUp() {
  PetscInt local = 0;

  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) {
    PetscInt m;
    PetscCall(VecGetLocalSize(u_[d], &m));
    local += m;
    PetscCall(VecDuplicate(uLocal_[d], &transLocal_[d]));
    PetscCall(VecDuplicate(u_[d], &transOut_[d]));
    PetscCall(VecDuplicate(u_[d], &transIn_[d]));
    PetscCall(VecDuplicate(u_[d], &transZero_[d]));
    // Views into the whole vector (VecPlaceArray), of the face DM's layout.
    PetscCall(VecDuplicate(u_[d], &coupledX_[d]));
    PetscCall(VecDuplicate(u_[d], &coupledY_[d]));
  }
  PetscCall(VecCreateMPI(grid_->Comm(), local, PETSC_DETERMINE, &coupledSolution_));
  PetscCall(VecDuplicate(coupledSolution_, &coupledRhs_));
  PetscCall(MatCreateShell(grid_->Comm(), local, local, PETSC_DETERMINE, PETSC_DETERMINE, this, &coupledOp_));
  PetscCall(MatShellSetOperation(coupledOp_, MATOP_MULT, (void (*)(void))CoupledMult));
  PetscCall(MatShellSetOperation(coupledOp_, MATOP_GET_DIAGONAL, (void (*)(void))CoupledDiagonal));
  PetscCall(KSPCreate(grid_->Comm(), &coupledKsp_));
  PetscCall(KSPSetOptionsPrefix(coupledKsp_, "flow_viscous_coupled_"));
  PetscCall(KSPSetOperators(coupledKsp_, coupledOp_, coupledOp_));
  // GMRES: the operator is symmetric in the interior, but the boundary ghosts (mirrored walls, inflow) are not
  // shown to keep it so. The residual is measured after Jacobi (left, preconditioned norm): a velocity-like
  // quantity, so a gas row (rho/dt ~ 1) counts as much as a metal row (8000 times more in the plain residual,
  // which left the gas to 1e-7 of its speed). 1e-10, not the per-component solves' 1e-6 (ViscousSolver, which
  // start from their exact answer in uniform flows): at 1e-6 ex26 differed between 1 and 2 ranks in the 5th digit
  // (GMRES stopping one iteration apart) and ex46's plug flow lost its uniformity to 6e-9 (now 2e-10); the metal
  // coalescence takes 25-28 iterations per step instead of 7-11 (its step 50 % dearer, still 60x faster to 2 us).
  PetscCall(KSPSetType(coupledKsp_, KSPGMRES));
  PetscCall(KSPSetNormType(coupledKsp_, KSP_NORM_PRECONDITIONED));
  PetscCall(KSPSetTolerances(coupledKsp_, 1e-10, 1e-300, PETSC_DEFAULT, 1000));
  PetscCall(KSPSetInitialGuessNonzero(coupledKsp_, PETSC_TRUE));
  {
    PC pc;
    PetscCall(KSPGetPC(coupledKsp_, &pc));
    PetscCall(PCSetType(pc, PCJACOBI));
  }
  PetscCall(KSPSetFromOptions(coupledKsp_));
  PetscFunctionReturn(0);
}

// Before the right-hand sides are made (Predict): T(0), the boundary part, from ghosts filled around zero.
PetscErrorCode Flow::CoupledBoundaryPart() {
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecSet(transLocal_[d], 0));
    PetscCall(bc_.FillVelocityGhosts(sg_, d, transLocal_[d]));
  }
  PetscCall(TransposeTerm(transLocal_, transZero_));
  PetscFunctionReturn(0);
}

// Solves for the three components at once: rhs[d] (ViscousSolver's, boundary part included) plus
// 1/2 (T(U^n) + T(0)) at the interior faces, u_ the initial guess in and the solution out.
PetscErrorCode Flow::CoupledSolve(Vec rhs[3]) {
  KSPConvergedReason reason;
  PetscInt           its;

  PetscFunctionBeginUser;
  PetscCall(PlaceCoupled(coupledRhs_, coupledY_));
  for (int d = 0; d < 3; ++d) PetscCall(VecCopy(rhs[d], coupledY_[d]));
  PetscCall(ResetCoupled(coupledRhs_, coupledY_));
  PetscCall(PlaceCoupled(coupledSolution_, coupledX_));
  for (int d = 0; d < 3; ++d) PetscCall(VecCopy(u_[d], coupledX_[d]));
  PetscCall(ResetCoupled(coupledSolution_, coupledX_));
  // A_d changed with dt and the properties, which the shell's state does not show: without this, PCJACOBI keeps
  // the first solve's diagonal (the iterations then went from ~15 to hundreds and stalled, dam break).
  PetscCall(MatAssemblyBegin(coupledOp_, MAT_FINAL_ASSEMBLY));  // raises the shell's state
  PetscCall(MatAssemblyEnd(coupledOp_, MAT_FINAL_ASSEMBLY));
  PetscCall(KSPSolve(coupledKsp_, coupledRhs_, coupledSolution_));
  PetscCall(KSPGetConvergedReason(coupledKsp_, &reason));
  PetscCall(KSPGetIterationNumber(coupledKsp_, &its));
  PetscCheck(reason > 0, grid_->Comm(), PETSC_ERR_NOT_CONVERGED, "coupled viscous solve did not converge: %s after %" PetscInt_FMT " iterations (-flow_viscous_coupled_ksp_monitor shows the history)",
             KSPConvergedReasons[reason], its);
  coupledIterations_ = its;
  PetscCall(PlaceCoupled(coupledSolution_, coupledX_));
  for (int d = 0; d < 3; ++d) PetscCall(VecCopy(coupledX_[d], u_[d]));
  PetscCall(ResetCoupled(coupledSolution_, coupledX_));
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::CoupledDestroy() {
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d)
    for (Vec *v : {&transLocal_[d], &transIn_[d], &transOut_[d], &transZero_[d], &coupledX_[d], &coupledY_[d]}) PetscCall(VecDestroy(v));
  PetscCall(VecDestroy(&coupledSolution_));
  PetscCall(VecDestroy(&coupledRhs_));
  PetscCall(MatDestroy(&coupledOp_));
  PetscCall(KSPDestroy(&coupledKsp_));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
