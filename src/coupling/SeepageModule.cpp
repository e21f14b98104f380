// SeepageModule.hpp: the seepage coupling's checks across modules, set-up, stages and monitor.
#include "vofdem/coupling/SeepageModule.hpp"

#include "vofdem/base/ModuleRegistry.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/darcy/DarcyModule.hpp"
#include "vofdem/dem/DemModule.hpp"

#include <cstdio>

namespace vofdem {

PetscErrorCode SeepageModule::Configure(ModuleSet &modules, const RunContext &run) {
  PetscFunctionBeginUser;
  dem_   = modules.Get<DemModule>("dem");
  darcy_ = modules.Get<DarcyModule>("darcy");
  Dem &dem = dem_->Get();
  dem.UseFluidFields();  // the particles' fluid_* arrays from the start
  if (dem.Balancing())
    VofdemInputError(run.comm, "option -dem_balance: coupled scenes keep the grid's decomposition (the particles' kernels live on its cells); use none (the default) and choose the split with -grid_ranks");
  PetscCall(darcy_->Get().TakeFluidFractionFromParticles());
  PetscFunctionReturn(0);
}

PetscErrorCode SeepageModule::SetUp(ModuleSet &, const RunContext &run) {
  PetscFunctionBeginUser;
  PetscCall(seepage_.SetUp(*run.grid, darcy_->Get(), dem_->Get(), run.gravity));
  // The particles are in the water from the start: their eps, the head, and its force before the first step.
  PetscCall(seepage_.Project());
  PetscCall(darcy_->Get().Solve(0));
  PetscCall(seepage_.Forces());
  PetscFunctionReturn(0);
}

PetscErrorCode SeepageModule::Run(Stage stage, StepState &step) {
  PetscFunctionBeginUser;
  const bool solving = (step.step + 1) % darcy_->Get().SolveEvery() == 0;  // the darcy module's rule
  if (stage == Stage::Exchange && solving) PetscCall(seepage_.Project());
  if (stage == Stage::Average && solving) PetscCall(seepage_.Forces());
  PetscFunctionReturn(0);
}

std::string SeepageModule::MonitorColumns() const {
  return ",seepage_force_x_N,seepage_force_y_N,seepage_force_z_N,seepage_grid_force_x_N,seepage_grid_force_y_N,seepage_grid_force_z_N,seepage_min_eps,seepage_clipped_cells,seepage_volume_error";
}

PetscErrorCode SeepageModule::Monitor(MonitorPart *part) {
  SeepageSummary s;
  char           b[512];

  PetscFunctionBeginUser;
  PetscCall(seepage_.Summarize(&s));
  const PetscReal verr = s.particleVolume > 0 ? std::fabs(s.projectedVolume / s.particleVolume - 1) : 0;
  std::snprintf(b, sizeof b, "  | seepage force (%.6e, %.6e, %.6e) N  grid (%.6e, %.6e, %.6e) N  eps_min %.4f  volume error %.1e", (double)s.force[0], (double)s.force[1], (double)s.force[2],
                (double)s.gridForce[0], (double)s.gridForce[1], (double)s.gridForce[2], (double)s.minEps, (double)verr);
  part->screen = b;
  std::snprintf(b, sizeof b, ",%.16e,%.16e,%.16e,%.16e,%.16e,%.16e,%.6f,%d,%.3e", (double)s.force[0], (double)s.force[1], (double)s.force[2], (double)s.gridForce[0], (double)s.gridForce[1],
                (double)s.gridForce[2], (double)s.minEps, (int)s.clipped, (double)verr);
  part->csv = b;
  PetscFunctionReturn(0);
}

void RegisterSeepageModule(ModuleRegistry &registry) {
  ModuleEntry e;
  e.name      = "seepage";
  e.summary   = "particles in the Darcy seepage: eps from their volumes by the kernel, the seepage force back (src/coupling; on with dem and darcy)";
  e.impliedBy = {"dem", "darcy"};
  e.create    = [] { return std::unique_ptr<Module>(new SeepageModule); };
  registry.Add(std::move(e));
}

}  // namespace vofdem
