// The particle-fluid coupling (Coupling.hpp) as a module of the simulation (base/Module.hpp). Never named in
// -physics: it is on exactly when dem and flow are. Its stages: "exchange" (the particles' eps and forces to
// the fluid, before it steps), "average" (the particles read the new fluid; how many DEM sub-steps fit the
// fluid's step), "finish" (the step taken, for the next d(eps)/dt). It wires the modules below it: the DEM
// takes the fluid's forces and sub-steps, the interface sees the particles' eps (docs/architecture.md).
#pragma once

#include "vofdem/base/Module.hpp"
#include "vofdem/coupling/Coupling.hpp"

namespace vofdem {

class DemModule;
class FlowModule;
class VofModule;

class CouplingModule final : public Module {
public:
  Coupling       &Get() { return coupling_; }
  const Coupling &Get() const { return coupling_; }

  const char    *Name() const override { return "coupling"; }
  const char    *LogStage() const override { return "Coupling"; }
  double         BytesPerCell() const override { return 900; }  // the kernel's wide-ghost vectors per location and eps's books; with the particle heat 1.5 kB per cell more (the reduced nozzle track, 24k to 648k cells)
  PetscErrorCode SetFromOptions(const RunContext &run) override { return coupling_.SetFromOptions(run.comm); }
  PetscErrorCode Configure(ModuleSet &modules, const RunContext &run) override;
  bool           CheapSetUp() const override { return false; }  // after the particles exist
  PetscErrorCode SetUp(ModuleSet &modules, const RunContext &run) override;

  std::vector<Stage> Stages() const override { return {Stage::Exchange, Stage::Average, Stage::Finish}; }
  PetscErrorCode     Run(Stage stage, StepState &step) override;

  std::string    MonitorColumns() const override;
  PetscErrorCode Monitor(MonitorPart *part) override;

  PetscErrorCode View(PetscViewer viewer, PetscReal dt) const override { return coupling_.View(viewer, dt); }
  PetscErrorCode Save(PetscViewer viewer) override { return coupling_.Save(viewer); }
  PetscErrorCode Load(PetscViewer viewer) override { return coupling_.Load(viewer); }
  PetscErrorCode Destroy() override { return coupling_.Destroy(); }

private:
  Coupling    coupling_;
  DemModule  *dem_  = nullptr;
  FlowModule *flow_ = nullptr;
  VofModule  *vof_  = nullptr;  // null without a free surface
};

}  // namespace vofdem
