// EnergyModule.hpp: the energy equation in the simulation's stages, monitor, banner and checkpoints.
#include "vofdem/energy/EnergyModule.hpp"

#include "vofdem/base/ModuleRegistry.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/base/ViewerGroup.hpp"

#include <cstdio>

namespace vofdem {

PetscErrorCode EnergyModule::SetFromOptions(const RunContext &run) { return energy_.SetFromOptions(*run.grid); }

PetscErrorCode EnergyModule::Configure(ModuleSet &modules, const RunContext &run) {
  PetscFunctionBeginUser;
  // The flow would carry heat through the interface's sweeps (F7 a) and particles would take their volume
  // and exchange heat (F9): neither is built, and energy beside them would be silently wrong.
  for (const char *other : {"flow", "dem"})
    if (modules.Has(other))
      VofdemInputError(run.comm, "option -physics: 'energy' with '%s' is not built yet (heat carried by the flow and exchanged with particles); -physics energy alone is conduction in still metal", other);
  if (!run.fixedDt && !(energy_.StepLimit() > 0) && !run.help)
    VofdemInputError(run.comm, "option -dt: the energy equation is implicit and sets no step of its own without a moving laser: give -dt");
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyModule::Run(Stage stage, StepState &step) {
  PetscFunctionBeginUser;
  if (stage == Stage::Transport) {
    PetscCall(energy_.Step(step.time, step.dt));
    PetscCall(energy_.CheckBoiling(step.time + step.dt));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyModule::LowerTimeStep(TimeStepLimit *limit) {
  PetscFunctionBeginUser;
  if (energy_.StepLimit() > 0) limit->Lower(energy_.StepLimit(), "laser (the beam moves at most -laser_step_fraction of its radius per step)");
  PetscFunctionReturn(0);
}

std::string EnergyModule::MonitorColumns() const {
  return ",energy_total_J,energy_accounted_J,energy_balance_J,energy_balance_relative,energy_input_W,energy_boundary_W,energy_loss_W,laser_beam_W,laser_absorbed_W,"
         "temperature_max_K,temperature_min_K,melt_volume_m3,pool_length_m,pool_width_m,pool_depth_m,energy_iterations,energy_linear_iterations";
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
  std::snprintf(b, sizeof b, ",%.16e,%.16e,%.6e,%.6e,%.10e,%.10e,%.10e,%.16e,%.16e,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%d,%d", (double)s.total, (double)s.accounted,
                (double)s.balance, (double)s.balanceRelative, (double)s.inputRate, (double)s.boundaryRate, (double)s.lossRate, (double)s.beam, (double)s.absorbed,
                (double)s.peak, (double)s.minimum, (double)s.meltVolume, (double)s.pool[0], (double)s.pool[1], (double)s.pool[2], (int)s.iterations,
                (int)s.linearIterations);
  part->csv = b;
  PetscFunctionReturn(0);
}

PetscErrorCode EnergyModule::Save(PetscViewer viewer) {
  return InViewerGroup(viewer, "energy", [&]() -> PetscErrorCode { return energy_.Save(viewer); });
}

PetscErrorCode EnergyModule::Load(PetscViewer viewer) {
  return InViewerGroup(viewer, "energy", [&]() -> PetscErrorCode { return energy_.Load(viewer); });
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
