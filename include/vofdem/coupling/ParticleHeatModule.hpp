// The particles' heat (ParticleHeat.hpp) as a module of the simulation (base/Module.hpp). Never named in -physics:
// it is on exactly when dem, flow and energy are (energy with flow needs vof: -physics dem,flow,vof,energy). It runs
// in the stage "exchange", after the coupling's projection and before the fluid: the particles' step of P11 and the
// cells' source of F9 for the energy's step; its enthalpy joins the energy module's account.
#pragma once

#include "vofdem/base/Module.hpp"
#include "vofdem/coupling/ParticleHeat.hpp"

namespace vofdem {

class CouplingModule;
class DemModule;
class FlowModule;
class VofModule;
class ModuleRegistry;

class ParticleHeatModule final : public Module {
public:
  ParticleHeat       &Get() { return heat_; }
  const ParticleHeat &Get() const { return heat_; }

  const char    *Name() const override { return "particle_heat"; }
  const char    *LogStage() const override { return "ParticleHeat"; }
  double         BytesPerCell() const override { return 300; }  // the heat's cell vectors (T, the deposit, capacities, held cells)
  PetscErrorCode SetFromOptions(const RunContext &run) override { return heat_.SetFromOptions(run.comm); }
  PetscErrorCode Configure(ModuleSet &modules, const RunContext &run) override;
  bool           CheapSetUp() const override { return false; }  // after the particles and the coupling
  PetscErrorCode SetUp(ModuleSet &modules, const RunContext &run) override;

  PetscErrorCode SetOutputDir(const std::string &dir) override { return dir.empty() ? 0 : heat_.SetOutputDir(dir, restarting_); }

  std::vector<Stage> Stages() const override { return {Stage::Prepare, Stage::Exchange}; }  // melting (P12), then the exchange
  PetscErrorCode     Run(Stage stage, StepState &step) override;

  std::string    MonitorColumns() const override;
  PetscErrorCode Monitor(MonitorPart *part) override;

  PetscErrorCode View(PetscViewer viewer, PetscReal) const override { return heat_.View(viewer); }
  PetscErrorCode Save(PetscViewer viewer) override { return heat_.Save(viewer); }
  PetscErrorCode Load(PetscViewer viewer) override { return heat_.Load(viewer); }
  PetscErrorCode Destroy() override { return heat_.Destroy(); }

private:
  ParticleHeat    heat_;
  CouplingModule *coupling_ = nullptr;
  DemModule      *dem_      = nullptr;
  FlowModule     *flow_     = nullptr;
  VofModule      *vof_      = nullptr;
  bool            restarting_ = false;
};

void RegisterParticleHeatModule(ModuleRegistry &registry);  // from the coupling's RegisterModule_coupling

}  // namespace vofdem
