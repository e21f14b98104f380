// A ParaView index (Xdmf.hpp) in a checkpoint: the steps and times of its entries so far, as one vector
// `name` (count, then step and time of each entry, on rank 0), so that a restarted run rewrites the whole
// index and not only the entries after the restart.
#pragma once

#include "vofdem/io/Xdmf.hpp"

#include <petscviewer.h>

#include <utility>
#include <vector>

namespace vofdem {

PetscErrorCode SaveXdmfIndex(PetscViewer viewer, MPI_Comm comm, const char *name, const std::vector<XdmfEntry> &entries);
// The (step, time) of each saved entry, on every rank.
PetscErrorCode LoadXdmfIndex(PetscViewer viewer, MPI_Comm comm, const char *name, std::vector<std::pair<PetscInt, PetscReal>> *entries);

}  // namespace vofdem
