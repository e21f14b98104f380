// ScalarModule.hpp: the passive scalar in the simulation's stages, monitor, banner and checkpoints.
#include "vofdem/scalar/ScalarModule.hpp"

#include "vofdem/base/ModuleRegistry.hpp"
#include "vofdem/base/Runtime.hpp"

#include "vofdem/base/ViewerGroup.hpp"

#include <cmath>
#include <cstdio>

namespace vofdem {

PetscErrorCode ScalarModule::Configure(ModuleSet &modules, const RunContext &run) {
  PetscFunctionBeginUser;
  flow_ = modules.Get<FlowModule>("flow");  // the registry makes scalar need flow
  // With particles the fluid occupies eps of a cell and the transport would have to carry eps c (F1b): not done.
  if (modules.Has("dem")) VofdemInputError(run.comm, "option -physics: 'scalar' does not take particles into account yet (leave out dem)");
  PetscFunctionReturn(0);
}

PetscErrorCode ScalarModule::SetUp(ModuleSet &, const RunContext &) {
  ScalarSummary s;

  PetscFunctionBeginUser;
  PetscCall(scalar_.SetUp(flow_->Get().Staggered()));
  PetscCall(scalar_.Summarize(&s));
  total0_ = s.total;
  PetscFunctionReturn(0);
}

PetscErrorCode ScalarModule::Run(Stage stage, StepState &step) {
  Flow &flow = flow_->Get();

  PetscFunctionBeginUser;
  if (stage == Stage::Transport) {
    Vec u[3] = {flow.Velocity(0), flow.Velocity(1), flow.Velocity(2)};
    PetscCall(scalar_.Step(u, step.dt));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ScalarModule::LowerTimeStep(TimeStepLimit *limit) {
  Flow     &flow = flow_->Get();
  Vec       u[3] = {flow.Velocity(0), flow.Velocity(1), flow.Velocity(2)};
  PetscReal dt;

  PetscFunctionBeginUser;
  PetscCall(scalar_.StableTimeStep(u, &dt));
  limit->Lower(dt, "scalar (-scalar_cfl over advection and diffusion)");
  PetscFunctionReturn(0);
}

PetscErrorCode ScalarModule::Monitor(MonitorPart *part) {
  ScalarSummary s;
  char          b[300];

  PetscFunctionBeginUser;
  PetscCall(scalar_.Summarize(&s));
  const PetscReal change = total0_ != 0 ? (s.total - total0_) / std::fabs(total0_) : s.total;
  std::snprintf(b, sizeof b, "  | scalar total %.10e  rel. change %.2e  range [%.6e, %.6e]", (double)s.total, (double)change, (double)s.min, (double)s.max);
  part->screen = b;
  std::snprintf(b, sizeof b, ",%.16e,%.6e,%.16e,%.16e", (double)s.total, (double)change, (double)s.min, (double)s.max);
  part->csv = b;
  PetscFunctionReturn(0);
}

PetscErrorCode ScalarModule::Save(PetscViewer viewer) {
  return InViewerGroup(viewer, "scalar", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(scalar_.Save(viewer));
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/scalar", "scalar_initial_total", PETSC_REAL, &total0_));
    PetscFunctionReturn(0);
  });
}

PetscErrorCode ScalarModule::Load(PetscViewer viewer) {
  return InViewerGroup(viewer, "scalar", [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscCall(scalar_.Load(viewer));
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/scalar", "scalar_initial_total", PETSC_REAL, nullptr, &total0_));
    PetscFunctionReturn(0);
  });
}

PetscErrorCode ScalarModule::SavedBytes(PetscInt64 *bytes) const {
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(VecGetSize(scalar_.Field(), &n));
  *bytes = 8 * (PetscInt64)n + 4096;
  PetscFunctionReturn(0);
}

void RegisterModule_scalar(ModuleRegistry &registry) {
  ModuleEntry e;
  e.name        = "scalar";
  e.summary     = "a passive scalar carried by the flow: bounded (TVD) advection and diffusion (src/scalar)";
  e.needs       = {"flow"};
  e.needsReason = "the scalar moves with the fluid";
  e.create      = [] { return std::unique_ptr<Module>(new ScalarModule); };
  registry.Add(std::move(e));
}

}  // namespace vofdem
