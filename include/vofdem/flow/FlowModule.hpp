// The fluid (Flow.hpp) as a module of the simulation (base/Module.hpp): -physics flow, stage "fluid". Its
// adaptive step follows the flow every step. Where a free surface's mass-consistent sweeps move the
// momentum (VofModule), its own advection is off and its limit is per direction (Flow::StableTimeStep).
#pragma once

#include "vofdem/base/Module.hpp"
#include "vofdem/flow/Flow.hpp"

namespace vofdem {

class FlowModule final : public Module {
public:
  Flow       &Get() { return flow_; }
  const Flow &Get() const { return flow_; }
  void        SetMomentumMovedElsewhere(bool on) { momentumElsewhere_ = on; }  // the interface's sweeps move rho u

  const char    *Name() const override { return "flow"; }
  const char    *LogStage() const override { return "Flow"; }
  double         BytesPerCell() const override { return 1500; }  // the flow's fields, its pressure and viscous matrices and hypre's hierarchy: 1.73 kB per cell measured at 80^3 (-physics flow)
  PetscErrorCode SetFromOptions(const RunContext &run) override;
  PetscErrorCode Configure(ModuleSet &, const RunContext &) override { return 0; }
  PetscErrorCode SetUp(ModuleSet &, const RunContext &run) override { return flow_.SetUp(run.gravity); }
  PetscErrorCode SetOutputDir(const std::string &dir) override { return flow_.SetOutputDir(dir); }

  std::vector<Stage> Stages() const override { return {Stage::Fluid}; }
  PetscErrorCode     Run(Stage stage, StepState &step) override;

  PetscErrorCode LowerTimeStep(TimeStepLimit *limit) override;
  bool           AdaptsEveryStep() const override { return true; }

  std::string    MonitorColumns() const override;
  PetscErrorCode Monitor(MonitorPart *part) override;

  PetscErrorCode View(PetscViewer viewer, PetscReal) const override { return flow_.View(viewer); }
  PetscErrorCode ViewTimeStep(PetscViewer viewer) const override;
  PetscErrorCode Save(PetscViewer viewer) override;  // group "flow"
  PetscErrorCode Load(PetscViewer viewer) override;
  PetscErrorCode SavedBytes(PetscInt64 *bytes) const override { return flow_.SavedBytes(bytes); }
  PetscErrorCode WriteOutput(PetscInt step, PetscReal time) override { return flow_.WriteOutput(step, time); }
  PetscErrorCode Finish() override;  // -flow_profile
  PetscErrorCode Destroy() override { return flow_.Destroy(); }

private:
  // The banner's limit is a query of the flow's own state (Flow::StableTimeStep sets no coefficient).
  mutable Flow flow_;
  bool         momentumElsewhere_ = false;
  bool         fixedDt_           = false;
};

}  // namespace vofdem
