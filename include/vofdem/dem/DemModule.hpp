// The particles (Dem.hpp) as a module of the simulation (base/Module.hpp): -physics dem, stage
// "particles". Alone, the DEM sets the time step; with a fluid, a coupling sub-steps it inside the
// fluid's step (SetSubstepped, StepState::substeps).
#pragma once

#include "vofdem/base/Module.hpp"
#include "vofdem/dem/Dem.hpp"

namespace vofdem {

class DemModule final : public Module {
public:
  Dem       &Get() { return dem_; }
  const Dem &Get() const { return dem_; }
  void       SetSubstepped(bool on) { substepped_ = on; }  // a coupling steps it inside the fluid's step

  const char    *Name() const override { return "dem"; }
  const char    *LogStage() const override { return "DEM"; }
  PetscErrorCode SetFromOptions(const RunContext &run) override { return dem_.SetFromOptions(run.comm); }
  PetscErrorCode Configure(ModuleSet &, const RunContext &) override { return 0; }
  bool           NeedsVertexGrid() const override { return true; }
  bool           CheapSetUp() const override { return false; }  // the fill: after the unused-option check
  PetscErrorCode SetUp(ModuleSet &, const RunContext &run) override { return dem_.SetUp(*run.grid, run.gravity, run.seed); }
  PetscErrorCode SetOutputDir(const std::string &dir) override { return dem_.SetOutputDir(dir); }

  std::vector<Stage> Stages() const override { return {Stage::Particles}; }
  PetscErrorCode     Run(Stage stage, StepState &step) override;

  PetscErrorCode LowerTimeStep(TimeStepLimit *limit) override;
  bool           LimitMoved(PetscReal dt) const override { return !substepped_ && dem_.StableTimeStep() != dt; }
  bool           HasRestEnergy() const override { return true; }

  std::string    MonitorColumnsLead() const override;
  std::string    MonitorColumns() const override { return dem_.WallLoadColumns() + dem_.BondColumns() + dem_.MonitorHeader(); }
  PetscErrorCode Monitor(MonitorPart *part) override;

  PetscErrorCode View(PetscViewer viewer, PetscReal) const override { return dem_.View(viewer); }
  PetscErrorCode ViewTimeStep(PetscViewer viewer) const override;
  PetscErrorCode Save(PetscViewer viewer) override { return dem_.Save(viewer); }  // its own group "dem"
  PetscErrorCode Load(PetscViewer viewer) override { return dem_.Load(viewer); }
  PetscErrorCode SavedBytes(PetscInt64 *bytes) const override { return dem_.SavedBytes(bytes); }
  PetscErrorCode WriteOutput(PetscInt, PetscReal time) override { return dem_.WriteOutput(time); }
  PetscErrorCode Finish() override;  // -dem_save_particles, -dem_save_contact_history
  PetscErrorCode Destroy() override { return dem_.Destroy(); }

private:
  Dem  dem_;
  bool substepped_ = false;
};

}  // namespace vofdem
