// The seepage coupling (Seepage.hpp) as a module (base/Module.hpp): never named in -physics, on exactly when dem
// and darcy are. Stages "exchange" (the particles' eps into the head equation, before the darcy module solves in
// "fluid") and "average" (the new head's seepage force onto the particles, before they move).
#pragma once

#include "vofdem/base/Module.hpp"
#include "vofdem/coupling/Seepage.hpp"

namespace vofdem {

class DemModule;
class DarcyModule;
class ModuleRegistry;

class SeepageModule final : public Module {
public:
  Seepage &Get() { return seepage_; }

  const char    *Name() const override { return "seepage"; }
  const char    *LogStage() const override { return "Seepage"; }
  PetscErrorCode SetFromOptions(const RunContext &run) override { return seepage_.SetFromOptions(run.comm); }
  PetscErrorCode Configure(ModuleSet &modules, const RunContext &run) override;
  bool           CheapSetUp() const override { return false; }  // after the particles exist
  PetscErrorCode SetUp(ModuleSet &modules, const RunContext &run) override;

  std::vector<Stage> Stages() const override { return {Stage::Exchange, Stage::Average}; }
  PetscErrorCode     Run(Stage stage, StepState &step) override;

  std::string    MonitorColumns() const override;
  PetscErrorCode Monitor(MonitorPart *part) override;

  PetscErrorCode View(PetscViewer viewer, PetscReal) const override { return seepage_.View(viewer); }
  PetscErrorCode Save(PetscViewer) override { return 0; }  // nothing of its own: eps and the force follow from the particles
  PetscErrorCode Load(PetscViewer) override { return 0; }
  PetscErrorCode Destroy() override { return seepage_.Destroy(); }

private:
  Seepage      seepage_;
  DemModule   *dem_   = nullptr;
  DarcyModule *darcy_ = nullptr;
};

// Its registry entry (implied by dem and darcy), added by RegisterModule_coupling after the coupling's own.
void RegisterSeepageModule(ModuleRegistry &registry);

}  // namespace vofdem
