#include "vofdem/flow/ViscousSolver.hpp"
#include "vofdem/grid/FaceProperties.hpp"

#include "vofdem/base/Runtime.hpp"

#include <cmath>

namespace vofdem {

namespace {

// ViscousSolver::Row for a face whose six neighbours all lie inside the box and no solid is present: the
// same arithmetic in the same order (the same matrix to the bit), without Row's boundary and solid branches.
// A full assembly runs it for nearly every face, every step in a coupled run (eps changes): Row was 13.5 %
// of a bubbling-bed step at cell/d 0.5. h2[e] = h_e^2.
PetscInt InteriorRow(int d, const PetscInt q[3], PetscReal dt, const PetscReal h2[3], const LocalField &eps, const LocalField &beta, const LocalField &em, MatStencil col[7],
                     PetscScalar val[7], PetscReal *K) {
  const PetscScalar *eq = &em.at(q);
  const PetscInt     sd = em.stride[d];
  const PetscReal    bL = PetscRealPart((&beta.at(q))[-beta.stride[d]]), bR = PetscRealPart(beta.at(q));
  const PetscScalar *epq = &eps.at(q);
  const FaceProperties face = FaceAverage(PetscRealPart(epq[-eps.stride[d]]), PetscRealPart(epq[0]), bL, bR);
  const PetscReal eF = face.eps, bF = face.beta;
  PetscReal          diag = 0;
  PetscInt           nc   = 1;
  col[0]                  = {q[2], q[1], q[0], 0};
  for (int e = 0; e < 3; ++e)
    for (int side = 0; side < 2; ++side) {
      PetscReal a;
      if (e == d) a = PetscRealPart(side ? eq[0] : eq[-sd]) / h2[e];
      else {
        const PetscInt o = side ? em.stride[e] : -em.stride[e];  // c1 = q + o, c3 = c1 - e_d
        a                = 0.25 * PetscRealPart(eq[0] + eq[-sd] + eq[o] + eq[o - sd]) / h2[e];
      }
      a *= 0.5;  // Crank-Nicolson half
      PetscInt nb[3] = {q[0], q[1], q[2]};
      nb[e] += side ? 1 : -1;
      col[nc]   = {nb[2], nb[1], nb[0], 0};
      val[nc++] = -a;
      diag += a;
    }
  *K     = diag;
  val[0] = ViscousSolver::MassOverDt(eF, bF, dt) + diag;
  return nc;
}

}  // namespace

PetscErrorCode ViscousSolver::Create(const StaggeredGrid &sg, const FlowBoundary &bc) {
  PetscFunctionBeginUser;
  sg_ = &sg;
  bc_ = &bc;
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMCreateMatrix(sg.FaceMatrixDM(d), &A_[d]));
    PetscCall(MatSetOption(A_[d], MAT_SYMMETRIC, PETSC_TRUE));
    PetscCall(DMCreateGlobalVector(sg.Face(d), &bcRhs_[d]));
    PetscCall(VecDuplicate(bcRhs_[d], &diag_[d]));
    PetscCall(VecDuplicate(bcRhs_[d], &K_[d]));
    PetscCall(KSPCreate(sg.Base().Comm(), &ksp_[d]));
    PetscCall(KSPSetOptionsPrefix(ksp_[d], "flow_viscous_"));
    PetscCall(KSPSetOperators(ksp_[d], A_[d], A_[d]));
    PetscCall(KSPSetType(ksp_[d], KSPCG));
    PetscCall(KSPSetNormType(ksp_[d], KSP_NORM_UNPRECONDITIONED));
    PetscCall(KSPSetTolerances(ksp_[d], 1e-6, 1e-300, PETSC_DEFAULT, 1000));
    PetscCall(KSPSetInitialGuessNonzero(ksp_[d], PETSC_TRUE));
    PC pc;
    PetscCall(KSPGetPC(ksp_[d], &pc));
    PetscCall(PCSetType(pc, PCJACOBI));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ViscousSolver::SetFromOptions() {
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) PetscCall(KSPSetFromOptions(ksp_[d]));
  PetscFunctionReturn(0);
}

// One row as in Flow's explicit evaluation of div(eps mu grad u) (FlowMomentum.cpp), halved for
// Crank-Nicolson: the same coefficients, so that the implicit and explicit halves are one operator.
// Row of face q of component d: col/val[0] the diagonal, then the nc-1 neighbours; *rhs the part
// of the prescribed boundary velocities. A boundary face of the component itself: identity row.
// The diagonal is returned as mass/dt + K with K the viscous part (*K), so that the diagonal-only
// update (Assemble) forms it from the stored K in the same way, bitwise as a full assembly at the
// new dt would (restarts rebuild the matrix from scratch).
// With solid cells (SolidMask.hpp): a blocked face gets an identity row (its rhs 0); a blocked
// neighbour contributes its known value 0, at the neighbour's distance, or half of it (a wall face:
// the neighbour lies inside the solid, the wall is at the shared cell face, ghost = -u).
// InteriorRow (above) repeats the interior case of this function for speed: change both together.
PetscInt ViscousSolver::Row(int d, const PetscInt q[3], PetscReal dt, const LocalField &eps, const LocalField &beta, const LocalField &em, const LocalField *solid,
                            MatStencil col[7], PetscScalar val[7], PetscReal *rhs, PetscReal *K) const {
  const Grid      &g = sg_->Base();
  const PetscReal *h = g.Spacing(), *lo = g.Lower();
  const PetscInt   lastFace = sg_->Points(d, d) - 1;
  col[0] = {q[2], q[1], q[0], 0};
  *rhs   = 0;
  if (!g.Periodic(d) && (q[d] == 0 || q[d] == lastFace)) {
    val[0] = *K = 1;
    return 1;
  }
  PetscInt nc = 1;
  PetscInt cm[3] = {q[0], q[1], q[2]};
  cm[d] -= 1;  // the cell below the face along d
  // solid cells on the two sides of the d-face at p (and whether both are)
  auto blocked = [&](const PetscInt p[3], bool *both) {
    PetscInt pm[3] = {p[0], p[1], p[2]};
    pm[d] -= 1;
    const bool a = PetscRealPart(solid->at(pm)) > 0.5, b = PetscRealPart(solid->at(p)) > 0.5;
    *both = a && b;
    return a || b;
  };
  bool both;
  if (solid && blocked(q, &both)) {
    val[0] = *K = 1;
    return 1;
  }
  const PetscReal bL = PetscRealPart(beta.at(cm)), bR = PetscRealPart(beta.at(q));
  const FaceProperties face = FaceAverage(PetscRealPart(eps.at(cm)), PetscRealPart(eps.at(q)), bL, bR);
  const PetscReal eF = face.eps, bF = face.beta;
  PetscReal       diag = 0;
  for (int e = 0; e < 3; ++e)
    for (int side = 0; side < 2; ++side) {
      PetscInt nb[3] = {q[0], q[1], q[2]};
      nb[e] += side ? 1 : -1;
      PetscReal a;  // eps*mu at the shared control-volume face, / h_e^2
      if (e == d) {
        const PetscInt *c = side ? q : cm;
        a = PetscRealPart(em.at(c)) / (h[e] * h[e]);
      } else {
        // the four cells around the edge: q and cm, and both shifted along e
        PetscInt c1[3] = {q[0], q[1], q[2]}, c3[3];
        c1[e] += side ? 1 : -1;
        for (int k = 0; k < 3; ++k) c3[k] = c1[k];
        c3[d] -= 1;
        a = 0.25 * PetscRealPart(em.at(q) + em.at(cm) + em.at(c1) + em.at(c3)) / (h[e] * h[e]);
      }
      a *= 0.5;  // Crank-Nicolson half
      const bool outside = !g.Periodic(e) && (e == d ? (nb[e] == 0 || nb[e] == lastFace) : (nb[e] < 0 || nb[e] >= g.Cells()[e]));
      if (!outside && solid && blocked(nb, &both)) {
        diag += (e != d && both) ? 2 * a : a;  // value 0 half a cell away (inside the solid) or one cell away
        continue;
      }
      if (!outside) {
        col[nc]   = {nb[2], nb[1], nb[0], 0};
        val[nc++] = -a;
        diag += a;
        continue;
      }
      const int       f = 2 * e + side;
      const FlowFace &F = bc_->Face(f);
      PetscReal       x[3];
      for (int k = 0; k < 3; ++k) x[k] = lo[k] + (k == d ? q[k] : q[k] + 0.5) * h[k];
      if (e == d) {  // a boundary face of this component: its value is known (or zero gradient)
        if (F.type == FlowBoundaryType::Outflow) continue;
        x[d] = side ? g.Upper()[d] : lo[d];
        diag += a;
        // an inflow's face value is superficial / eps of its cell (FlowBoundary::ApplyNormal): cm or q
        const PetscReal epsB = F.type == FlowBoundaryType::Inflow ? PetscRealPart(side ? eps.at(q) : eps.at(cm)) : 1;
        *rhs += a * bc_->Prescribed(f, d, x) / epsB;
      } else if (F.type == FlowBoundaryType::Wall || F.type == FlowBoundaryType::Inflow) {
        // ghost = 2 U_b - u: the face value U_b is half a cell away
        x[e] = side ? g.Upper()[e] : lo[e];
        diag += 2 * a;
        *rhs += 2 * a * bc_->Prescribed(f, d, x);
      }  // slip, outflow: zero gradient, no flux
    }
  *K     = diag;
  val[0] = MassOverDt(eF, bF, dt) + diag;
  return nc;
}

// Full assembly when the coefficients changed; when only dt did, only the diagonal holds 1/dt, so
// it alone is recomputed and set (MatDiagonalSet): the same matrix for a fraction of the cost of
// MatSetValuesStencil on every row (dt changes every few steps while a flow develops).
PetscErrorCode ViscousSolver::Assemble(PetscReal dt, Vec epsLocal, Vec betaLocal, Vec emLocal, PetscBool coefficientsChanged) {
  LocalField eps, beta, em, out;  // out: K (full assembly) or the new diagonal
  LocalField solid, *sp = nullptr;
  PetscInt   s[3], n[3], q[3];
  MatStencil  col[7];
  PetscScalar val[7];
  PetscReal   rhs;

  PetscFunctionBeginUser;
  dt_ = dt;
  PetscCall(sg_->GetLocal(3, epsLocal, &eps));
  PetscCall(sg_->GetLocal(3, betaLocal, &beta));
  PetscCall(sg_->GetLocal(3, emLocal, &em));
  if (solid_) {
    PetscCall(sg_->GetLocal(3, solid_->CellsLocal(), &solid));
    sp = &solid;
  }
  for (int d = 0; d < 3; ++d) {
    sg_->Owned(d, s, n);
    if (coefficientsChanged || !assembled_) {
      LocalField rb;
      PetscCall(sg_->GetGlobal(d, bcRhs_[d], &rb));
      PetscCall(sg_->GetGlobal(d, K_[d], &out));
      // The faces whose neighbours are all inside (Row's boundary cases need a neighbour outside or a
      // boundary face of the component): along a walled e, faces 2..N-2 (e = d) or cells 1..N-2.
      const Grid &g = sg_->Base();
      PetscInt    inLo[3], inHi[3];
      PetscReal   h2[3];
      for (int e = 0; e < 3; ++e) {
        h2[e]   = g.Spacing()[e] * g.Spacing()[e];
        inLo[e] = g.Periodic(e) ? PETSC_MIN_INT : e == d ? 2 : 1;
        inHi[e] = g.Periodic(e) ? PETSC_MAX_INT : e == d ? sg_->Points(d, d) - 3 : g.Cells()[e] - 2;
      }
      // Every row, in place if the writer has this matrix's rows (AijRowWriter.hpp), else through
      // MatSetValuesStencil, recording them for the next time; a row of another shape (a solid moved)
      // sends the whole matrix the slow way again.
      bool inPlace = writer_[d].Ready();
      for (int pass = inPlace ? 0 : 1; pass < 2; ++pass) {
        if (pass == 0) PetscCall(writer_[d].Begin(A_[d]));
        else {
          PetscCall(MatZeroEntries(A_[d]));
          writer_[d].Reset();
        }
        bool fits = true;
        for (q[2] = s[2]; q[2] < s[2] + n[2]; ++q[2])
          for (q[1] = s[1]; q[1] < s[1] + n[1]; ++q[1])
            for (q[0] = s[0]; q[0] < s[0] + n[0]; ++q[0]) {
              const bool interior = !sp && q[0] >= inLo[0] && q[0] <= inHi[0] && q[1] >= inLo[1] && q[1] <= inHi[1] && q[2] >= inLo[2] && q[2] <= inHi[2];
              PetscInt   nc;
              if (interior) {
                nc  = InteriorRow(d, q, dt, h2, eps, beta, em, col, val, &out.at(q));
                rhs = 0;
              } else nc = Row(d, q, dt, eps, beta, em, sp, col, val, &rhs, &out.at(q));
              rb.at(q) = rhs;
              if (pass == 0) fits = fits && writer_[d].Put(nc, col, val);
              else {
                PetscCall(MatSetValuesStencil(A_[d], 1, col, nc, col, val, INSERT_VALUES));
                PetscCall(writer_[d].Note(A_[d], sg_->FaceMatrixDM(d), col[0], nc, col));
              }
            }
        if (pass == 0) {
          bool complete;
          PetscCall(writer_[d].End(A_[d], &complete));
          if (fits && complete) break;
          continue;
        }
        PetscCall(MatAssemblyBegin(A_[d], MAT_FINAL_ASSEMBLY));
        PetscCall(MatAssemblyEnd(A_[d], MAT_FINAL_ASSEMBLY));
        PetscCall(writer_[d].Finish(A_[d]));
      }
      PetscCall(sg_->RestoreGlobal(d, K_[d], &out));
      PetscCall(sg_->RestoreGlobal(d, bcRhs_[d], &rb));
    }
    if (!(coefficientsChanged || !assembled_) || damping_[d]) {  // the diagonal alone (and the damping's share, SetDamping)
      LocalField K, C;
      PetscCall(sg_->GetGlobal(d, diag_[d], &out));
      PetscCall(sg_->GetGlobal(d, K_[d], &K));
      if (damping_[d]) PetscCall(sg_->GetGlobal(d, damping_[d], &C));
      const PetscInt last = sg_->Points(d, d) - 1, cs = beta.stride[d];
      const bool     walls = !sg_->Base().Periodic(d);
      for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
        for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
          PetscScalar       *o = &out.at(s[0], j, k);
          const PetscScalar *Kq = &K.at(s[0], j, k), *bq = &beta.at(s[0], j, k), *eq = &eps.at(s[0], j, k);
          const PetscScalar *cq = damping_[d] ? &C.at(s[0], j, k) : nullptr;
          const PetscInt     qd = d == 1 ? j : k;
          const bool         rowOnWall = walls && d != 0 && (qd == 0 || qd == last);
          for (PetscInt i = 0; i < n[0]; ++i) {
            if (rowOnWall || (walls && d == 0 && (s[0] + i == 0 || s[0] + i == last))) {
              o[i] = Kq[i];  // identity row
              continue;
            }
            const PetscReal bL = PetscRealPart(bq[i - cs]), bR = PetscRealPart(bq[i]);
            const FaceProperties face = FaceAverage(PetscRealPart(eq[i - cs]), PetscRealPart(eq[i]), bL, bR);
            const PetscReal eF = face.eps, bF = face.beta;
            o[i] = MassOverDt(eF, bF, dt) + PetscRealPart(Kq[i]);
            if (cq) {
              const PetscReal c = PetscRealPart(cq[i]);
              o[i] += std::isinf(c) ? kHeldFactor * MassOverDt(eF, bF, dt) : eF * eF / bF * c;
            }
          }
        }
      if (damping_[d]) PetscCall(sg_->RestoreGlobal(d, damping_[d], &C));
      if (solid_)
        for (PetscInt o : solid_->Blocked(d)) out.data[o] = 1;  // identity rows (K is 1 there)
      PetscCall(sg_->RestoreGlobal(d, K_[d], &K));
      PetscCall(sg_->RestoreGlobal(d, diag_[d], &out));
      PetscCall(MatDiagonalSet(A_[d], diag_[d], INSERT_VALUES));
    }
  }
  assembled_ = PETSC_TRUE;
  if (solid_) PetscCall(sg_->RestoreLocal(3, solid_->CellsLocal(), &solid));
  PetscCall(sg_->RestoreLocal(3, emLocal, &em));
  PetscCall(sg_->RestoreLocal(3, betaLocal, &beta));
  PetscCall(sg_->RestoreLocal(3, epsLocal, &eps));
  PetscFunctionReturn(0);
}

PetscErrorCode ViscousSolver::Solve(int d, Vec rhs, Vec u) {
  KSPConvergedReason reason;
  PetscInt           its;

  PetscFunctionBeginUser;
  PetscCall(KSPSolve(ksp_[d], rhs, u));
  PetscCall(KSPGetConvergedReason(ksp_[d], &reason));
  PetscCall(KSPGetIterationNumber(ksp_[d], &its));
  if (d == 0) iterations_ = 0;
  iterations_ += its;
  PetscCheck(reason > 0, sg_->Base().Comm(), PETSC_ERR_NOT_CONVERGED, "viscous solve (component %c) did not converge: %s after %" PetscInt_FMT " iterations",
             "xyz"[d], KSPConvergedReasons[reason], its);
  PetscFunctionReturn(0);
}

PetscErrorCode ViscousSolver::View(PetscViewer viewer) const {
  KSPType type;
  PC      pc;
  PCType  pctype;

  PetscFunctionBeginUser;
  PetscCall(KSPGetType(ksp_[0], &type));
  PetscCall(KSPGetPC(ksp_[0], &pc));
  PetscCall(PCGetType(pc, &pctype));
  PetscCall(PetscViewerASCIIPrintf(viewer, "flow viscous: implicit (Crank-Nicolson), %s + %s (-flow_viscous_ksp_type, -flow_viscous_pc_type)\n", type, pctype));
  PetscFunctionReturn(0);
}

PetscErrorCode ViscousSolver::Destroy() {
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) {
    PetscCall(KSPDestroy(&ksp_[d]));
    PetscCall(MatDestroy(&A_[d]));
    PetscCall(VecDestroy(&bcRhs_[d]));
    PetscCall(VecDestroy(&diag_[d]));
    PetscCall(VecDestroy(&K_[d]));
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
