// VofModule.hpp: the interface in the simulation's stages, monitor, banner and checkpoints.
#include "vofdem/vof/VofModule.hpp"

#include "vofdem/base/ModuleRegistry.hpp"

#include "vofdem/base/ViewerGroup.hpp"

#include <algorithm>
#include <cstdio>

namespace vofdem {

void VofModule::SetWithParticles(bool on) {
  withParticles_ = on;
  if (flow_) flow_->SetMomentumMovedElsewhere(Consistent());
}

PetscErrorCode VofModule::Configure(ModuleSet &modules, const RunContext &) {
  PetscFunctionBeginUser;
  flow_ = modules.Get<FlowModule>("flow");  // the registry makes vof need flow
  PetscCall(vof_.CheckFlowOptions(flow_->Get()));
  flow_->SetMomentumMovedElsewhere(Consistent());
  PetscFunctionReturn(0);
}

PetscErrorCode VofModule::SetUp(ModuleSet &, const RunContext &) {
  Flow &flow = flow_->Get();

  PetscFunctionBeginUser;  // after the flow: alpha lives on the flow's cells and sets its density and viscosity
  PetscCall(vof_.SetUp(flow.Staggered()));
  PetscCall(vof_.SetInitialShapes());
  PetscCall(vof_.UpdateProperties(flow));
  flow.AddOutputField(vof_.Fraction());  // alpha in flow_<step>.h5 / flow.xmf (-flow_output_every)
  VofSummary vs;
  PetscCall(vof_.Summarize(&vs));
  volume0_ = vs.volume;
  PetscFunctionReturn(0);
}

PetscErrorCode VofModule::RecordInitialVolumes() {
  VofSummary vs;

  PetscFunctionBeginUser;
  PetscCall(vof_.Summarize(&vs));
  volume0_      = vs.volume;
  otherVolume0_ = vs.otherVolume;
  PetscFunctionReturn(0);
}

std::vector<Stage> VofModule::Stages() const {
  if (Consistent()) return {Stage::Prepare, Stage::Forces};
  return {Stage::Forces, Stage::Transport, Stage::Properties};
}

PetscErrorCode VofModule::Run(Stage stage, StepState &step) {
  Flow &flow = flow_->Get();

  PetscFunctionBeginUser;
  switch (stage) {
  case Stage::Prepare:  // mass-consistent momentum (VofMomentum.cpp): alpha and rho u move together with u^n
    PetscCall(vof_.AdvectWithMomentum(flow, step.dt));
    PetscCall(vof_.UpdateProperties(flow));
    break;
  case Stage::Forces:
    PetscCall(vof_.SurfaceTension(flow));
    break;
  case Stage::Transport: {
    Vec u[3] = {flow.Velocity(0), flow.Velocity(1), flow.Velocity(2)};
    PetscCall(vof_.Advect(u, step.dt));
  } break;
  case Stage::Properties:
    PetscCall(vof_.UpdateProperties(flow));
    break;
  default:
    break;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode VofModule::LowerTimeStep(TimeStepLimit *limit) {
  Flow       &flow = flow_->Get();
  PetscReal   f;
  std::string basis;
  Vec         u[3] = {flow.Velocity(0), flow.Velocity(1), flow.Velocity(2)};

  PetscFunctionBeginUser;
  PetscCall(vof_.StableTimeStep(u, &f, &basis));
  limit->Lower(f, basis);
  limit->Lower(vof_.CapillaryTimeStep(flow.ReferenceDensity()), "capillary sqrt(rho_mean h^3/(2 pi sigma))");
  PetscFunctionReturn(0);
}

std::string VofModule::MonitorColumns() const {
  std::string c = withParticles_ ? ",vof_volume_m3,vof_volume_relative_change,vof_bound_violation,vof_interface_cells,vof_phase0_volume_m3,vof_phase0_volume_relative_change"
                                 : ",vof_volume_m3,vof_volume_relative_change,vof_bound_violation,vof_interface_cells";
  if (vof_.HasOpenFaces()) c += ",vof_inflow_volume_m3,vof_outflow_volume_m3,vof_balance_error";
  return c;
}

PetscErrorCode VofModule::Monitor(MonitorPart *part) {
  VofSummary vs;
  char       vb[300];

  PetscFunctionBeginUser;
  PetscCall(vof_.Summarize(&vs));
  const PetscReal volErr = volume0_ > 0 ? (vs.volume - volume0_) / volume0_ : 0;
  std::snprintf(vb, sizeof vb, "  | vof volume %.10e m^3  rel. change %.2e  bounds %.1e  interface cells %d", (double)vs.volume, (double)volErr, (double)vs.boundViolation,
                (int)vs.interfaceCells);
  part->screen = vb;
  std::snprintf(vb, sizeof vb, ",%.16e,%.6e,%.6e,%d", (double)vs.volume, (double)volErr, (double)vs.boundViolation, (int)vs.interfaceCells);
  part->csv = vb;
  if (withParticles_) {  // F1b with particles: the other phase's volume too (eps (1 - alpha) V)
    const PetscReal otherErr = otherVolume0_ > 0 ? (vs.otherVolume - otherVolume0_) / otherVolume0_ : 0;
    std::snprintf(vb, sizeof vb, "  phase-0 volume %.10e m^3  rel. change %.2e", (double)vs.otherVolume, (double)otherErr);
    part->screen += vb;
    std::snprintf(vb, sizeof vb, ",%.16e,%.6e", (double)vs.otherVolume, (double)otherErr);
    part->csv += vb;
  }
  if (vs.openFaces) {  // inflow/outflow (VofOpenFaces.cpp): V - V0 = in - out, the error relative to the largest of the four
    const PetscReal scale   = std::max({volume0_, vs.volume, vs.inflowVolume, vs.outflowVolume, (PetscReal)PETSC_SMALL});
    const PetscReal balance = (vs.volume - volume0_ - (vs.inflowVolume - vs.outflowVolume)) / scale;
    std::snprintf(vb, sizeof vb, "  in %.6e out %.6e m^3  balance %.1e", (double)vs.inflowVolume, (double)vs.outflowVolume, (double)balance);
    part->screen += vb;
    std::snprintf(vb, sizeof vb, ",%.16e,%.16e,%.6e", (double)vs.inflowVolume, (double)vs.outflowVolume, (double)balance);
    part->csv += vb;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode VofModule::ViewTimeStep(PetscViewer viewer) const {
  PetscFunctionBeginUser;  // the interface's fixed limit (PETSC_MAX_REAL: none)
  const PetscReal cap = vof_.CapillaryTimeStep(flow_->Get().ReferenceDensity());
  if (cap < PETSC_MAX_REAL) PetscCall(PetscViewerASCIIPrintf(viewer, "time step limits: vof capillary %g s\n", (double)cap));
  PetscFunctionReturn(0);
}

PetscErrorCode VofModule::Save(PetscViewer viewer) {
  return InViewerGroup(viewer, "vof", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(vof_.Save(viewer));
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/vof", "vof_initial_volume", PETSC_REAL, &volume0_));
    if (withParticles_) PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/vof", "vof_initial_phase0_volume", PETSC_REAL, &otherVolume0_));
    PetscFunctionReturn(0);
  });
}

PetscErrorCode VofModule::Load(PetscViewer viewer) {  // after the flow: the flow's loaded density and viscosity already match alpha
  return InViewerGroup(viewer, "vof", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(vof_.Load(viewer));
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/vof", "vof_initial_volume", PETSC_REAL, nullptr, &volume0_));
    if (withParticles_) PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/vof", "vof_initial_phase0_volume", PETSC_REAL, nullptr, &otherVolume0_));
    PetscFunctionReturn(0);
  });
}

void RegisterModule_vof(ModuleRegistry &registry) {
  ModuleEntry e;
  e.name        = "vof";
  e.summary     = "interface: geometric VOF (PLIC, split sweeps), balanced-force surface tension, Marangoni (src/vof)";
  e.needs       = {"flow"};
  e.needsReason = "the interface moves with the fluid";
  e.create      = [] { return std::unique_ptr<Module>(new VofModule); };
  registry.Add(std::move(e));
}

}  // namespace vofdem
