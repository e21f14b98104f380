// A module's part of a checkpoint in its own HDF5 group: f() runs between PetscViewerHDF5PushGroup and
// PopGroup (base/Module.hpp, Save/Load).
#pragma once

#include <petscviewerhdf5.h>

namespace vofdem {

template <class F>
PetscErrorCode InViewerGroup(PetscViewer viewer, const char *group, F &&f) {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5PushGroup(viewer, group));
  PetscCall(f());
  PetscCall(PetscViewerHDF5PopGroup(viewer));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
