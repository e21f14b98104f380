#include "vofdem/coupling/KernelAverager.hpp"

#include "vofdem/core/Runtime.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

PetscErrorCode KernelAverager::Layout(int loc, DM *dm) const {
  const Grid     &grid = sg_->Base();
  const PetscInt *l[3];
  PetscInt        m[3], N[3];
  DMBoundaryType  bt[3];

  PetscFunctionBeginUser;
  DM base = sg_->Location(loc);
  PetscCall(DMDAGetInfo(base, nullptr, &N[0], &N[1], &N[2], &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(base, &l[0], &l[1], &l[2]));
  for (int d = 0; d < 3; ++d) {
    bt[d] = grid.Periodic(d) ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_NONE;
    // PETSc needs every rank to own at least the ghost width wherever there is a neighbour.
    for (PetscInt r = 0; r < m[d] && m[d] > 1; ++r)
      if (l[d][r] < width_)
        VofdemInputError(grid.Comm(),
                         "coupling: the kernel reaches %" PetscInt_FMT " cells, more than the %" PetscInt_FMT " cells a rank owns in %c; use fewer ranks in %c (-grid_ranks), more cells, or a narrower kernel (-coupling_kernel_width)",
                         width_, l[d][r], "xyz"[d], "xyz"[d]);
    if (m[d] == 1 && grid.Periodic(d) && N[d] < width_)
      VofdemInputError(grid.Comm(), "coupling: the kernel reaches %" PetscInt_FMT " cells, more than the %" PetscInt_FMT " periodic cells in %c; use a narrower kernel (-coupling_kernel_width)",
                       width_, N[d], "xyz"[d]);
  }
  PetscCall(DMDACreate3d(grid.Comm(), bt[0], bt[1], bt[2], DMDA_STENCIL_BOX, N[0], N[1], N[2], m[0], m[1], m[2], 1, width_, l[0], l[1], l[2], dm));
  PetscCall(DMSetUp(*dm));
  PetscFunctionReturn(0);
}

PetscErrorCode KernelAverager::SetUp(const StaggeredGrid &sg, const Settings &s, PetscReal maxCutoff, PetscReal margin) {
  PetscFunctionBeginUser;
  sg_       = &sg;
  settings_ = s;
  const PetscReal *h    = sg.Base().Spacing();
  const PetscReal  hmin = std::min(h[0], std::min(h[1], h[2]));
  // Unresolved: the containing cell and its faces (one point beyond the cell's index either way).
  const PetscReal reach = s.shape == kernel::Shape::Unresolved ? hmin : maxCutoff;
  width_ = (PetscInt)std::ceil((reach + margin) / hmin) + 1;
  for (int loc = 0; loc < 4; ++loc) {
    PetscCall(Layout(loc, &dm_[loc]));
    PetscCall(DMCreateLocalVector(dm_[loc], &local_[loc]));
    PetscCall(DMDAGetGhostCorners(dm_[loc], &gs_[loc][0], &gs_[loc][1], &gs_[loc][2], &gm_[loc][0], &gm_[loc][1], &gm_[loc][2]));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode KernelAverager::Destroy() {
  PetscFunctionBeginUser;
  for (int loc = 0; loc < 4; ++loc) {
    PetscCall(VecDestroy(&local_[loc]));
    PetscCall(DMDestroy(&dm_[loc]));
  }
  PetscCall(VecDestroy(&weightLocal_));
  PetscFunctionReturn(0);
}

bool KernelAverager::Support(int loc, const PetscReal x[3], PetscReal H, bool deposit, std::vector<PetscInt> &offsets, std::vector<PetscReal> &weights) const {
  const Grid      &grid = sg_->Base();
  const PetscReal *h = grid.Spacing();
  PetscInt         q0[3], q1[3], N[3];
  PetscReal        s[3];
  offsets.clear();
  weights.clear();
  const bool unresolved = settings_.shape == kernel::Shape::Unresolved;
  const PetscReal rc    = unresolved ? 0 : Cutoff(H);
  PetscInt lo[3], hi[3];  // the points that may take part, per direction
  for (int e = 0; e < 3; ++e) {
    N[e] = sg_->Points(loc, e);
    // Continuous index of x in the location's numbering (faces normal to e sit at integer indices).
    s[e] = (x[e] - grid.Lower()[e]) / h[e] - (loc == e ? 0 : 0.5);
    PetscReal c = (x[e] - grid.Lower()[e]) / h[e];  // in cells
    if (grid.Periodic(e)) {
      // A particle held by this rank may have been wrapped to the far side of the box since it last
      // migrated: use its image nearest this rank's points.
      const PetscReal mid = gs_[loc][e] + 0.5 * gm_[loc][e];
      if (s[e] - mid > 0.5 * N[e]) s[e] -= N[e], c -= N[e];
      else if (s[e] - mid < -0.5 * N[e]) s[e] += N[e], c += N[e];
      lo[e] = PETSC_MIN_INT, hi[e] = PETSC_MAX_INT;
    } else {
      // Deposits skip the wall faces of their own component (the boundary conditions set them).
      const bool skipWalls = deposit && loc == e;
      lo[e] = skipWalls ? 1 : 0, hi[e] = skipWalls ? N[e] - 2 : N[e] - 1;
    }
    if (unresolved) {
      const PetscInt cell = (PetscInt)std::floor(c);  // the containing cell
      const PetscInt cc = grid.Periodic(e) ? cell : std::min(std::max(cell, (PetscInt)0), grid.Cells()[e] - 1);
      q0[e] = cc, q1[e] = loc == e ? cc + 1 : cc;
    } else {
      q0[e] = (PetscInt)std::ceil(s[e] - rc / h[e]);
      q1[e] = (PetscInt)std::floor(s[e] + rc / h[e]);
    }
    q0[e] = std::max(q0[e], lo[e]);
    q1[e] = std::min(q1[e], hi[e]);
    if (q0[e] < gs_[loc][e] || q1[e] >= gs_[loc][e] + gm_[loc][e]) return false;
  }
  const PetscInt sy = gm_[loc][0], sz = gm_[loc][0] * gm_[loc][1];
  PetscReal      sum = 0;
  for (PetscInt k = q0[2]; k <= q1[2]; ++k) {
    const PetscReal dz = (k - s[2]) * h[2];
    for (PetscInt j = q0[1]; j <= q1[1]; ++j) {
      const PetscReal dy = (j - s[1]) * h[1];
      for (PetscInt i = q0[0]; i <= q1[0]; ++i) {
        const PetscReal dx = (i - s[0]) * h[0];
        const PetscReal w  = unresolved ? 1 : kernel::Weight(settings_.shape, dx * dx + dy * dy + dz * dz, H, rc);
        if (w <= 0) continue;
        offsets.push_back((i - gs_[loc][0]) + (j - gs_[loc][1]) * sy + (k - gs_[loc][2]) * sz);
        weights.push_back(w);
        sum += w;
      }
    }
  }
  if (!(sum > 0)) {  // a kernel narrower than the point spacing missed every point: take the nearest
    PetscInt q[3];
    for (int e = 0; e < 3; ++e) {
      q[e] = std::min(std::max((PetscInt)std::lround(s[e]), lo[e]), hi[e]);
      if (q[e] < gs_[loc][e] || q[e] >= gs_[loc][e] + gm_[loc][e]) return false;
    }
    offsets.assign(1, (q[0] - gs_[loc][0]) + (q[1] - gs_[loc][1]) * sy + (q[2] - gs_[loc][2]) * sz);
    weights.assign(1, 1.0);
    return true;
  }
  for (PetscReal &w : weights) w /= sum;
  return true;
}

PetscErrorCode KernelAverager::Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, const PetscReal *value, PetscInt stride, Vec out) {
  PetscScalar *a;
  PetscInt     bad = 0, anyBad;

  PetscFunctionBeginUser;
  PetscCall(VecSet(local_[loc], 0));
  PetscCall(VecGetArray(local_[loc], &a));
  for (PetscInt p = 0; p < n; ++p) {
    if (!Support(loc, &x[3 * p], H[p], true, offsets_, weights_)) {
      ++bad;
      continue;
    }
    const PetscReal v = value[p * stride];
    for (size_t k = 0; k < offsets_.size(); ++k) a[offsets_[k]] += v * weights_[k];
  }
  PetscCall(VecRestoreArray(local_[loc], &a));
  PetscCallMPI(MPI_Allreduce(&bad, &anyBad, 1, MPIU_INT, MPI_SUM, sg_->Base().Comm()));
  PetscCheck(anyBad == 0, sg_->Base().Comm(), PETSC_ERR_PLIB, "coupling: %" PetscInt_FMT " particle kernels reach beyond the ghost layer (%" PetscInt_FMT " cells)", anyBad, width_);
  PetscCall(DMLocalToGlobal(dm_[loc], local_[loc], ADD_VALUES, out));
  PetscFunctionReturn(0);
}

PetscErrorCode KernelAverager::Average(int loc, Vec field, Vec weight, PetscInt n, const PetscReal *x, const PetscReal *H, PetscReal *out, PetscInt stride, bool walls) {
  const PetscScalar *f, *c = nullptr;
  PetscInt           bad = 0, anyBad;

  PetscFunctionBeginUser;
  PetscCall(DMGlobalToLocal(dm_[loc], field, INSERT_VALUES, local_[loc]));
  if (weight) {
    if (!weightLocal_) PetscCall(VecDuplicate(local_[3], &weightLocal_));
    PetscInt nw, nl;
    PetscCall(VecGetSize(weightLocal_, &nw));
    PetscCall(VecGetSize(local_[loc], &nl));
    if (nw != nl) {  // sized for another location
      PetscCall(VecDestroy(&weightLocal_));
      PetscCall(VecDuplicate(local_[loc], &weightLocal_));
    }
    PetscCall(DMGlobalToLocal(dm_[loc], weight, INSERT_VALUES, weightLocal_));
    PetscCall(VecGetArrayRead(weightLocal_, &c));
  }
  PetscCall(VecGetArrayRead(local_[loc], &f));
  for (PetscInt p = 0; p < n; ++p) {
    if (!Support(loc, &x[3 * p], H[p], !walls, offsets_, weights_)) {
      ++bad;
      out[p * stride] = 0;
      continue;
    }
    PetscReal num = 0, den = 0;
    for (size_t k = 0; k < offsets_.size(); ++k) {
      const PetscReal w = c ? weights_[k] * PetscRealPart(c[offsets_[k]]) : weights_[k];
      num += w * PetscRealPart(f[offsets_[k]]);
      den += w;
    }
    out[p * stride] = den > 0 ? num / den : 0;
  }
  PetscCall(VecRestoreArrayRead(local_[loc], &f));
  if (c) PetscCall(VecRestoreArrayRead(weightLocal_, &c));
  PetscCallMPI(MPI_Allreduce(&bad, &anyBad, 1, MPIU_INT, MPI_SUM, sg_->Base().Comm()));
  PetscCheck(anyBad == 0, sg_->Base().Comm(), PETSC_ERR_PLIB, "coupling: %" PetscInt_FMT " particle kernels reach beyond the ghost layer (%" PetscInt_FMT " cells)", anyBad, width_);
  PetscFunctionReturn(0);
}

}  // namespace vofdem
