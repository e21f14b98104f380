// What a request costs in memory against what this machine has, so that a request that cannot fit is refused
// up front with one line (the count, what it would need, what there is) instead of std::bad_alloc and a core dump.
#pragma once

#include <petscsys.h>

namespace vofdem {

// The memory a rank of comm may use: MemAvailable of /proc/meminfo shared among the ranks of comm on this node;
// the smallest over comm. 0 where it cannot be read (then nothing is refused on memory grounds).
PetscErrorCode AvailableMemoryPerRank(MPI_Comm comm, PetscInt64 *bytes);

// An input error naming `option` when `count` items of `bytesEach` bytes per rank (at least) exceed what a rank
// has: "option -dem_fill_count: 2000000000 particles need at least 184 GB on each rank (the random fill places all
// of them on every rank), 11.6 GB are available". `what` names the items and how they are held.
PetscErrorCode CheckMemoryRequest(MPI_Comm comm, const char *option, PetscInt64 count, double bytesEach, const char *what);

}  // namespace vofdem
