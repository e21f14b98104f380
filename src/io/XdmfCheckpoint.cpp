// XdmfCheckpoint.hpp: the index's entries as a checkpoint vector.
#include "vofdem/io/XdmfCheckpoint.hpp"

#include <petscvec.h>

namespace vofdem {

PetscErrorCode SaveXdmfIndex(PetscViewer viewer, MPI_Comm comm, const char *name, const std::vector<XdmfEntry> &entries) {
  Vec         v;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const PetscInt m = (PetscInt)entries.size();
  PetscCall(VecCreateMPI(comm, rank == 0 ? 1 + 2 * m : 0, 1 + 2 * m, &v));
  PetscCall(PetscObjectSetName((PetscObject)v, name));
  if (rank == 0) {
    PetscCall(VecSetValue(v, 0, (PetscScalar)m, INSERT_VALUES));
    for (PetscInt k = 0; k < m; ++k) {
      PetscCall(VecSetValue(v, 1 + 2 * k, (PetscScalar)entries[k].step, INSERT_VALUES));
      PetscCall(VecSetValue(v, 2 + 2 * k, entries[k].time, INSERT_VALUES));
    }
  }
  PetscCall(VecAssemblyBegin(v));
  PetscCall(VecAssemblyEnd(v));
  PetscCall(VecView(v, viewer));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

PetscErrorCode LoadXdmfIndex(PetscViewer viewer, MPI_Comm comm, const char *name, std::vector<std::pair<PetscInt, PetscReal>> *entries) {
  Vec                v, all;
  VecScatter         toAll;
  const PetscScalar *a;

  PetscFunctionBeginUser;
  PetscCall(VecCreate(comm, &v));
  PetscCall(VecSetType(v, VECMPI));
  PetscCall(PetscObjectSetName((PetscObject)v, name));
  PetscCall(VecLoad(v, viewer));
  PetscCall(VecScatterCreateToAll(v, &toAll, &all));
  PetscCall(VecScatterBegin(toAll, v, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(toAll, v, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(all, &a));
  entries->clear();
  for (PetscInt k = 0; k < (PetscInt)PetscRealPart(a[0]); ++k) entries->emplace_back((PetscInt)PetscRealPart(a[1 + 2 * k]), PetscRealPart(a[2 + 2 * k]));
  PetscCall(VecRestoreArrayRead(all, &a));
  PetscCall(VecScatterDestroy(&toAll));
  PetscCall(VecDestroy(&all));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
