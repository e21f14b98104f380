// EnergyModule.hpp: the energy equation in the simulation's stages, monitor, banner and checkpoints.
#include "vofdem/energy/EnergyModule.hpp"

#include "vofdem/base/ModuleRegistry.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/base/ViewerGroup.hpp"
#include "vofdem/flow/FlowModule.hpp"
#include "vofdem/vof/VofModule.hpp"

#include <cmath>
#include <cstdio>

namespace vofdem {

PetscErrorCode EnergyModule::SetFromOptions(const RunContext &run) { return energy_.SetFromOptions(*run.grid); }

PetscErrorCode EnergyModule::Configure(ModuleSet &modules, const RunContext &run) {
  PetscFunctionBeginUser;
  // Particles exchange heat through the coupling (F9, coupling/ParticleHeat.hpp), which needs the flow.
  if (modules.Has("dem") && !modules.Has("particle_heat"))
    VofdemInputError(run.comm, "option -physics: 'energy' with 'dem' exchanges heat through the fluid's coupling; use -physics dem,flow,vof,energy");
  if (modules.Has("flow") && energy_.SubstrateMoving())
    VofdemInputError(run.comm, "option -energy_substrate_velocity: with a flow the melt moves with its own velocity; move the beam (-laser_path) instead");
  if (modules.Has("flow") && !modules.Has("vof"))
    VofdemInputError(run.comm, "option -physics: 'energy' with 'flow' needs 'vof' (the metal is the interface's heavy phase)");
  if (VofModule *vof = modules.Get<VofModule>("vof")) {  // the energy moves with the interface's sweeps (F7 a)
    FlowModule *flow = modules.Get<FlowModule>("flow");
    Vof        &v    = vof->Get();
    // One density per phase: the momentum moves with the interface's, the energy with the materials'.
    const PetscReal rm = energy_.Metal().density, rg = energy_.Gas().density;
    if (std::fabs(rm - v.Density()) > 1e-12 * rm)
      VofdemInputError(run.comm, "option -energy_metal_density: %g kg/m^3 (%s) differs from the interface's -vof_density %g kg/m^3; give them one value", (double)rm,
                       energy_.Metal().path.c_str(), (double)v.Density());
    if (std::fabs(rg - flow->Get().ReferenceDensity()) > 1e-12 * rg)
      VofdemInputError(run.comm, "option -energy_gas_density: %g kg/m^3 (%s) differs from the flow's -flow_density %g kg/m^3; give them one value", (double)rg,
                       energy_.Gas().path.c_str(), (double)flow->Get().ReferenceDensity());
    energy_.AttachInterface(flow->Get().Staggered(), [&v]() { return v.Fraction(); });
    // The energy's sweeps run inside the interface's; -log_view counts them in the energy's stage.
    v.AddSweepObserver([this, &v](int d, PetscReal dt, Vec u, Vec phaseFlux) -> PetscErrorCode {
      PetscFunctionBeginUser;
      if (logStage_ < 0) PetscCall(PetscLogStageGetId(LogStage(), &logStage_));
      if (logStage_ >= 0) PetscCall(PetscLogStagePush(logStage_));
      PetscCall(energy_.TransportSweep(d, dt, u, phaseFlux, v.FullAtStart()));
      if (logStage_ >= 0) PetscCall(PetscLogStagePop());
      PetscFunctionReturn(0);
    });
    v.AddRedistributionObserver([this](const std::vector<CellMove> &moves) -> PetscErrorCode {
      PetscFunctionBeginUser;
      if (logStage_ >= 0) PetscCall(PetscLogStagePush(logStage_));
      PetscCall(energy_.FollowRedistribution(moves));
      if (logStage_ >= 0) PetscCall(PetscLogStagePop());
      PetscFunctionReturn(0);
    });
    // The surface forces take the computed temperature: sigma(T) and Marangoni (docs/physics.md F2).
    v.SetTemperature([this]() { return energy_.Temperature(); }, [this]() { return liquid_; });
    flow_ = flow, vof_ = vof;
  }
  if (!modules.Has("flow") && !run.fixedDt && !(energy_.StepLimit() > 0) && !run.help)
    VofdemInputError(run.comm, "option -dt: the energy equation is implicit and sets no step of its own without a moving laser: give -dt");
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyModule::SetUp(ModuleSet &, const RunContext &) {
  PetscFunctionBeginUser;
  PetscCall(energy_.SetUp());
  if (flow_) {  // the Darcy term, taken implicitly by the flow (docs/physics.md F2)
    Flow &flow = static_cast<FlowModule *>(flow_)->Get();
    for (int d = 0; d < 3; ++d) PetscCall(DMCreateGlobalVector(flow.Staggered().Face(d), &damping_[d]));
    PetscCall(DMCreateGlobalVector(flow.Staggered().Cells(), &liquid_));
    PetscCall(VecSet(liquid_, 1));
    flow.SetFaceDamping(damping_);
    PetscCall(UpdateMushyDrag());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyModule::UpdateMushyDrag() {
  PetscFunctionBeginUser;
  if (flow_) PetscCall(energy_.MushyDrag(damping_, liquid_));
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyModule::Run(Stage stage, StepState &step) {
  PetscFunctionBeginUser;
  if (stage == Stage::Transport) {
    PetscCall(energy_.Step(step.time, step.dt));
    PetscCall(energy_.CheckBoiling(step.time + step.dt));
    PetscCall(UpdateMushyDrag());  // for the next step's surface forces and predictor
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyModule::Destroy() {
  PetscFunctionBeginUser;
  for (Vec *v : {&damping_[0], &damping_[1], &damping_[2], &liquid_}) PetscCall(VecDestroy(v));
  PetscCall(energy_.Destroy());
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyModule::LowerTimeStep(TimeStepLimit *limit) {
  PetscFunctionBeginUser;
  if (energy_.StepLimit() > 0) limit->Lower(energy_.StepLimit(), "energy (the beam moves at most -laser_step_fraction of its radius per step; a moving substrate half a cell)");
  PetscFunctionReturn(0);
}

std::string EnergyModule::MonitorColumns() const {
  return ",energy_total_J,energy_accounted_J,energy_balance_J,energy_balance_relative,energy_input_W,energy_boundary_W,energy_loss_W,laser_beam_W,laser_absorbed_W,"
         "temperature_max_K,temperature_min_K,melt_volume_m3,pool_length_m,pool_width_m,pool_depth_m,energy_iterations,energy_linear_iterations" +
         std::string(flow_ ? ",held_cells" : "");
}

PetscErrorCode EnergyModule::Monitor(MonitorPart *part) {
  EnergySummary s;
  char          b[800];

  PetscFunctionBeginUser;
  PetscCall(energy_.Summarize(&s));
  std::snprintf(b, sizeof b, "  | energy %.10e J  balance %.2e J (%.1e)  T max %.2f K  absorbed %.4e W of %.4e W  pool %.3e x %.3e x %.3e m  iterations %d",
                (double)s.total, (double)s.balance, (double)s.balanceRelative, (double)s.peak, (double)s.absorbed, (double)s.beam, (double)s.pool[0], (double)s.pool[1],
                (double)s.pool[2], (int)s.iterations);
  part->screen = b;
  std::snprintf(b, sizeof b, ",%.16e,%.16e,%.6e,%.6e,%.10e,%.10e,%.10e,%.16e,%.16e,%.16e,%.16e,%.10e,%.10e,%.10e,%.10e,%d,%d", (double)s.total, (double)s.accounted,
                (double)s.balance, (double)s.balanceRelative, (double)s.inputRate, (double)s.boundaryRate, (double)s.lossRate, (double)s.beam, (double)s.absorbed,
                (double)s.peak, (double)s.minimum, (double)s.meltVolume, (double)s.pool[0], (double)s.pool[1], (double)s.pool[2], (int)s.iterations,
                (int)s.linearIterations);
  part->csv = b;
  if (flow_) {  // the cells of solid metal held at rest (Energy::MushyDrag)
    part->csv += "," + std::to_string((long long)energy_.HeldCells());
    part->screen += "  held " + std::to_string((long long)energy_.HeldCells());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyModule::Save(PetscViewer viewer) {
  return InViewerGroup(viewer, "energy", [&]() -> PetscErrorCode { return energy_.Save(viewer); });
}

PetscErrorCode EnergyModule::Load(PetscViewer viewer) {
  PetscFunctionBeginUser;
  PetscCall(InViewerGroup(viewer, "energy", [&]() -> PetscErrorCode { return energy_.Load(viewer); }));
  PetscCall(UpdateMushyDrag());  // from the loaded state (the flow's and the interface's are loaded first)
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyModule::SavedBytes(PetscInt64 *bytes) const {
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(VecGetSize(energy_.Temperature(), &n));
  *bytes = 16 * (PetscInt64)n + 4096;
  PetscFunctionReturn(0);
}

void RegisterModule_energy(ModuleRegistry &registry) {
  ModuleEntry e;
  e.name    = "energy";
  e.summary = "temperature with latent heat, a mushy range and a moving laser; implicit (src/energy)";
  e.create  = [] { return std::unique_ptr<Module>(new EnergyModule); };
  registry.Add(std::move(e));
}

}  // namespace vofdem
