#include "vofdem/grid/StaggeredGrid.hpp"

#include "vofdem/base/Runtime.hpp"

#include <vector>

namespace vofdem {

PetscErrorCode StaggeredGrid::Create(const Grid &grid) {
  const PetscInt *l[3];
  PetscInt        m[3];

  PetscFunctionBeginUser;
  grid_ = &grid;
  PetscCall(DMDAGetInfo(grid.CellDM(), nullptr, nullptr, nullptr, nullptr, &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(grid.CellDM(), &l[0], &l[1], &l[2]));
  std::vector<PetscInt> own[3];
  for (int d = 0; d < 3; ++d) {
    own[d].assign(l[d], l[d] + m[d]);
    // The 2-wide ghost layer (TVD stencil) needs 2 owned cells per rank per direction, unless the
    // direction is one cell across on one rank and not periodic: a quasi-2-D case, whose ghosts the
    // boundary conditions fill without neighbours (with slip walls on both sides it is the 2-D problem:
    // ex30 gives the same fronts as with two layers). Say so here instead of PETSc's message about
    // stencil widths.
    const bool single = m[d] == 1 && grid.Cells()[d] == 1 && !grid.Periodic(d);
    for (PetscInt r = 0; r < m[d]; ++r)
      if (own[d][r] < 2 && !single)
        VofdemInputError(grid.Comm(),
                         "option -grid_cells: the flow solver needs at least 2 cells per rank in each direction (or one cell across a non-periodic direction on one rank), but %c has %" PetscInt_FMT
                         " cells on %" PetscInt_FMT " ranks (fewer ranks, more cells, or -grid_ranks)",
                         "xyz"[d], grid.Cells()[d], m[d]);
  }
  DMBoundaryType bt[3];
  for (int d = 0; d < 3; ++d) bt[d] = grid.Periodic(d) ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_GHOSTED;
  const PetscInt *N = grid.Cells();
  PetscCall(DMDACreate3d(grid.Comm(), bt[0], bt[1], bt[2], DMDA_STENCIL_BOX, N[0], N[1], N[2], m[0], m[1], m[2], 1, 2, own[0].data(), own[1].data(),
                         own[2].data(), &cells_));
  PetscCall(grid.SetUpDMDA(cells_));
  for (int d = 0; d < 3; ++d) {
    std::vector<PetscInt> lf[3] = {own[0], own[1], own[2]};
    PetscInt              n[3]  = {N[0], N[1], N[2]};
    if (!grid.Periodic(d)) {
      lf[d].back() += 1;  // the extra face along the normal belongs to the last rank (LaMEM layout)
      n[d] += 1;
    }
    PetscCall(DMDACreate3d(grid.Comm(), bt[0], bt[1], bt[2], DMDA_STENCIL_BOX, n[0], n[1], n[2], m[0], m[1], m[2], 1, 2, lf[0].data(), lf[1].data(),
                           lf[2].data(), &face_[d]));
    PetscCall(grid.SetUpDMDA(face_[d]));
    // Matrices only on STAR width 1 (notes: BOX preallocates (2s+1)^3 entries per row).
    DMBoundaryType bs[3];
    for (int e = 0; e < 3; ++e) bs[e] = grid.Periodic(e) ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_NONE;
    PetscCall(DMDACreate3d(grid.Comm(), bs[0], bs[1], bs[2], DMDA_STENCIL_STAR, n[0], n[1], n[2], m[0], m[1], m[2], 1, 1, lf[0].data(), lf[1].data(),
                           lf[2].data(), &faceStar_[d]));
    PetscCall(grid.SetUpDMDA(faceStar_[d]));
  }
  PetscFunctionReturn(0);
}

void StaggeredGrid::Owned(int loc, PetscInt start[3], PetscInt count[3]) const {
  DMDAGetCorners(Location(loc), &start[0], &start[1], &start[2], &count[0], &count[1], &count[2]);
}

PetscErrorCode StaggeredGrid::GetLocal(int loc, Vec local, LocalField *f) const {
  PetscInt gs[3], gm[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetGhostCorners(Location(loc), &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  PetscCall(VecGetArray(local, &f->data));
  for (int d = 0; d < 3; ++d) f->g0[d] = gs[d];
  f->stride[0] = 1;
  f->stride[1] = gm[0];
  f->stride[2] = gm[0] * gm[1];
  PetscFunctionReturn(0);
}

PetscErrorCode StaggeredGrid::RestoreLocal(int, Vec local, LocalField *f) const {
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArray(local, &f->data));
  PetscFunctionReturn(0);
}

PetscErrorCode StaggeredGrid::GetGlobal(int loc, Vec global, LocalField *f) const {
  PetscInt s[3], c[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetCorners(Location(loc), &s[0], &s[1], &s[2], &c[0], &c[1], &c[2]));
  PetscCall(VecGetArray(global, &f->data));
  for (int d = 0; d < 3; ++d) f->g0[d] = s[d];
  f->stride[0] = 1;
  f->stride[1] = c[0];
  f->stride[2] = c[0] * c[1];
  PetscFunctionReturn(0);
}

PetscErrorCode StaggeredGrid::RestoreGlobal(int, Vec global, LocalField *f) const {
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArray(global, &f->data));
  PetscFunctionReturn(0);
}

PetscErrorCode StaggeredGrid::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(DMDestroy(&cells_));
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMDestroy(&face_[d]));
    PetscCall(DMDestroy(&faceStar_[d]));
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
