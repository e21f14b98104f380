// Checkpoint/restart of a whole run (issue 5): when to write a checkpoint (-checkpoint_every steps,
// -checkpoint_minutes of wall time, at the end, on SIGTERM/SIGINT/SIGUSR1/SIGUSR2), how (atomically: a temporary
// file, sealed, then renamed; the last -checkpoint_keep kept) and -restart FILE|latest. What a
// checkpoint holds is the Simulation's (Simulation::SaveState/LoadState); the file format and its
// validation are CheckpointFile.hpp.
#pragma once

#include <petscsys.h>
#include <petscviewer.h>

#include <string>

namespace vofdem {

class Simulation;

class Checkpoint {
public:
  // Reads -checkpoint_* and -restart. `outputDir` is -output_dir (may be empty).
  PetscErrorCode SetFromOptions(MPI_Comm comm, const std::string &outputDir);
  // Collective, after the modules are set up: checks that the checkpoint folder can be written
  // (when checkpoints are on) and installs the SIGTERM/SIGINT/SIGUSR1/SIGUSR2 handlers.
  PetscErrorCode SetUp();
  // Collective: with -restart, finds and validates the file and loads `sim` from it.
  PetscErrorCode Restore(Simulation &sim);
  // Collective, after each step: writes a checkpoint when one is due (`last`: the run's final step)
  // and sets *stop when a signal asked the run to end.
  PetscErrorCode AfterStep(Simulation &sim, bool last, bool *stop);
  PetscErrorCode Destroy();  // puts the previous signal handlers back

  bool Enabled() const { return enabled_; }
  bool Restarting() const { return !restart_.empty(); }

private:
  PetscErrorCode Write(Simulation &sim);
  PetscErrorCode FindLatest(std::string *path);
  PetscErrorCode RemoveOld();

  MPI_Comm       comm_ = MPI_COMM_NULL;
  std::string    dir_, restart_;
  PetscInt       every_ = 0, keep_ = 2;
  PetscReal      minutes_ = 0;
  PetscBool      final_ = PETSC_TRUE, spaceCheck_ = PETSC_TRUE;
  bool           enabled_ = false, handlers_ = false;
  PetscLogDouble lastWrite_ = 0;  // wall time of the last checkpoint (rank 0 decides)
  PetscInt       lastStep_  = -1; // step of the last checkpoint written
  PetscLogEvent  evWrite_ = 0, evSeal_ = 0;  // -log_view: the HDF5 write (all ranks); the checksum, rename, clean-up (rank 0)
  PetscInt64     lastBytes_ = 0;  // its size (rank 0): the next one needs about as much room
};

}  // namespace vofdem
