// CouplingModule.hpp: the coupling's checks across modules, its set-up, stages and monitor.
#include "vofdem/coupling/CouplingModule.hpp"
#include "vofdem/coupling/ParticleHeatModule.hpp"
#include "vofdem/coupling/SeepageModule.hpp"

#include "vofdem/base/ModuleRegistry.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/dem/DemModule.hpp"
#include "vofdem/flow/FlowModule.hpp"
#include "vofdem/vof/VofModule.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace vofdem {

PetscErrorCode CouplingModule::Configure(ModuleSet &modules, const RunContext &run) {
  PetscFunctionBeginUser;
  dem_  = modules.Get<DemModule>("dem");
  flow_ = modules.Get<FlowModule>("flow");
  vof_  = modules.Get<VofModule>("vof");
  Dem &dem = dem_->Get();
  PetscCall(coupling_.CheckParticleSize(*run.grid, 2 * dem.Radius()));
  // The particles' fluid_* arrays are taken from the start (the DEM's set-up already reads some).
  dem.UseFluidFields();
  // The kernels and deposits live on the flow's decomposition: a DEM repartition would leave particles
  // outside their rank's fluid cells (DemBalance.cpp).
  if (dem.Balancing())
    VofdemInputError(run.comm, "option -dem_balance: coupled scenes keep the fluid's decomposition (the particles' kernels live on its cells); use none (the default) and choose the split with -grid_ranks");
  // F1b: with moving particles, the interface's transport conserves both phases only with d(eps)/dt.
  if (vof_ && !coupling_.EpsRate())
    VofdemInputError(run.comm, "option -coupling_eps_rate: particles with a free surface (dem,flow,vof) need it on: without d(eps)/dt the volumes of both phases drift as particles move");
  if (!vof_ && coupling_.ContactAngleSet())
    VofdemInputError(run.comm, "option -coupling_contact_angle: the capillary force acts at a free surface; it needs -physics dem,flow,vof");
  // P8 with the fluid's viscosity: the flow's single one, or with a free surface each particle's mixture (Coupling.hpp).
  if (coupling_.Lubrication()) PetscCall(dem.SetFluidLubrication(vof_ ? 0 : flow_->Get().ReferenceViscosity()));
  dem_->SetSubstepped(true);
  if (vof_) vof_->SetWithParticles(true);
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingModule::SetUp(ModuleSet &, const RunContext &run) {
  Flow &flow = flow_->Get();

  PetscFunctionBeginUser;
  PetscCall(coupling_.SetUp(flow, dem_->Get()));
  flow.AddOutputField(flow.FluidFraction());  // eps in flow_<step>.h5 / flow.xmf: where the bed is, its bubbles
  if (vof_) {  // particles with a free surface: eps in the interface's transport (F1b), its forces on them (P1)
    Vof &vof = vof_->Get();
    vof.SetFluidFraction(flow.FluidFraction(), coupling_.FluidFractionChange());
    coupling_.SetPhaseFraction(vof.Fraction());  // where new particles' volume is taken from the gas (Coupling::Project)
    coupling_.SetInterfaceForces(vof.SurfaceTensionCoefficient() > 0);
    PetscCall(coupling_.SetFreeSurface(vof.Fraction(), vof.SurfaceTensionCoefficient()));
    PetscCall(coupling_.Average());  // again, with the interface's force field
    PetscCall(vof_->RecordInitialVolumes());  // the particles displace their volume of either phase from the start
  }
  // A fluid set moving at the start (an inflow's velocity everywhere, divergence-free for eps = 1), or an inflow
  // into fluid at rest (the first step's projection would set it moving): with the particles' eps the pores carry
  // U/eps (F1). Projected now, so that the first step's limit sees that speed (a packed bed's first step ran at
  // CFL 1.16 with the limit of U alone) and the particles read it. A fluid at rest with closed boundaries needs
  // nothing; a restart loads its own velocity.
  if (!run.restarting) {
    PetscReal umax = 0;
    for (int d = 0; d < 3; ++d) {
      PetscReal m;
      PetscCall(VecNorm(flow.Velocity(d), NORM_INFINITY, &m));
      umax = std::fmax(umax, m);
      for (int f = 0; f < 6; ++f) umax = std::fmax(umax, std::fabs(flow.Boundary().Face(f).velocity[d]));
    }
    if (umax > 0) {
      PetscCall(flow.ProjectInitialVelocity());
      PetscCall(coupling_.Average());
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingModule::Run(Stage stage, StepState &step) {
  PetscFunctionBeginUser;
  switch (stage) {
  case Stage::Exchange:
    PetscCall(coupling_.Project(step.dt));
    break;
  case Stage::Average:
    PetscCall(coupling_.Average(step.dt));
    step.substeps = coupling_.Substeps(step.dt);
    break;
  case Stage::Finish:
    coupling_.Finish(step.dt);
    break;
  default:
    break;
  }
  PetscFunctionReturn(0);
}

std::string CouplingModule::MonitorColumns() const {
  return ",coupling_min_eps,coupling_eps_clipped_cells,coupling_drag_x_N,coupling_drag_y_N,coupling_drag_z_N,coupling_exchange_error,coupling_volume_error";
}

PetscErrorCode CouplingModule::Monitor(MonitorPart *part) {
  CouplingSummary c;

  PetscFunctionBeginUser;  // C3 in every run: the fluid's source is minus the particles' drag, projected volume = particle volume
  PetscCall(coupling_.Summarize(&c));
  const PetscReal drag = std::sqrt(c.dragSum[0] * c.dragSum[0] + c.dragSum[1] * c.dragSum[1] + c.dragSum[2] * c.dragSum[2]);
  PetscReal       miss = 0;
  for (int d = 0; d < 3; ++d) miss += (c.sourceSum[d] + c.dragSum[d]) * (c.sourceSum[d] + c.dragSum[d]);
  const PetscReal exch = drag > 0 ? std::sqrt(miss) / drag : 0, verr = c.particleVolume > 0 ? std::fabs(c.projectedVolume / c.particleVolume - 1) : 0;
  char            cb[400];
  std::snprintf(cb, sizeof cb, "  | coupling eps_min %.4f%s  drag (%.4e, %.4e, %.4e) N  exchange error %.1e  volume error %.1e", (double)c.minEps,
                c.clipped ? (" (" + std::to_string((long long)c.clipped) + " cells clipped)").c_str() : "", (double)c.dragSum[0], (double)c.dragSum[1], (double)c.dragSum[2],
                (double)exch, (double)verr);
  part->screen = cb;
  std::snprintf(cb, sizeof cb, ",%.6f,%d,%.10e,%.10e,%.10e,%.3e,%.3e", (double)c.minEps, (int)c.clipped, (double)c.dragSum[0], (double)c.dragSum[1], (double)c.dragSum[2],
                (double)exch, (double)verr);
  part->csv = cb;
  PetscFunctionReturn(0);
}

void RegisterModule_coupling(ModuleRegistry &registry) {
  ModuleEntry e;
  e.name      = "coupling";
  e.summary   = "semi-resolved particle-fluid coupling: kernel averages, drag and the fluid's reaction (src/coupling; on with dem and flow)";
  e.impliedBy = {"dem", "flow"};
  e.create    = [] { return std::unique_ptr<Module>(new CouplingModule); };
  registry.Add(std::move(e));
  RegisterSeepageModule(registry);  // the same floor's other coupling: particles with the Darcy seepage
  RegisterParticleHeatModule(registry);  // and the particles' heat with the energy equation (ParticleHeat.hpp)
}

}  // namespace vofdem
