// The staggered (MAC) layout on the grid, shared by flow, vof and coupling (docs/architecture.md, "face velocities"; DMDA traps: docs/petsc-notes.md):
// one DMDA per staggered location, all with the ownership ranges of the grid's cell DMDA.
//  - Cells(): cell-centred fields (density, viscosity, eps, pressure) as vectors with a 2-wide BOX
//    ghost layer (the TVD stencil); matrices are never assembled on it.
//  - Face(d): the d-component of velocity at the faces normal to d. Along d it has one point more
//    than there are cells (owned by the last rank) unless d is periodic; face index i sits at
//    x_d = lower + i h, between cells i-1 and i. Also BOX, width 2.
//  - FaceMatrixDM(d): the same layout with a STAR width-1 stencil, for the implicit viscous matrix.
// Outside a non-periodic box the DMDAs are DM_BOUNDARY_GHOSTED: the ghost layers there are filled
// by the boundary conditions (FlowBoundary), never by PETSc.
#pragma once

#include "vofdem/grid/Grid.hpp"

#include <petscdmda.h>

namespace vofdem {

// Raw access to a ghosted local array with global (i,j,k) indices, whatever DMDA it belongs to:
// one type for every staggered location lets the momentum kernels be written once for all three
// components (the component's direction becomes a run-time offset, not a copy of the code).
struct LocalField {
  PetscScalar *data = nullptr;
  PetscInt     g0[3] = {0, 0, 0};   // first ghosted index per direction
  PetscInt     stride[3] = {1, 0, 0};
  inline PetscScalar &at(PetscInt i, PetscInt j, PetscInt k) const {
    return data[(i - g0[0]) * stride[0] + (j - g0[1]) * stride[1] + (k - g0[2]) * stride[2]];
  }
  inline PetscScalar &at(const PetscInt q[3]) const { return at(q[0], q[1], q[2]); }
};

class StaggeredGrid {
public:
  PetscErrorCode Create(const Grid &grid);
  PetscErrorCode Destroy();

  DM Cells() const { return cells_; }
  DM Face(int d) const { return face_[d]; }
  DM FaceMatrixDM(int d) const { return faceStar_[d]; }
  const Grid &Base() const { return *grid_; }

  // Owned index range [start, start+count) of a location (d = 0..2 faces, 3 cells), per direction.
  void Owned(int loc, PetscInt start[3], PetscInt count[3]) const;
  // Number of points of location `loc` in direction e (cells N, faces N+1 along their normal unless periodic).
  PetscInt Points(int loc, int e) const { return (loc == e && !grid_->Periodic(e)) ? grid_->Cells()[e] + 1 : grid_->Cells()[e]; }

  // Access to the array of a LOCAL (ghosted) vector of location loc; restore after use.
  PetscErrorCode GetLocal(int loc, Vec local, LocalField *f) const;
  PetscErrorCode RestoreLocal(int loc, Vec local, LocalField *f) const;
  // Access to a GLOBAL vector with the same indexing (owned points only).
  PetscErrorCode GetGlobal(int loc, Vec global, LocalField *f) const;
  PetscErrorCode RestoreGlobal(int loc, Vec global, LocalField *f) const;

  DM Location(int loc) const { return loc == 3 ? cells_ : face_[loc]; }

private:
  const Grid *grid_ = nullptr;
  DM          cells_ = nullptr;
  DM          face_[3] = {nullptr, nullptr, nullptr};
  DM          faceStar_[3] = {nullptr, nullptr, nullptr};
};

}  // namespace vofdem
