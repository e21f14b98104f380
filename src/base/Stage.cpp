// The stages of a step (Module.hpp) and why each sits where it does (docs/architecture.md, "The coupled
// step"; the order of seed 000's Fig. 1).
#include "vofdem/base/Module.hpp"

namespace vofdem {

const char *StageName(Stage s) {
  static const char *names[kStageCount] = {"prepare", "exchange", "forces", "fluid", "transport", "properties", "average", "particles", "finish"};
  return names[(int)s];
}

const char *StageReason(Stage s) {
  static const char *reasons[kStageCount] = {
    "state the fluid step starts from: mass-consistent sweeps move alpha and rho u together with u^n (F2)",
    "the particles' volume fraction and forces reach the fluid's cells before it steps (F1, F5)",
    "forces of the current interface (surface tension, Marangoni) for the fluid's predictor (F2)",
    "the fluid's predictor and projection with the particles' eps and sources (F1, F2)",
    "what the fluid carries (the interface, a scalar) moves with the projected velocity of the step just taken",
    "density and viscosity of the moved interface, for the particles' read and the next step",
    "the particles read kernel averages of the new fluid: drag, buoyancy, added mass, capillarity (K1, P1)",
    "the particles' sub-steps in the fluid they read (the DEM's own stable step)",
    "the step taken is recorded: the next step's d(eps)/dt takes its share of the particles' displacement (F1)",
  };
  return reasons[(int)s];
}

Module *ModuleSet::Find(const std::string &name) const {
  for (const auto &m : modules_)
    if (name == m->Name()) return m.get();
  return nullptr;
}

}  // namespace vofdem
