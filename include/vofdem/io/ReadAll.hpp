// Every value of a dataset of an HDF5 viewer's current group on every rank of comm: a parallel read
// into a Vec of block size bs (total values, or -1: as the file has them), then an all-gather. For
// data read once (a checkpoint's arrays on another rank count, saved particles for the analysis).
#pragma once

#include <petscviewer.h>

#include <vector>

namespace vofdem {

PetscErrorCode ReadAll(PetscViewer viewer, MPI_Comm comm, const char *name, PetscInt total, PetscInt bs, std::vector<PetscReal> *out);

}  // namespace vofdem
