#include "vofdem/io/TextFile.hpp"

#include "vofdem/base/Runtime.hpp"

#include <cstdio>

namespace vofdem {

PetscErrorCode WriteTextFile(MPI_Comm comm, const std::string &path, const std::string &text, const char *what) {
  PetscMPIInt rank;
  int         ok = 1;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    const std::string tmp = path + ".tmp";
    FILE             *f   = std::fopen(tmp.c_str(), "w");
    ok                    = f && std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (f) ok = (std::fclose(f) == 0) && ok;
    ok = ok && std::rename(tmp.c_str(), path.c_str()) == 0;
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  if (!ok) VofdemInputError(comm, "%s: cannot write '%s'", what, path.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode CheckWritable(MPI_Comm comm, const std::string &path, const char *what) {
  PetscMPIInt rank;
  int         ok = 1;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    const std::string tmp = path + ".tmp";
    FILE             *f   = std::fopen(tmp.c_str(), "w");
    ok                    = f != nullptr;
    if (f) {
      std::fclose(f);
      std::remove(tmp.c_str());
    }
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  if (!ok) VofdemInputError(comm, "%s: cannot write '%s'", what, path.c_str());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
