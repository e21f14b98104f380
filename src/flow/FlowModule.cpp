// FlowModule.hpp: the fluid in the simulation's stages, monitor, banner and checkpoints.
#include "vofdem/flow/FlowModule.hpp"

#include "vofdem/base/ModuleRegistry.hpp"

#include "vofdem/base/ViewerGroup.hpp"

#include <cstdio>

namespace vofdem {

PetscErrorCode FlowModule::SetFromOptions(const RunContext &run) {
  PetscFunctionBeginUser;
  fixedDt_ = run.fixedDt;
  PetscCall(flow_.SetFromOptions(*run.grid));
  PetscFunctionReturn(0);
}

PetscErrorCode FlowModule::Run(Stage stage, StepState &step) {
  PetscFunctionBeginUser;
  if (stage == Stage::Fluid) PetscCall(flow_.Step(step.time, step.dt));
  PetscFunctionReturn(0);
}

PetscErrorCode FlowModule::LowerTimeStep(TimeStepLimit *limit) {
  PetscReal   f;
  std::string basis;

  PetscFunctionBeginUser;
  PetscCall(flow_.StableTimeStep(&f, &basis, !momentumElsewhere_));
  limit->Lower(f, basis);
  PetscFunctionReturn(0);
}

std::string FlowModule::MonitorColumns() const {
  return ",flow_kinetic_energy_J,flow_max_velocity_m_s,flow_max_divergence_1_s,flow_cfl,pressure_iterations,pressure_residual,pressure_pc_reused,viscous_iterations";
}

PetscErrorCode FlowModule::Monitor(MonitorPart *part) {
  FlowSummary fs;
  char        fb[400];

  PetscFunctionBeginUser;
  PetscCall(flow_.Summarize(&fs));
  std::snprintf(fb, sizeof fb, "  | flow KE %.6e J  max|u_i| %.4e m/s  div %.2e 1/s  CFL %.3f  p its %d%s  visc its %d", (double)fs.kinetic, (double)fs.maxSpeed,
                (double)fs.maxDivergence, (double)fs.cfl, (int)fs.pressureIterations, fs.preconditionerReused ? " (pc reused)" : "", (int)fs.viscousIterations);
  part->screen = fb;
  std::snprintf(fb, sizeof fb, ",%.10e,%.10e,%.6e,%.6f,%d,%.6e,%d,%d", (double)fs.kinetic, (double)fs.maxSpeed, (double)fs.maxDivergence, (double)fs.cfl,
                (int)fs.pressureIterations, (double)fs.pressureResidual, (int)fs.preconditionerReused, (int)fs.viscousIterations);
  part->csv = fb;
  PetscFunctionReturn(0);
}

PetscErrorCode FlowModule::ViewTimeStep(PetscViewer viewer) const {
  PetscReal   f;
  std::string basis;

  PetscFunctionBeginUser;
  PetscCall(flow_.StableTimeStep(&f, &basis, !momentumElsewhere_));
  PetscCall(PetscViewerASCIIPrintf(viewer, "time step limits: flow %g s (%s)%s\n", (double)f, basis.c_str(), fixedDt_ ? "" : "; adapted every step"));
  PetscFunctionReturn(0);
}

PetscErrorCode FlowModule::Save(PetscViewer viewer) {
  return InViewerGroup(viewer, "flow", [&] { return flow_.Save(viewer); });
}

PetscErrorCode FlowModule::Load(PetscViewer viewer) {
  return InViewerGroup(viewer, "flow", [&] { return flow_.Load(viewer); });
}

PetscErrorCode FlowModule::Finish() {
  PetscFunctionBeginUser;
  if (!flow_.ProfilePath().empty()) PetscCall(flow_.WriteProfile(flow_.ProfilePath()));
  PetscFunctionReturn(0);
}

void RegisterModule_flow(ModuleRegistry &registry) {
  ModuleEntry e;
  e.name    = "flow";
  e.summary = "fluid: volume-averaged incompressible Navier-Stokes on the MAC grid, pressure by hypre (src/flow)";
  e.create  = [] { return std::unique_ptr<Module>(new FlowModule); };
  registry.Add(std::move(e));
}

}  // namespace vofdem
