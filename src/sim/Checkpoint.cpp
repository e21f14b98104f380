#include "vofdem/sim/Checkpoint.hpp"

#include "vofdem/sim/CheckpointFile.hpp"
#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/Simulation.hpp"

#include <petsctime.h>
#include <petscviewerhdf5.h>

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>
#include <system_error>
#include <vector>

namespace fs = std::filesystem;

namespace vofdem {

namespace {

// The handler only records the signal; the ranks agree on it after the step (AfterStep).
volatile std::sig_atomic_t g_signal = 0;
void OnSignal(int sig) { g_signal = sig; }
// The signals that stop a run with a checkpoint. SIGTERM and SIGINT reach the ranks when sent to
// them (a batch system's scancel, kill); Open MPI's mpiexec, when it gets them itself (Ctrl-C), kills
// the ranks one second later (odls_base_sigkill_timeout) but forwards SIGUSR1 and SIGUSR2 untouched:
// `kill -USR1 <mpiexec>` or Slurm's --signal=USR1@120 stop a run cleanly through mpiexec.
const int        kStopSignals[] = {SIGTERM, SIGINT, SIGUSR1, SIGUSR2};
struct sigaction g_oldHandlers[4];

// Step number of a file name checkpoint_<8 digits>.h5, or -1.
long long StepOf(const fs::path &p) {
  const std::string n = p.filename().string();
  if (n.size() != 22 || n.compare(0, 11, "checkpoint_") || n.compare(19, 3, ".h5")) return -1;
  long long step = 0;
  for (int k = 11; k < 19; ++k) {
    if (!std::isdigit((unsigned char)n[k])) return -1;
    step = 10 * step + (n[k] - '0');
  }
  return step;
}

std::string Name(long long step, bool temporary) {
  char buf[64];
  std::snprintf(buf, sizeof buf, temporary ? ".checkpoint_%08lld.h5.tmp" : "checkpoint_%08lld.h5", step);
  return buf;
}

// The checkpoints of `dir`, newest first.
std::vector<fs::path> Checkpoints(const std::string &dir) {
  std::vector<std::pair<long long, fs::path>> found;
  std::error_code                             ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (StepOf(it->path()) >= 0) found.emplace_back(StepOf(it->path()), it->path());
  std::sort(found.begin(), found.end(), [](const auto &a, const auto &b) { return a.first > b.first; });
  std::vector<fs::path> paths;
  for (const auto &f : found) paths.push_back(f.second);
  return paths;
}

// While a checkpoint is written: the temporary file and what is kept. An error inside the HDF5
// write (the disk filled up after the space check, or without it) may strike some ranks only, which
// cannot return: the others would wait for them in the next collective call. Nor can a lone rank go
// on: HDF5 keeps the file it could not close and crashes in MPI_Finalize. So the job ends here, with
// one line and MPI_Abort (exit 1 on every rank); the temporary file is removed by the next run.
std::string g_writing, g_kept;
PetscErrorCode WriteErrorHandler(MPI_Comm, int, const char *, const char *, PetscErrorCode n, PetscErrorType p, const char *mess, void *) {
  if (p != PETSC_ERROR_INITIAL) return n;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::fprintf(stderr, "vofdem: error: checkpoint: writing '%s' failed on rank %d (%s; disk full?); %s\n", g_writing.c_str(), rank, mess ? mess : "an HDF5 error",
               g_kept.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 1);
  return n;
}

// Rank 0, before a checkpoint of about `bytes` is written to `path`: the space is there (taken with
// posix_fallocate, which sees a full disk, a quota and a file-size limit alike, then given back).
bool ReserveSpace(const std::string &path, PetscInt64 bytes, std::string *why) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) {
    *why = std::string("cannot create it: ") + std::strerror(errno);
    return false;
  }
  const int err = posix_fallocate(fd, 0, (off_t)bytes);
  const bool ok = err == 0 && ftruncate(fd, 0) == 0;
  close(fd);
  if (!ok) {
    char mb[64];
    std::snprintf(mb, sizeof mb, "%.1f MB", bytes / 1e6);
    *why = std::string("no room for about ") + mb + " (" + std::strerror(err ? err : errno) + ")";
    std::remove(path.c_str());
  }
  return ok;
}

// Rank 0's verdict (ok, and the reason when not) on every rank.
PetscErrorCode Agree(MPI_Comm comm, bool *ok, std::string *why) {
  int len = (int)why->size(), flag = *ok;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Bcast(&flag, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, 0, comm));
  why->resize((size_t)len);
  PetscCallMPI(MPI_Bcast(why->data(), len, MPI_CHAR, 0, comm));
  *ok = flag != 0;
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode Checkpoint::SetFromOptions(MPI_Comm comm, const std::string &outputDir) {
  PetscBool everySet = PETSC_FALSE, minutesSet = PETSC_FALSE, dirSet = PETSC_FALSE, finalSet = PETSC_FALSE;

  PetscFunctionBeginUser;
  comm_ = comm;
  dir_  = outputDir.empty() ? "checkpoints" : outputDir + "/checkpoints";
  PetscOptionsBegin(comm_, nullptr, "Checkpoint/restart (on when -checkpoint_every, -checkpoint_minutes, -checkpoint_dir, -checkpoint_final 1 or -restart is given)", "Checkpoint");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.Int("-checkpoint_every", "Write a checkpoint every this many steps (0: never by step count)", &every_, 0, PETSC_MAX_INT, &everySet));
    PetscCall(opt.Real("-checkpoint_minutes", "Write a checkpoint every this much wall time (0: never by wall time)", "min", &minutes_,
                       RealRange::NonNegative(), &minutesSet));
    PetscCall(opt.Int("-checkpoint_keep", "Number of newest checkpoints kept; older ones are removed", &keep_, 1));
    PetscCall(opt.String("-checkpoint_dir", "Folder of the checkpoints (default: <-output_dir>/checkpoints, or checkpoints)", &dir_, &dirSet));
    PetscCall(opt.Bool("-checkpoint_final", "Write a checkpoint at the end of the run (given alone: only that one)", &final_, &finalSet));
    PetscCall(opt.Bool("-checkpoint_space_check", "Before each checkpoint, make sure the disk has room for it (posix_fallocate of its estimated size)", &spaceCheck_));
    PetscCall(opt.String("-restart", "Continue the run from this checkpoint file, or from the newest valid one in -checkpoint_dir (latest)", &restart_));
  }
  PetscOptionsEnd();
  enabled_ = everySet || minutesSet || dirSet || (finalSet && final_) || !restart_.empty();
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::SetUp() {
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  if (!enabled_) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  bool        ok = true;
  std::string why;
  if (rank == 0) {  // the folder exists and takes a file: a failure now beats one after hours
    std::error_code ec;
    fs::create_directories(dir_, ec);
    const std::string probe = dir_ + "/.checkpoint_probe";
    FILE             *f     = ec ? nullptr : std::fopen(probe.c_str(), "w");
    ok                      = f != nullptr;
    if (f) std::fclose(f), std::remove(probe.c_str());
  }
  PetscCall(Agree(comm_, &ok, &why));
  if (!ok) VofdemInputError(comm_, "option -checkpoint_dir: cannot create '%s' or write a file in it", dir_.c_str());
  // A file-size limit (ulimit -f) then fails the write (reported) instead of killing the rank.
  std::signal(SIGXFSZ, SIG_IGN);
  struct sigaction sa = {};
  sa.sa_handler       = OnSignal;
  sigemptyset(&sa.sa_mask);
  for (int k = 0; k < 4; ++k) sigaction(kStopSignals[k], &sa, &g_oldHandlers[k]);
  handlers_ = true;
  g_signal  = 0;
  PetscCall(PetscLogEventRegister("CheckpointWrite", PETSC_VIEWER_CLASSID, &evWrite_));
  PetscCall(PetscLogEventRegister("CheckpointSeal", PETSC_VIEWER_CLASSID, &evSeal_));
  PetscCall(PetscTime(&lastWrite_));
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::FindLatest(std::string *path) {
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  bool        ok = false;
  std::string why;
  if (rank == 0) {
    std::string skipped;  // reported as warnings when a valid file is found, else in the error
    for (const fs::path &p : Checkpoints(dir_)) {
      CheckpointHeader h;
      if (ReadCheckpointHeader(p.string(), &h, &why)) {
        ok    = true;
        *path = p.string();
        break;
      }
      skipped += (skipped.empty() ? "" : "; ") + p.string() + ": " + why;
    }
    if (ok && !skipped.empty()) std::fprintf(stderr, "vofdem: warning: -restart latest: skipped %s\n", skipped.c_str());
    why = ok ? *path : skipped.empty() ? "none there" : "skipped " + skipped;
  }
  PetscCall(Agree(comm_, &ok, &why));
  if (!ok) VofdemInputError(comm_, "option -restart: no valid checkpoint in '%s' (%s)", dir_.c_str(), why.c_str());
  *path = why;
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::Restore(Simulation &sim) {
  PetscMPIInt rank, size;
  std::string path = restart_, options, why, changed;
  PetscViewer viewer;

  PetscFunctionBeginUser;
  if (restart_.empty()) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  if (restart_ == "latest") PetscCall(FindLatest(&path));
  PetscCall(RunDefiningOptions(&options));
  bool             ok = true;
  CheckpointHeader h;
  if (rank == 0) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) ok = false, why = "no such file";
    else ok = ReadCheckpointHeader(path, &h, &why);
    if (ok && h.physics != sim.PhysicsDescription()) ok = false, why = "it is of physics " + h.physics + ", this run " + sim.PhysicsDescription();
    if (ok && !FirstDifference(h.options, options).empty()) ok = false, why = "another scene: " + FirstDifference(h.options, options);
    if (ok) why = std::to_string(h.ranks);
    if (ok) changed = ChangedAtRestart(h.options, options);
  }
  PetscCall(Agree(comm_, &ok, &why));
  if (!ok) VofdemInputError(comm_, "option -restart: '%s': %s", path.c_str(), why.c_str());
  const int savedRanks = std::stoi(why);
  PetscCall(PetscViewerHDF5Open(comm_, path.c_str(), FILE_MODE_READ, &viewer));
  PetscCall(sim.LoadState(viewer));
  PetscCall(PetscViewerDestroy(&viewer));
  lastStep_ = sim.StepNumber();
  PetscCall(PetscPrintf(comm_, "vofdem: restarted from %s at step %" PetscInt_FMT ", t = %.17g s (written on %d rank%s)\n", path.c_str(), sim.StepNumber(),
                        (double)sim.Time(), savedRanks, savedRanks > 1 ? "s" : ""));
  if (!changed.empty()) PetscCall(PetscPrintf(comm_, "vofdem: the restart changes %s (from t = %.17g s on)\n", changed.c_str(), (double)sim.Time()));
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::AfterStep(Simulation &sim, bool last, bool *stop) {
  PetscMPIInt    rank;
  PetscLogDouble now;

  PetscFunctionBeginUser;
  *stop = false;
  if (!enabled_) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  PetscCall(PetscTime(&now));
  // Only rank 0's clock decides about wall time, and any rank's signal stops all: one reduction.
  int flags[2] = {(int)g_signal, rank == 0 && minutes_ > 0 && now - lastWrite_ >= 60 * minutes_}, all[2];
  PetscCallMPI(MPI_Allreduce(flags, all, 2, MPI_INT, MPI_MAX, comm_));
  const PetscInt step = sim.StepNumber();
  const bool     due  = (every_ > 0 && step % every_ == 0) || all[1] || all[0] || (last && final_);
  if (due && step != lastStep_) PetscCall(Write(sim));
  if (all[0]) {
    *stop = true;
    PetscCall(PetscPrintf(comm_, "vofdem: stopped by signal %d at step %" PetscInt_FMT ", t = %g s; continue with -restart latest\n", all[0], step,
                          (double)sim.Time()));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::Write(Simulation &sim) {
  PetscMPIInt rank, size;
  PetscViewer viewer;
  const PetscInt format = kCheckpointFormat;
  std::string options, why;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  const PetscInt    step = sim.StepNumber();
  const std::string tmp = dir_ + "/" + Name(step, true), final = dir_ + "/" + Name(step, false);
  PetscInt64        bytes;
  PetscCall(sim.StateBytes(&bytes));
  bytes = std::max(bytes, lastBytes_) + std::max(bytes, lastBytes_) / 10;  // HDF5's own structures, growth since the last one
  bool ok = true;
  if (rank == 0) {  // the folder may have gone or filled up since the start
    std::error_code ec;
    fs::create_directories(dir_, ec);
    ok = ec ? (why = "cannot create the folder: " + ec.message(), false) : spaceCheck_ ? ReserveSpace(tmp, bytes, &why) : true;
  }
  PetscCall(Agree(comm_, &ok, &why));
  const std::string kept = lastStep_ < 0 ? "no checkpoint written yet" : Name(lastStep_, false) + " is kept";
  if (!ok) VofdemRunError(comm_, "checkpoint: cannot write '%s' (-checkpoint_dir): %s; %s", tmp.c_str(), why.c_str(), kept.c_str());
  PetscCall(RunDefiningOptions(&options));
  const std::string physics = sim.PhysicsDescription();
  const PetscInt    ranks   = size;
  g_writing = tmp, g_kept = kept;
  PetscCall(PetscLogEventBegin(evWrite_, 0, 0, 0, 0));
  {
    QuietHdf5 quiet;
    PetscCall(PetscPushErrorHandler(WriteErrorHandler, nullptr));
    PetscCall(PetscViewerHDF5Open(comm_, tmp.c_str(), FILE_MODE_WRITE, &viewer));
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "vofdem_checkpoint_format", PETSC_INT, &format));
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "run_options", PETSC_STRING, options.c_str()));
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "physics", PETSC_STRING, physics.c_str()));
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "ranks", PETSC_INT, &ranks));
    PetscCall(sim.SaveState(viewer));
    PetscCall(PetscViewerDestroy(&viewer));  // every rank has closed the file after this
    PetscCall(PetscPopErrorHandler());
  }
  PetscCallMPI(MPI_Barrier(comm_));
  PetscCall(PetscLogEventEnd(evWrite_, 0, 0, 0, 0));
  PetscCall(PetscLogEventBegin(evSeal_, 0, 0, 0, 0));
  if (rank == 0) {
    ok = SealCheckpoint(tmp, &why);
    std::error_code ec;
    if (ok) lastBytes_ = (PetscInt64)fs::file_size(tmp, ec);
    if (ok) fs::rename(tmp, final, ec);
    if (ok && ec) ok = false, why = "cannot rename it: " + ec.message();
    if (!ok) std::remove(tmp.c_str());
  }
  PetscCall(Agree(comm_, &ok, &why));
  PetscCall(PetscLogEventEnd(evSeal_, 0, 0, 0, 0));
  if (!ok) VofdemRunError(comm_, "checkpoint: '%s': %s; %s", tmp.c_str(), why.c_str(), kept.c_str());
  lastStep_ = step;
  PetscCall(PetscTime(&lastWrite_));
  PetscCall(RemoveOld());
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::RemoveOld() {
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  if (rank == 0) {
    const std::vector<fs::path> all = Checkpoints(dir_);
    std::error_code             ec;
    for (size_t k = (size_t)keep_; k < all.size(); ++k) fs::remove(all[k], ec);
    // Temporary files left by a run that was killed while writing (none is being written now).
    for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string n = it->path().filename().string();
      if (n.size() > 16 && !n.compare(0, 12, ".checkpoint_") && !n.compare(n.size() - 7, 7, ".h5.tmp") && it->is_regular_file(ec)) fs::remove(it->path(), ec);
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::Destroy() {
  PetscFunctionBeginUser;
  if (handlers_) {
    for (int k = 0; k < 4; ++k) sigaction(kStopSignals[k], &g_oldHandlers[k], nullptr);
    handlers_ = false;
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
