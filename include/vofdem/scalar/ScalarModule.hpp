// The passive scalar (Scalar.hpp) as a module (base/Module.hpp): -physics flow,scalar. Stage "transport":
// after the fluid step, with its projected (divergence-free) velocity, like the interface.
#pragma once

#include "vofdem/base/Module.hpp"
#include "vofdem/flow/FlowModule.hpp"
#include "vofdem/scalar/Scalar.hpp"

namespace vofdem {

class ScalarModule final : public Module {
public:
  Scalar       &Get() { return scalar_; }
  const Scalar &Get() const { return scalar_; }

  const char    *Name() const override { return "scalar"; }
  const char    *LogStage() const override { return "Scalar"; }
  PetscErrorCode SetFromOptions(const RunContext &run) override { return scalar_.SetFromOptions(*run.grid); }
  PetscErrorCode Configure(ModuleSet &modules, const RunContext &run) override;
  PetscErrorCode SetUp(ModuleSet &, const RunContext &) override;

  std::vector<Stage> Stages() const override { return {Stage::Transport}; }
  PetscErrorCode     Run(Stage stage, StepState &step) override;
  PetscErrorCode     LowerTimeStep(TimeStepLimit *limit) override;

  std::string    MonitorColumns() const override { return ",scalar_total,scalar_total_relative_change,scalar_min,scalar_max"; }
  PetscErrorCode Monitor(MonitorPart *part) override;

  PetscErrorCode View(PetscViewer viewer, PetscReal) const override { return scalar_.View(viewer); }
  PetscErrorCode Save(PetscViewer viewer) override;  // group "scalar"
  PetscErrorCode Load(PetscViewer viewer) override;
  PetscErrorCode SavedBytes(PetscInt64 *bytes) const override;
  PetscErrorCode Destroy() override { return scalar_.Destroy(); }

private:
  Scalar      scalar_;
  FlowModule *flow_   = nullptr;
  PetscReal   total0_ = 0;  // sum c dV at the start
};

}  // namespace vofdem
