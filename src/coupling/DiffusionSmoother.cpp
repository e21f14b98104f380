#include "vofdem/coupling/DiffusionSmoother.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace vofdem {

PetscErrorCode DiffusionSmoother::SetUp(const StaggeredGrid &sg, const PetscReal spread[3], PetscInt steps, PetscReal margin, const char *prefix, Operator op) {
  PetscFunctionBeginUser;
  sg_ = &sg;
  op_ = op;
  for (int e = 0; e < 3; ++e) spread_[e] = spread[e];
  steps_  = steps;
  prefix_ = prefix ? prefix : "";
  KernelAverager::Settings tent;
  tent.shape = kernel::Shape::Linear;
  PetscCall(compact_.SetUp(sg, tent, 0, margin));
  for (int loc = 0; loc < 4; ++loc) PetscCall(Assemble(loc));
  PetscFunctionReturn(0);
}

// Chebyshev iteration without a preconditioner and without norms: the spectrum of I - tau sum_e D_e L_e lies in
// [1, 1 + 4 sum_e a_e] (Gershgorin; a_e = tau D_e/h_e^2), so the bounds are known and a fixed number of
// iterations reaches the tolerance: no reductions (CG's two per iteration dominated on shared cores), and the
// smoothing is a fixed polynomial of the matrix, linear and symmetric to round-off on any rank count.
PetscErrorCode DiffusionSmoother::CreateSolver(MPI_Comm comm, const char *prefix, KSP *ksp) {
  PC pc;

  PetscFunctionBeginUser;
  PetscCall(KSPCreate(comm, ksp));
  PetscCall(KSPSetType(*ksp, KSPCHEBYSHEV));
  PetscCall(KSPGetPC(*ksp, &pc));
  PetscCall(PCSetType(pc, PCNONE));
  PetscCall(KSPSetNormType(*ksp, KSP_NORM_NONE));
  // 1e-6: S is a fixed polynomial, so conservation and adjointness hold to round-off at any tolerance; it only
  // sets how closely S follows backward Euler (the smoothing's shape), and halves the iterations of 1e-10.
  PetscCall(KSPSetTolerances(*ksp, kDefaultTolerance, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(KSPSetInitialGuessNonzero(*ksp, PETSC_TRUE));  // the field before the step
  PetscCall(KSPSetOptionsPrefix(*ksp, prefix));
  PetscCall(KSPSetFromOptions(*ksp));
  PetscFunctionReturn(0);
}

// Error after n iterations <= 2 r^n of the initial one, r = (sqrt(k) - 1)/(sqrt(k) + 1), k = emax/emin the
// spectrum bounds' ratio.
PetscInt DiffusionSmoother::ChebyshevIterations(const PetscReal spread[3], PetscInt steps, const PetscReal h[3], PetscReal rtol) {
  PetscReal sum = 0;
  for (int e = 0; e < 3; ++e) sum += spread[e] / (2.0 * steps * h[e] * h[e]);
  const PetscReal sk = std::sqrt(1 + 4 * sum), r = (sk - 1) / (sk + 1);
  return std::max((PetscInt)1, (PetscInt)std::ceil(std::log(rtol / 2) / std::log(r)));
}

// The matrix I - tau sum_e D_e d^2/dx_e^2 of location loc (tau D_e = b_e^2/(2 steps)): the usual 7-point
// Laplacian with the flux through a wall left out (zero flux: the row's diagonal loses that neighbour's
// share, so rows and columns still sum to one). The wall faces of a velocity component are not part of
// the smoothing (their velocity is the boundary condition's; nothing is deposited there): identity rows.
PetscErrorCode DiffusionSmoother::Assemble(int loc) {
  const Grid     &grid = sg_->Base();
  const PetscInt *l[3];
  PetscInt        m[3], N[3], s[3], n[3];
  DMBoundaryType  bt[3];

  PetscFunctionBeginUser;
  DM base = sg_->Location(loc);
  PetscCall(DMDAGetInfo(base, nullptr, &N[0], &N[1], &N[2], &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(base, &l[0], &l[1], &l[2]));
  for (int e = 0; e < 3; ++e) bt[e] = grid.Periodic(e) ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_NONE;
  PetscCall(DMDACreate3d(grid.Comm(), bt[0], bt[1], bt[2], DMDA_STENCIL_STAR, N[0], N[1], N[2], m[0], m[1], m[2], 1, 1, l[0], l[1], l[2], &dm_[loc]));
  PetscCall(DMSetUp(dm_[loc]));
  const bool diffusion = op_ == Operator::Diffusion;
  if (diffusion) {
    PetscCall(DMSetMatType(dm_[loc], MATAIJ));
    PetscCall(DMCreateMatrix(dm_[loc], &A_[loc]));
  }
  PetscCall(DMCreateGlobalVector(dm_[loc], &mask_[loc]));
  PetscCall(VecDuplicate(mask_[loc], &rhs_[loc]));
  PetscCall(DMDAGetCorners(dm_[loc], &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  const PetscReal *h = grid.Spacing();
  PetscReal        a[3];
  for (int e = 0; e < 3; ++e) a[e] = spread_[e] / (2.0 * steps_ * h[e] * h[e]);
  // The points the smoothing acts on along each direction: faces 1..N-2 along their own (walled)
  // direction, all points otherwise.
  PetscInt lo[3], hi[3];
  bool     periodic[3];
  for (int e = 0; e < 3; ++e) {
    periodic[e] = grid.Periodic(e);
    lo[e] = 0, hi[e] = N[e] - 1;
    if (loc == e && !periodic[e]) lo[e] = 1, hi[e] = N[e] - 2;
  }
  PetscScalar ***mk;
  PetscReal      count = 0;
  PetscCall(DMDAVecGetArray(dm_[loc], mask_[loc], &mk));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscInt q[3] = {i, j, k};
        MatStencil     row  = {k, j, i, 0}, col[7];
        PetscScalar    v[7];
        bool           wallFace = false;
        for (int e = 0; e < 3; ++e)
          if (q[e] < lo[e] || q[e] > hi[e]) wallFace = true;
        mk[k][j][i] = wallFace ? 0 : 1;
        col[0]      = row;
        v[0]        = 1;
        PetscInt nc = 1;
        if (!wallFace) {
          count += 1;
          for (int e = 0; e < 3; ++e)
            for (int side = -1; side <= 1; side += 2) {
              const PetscInt nb = q[e] + side;
              if (!grid.Periodic(e) && (nb < lo[e] || nb > hi[e])) continue;  // zero flux through the wall
              MatStencil c = row;
              (e == 0 ? c.i : e == 1 ? c.j : c.k) = nb;  // periodic: the DMDA wraps -1 and N
              col[nc] = c;
              v[nc++] = -a[e];
              v[0] += a[e];
            }
        }
        if (diffusion) PetscCall(MatSetValuesStencil(A_[loc], 1, &row, nc, col, v, ADD_VALUES));
      }
  PetscCall(DMDAVecRestoreArray(dm_[loc], mask_[loc], &mk));
  PetscCallMPI(MPI_Allreduce(&count, &count_[loc], 1, MPIU_REAL, MPIU_SUM, grid.Comm()));
  if (!diffusion) {
    PetscCall(filter_[loc].SetUp(dm_[loc], h, spread_, lo, hi, periodic));
    PetscFunctionReturn(0);
  }
  PetscCall(MatAssemblyBegin(A_[loc], MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A_[loc], MAT_FINAL_ASSEMBLY));
  PetscCall(CreateSolver(grid.Comm(), prefix_.c_str(), &ksp_[loc]));
  // The products by the stencil (DiffusionOperator.hpp); the assembled matrix stays for preconditioners.
  PetscCall(stencil_[loc].Create(dm_[loc], a, lo, hi, periodic, &S_[loc]));
  PetscCall(KSPSetOperators(ksp_[loc], S_[loc], A_[loc]));
  PetscBool chebyshev;
  PetscCall(PetscObjectTypeCompare((PetscObject)ksp_[loc], KSPCHEBYSHEV, &chebyshev));
  if (chebyshev) {
    PetscReal rtol, atol, dtol;
    PetscInt  maxit;
    PetscCall(KSPGetTolerances(ksp_[loc], &rtol, &atol, &dtol, &maxit));
    PetscCall(KSPSetTolerances(ksp_[loc], rtol, atol, dtol, ChebyshevIterations(spread_, steps_, h, rtol)));
    PetscCall(KSPChebyshevSetEigenvalues(ksp_[loc], 1 + 4 * (a[0] + a[1] + a[2]), 1.0));
  }
  PetscCall(KSPSetUp(ksp_[loc]));
  PetscFunctionReturn(0);
}

PetscErrorCode DiffusionSmoother::Destroy() {
  PetscFunctionBeginUser;
  for (int loc = 0; loc < 4; ++loc) {
    for (Vec &v : work_[loc]) PetscCall(VecDestroy(&v));
    work_[loc].clear();
    PetscCall(KSPDestroy(&ksp_[loc]));
    PetscCall(MatDestroy(&A_[loc]));
    PetscCall(MatDestroy(&S_[loc]));
    PetscCall(stencil_[loc].Destroy());
    PetscCall(filter_[loc].Destroy());
    PetscCall(VecDestroy(&mask_[loc]));
    PetscCall(VecDestroy(&rhs_[loc]));
    PetscCall(DMDestroy(&dm_[loc]));
  }
  PetscCall(compact_.Destroy());
  PetscFunctionReturn(0);
}

PetscErrorCode DiffusionSmoother::Work(int loc, size_t count) {
  PetscFunctionBeginUser;
  while (work_[loc].size() < count) {
    Vec v;
    PetscCall(VecDuplicate(mask_[loc], &v));
    work_[loc].push_back(v);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode DiffusionSmoother::TentPlanes(int loc, PetscInt n, const PetscReal *x, PetscInt planes[2]) const {
  const Grid     &grid = sg_->Base();
  const PetscReal h = grid.Spacing()[2], z0 = grid.Lower()[2] + (loc == 2 ? 0 : 0.5 * h);  // plane k at z0 + k h
  PetscReal       ext[2] = {-PETSC_MAX_REAL, -PETSC_MAX_REAL};                                 // -min z, max z

  PetscFunctionBeginUser;
  for (PetscInt p = 0; p < n; ++p) ext[0] = std::max(ext[0], -x[3 * p + 2]), ext[1] = std::max(ext[1], x[3 * p + 2]);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, ext, 2, MPIU_REAL, MPIU_MAX, grid.Comm()));
  if (ext[1] < -ext[0]) {
    planes[0] = 1, planes[1] = 0;
    PetscFunctionReturn(0);
  }
  // The tent's two points along z are floor((z - z0)/h) and the next; two planes more each side for the
  // mirror images at walls and round-off.
  const PetscInt last = sg_->Points(loc, 2) - 1;
  planes[0]           = std::max((PetscInt)0, (PetscInt)std::floor((-ext[0] - z0) / h) - 2);
  planes[1]           = std::min(last, (PetscInt)std::floor((ext[1] - z0) / h) + 3);
  PetscFunctionReturn(0);
}

PetscErrorCode DiffusionSmoother::Smooth(int loc, Vec v) {
  PetscFunctionBeginUser;
  PetscCall(Smooth(loc, v, nullptr, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode DiffusionSmoother::Smooth(int loc, Vec v, const PetscInt inPlanes[2], const PetscInt outPlanes[2]) {
  PetscFunctionBeginUser;
  if (op_ == Operator::Gaussian) {
    PetscCall(filter_[loc].Apply(v, inPlanes, outPlanes));
    PetscFunctionReturn(0);
  }
  for (PetscInt step = 0; step < steps_; ++step) {
    PetscScalar before, after;
    PetscInt    its;
    PetscCall(VecDot(v, mask_[loc], &before));
    PetscCall(VecCopy(v, rhs_[loc]));
    PetscCall(KSPSolve(ksp_[loc], rhs_[loc], v));
    PetscCall(KSPGetIterationNumber(ksp_[loc], &its));
    iterations_ += its;
    KSPConvergedReason reason;
    PetscCall(KSPGetConvergedReason(ksp_[loc], &reason));
    PetscCheck(reason > 0, PetscObjectComm((PetscObject)ksp_[loc]), PETSC_ERR_NOT_CONVERGED, "coupling: the diffusion smoothing's KSP did not converge (reason %d)", (int)reason);
    // The total the solve lost to its residual, put back evenly (K3: exact conservation).
    PetscCall(VecDot(v, mask_[loc], &after));
    PetscCall(VecAXPY(v, (before - after) / count_[loc], mask_[loc]));
    if (loc < 3) {  // the wall faces' identity rows, solved only to the tolerance: their values exactly as given
      const PetscScalar *m, *b;
      PetscScalar       *a;
      PetscInt           n;
      PetscCall(VecGetLocalSize(v, &n));
      PetscCall(VecGetArrayRead(mask_[loc], &m));
      PetscCall(VecGetArrayRead(rhs_[loc], &b));
      PetscCall(VecGetArray(v, &a));
      for (PetscInt k = 0; k < n; ++k)
        if (PetscRealPart(m[k]) == 0) a[k] = b[k];
      PetscCall(VecRestoreArray(v, &a));
      PetscCall(VecRestoreArrayRead(rhs_[loc], &b));
      PetscCall(VecRestoreArrayRead(mask_[loc], &m));
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode DiffusionSmoother::Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, const PetscReal *value, PetscInt stride, Vec out, bool walls) {
  PetscFunctionBeginUser;
  PetscCall(Deposit(loc, n, x, H, 1, &value, stride, &out, walls));
  PetscFunctionReturn(0);
}

PetscErrorCode DiffusionSmoother::Average(int loc, Vec field, Vec weight, PetscInt n, const PetscReal *x, const PetscReal *H, PetscReal *out, PetscInt stride, bool walls) {
  PetscFunctionBeginUser;
  PetscCall(Average(loc, 1, &field, &weight, &walls, n, x, H, &out, stride));
  PetscFunctionReturn(0);
}

// With walls, the wall faces' shares stay where the tent put them: the smoothing keeps a wall face's value
// (identity rows; the filter leaves it), so the total is kept.
PetscErrorCode DiffusionSmoother::Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, PetscInt nf, const PetscReal *const value[], PetscInt stride, Vec out[], bool walls) {
  PetscFunctionBeginUser;
  PetscCall(Work(loc, nf));
  for (PetscInt f = 0; f < nf; ++f) PetscCall(VecSet(work_[loc][f], 0));
  PetscCall(compact_.Deposit(loc, n, x, H, nf, value, stride, work_[loc].data(), walls));
  // The deposits are zero beyond the particles' tent planes, their smoothed fields beyond those widened by the taps.
  PetscInt from[2] = {0, -1}, to[2] = {0, -1};
  if (op_ == Operator::Gaussian && filter_[loc].Restricts()) {
    PetscCall(TentPlanes(loc, n, x, from));
    to[0] = from[0] - filter_[loc].Radius(2), to[1] = from[1] + filter_[loc].Radius(2);
  }
  for (PetscInt f = 0; f < nf; ++f) {
    if (to[0] <= to[1]) PetscCall(Smooth(loc, work_[loc][f], from, to));
    else PetscCall(Smooth(loc, work_[loc][f]));
    PetscCall(VecAXPY(out[f], 1, work_[loc][f]));
  }
  PetscFunctionReturn(0);
}

// Weighted: the tent average of g = S(c f)/S(c) with the weight S(c), i.e. P S(c f)/P S(c) (P the tent
// interpolation), the diffusion counterpart of sum_J c_J f_J w_J/sum_J c_J w_J. The solves are the cost, so
// none is done twice or in vain: S(v) of a vector v is computed once per call (a weight shared by several
// fields, or eps both as a field and as the weight), and a constant field or weight needs none (S keeps a
// constant, and S(c f)/S(c) = f for constant f, = S(f) for constant c).
PetscErrorCode DiffusionSmoother::Average(int loc, PetscInt nf, const Vec field[], const Vec weight[], const bool walls[], PetscInt n, const PetscReal *x, const PetscReal *H,
                                          PetscReal *const out[], PetscInt stride) {
  PetscFunctionBeginUser;
  PetscCall(Work(loc, 2 * nf));
  std::vector<Vec>  g(nf), c(nf, nullptr), source, smoothed;
  size_t            next = 0;
  // Read only at the particles: the smoothed fields are needed on their tent planes only (the work vectors
  // are this call's; beyond those planes they hold partly smoothed values nobody reads).
  PetscInt all[2] = {0, sg_->Points(loc, 2) - 1}, at[2] = {0, -1};
  if (op_ == Operator::Gaussian && filter_[loc].Restricts()) PetscCall(TentPlanes(loc, n, x, at));
  const bool part = at[0] <= at[1];
  auto       smoothAt = [&](Vec v) -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (part) PetscCall(Smooth(loc, v, all, at));
    else PetscCall(Smooth(loc, v));
    PetscFunctionReturn(0);
  };
  auto constant = [](Vec v, bool *is, PetscReal *value) -> PetscErrorCode {  // min == max: one reduction; the local scan stops at the first value that differs
    const PetscScalar *a;
    PetscInt           m;
    PetscReal          range[2] = {-PETSC_MAX_REAL, -PETSC_MAX_REAL};  // -min, max (both MAX: not constant here)
    PetscFunctionBeginUser;
    PetscCall(VecGetLocalSize(v, &m));
    PetscCall(VecGetArrayRead(v, &a));
    if (m > 0) {
      const PetscReal first = PetscRealPart(a[0]);
      PetscInt        k     = 1;
      while (k < m && PetscRealPart(a[k]) == first) ++k;
      if (k == m) range[0] = -first, range[1] = first;
      else range[0] = range[1] = PETSC_MAX_REAL;
    }
    PetscCall(VecRestoreArrayRead(v, &a));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, range, 2, MPIU_REAL, MPIU_MAX, PetscObjectComm((PetscObject)v)));
    *is = -range[0] == range[1];
    if (value) *value = range[1];
    PetscFunctionReturn(0);
  };
  auto smooth = [&](Vec v, Vec *s) -> PetscErrorCode {  // S(v), once per vector
    PetscFunctionBeginUser;
    for (size_t k = 0; k < source.size(); ++k)
      if (source[k] == v) {
        *s = smoothed[k];
        PetscFunctionReturn(0);
      }
    *s = work_[loc][next++];
    PetscCall(VecCopy(v, *s));
    PetscCall(smoothAt(*s));
    source.push_back(v), smoothed.push_back(*s);
    PetscFunctionReturn(0);
  };
  // A constant field reads as its value at every particle (any weighted mean of a constant is the constant):
  // no smoothing, no ghost update, no particle loop for it.
  std::vector<Vec>         keepField, keepWeight;
  std::vector<PetscReal *> keepOut;
  std::vector<bool>        keepWalls;
  for (PetscInt f = 0; f < nf; ++f) {
    bool      fieldConstant = false, weightConstant = true;
    PetscReal value         = 0;
    PetscCall(constant(field[f], &fieldConstant, &value));
    if (fieldConstant) {
      for (PetscInt p = 0; p < n; ++p) out[f][p * stride] = value;
      continue;
    }
    if (weight[f]) PetscCall(constant(weight[f], &weightConstant, nullptr));
    keepOut.push_back(out[f]), keepWalls.push_back(walls[f]);
    if (weightConstant) {
      PetscCall(smooth(field[f], &g[f]));
      keepField.push_back(g[f]), keepWeight.push_back(nullptr);
      continue;
    }
    PetscCall(smooth(weight[f], &c[f]));
    g[f] = work_[loc][next++];
    PetscCall(VecPointwiseMult(g[f], field[f], weight[f]));
    PetscCall(smoothAt(g[f]));
    PetscScalar       *ga;
    const PetscScalar *ca;
    PetscInt           m;
    PetscCall(VecGetLocalSize(g[f], &m));
    PetscCall(VecGetArray(g[f], &ga));
    PetscCall(VecGetArrayRead(c[f], &ca));
    for (PetscInt k = 0; k < m; ++k) ga[k] = PetscRealPart(ca[k]) != 0 ? ga[k] / ca[k] : 0;
    PetscCall(VecRestoreArrayRead(c[f], &ca));
    PetscCall(VecRestoreArray(g[f], &ga));
    keepField.push_back(g[f]), keepWeight.push_back(c[f]);
  }
  if (keepField.empty()) PetscFunctionReturn(0);
  const PetscInt          nk = (PetscInt)keepField.size();
  std::unique_ptr<bool[]> w(new bool[nk]);
  for (PetscInt f = 0; f < nk; ++f) w[f] = keepWalls[f];
  PetscCall(compact_.Average(loc, nk, keepField.data(), keepWeight.data(), w.get(), n, x, H, keepOut.data(), stride));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
