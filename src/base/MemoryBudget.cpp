#include "vofdem/base/MemoryBudget.hpp"

#include "vofdem/base/Runtime.hpp"

#include <cstdio>
#include <cstring>

namespace vofdem {

namespace {
PetscInt64 MemAvailable() {
  std::FILE *f = std::fopen("/proc/meminfo", "r");
  if (!f) return 0;
  char       line[256];
  PetscInt64 kb = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, "MemAvailable:", 13) == 0) {
      long long v = 0;
      if (std::sscanf(line + 13, "%lld", &v) == 1) kb = v;
      break;
    }
  std::fclose(f);
  return 1024 * kb;
}

void Human(double bytes, char *out, size_t n) {
  const char *unit[] = {"B", "kB", "MB", "GB", "TB", "PB"};
  int         u      = 0;
  while (bytes >= 1000 && u < 5) bytes /= 1000, ++u;
  std::snprintf(out, n, "%.3g %s", bytes, unit[u]);
}
}  // namespace

PetscErrorCode AvailableMemoryPerRank(MPI_Comm comm, PetscInt64 *bytes) {
  MPI_Comm    node;
  PetscMPIInt share;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node));
  PetscCallMPI(MPI_Comm_size(node, &share));
  PetscCallMPI(MPI_Comm_free(&node));
  const PetscInt64 mine = MemAvailable() / share;
  PetscCallMPI(MPI_Allreduce(&mine, bytes, 1, MPIU_INT64, MPI_MIN, comm));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckMemoryRequest(MPI_Comm comm, const char *option, PetscInt64 count, double bytesEach, const char *what) {
  PetscInt64 have;

  PetscFunctionBeginUser;
  PetscCall(AvailableMemoryPerRank(comm, &have));
  const double need = (double)count * bytesEach;
  if (have > 0 && need > (double)have) {
    char n[32], h[32];
    Human(need, n, sizeof n);
    Human((double)have, h, sizeof h);
    VofdemInputError(comm, "option %s: %" PetscInt64_FMT " %s need at least %s on each rank, %s are available", option, count, what, n, h);
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
