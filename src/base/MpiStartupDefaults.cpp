#include "vofdem/base/MpiStartupDefaults.hpp"

#include <cstdlib>
#include <cstring>

namespace vofdem {

namespace {

bool IsSet(const char *name) { return std::getenv(name) != nullptr; }

}  // namespace

void ApplyMpiStartupDefaults() {
  const char *off = std::getenv("VOFDEM_MPI_DEFAULTS");
  if (off && !std::strcmp(off, "0")) return;
  const char *size  = std::getenv("OMPI_COMM_WORLD_SIZE");
  const char *local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  // Started by another launcher (Slurm's srun, a PMI/PMIx server): its transports are its business.
  const bool otherLauncher = !size && (IsSet("PMIX_RANK") || IsSet("PMI_RANK") || IsSet("PMI_SIZE") || IsSet("SLURM_STEP_ID"));
  if (otherLauncher) return;
  const bool singleton = !size;
  const bool oneNode   = singleton || (local && !std::strcmp(size, local));
  if (!oneNode) return;
  // One process, no daemon: a singleton never spawns processes (vofdem does not call MPI_Comm_spawn).
  if (singleton) setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  // Isolated singletons share one session folder (.../jf.0/1); the first to finish removes it, and
  // MPI-IO's shared-memory file-pointer component then fails to map its file in every HDF5 file the
  // others open ("mca_sharedfp_sm_component_file_query: Error", 26 lines while 15 short runs ended
  // beside one writing output). HDF5 never uses shared file pointers: leave that component out.
  if (singleton) setenv("OMPI_MCA_sharedfp", "^sm", 0);
  // Shared memory between the ranks of one machine, without opening the network layers first.
  if (!IsSet("OMPI_MCA_pml") && !IsSet("OMPI_MCA_mtl")) setenv("OMPI_MCA_pml", "ob1", 0);
}

}  // namespace vofdem
