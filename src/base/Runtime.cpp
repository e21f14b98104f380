#include "vofdem/base/Runtime.hpp"

#include "vofdem/base/Options.hpp"

#include "vofdem/base/MpiStartupDefaults.hpp"
#include "vofdem/base/SceneFile.hpp"

#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace vofdem {

namespace {

bool g_mpiInitialisedHere = false;

int WorldRankOf() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

// A bad value of one of PETSc's own solver options (-flow_viscous_ksp_type foo: "Unable to find
// requested KSP type foo"; -..._pc_pfmg_relax_type foo: "Unknown option foo for -..."). Options are
// the same on every rank, so every rank raises it, often on PETSC_COMM_SELF.
bool PetscOptionValueError(PetscErrorCode n, const char *mess) {
  if (!mess) return false;
  return n == PETSC_ERR_ARG_UNKNOWN_TYPE || (n == PETSC_ERR_USER && !std::strncmp(mess, "Unknown option ", 15));
}

// Prints PETSC_ERR_USER_INPUT (bad input), PETSC_ERR_NOT_CONVERGED (a solver that did not
// converge) and bad values of PETSc's options as one line; everything else goes to PETSc's
// trace-back handler.
PetscErrorCode InputErrorHandler(MPI_Comm comm, int line, const char *func, const char *file,
                                 PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx) {
  static PetscErrorCode optionError = 0;  // raised: its passage up the stack is silent too
  if (optionError && n == optionError && p != PETSC_ERROR_INITIAL) return n;
  if (PetscOptionValueError(n, mess)) {
    if (p != PETSC_ERROR_INITIAL) return n;
    optionError = n;
    if (WorldRankOf() == 0) {
      std::fprintf(stderr, "vofdem: error: %s (a PETSc solver option; -help lists the choices)\n", mess);
      std::fflush(stderr);
    }
    return n;
  }
  if (n != PETSC_ERR_USER_INPUT && n != PETSC_ERR_NOT_CONVERGED) return PetscTraceBackErrorHandler(comm, line, func, file, n, p, mess, ctx);
  if (p != PETSC_ERROR_INITIAL) return n;  // the same error passing up the call stack
  int rank = 0, size = 1, worldSize = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  MPI_Comm_size(MPI_COMM_WORLD, &worldSize);
  if (rank == 0) {
    std::fprintf(stderr, "vofdem: error: %s\n", mess ? mess : "bad input");
    std::fflush(stderr);
  }
  // Raised on part of the job only: the other ranks would wait forever in the next collective.
  if (size < worldSize) MPI_Abort(MPI_COMM_WORLD, 1);
  return n;
}

int WorldRank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

// Every scene file on the command line, with its format.
std::vector<std::pair<std::string, SceneFormat>> SceneFiles(int argc, char **argv) {
  std::vector<std::pair<std::string, SceneFormat>> files;
  for (int i = 1; i < argc; ++i) {
    const bool yaml = !std::strcmp(argv[i], "-options_file_yaml");
    const bool plain = !std::strcmp(argv[i], "-options_file");
    if (!yaml && !plain) continue;
    if (i + 1 >= argc || argv[i + 1][0] == '\0') {
      files.emplace_back("", yaml ? SceneFormat::Yaml : SceneFormat::Plain);
    } else {
      files.emplace_back(argv[i + 1], yaml ? SceneFormat::Yaml : SceneFormat::Plain);
      ++i;
    }
  }
  return files;
}

}  // namespace

int Initialize(int *argc, char ***argv, const char help[]) {
  int flag = 0;
  MPI_Initialized(&flag);
  if (!flag) {
    ApplyMpiStartupDefaults();
    MPI_Init(argc, argv);
    g_mpiInitialisedHere = true;
  }
  // Every rank checks the file itself (same file system), so every rank takes the same branch.
  for (const auto &[path, format] : SceneFiles(*argc, *argv)) {
    std::string message;
    const bool ok = path.empty() ? (message = std::string(format == SceneFormat::Yaml ? "-options_file_yaml" : "-options_file") +
                                              ": needs a file name", false)
                                 : CheckSceneFile(path, format, &message);
    if (!ok) {
      if (WorldRank() == 0) std::fprintf(stderr, "vofdem: error: %s\n", message.c_str());
      if (g_mpiInitialisedHere) MPI_Finalize();
      return 1;
    }
  }
  if (PetscInitialize(argc, argv, nullptr, help)) {
    if (WorldRank() == 0) std::fprintf(stderr, "vofdem: error: PETSc failed to initialise\n");
    if (g_mpiInitialisedHere) MPI_Finalize();
    return 1;
  }
  if (PetscPushErrorHandler(InputErrorHandler, nullptr)) return 1;
  return 0;
}

int Finalize(PetscErrorCode status) {
  PetscPopErrorHandler();
  PetscErrorCode ierr = PetscFinalize();
  if (g_mpiInitialisedHere) MPI_Finalize();
  return (status || ierr) ? 1 : 0;
}

PetscErrorCode CheckUnusedOptions(MPI_Comm comm) {
  PetscBool allow = PETSC_FALSE;
  PetscInt  n     = 0;
  char    **names = nullptr, **values = nullptr;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-allow_unused_options", &allow, nullptr));
  if (allow) PetscFunctionReturn(0);
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  // Options PETSc itself reads only at the end of the run, so they look unused now.
  static const char *const lateReaders[] = {"log_view", "log_view_memory", "log_view_gpu_time", "options_left",
                                             "malloc_dump", "malloc_view", "memory_view", "objects_dump",
                                             "log_trace", "log_all", "log_summary", "options_view"};
  std::string unused;
  for (PetscInt i = 0; i < n; ++i) {
    bool late = false;
    for (const char *l : lateReaders) late = late || !std::strcmp(names[i], l);
    if (late) continue;
    unused += (unused.empty() ? "-" : ", -") + std::string(names[i]);
    const std::string close = ClosestOptionName("-" + std::string(names[i]));
    if (!close.empty()) unused += " (did you mean " + close + "?)";
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  if (!unused.empty())
    VofdemInputError(comm, "unknown or unused option%s %s (check the spelling and the -physics list; -help lists all options; -allow_unused_options accepts them)",
                     unused.find(',') == std::string::npos ? "" : "s", unused.c_str());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
