// A driver's way to a module's object in a simulation (the examples, the program's analysis): nullptr where
// the scene did not switch the module on. The simulation itself names no module (Simulation.hpp).
#pragma once

#include "vofdem/coupling/CouplingModule.hpp"
#include "vofdem/dem/DemModule.hpp"
#include "vofdem/flow/FlowModule.hpp"
#include "vofdem/sim/Simulation.hpp"
#include "vofdem/vof/VofModule.hpp"

namespace vofdem {

inline Dem *Particles(const Simulation &sim) {
  DemModule *m = sim.Modules().Get<DemModule>("dem");
  return m ? &m->Get() : nullptr;
}
inline Flow *Fluid(const Simulation &sim) {
  FlowModule *m = sim.Modules().Get<FlowModule>("flow");
  return m ? &m->Get() : nullptr;
}
inline Vof *Interface(const Simulation &sim) {
  VofModule *m = sim.Modules().Get<VofModule>("vof");
  return m ? &m->Get() : nullptr;
}
inline Coupling *Coupled(const Simulation &sim) {
  CouplingModule *m = sim.Modules().Get<CouplingModule>("coupling");
  return m ? &m->Get() : nullptr;
}

}  // namespace vofdem
