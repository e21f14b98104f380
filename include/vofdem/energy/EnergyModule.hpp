// The energy equation (Energy.hpp) as a module (base/Module.hpp): -physics energy, conduction with latent
// heat and the laser in metal that does not move (the metal below -energy_metal_top), or -physics
// flow,vof,energy, where the energy moves with the interface's sweeps (an observer of Vof) and the metal is
// the interface's heavy phase. Stage "transport": the implicit diffusion after the sweeps (docs/modules/energy.md).
#pragma once

#include "vofdem/base/Module.hpp"
#include "vofdem/energy/Energy.hpp"

namespace vofdem {

class EnergyModule final : public Module {
public:
  Energy       &Get() { return energy_; }
  const Energy &Get() const { return energy_; }

  const char    *Name() const override { return "energy"; }
  const char    *LogStage() const override { return "Energy"; }
  double         BytesPerCell() const override { return 450; }  // T, E, the enthalpy's matrix and its preconditioner: 0.56 kB per cell more at 80^3
  PetscErrorCode SetFromOptions(const RunContext &run) override;
  PetscErrorCode Configure(ModuleSet &modules, const RunContext &run) override;
  PetscErrorCode SetUp(ModuleSet &, const RunContext &) override;

  std::vector<Stage> Stages() const override { return {Stage::Transport}; }
  PetscErrorCode     Run(Stage stage, StepState &step) override;
  PetscErrorCode     LowerTimeStep(TimeStepLimit *limit) override;

  std::string    MonitorColumns() const override;
  PetscErrorCode Monitor(MonitorPart *part) override;

  PetscErrorCode View(PetscViewer viewer, PetscReal) const override { return energy_.View(viewer); }
  PetscErrorCode Save(PetscViewer viewer) override;  // group "energy"
  PetscErrorCode Load(PetscViewer viewer) override;
  PetscErrorCode SavedBytes(PetscInt64 *bytes) const override;
  PetscErrorCode Destroy() override;
  PetscErrorCode SetOutputDir(const std::string &dir) override { return energy_.SetOutputDir(dir); }
  PetscErrorCode WriteOutput(PetscInt step, PetscReal time) override { return energy_.WriteOutput(step, time); }

private:
  Energy    energy_;
  Module   *flow_ = nullptr, *vof_ = nullptr;  // with a moving interface
  PetscLogStage logStage_ = -1;                 // the sweeps' share of the energy is logged in its own stage
  PetscReal time_ = 0;
  // With a flow: the Darcy rates per face (Flow::SetFaceDamping) and the cells' liquid share (Vof::SetTemperature),
  // from the state after each step (Energy::MushyDrag).
  Vec       damping_[3] = {nullptr, nullptr, nullptr}, liquid_ = nullptr;
  PetscErrorCode UpdateMushyDrag();
};

}  // namespace vofdem
