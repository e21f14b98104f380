#include "vofdem/grid/Grid.hpp"

namespace vofdem {

// New ownership ranges: both DMDAs are rebuilt through SetUp, which reads ownership_; the vertex
// DMDA follows the cell DMDA as at start-up (its extra node on the first rank).
PetscErrorCode Grid::Repartition(const std::vector<PetscInt> cellsPerRank[3]) {
  PetscFunctionBeginUser;
  const PetscBool vertex = vertexDM_ ? PETSC_TRUE : PETSC_FALSE;
  for (int d = 0; d < 3; ++d) {
    PetscInt sum = 0;
    for (PetscInt c : cellsPerRank[d]) {
      PetscCheck(c >= 1, comm_, PETSC_ERR_ARG_OUTOFRANGE, "repartition: a rank needs at least one cell in %c", "xyz"[d]);
      sum += c;
    }
    PetscCheck(sum == cells_[d], comm_, PETSC_ERR_ARG_SIZ, "repartition: %" PetscInt_FMT " cells in %c, the grid has %" PetscInt_FMT, sum, "xyz"[d], cells_[d]);
    ownership_[d] = cellsPerRank[d];
  }
  PetscCall(DMDestroy(&vertexDM_));
  PetscCall(DMDestroy(&cellDM_));
  PetscCall(SetUp(vertex));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
