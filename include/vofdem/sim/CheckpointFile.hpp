// The checkpoint file format (issue 5): one HDF5 file per checkpoint, written through a
// PetscViewerHDF5 by every rank, then sealed and checked by rank 0 with the HDF5 library directly.
//
// Root attributes: "vofdem_checkpoint_format" (kCheckpointFormat), "run_options" (the options that
// define the run, RunDefiningOptions()), "physics", "ranks" (the rank count that wrote it), the
// Simulation's clock ("simulation_*", Simulation::SaveState) and, added by SealCheckpoint once every
// rank has closed the file, "checksum": a 64-bit FNV-1a hash of the other root attributes and of
// every dataset's name and values.
// A file without a checksum (never sealed) or whose data no longer hash to it (truncated,
// corrupted) fails ReadCheckpointHeader.
#pragma once

#include <hdf5.h>
#include <petscsys.h>

#include <string>

namespace vofdem {

// HDF5 prints its own error stack by default; the checkpoint code reports one reason instead. The
// previous printing is put back when the guard goes, so PETSc's HDF5 use is unaffected.
class QuietHdf5 {
public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

private:
  H5E_auto2_t func_ = nullptr;
  void       *data_ = nullptr;
};

// Raised whenever what a checkpoint holds or how it is laid out changes incompatibly.
constexpr int kCheckpointFormat = 1;

// The options of the PETSc options database that define the run, one "-name value" per line,
// sorted: everything except the options that may legitimately differ between a run and its
// restart (restart and checkpoint control, run length, monitors, output places, -grid_ranks, the
// options-file names whose contents are already in the database, PETSc's logging and debugging).
PetscErrorCode RunDefiningOptions(std::string *text);

// The first line where two RunDefiningOptions() texts differ, as "A (in the checkpoint) against B
// (in this run)"; empty when they are equal.
std::string FirstDifference(const std::string &saved, const std::string &current);  // ignores the options a restart may change
// The options a restart may change (the laser's power, path and timing) that differ: "-laser_power 300 -> 500; ...", or "".
std::string ChangedAtRestart(const std::string &saved, const std::string &current);

// What ReadCheckpointHeader returns.
struct CheckpointHeader {
  int         format = 0, ranks = 0;
  long long   step   = -1;
  std::string options, physics;
};

// Not collective (rank 0). Computes the checksum of the closed file `path` and stores it as the
// root attribute "checksum". False with a reason when the file cannot be opened or written.
bool SealCheckpoint(const std::string &path, std::string *why);

// Not collective (rank 0). Opens `path` read-only, reads the header attributes and verifies the
// checksum over all datasets. False with a one-phrase reason ("cannot open it as HDF5 (missing,
// truncated or not a checkpoint)", "checksum mismatch (corrupted)", ...) otherwise.
bool ReadCheckpointHeader(const std::string &path, CheckpointHeader *header, std::string *why);

}  // namespace vofdem
