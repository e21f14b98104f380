// Which physics a scene switches on (-physics dem,flow,vof,energy). Only the named modules are
// created and only their fields allocated.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace vofdem {

struct PhysicsSet {
  bool dem = false, flow = false, vof = false, energy = false;
  std::string Describe() const;  // "dem,flow"
};

// All names a scene may use, and those this build can run.
const std::vector<std::string> &KnownPhysics();
const std::vector<std::string> &AvailablePhysics();

// Builds the set from names already checked to be known; raises an input error naming -physics
// for a module this build does not have yet or a combination that makes no sense.
PetscErrorCode MakePhysicsSet(MPI_Comm comm, const std::vector<std::string> &names, PhysicsSet *set);

}  // namespace vofdem
