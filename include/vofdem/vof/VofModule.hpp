// The interface (Vof.hpp) as a module of the simulation (base/Module.hpp): -physics vof, on the flow's
// cells. Its stages: "forces" (surface tension for the flow's predictor), then "transport" and "properties"
// (the interface moves with the projected velocity, then sets rho and mu); with mass-consistent momentum
// (-vof_momentum consistent, no particles) "prepare" instead moves alpha and rho u together before the
// flow steps (docs/physics.md, F2). Particles (a coupling, SetWithParticles) displace both phases: the
// monitor follows the other phase's volume too.
#pragma once

#include "vofdem/base/Module.hpp"
#include "vofdem/flow/FlowModule.hpp"
#include "vofdem/vof/Vof.hpp"

namespace vofdem {

class VofModule final : public Module {
public:
  Vof       &Get() { return vof_; }
  const Vof &Get() const { return vof_; }
  // Particles in the fluid (a coupling, before the stages are read): the interface moves after the flow step
  // with the flow's own momentum transport (the mass-consistent sweeps do not carry eps yet).
  void           SetWithParticles(bool on);
  PetscErrorCode RecordInitialVolumes();  // the phases' volumes the monitor compares with (after the particles' eps)

  const char    *Name() const override { return "vof"; }
  const char    *LogStage() const override { return "VOF"; }
  double         BytesPerCell() const override { return 150; }  // alpha, its ghosts and the interface's scratch: 0.2 kB per cell more at 80^3
  PetscErrorCode SetFromOptions(const RunContext &run) override { return vof_.SetFromOptions(*run.grid); }
  PetscErrorCode Configure(ModuleSet &modules, const RunContext &run) override;
  PetscErrorCode SetUp(ModuleSet &modules, const RunContext &run) override;

  std::vector<Stage> Stages() const override;
  PetscErrorCode     Run(Stage stage, StepState &step) override;

  PetscErrorCode LowerTimeStep(TimeStepLimit *limit) override;

  std::string    MonitorColumns() const override;
  PetscErrorCode Monitor(MonitorPart *part) override;

  PetscErrorCode View(PetscViewer viewer, PetscReal) const override { return vof_.View(viewer); }
  PetscErrorCode ViewTimeStep(PetscViewer viewer) const override;
  PetscErrorCode Save(PetscViewer viewer) override;  // group "vof"
  PetscErrorCode Load(PetscViewer viewer) override;
  PetscErrorCode Destroy() override { return vof_.Destroy(); }

private:
  bool Consistent() const { return !withParticles_ && vof_.ConsistentMomentum(); }

  Vof         vof_;
  FlowModule *flow_          = nullptr;
  bool        withParticles_ = false;
  PetscReal   volume0_ = 0, otherVolume0_ = 0;  // phase 1 and (with particles) phase 0 at the start, m^3
};

}  // namespace vofdem
