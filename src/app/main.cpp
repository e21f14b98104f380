// vofdem: mpiexec -n N vofdem -options_file_yaml scene.yaml [-option value ...]
#include "vofdem/analysis/Analysis.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"

static const char help[] = "vofdem: particles (DEM) in incompressible flow with a free surface (VOF), coupled semi-resolved.\n"
                           "Usage: mpiexec -n N vofdem -options_file_yaml scene.yaml [-option value ...]\n\n";

static PetscErrorCode Run() {
  vofdem::Simulation     sim;
  vofdem::PowderAnalysis analysis;  // -analysis_*: powder-bed metrics of the particles at the end
  PetscBool              help = PETSC_FALSE, outSet = PETSC_FALSE;
  char                   out[PETSC_MAX_PATH_LEN] = "";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-output_dir", out, sizeof out, &outSet));
  PetscCall(analysis.SetFromOptions(PETSC_COMM_WORLD, {}, outSet ? std::string(out) + "/analysis" : std::string()));
  if (!help) {
    if (analysis.Enabled() && !sim.Modules().Has("dem")) VofdemInputError(PETSC_COMM_WORLD, "option -analysis_metrics: the analysis needs particles (-physics dem)");
    PetscCall(sim.SetUp());
    vofdem::analysis::Window box;  // the default window, and what a given one must overlap
    for (int d = 0; d < 3; ++d) box.lo[d] = sim.GetGrid().Lower()[d], box.hi[d] = sim.GetGrid().Upper()[d];
    PetscCall(analysis.SetUp(&box));
    PetscCall(sim.View(PETSC_VIEWER_STDOUT_WORLD));
    PetscCall(sim.Run());
    if (analysis.Enabled() && sim.Interrupted())
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "vofdem: the run was stopped before its end: no analysis (-restart latest goes on)\n"));
    else if (analysis.Enabled()) {
      vofdem::analysis::Spheres s;
      PetscCall(vofdem::PowderAnalysis::Gather(*Particles(sim), sim.GetGrid(), &s));
      PetscCall(analysis.Run(s, box, "the particles at the end of the run"));
    }
  }
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}
