#include "vofdem/core/Physics.hpp"

#include "vofdem/core/Runtime.hpp"

#include <algorithm>

namespace vofdem {

const std::vector<std::string> &KnownPhysics() {
  return AvailablePhysics();  // -help and the checks list only what this build has
}

const std::vector<std::string> &AvailablePhysics() {
  static const std::vector<std::string> names = {"dem", "flow", "vof"};
  return names;
}

std::string PhysicsSet::Describe() const {
  std::string s;
  auto add = [&s](bool on, const char *name) {
    if (on) s += (s.empty() ? "" : ",") + std::string(name);
  };
  add(dem, "dem");
  add(flow, "flow");
  add(vof, "vof");
  add(energy, "energy");
  return s.empty() ? "none" : s;
}

PetscErrorCode MakePhysicsSet(MPI_Comm comm, const std::vector<std::string> &names, PhysicsSet *set) {
  const auto &available = AvailablePhysics();

  PetscFunctionBeginUser;
  *set = PhysicsSet{};
  if (names.empty()) VofdemInputError(comm, "option -physics: name at least one module (available: dem, flow, vof)");
  for (const auto &n : names) {
    if (std::find(available.begin(), available.end(), n) == available.end())
      VofdemInputError(comm, "option -physics: '%s' is not available in this build of vofdem yet (available: dem, flow, vof)", n.c_str());
    set->dem    = set->dem || n == "dem";
    set->flow   = set->flow || n == "flow";
    set->vof    = set->vof || n == "vof";
    set->energy = set->energy || n == "energy";
  }
  // Particles and fluid in one scene are coupled (src/coupling, -coupling_*).
  if (set->vof && !set->flow) VofdemInputError(comm, "option -physics: 'vof' needs 'flow' (the interface moves with the fluid)");
  PetscFunctionReturn(0);
}

}  // namespace vofdem
