// What every example does with -help: list the options of every module, as `vofdem -help` does, and stop
// before it runs or writes anything (its own options are in the help text PETSc prints first).
//   PetscBool help;
//   PetscCall(vofdem::example::Help(&help));
//   if (help) PetscFunctionReturn(0);
#pragma once

#include "vofdem/sim/Simulation.hpp"

namespace vofdem::example {

inline PetscErrorCode Help(PetscBool *help) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, help));
  if (*help) {
    Simulation sim;
    PetscCall(sim.Create(PETSC_COMM_WORLD));
    PetscCall(sim.SetFromOptions());
    PetscCall(sim.Destroy());
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem::example
