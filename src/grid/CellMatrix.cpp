// CellMatrix.hpp: a cell matrix of the shared DM.
#include "vofdem/grid/CellMatrix.hpp"

#include <petscmat.h>

#include <string>

namespace vofdem {

PetscErrorCode CreateCellMatrix(DM dm, bool hypreStructured, Mat *A) {
  PetscFunctionBeginUser;
  if (!hypreStructured) {
    PetscCall(DMCreateMatrix(dm, A));
    PetscFunctionReturn(0);
  }
  MatType old;
  PetscCall(DMGetMatType(dm, &old));
  const std::string keep = old ? old : MATAIJ;
  PetscCall(DMSetMatType(dm, MATHYPRESTRUCT));
  PetscCall(DMCreateMatrix(dm, A));
  PetscCall(DMSetMatType(dm, keep.c_str()));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
