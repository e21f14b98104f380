// Start-up and shut-down of a vofdem program, and how bad input is reported.
//
// Bad input (a scene file that is missing or malformed, an option with a wrong value, an option
// nobody read) is reported as one line, "vofdem: error: ...", naming the file or option, and every
// rank exits non-zero. Inside PETSc code such an error is raised with VofdemInputError(), which is
// SETERRQ with PETSC_ERR_USER_INPUT; the error handler installed by Initialize() prints that one
// line (once, on rank 0 of the communicator) instead of PETSc's trace, and aborts the job if the
// error was raised on fewer ranks than all, so that no rank is left waiting.
//
// A run that cannot go on for a reason the user can act on, not a bug (a solver that did not
// converge), is reported the same way, one line on every rank and a non-zero exit: VofdemRunError(),
// SETERRQ with PETSC_ERR_NOT_CONVERGED.
#pragma once

#include <petscsys.h>

#define VofdemInputError(comm, ...) SETERRQ(comm, PETSC_ERR_USER_INPUT, __VA_ARGS__)
#define VofdemRunError(comm, ...)   SETERRQ(comm, PETSC_ERR_NOT_CONVERGED, __VA_ARGS__)

namespace vofdem {

// Initialises MPI, checks every scene file named by -options_file / -options_file_yaml (before
// PETSc parses it: PETSc's YAML errors name neither file nor line), then initialises PETSc and
// installs the one-line input-error handler. Returns 0 to go on; otherwise the error was printed,
// everything is finalised, and the value is the exit code for main().
int Initialize(int *argc, char ***argv, const char help[]);

// Finalises PETSc and MPI. `status` is what the program's work returned; the return value is the
// exit code for main(): 0 when status is 0, else 1.
int Finalize(PetscErrorCode status);

// Raises an input error naming every option that nothing has read so far (a typo in a scene), unless
// -allow_unused_options is given. Call once all modules are set up, before time stepping.
PetscErrorCode CheckUnusedOptions(MPI_Comm comm);

}  // namespace vofdem
