// Writing a small text file from a parallel program: rank 0 writes it to a temporary name and
// renames it (so a reader never sees half a file), and every rank learns whether that worked.
#pragma once

#include <petscsys.h>

#include <string>

namespace vofdem {

// Collective. Raises an input error naming `what` (an option or purpose) and the path on failure.
PetscErrorCode WriteTextFile(MPI_Comm comm, const std::string &path, const std::string &text, const char *what);

// Collective. Checks at start-up that `path` can be written later (rank 0 creates and removes its
// temporary file), so a bad output path stops the run before it starts, not after hours.
PetscErrorCode CheckWritable(MPI_Comm comm, const std::string &path, const char *what);

}  // namespace vofdem
