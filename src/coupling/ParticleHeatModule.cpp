// ParticleHeatModule.hpp: the particles' heat in the simulation's stages, its checks, monitor and checkpoints.
#include "vofdem/coupling/ParticleHeatModule.hpp"

#include "vofdem/base/ModuleRegistry.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/coupling/CouplingModule.hpp"
#include "vofdem/dem/DemModule.hpp"
#include "vofdem/energy/EnergyModule.hpp"
#include "vofdem/flow/FlowModule.hpp"
#include "vofdem/vof/VofModule.hpp"

#include <cmath>
#include <cstdio>

namespace vofdem {

PetscErrorCode ParticleHeatModule::Configure(ModuleSet &modules, const RunContext &run) {
  PetscFunctionBeginUser;
  dem_      = modules.Get<DemModule>("dem");
  flow_     = modules.Get<FlowModule>("flow");
  coupling_ = modules.Get<CouplingModule>("coupling");
  vof_      = modules.Get<VofModule>("vof");
  PetscCheck(dem_ && flow_ && coupling_, run.comm, PETSC_ERR_PLIB, "particle heat: needs the dem, flow and coupling modules below it");
  // The energy moves with the interface's sweeps (and steps with backward Euler there): the energy module refuses flow without vof.
  dem_->Get().UseHeatFields();  // the swarm's enthalpy and temperature, before the particles are made
  PetscCall(heat_.SetTypeOptions(dem_->Get().TypeNames()));  // -coupling_heat_type_<name>_*
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleHeatModule::SetUp(ModuleSet &modules, const RunContext &run) {
  PetscFunctionBeginUser;
  restarting_ = run.restarting;
  EnergyModule *energy = modules.Get<EnergyModule>("energy");  // after this module in the registry: found at set-up
  PetscCheck(energy, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "particle heat: no energy module");
  PetscCheck(vof_, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "particle heat: no vof module");
  PetscCall(heat_.SetUp(coupling_->Get(), flow_->Get(), vof_->Get(), dem_->Get(), energy->Get()));
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleHeatModule::Run(Stage stage, StepState &step) {
  PetscFunctionBeginUser;
  if (stage == Stage::Prepare) PetscCall(heat_.Melt(step.time));
  if (stage == Stage::Exchange) PetscCall(heat_.Exchange(step.time, step.dt));
  PetscFunctionReturn(0);
}

std::string ParticleHeatModule::MonitorColumns() const {
  return ",particle_enthalpy_J,particle_heat_to_fluid_W,particle_heat_deposited_W,particle_heat_exchanged_J,particle_temperature_max_K,particle_temperature_min_K,particle_nusselt_max,particle_beam_absorbed_W,particle_beam_intercepted_W,particle_conduction_W,particle_conducting_pairs,particles_melted,melted_mass_kg,melt_spin_energy_J,melt_volume_error,melt_energy_error,melt_momentum_error";
}

PetscErrorCode ParticleHeatModule::Monitor(MonitorPart *part) {
  ParticleHeatSummary s;
  char                b[640];

  PetscFunctionBeginUser;
  PetscCall(heat_.Summarize(&s));
  const PetscReal miss = s.toFluid != 0 ? std::fabs(s.deposited / s.toFluid - 1) : std::fabs(s.deposited);
  std::snprintf(b, sizeof b, "  | particle heat %.8e J  to fluid %.4e W (deposit error %.1e)  T_p %.2f-%.2f K", (double)s.enthalpy, (double)s.toFluid, (double)miss, (double)s.Tmin,
                (double)s.Tmax);
  part->screen = b;
  if (heat_.MeltBooks().melted > 0) {
    std::snprintf(b, sizeof b, "  melted %lld (%.3e kg)", (long long)heat_.MeltBooks().melted, (double)heat_.MeltBooks().mass);
    part->screen += b;
  }
  if (s.beamIntercepted > 0) {
    std::snprintf(b, sizeof b, "  beam on particles %.4e W (absorbed %.4e W)", (double)s.beamIntercepted, (double)s.beamAbsorbed);
    part->screen += b;
  }
  const MeltSummary &m = heat_.MeltBooks();
  std::snprintf(b, sizeof b, ",%.16e,%.16e,%.16e,%.16e,%.12e,%.12e,%.8e,%.16e,%.16e,%.16e,%lld,%lld,%.16e,%.6e,%.3e,%.3e,%.3e", (double)s.enthalpy, (double)s.toFluid, (double)s.deposited,
                (double)s.exchanged, (double)s.Tmax, (double)s.Tmin, (double)s.nusseltMax, (double)s.beamAbsorbed, (double)s.beamIntercepted, (double)s.conducted, (long long)s.contacts, (long long)m.melted, (double)m.mass,
                (double)m.spin, (double)m.volumeError, (double)m.energyError, (double)m.momentumError);
  part->csv = b;
  PetscFunctionReturn(0);
}

void RegisterParticleHeatModule(ModuleRegistry &registry) {
  ModuleEntry e;
  e.name      = "particle_heat";
  e.summary   = "the particles' enthalpy and its exchange with the fluid's energy by the kernel (src/coupling; on with dem, flow and energy)";
  e.impliedBy = {"dem", "flow", "energy"};
  e.create    = [] { return std::unique_ptr<Module>(new ParticleHeatModule); };
  registry.Add(std::move(e));
}

}  // namespace vofdem
