// DarcyModule.hpp: the Darcy seepage in the simulation's stages, monitor, banner and checkpoints.
#include "vofdem/darcy/DarcyModule.hpp"

#include "vofdem/base/ModuleRegistry.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/base/ViewerGroup.hpp"

#include <cstdio>

namespace vofdem {

PetscErrorCode DarcyModule::Configure(ModuleSet &modules, const RunContext &run) {
  PetscFunctionBeginUser;
  if (modules.Has("flow"))
    VofdemInputError(run.comm, "option -physics: 'darcy' and 'flow' are two models of the same pore water; name one of them");
  PetscFunctionReturn(0);
}

PetscErrorCode DarcyModule::SetUp(ModuleSet &modules, const RunContext &run) {
  PetscFunctionBeginUser;
  PetscCall(darcy_.SetUp(*run.grid));
  // With particles the seepage coupling solves once it has their eps (its set-up follows the particles').
  if (!modules.Has("dem")) PetscCall(darcy_.Solve(0));
  PetscFunctionReturn(0);
}

PetscErrorCode DarcyModule::Run(Stage stage, StepState &step) {
  PetscFunctionBeginUser;
  // The head of the step's end: the ramp's level at t + dt, the particles' eps as the exchange left it.
  if (stage == Stage::Fluid && (step.step + 1) % darcy_.SolveEvery() == 0) PetscCall(darcy_.Solve(step.time + step.dt));
  PetscFunctionReturn(0);
}

std::string DarcyModule::MonitorColumns() const {
  return ",darcy_head_difference_m,darcy_hydraulic_gradient,darcy_inflow_m3_s,darcy_outflow_m3_s,darcy_permeability_m2,darcy_min_eps,darcy_max_eps,darcy_ksp_iterations,darcy_picard_iterations";
}

PetscErrorCode DarcyModule::Monitor(MonitorPart *part) {
  DarcySummary s;
  char         b[512];

  PetscFunctionBeginUser;
  PetscCall(darcy_.Summarize(&s));
  std::snprintf(b, sizeof b, "  | darcy dH %.6e m  i %.6e  Q_out %.10e m^3/s  (in %.10e)  k %.6e m^2  eps [%.4f, %.4f]  its %d/%d", (double)s.headDifference, (double)s.gradient,
                (double)s.outflow, (double)s.inflow, (double)s.permeability, (double)s.minEps, (double)s.maxEps, (int)s.iterations, (int)s.picard);
  part->screen = b;
  std::snprintf(b, sizeof b, ",%.16e,%.16e,%.16e,%.16e,%.16e,%.10f,%.10f,%d,%d", (double)s.headDifference, (double)s.gradient, (double)s.inflow, (double)s.outflow, (double)s.permeability,
                (double)s.minEps, (double)s.maxEps, (int)s.iterations, (int)s.picard);
  part->csv = b;
  PetscFunctionReturn(0);
}

PetscErrorCode DarcyModule::Save(PetscViewer viewer) {
  return InViewerGroup(viewer, "darcy", [&]() -> PetscErrorCode { return darcy_.Save(viewer); });
}

PetscErrorCode DarcyModule::Load(PetscViewer viewer) {
  return InViewerGroup(viewer, "darcy", [&]() -> PetscErrorCode { return darcy_.Load(viewer); });
}

PetscErrorCode DarcyModule::SavedBytes(PetscInt64 *bytes) const {
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(VecGetSize(darcy_.Pressure(), &n));
  *bytes = 3 * 8 * (PetscInt64)n + 4096;  // p, the coefficient, the speeds
  PetscFunctionReturn(0);
}

void RegisterModule_darcy(ModuleRegistry &registry) {
  ModuleEntry e;
  e.name    = "darcy";
  e.summary = "Darcy seepage: the steady head equation with a permeability law k(eps), fixed head on two faces (src/darcy)";
  e.create  = [] { return std::unique_ptr<Module>(new DarcyModule); };
  registry.Add(std::move(e));
}

}  // namespace vofdem
