// The Darcy seepage (Darcy.hpp) as a module (base/Module.hpp): -physics darcy (a fixed eps, -darcy_fluid_fraction)
// or -physics dem,darcy (eps from the particles; the seepage coupling, src/coupling/Seepage*.cpp, gives it and
// hands the seepage force back). Stage "fluid": the steady head solve of this step (every -darcy_solve_every
// steps), after the particles' eps is projected and before they read its gradient. It sets no time step.
#pragma once

#include "vofdem/base/Module.hpp"
#include "vofdem/darcy/Darcy.hpp"

namespace vofdem {

class DarcyModule final : public Module {
public:
  Darcy       &Get() { return darcy_; }
  const Darcy &Get() const { return darcy_; }

  const char    *Name() const override { return "darcy"; }
  const char    *LogStage() const override { return "Darcy"; }
  PetscErrorCode SetFromOptions(const RunContext &run) override { return darcy_.SetFromOptions(*run.grid, run.gravity); }
  PetscErrorCode Configure(ModuleSet &modules, const RunContext &run) override;
  PetscErrorCode SetUp(ModuleSet &modules, const RunContext &run) override;

  std::vector<Stage> Stages() const override { return {Stage::Fluid}; }
  PetscErrorCode     Run(Stage stage, StepState &step) override;

  std::string    MonitorColumns() const override;
  PetscErrorCode Monitor(MonitorPart *part) override;

  PetscErrorCode View(PetscViewer viewer, PetscReal) const override { return darcy_.View(viewer); }
  PetscErrorCode Save(PetscViewer viewer) override;  // group "darcy"
  PetscErrorCode Load(PetscViewer viewer) override;
  PetscErrorCode SavedBytes(PetscInt64 *bytes) const override;
  PetscErrorCode Destroy() override { return darcy_.Destroy(); }

private:
  Darcy darcy_;
};

}  // namespace vofdem
