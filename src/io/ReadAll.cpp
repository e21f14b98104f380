#include "vofdem/io/ReadAll.hpp"

#include <petscvec.h>
#include <petscviewerhdf5.h>

namespace vofdem {

PetscErrorCode ReadAll(PetscViewer viewer, MPI_Comm comm, const char *name, PetscInt total, PetscInt bs, std::vector<PetscReal> *out) {
  Vec                v, all;
  VecScatter         scatter;
  const PetscScalar *a;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(VecCreate(comm, &v));
  if (total >= 0) PetscCall(VecSetSizes(v, PETSC_DECIDE, total));
  PetscCall(VecSetBlockSize(v, bs));
  PetscCall(VecSetType(v, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)v, name));
  PetscCall(VecLoad(v, viewer));
  PetscCall(VecScatterCreateToAll(v, &scatter, &all));
  PetscCall(VecScatterBegin(scatter, v, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(scatter, v, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetLocalSize(all, &n));
  PetscCall(VecGetArrayRead(all, &a));
  out->assign(a, a + n);
  PetscCall(VecRestoreArrayRead(all, &a));
  PetscCall(VecScatterDestroy(&scatter));
  PetscCall(VecDestroy(&all));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
