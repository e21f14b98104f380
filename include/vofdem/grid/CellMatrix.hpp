// A matrix on the grid's cell DMDA (Grid::CellDM, STAR width 1) for a cell-centred implicit solve (the pressure,
// the energy): hypre's structured type (for PFMG) or the DM's own, set for this matrix only, since the DM is
// shared (docs/petsc-notes.md, "PFMG wants even counts").
#pragma once

#include <petscdm.h>

namespace vofdem {

PetscErrorCode CreateCellMatrix(DM dm, bool hypreStructured, Mat *A);

}  // namespace vofdem
