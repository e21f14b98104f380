// vofdem-analyze: the powder-bed metrics of a saved particle file (src/analysis), e.g.
//   vofdem-analyze -analysis_input out/particles_000400.h5 -analysis_lower 2.75e-3,0,0 -analysis_upper 5.25e-3,4e-4,5e-5
// The box and its periodic directions come from -grid_lower/-grid_upper/-grid_periodic (as in the
// scene of the run); without them the default window is the particles' bounding box. The files go
// to -analysis_dir, by default <input without .h5>_analysis next to the input.
#include "vofdem/analysis/Analysis.hpp"
#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/grid/Grid.hpp"

#include <algorithm>
#include <filesystem>

static const char help[] = "vofdem-analyze: powder-bed metrics of a particles_<step>.h5 file (CSV into -analysis_dir).\n"
                           "Usage: vofdem-analyze -analysis_input FILE [-analysis_* ...] [-grid_lower x,y,z -grid_upper x,y,z -grid_periodic x,y]\n\n";

static PetscErrorCode Run() {
  MPI_Comm               comm = PETSC_COMM_WORLD;
  PetscBool              help = PETSC_FALSE, lowerGiven = PETSC_FALSE, upperGiven = PETSC_FALSE;
  std::string            input;
  vofdem::Grid           grid;
  vofdem::PowderAnalysis analysis;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  PetscOptionsBegin(comm, "analysis_", "vofdem-analyze", "Analysis");
  {
    vofdem::OptionReader opt(PetscOptionsObject);
    PetscCall(opt.String("-input", "The particles_<step>.h5 file to analyse (written by -dem_output_every)", &input));
  }
  PetscOptionsEnd();
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-grid_lower", &lowerGiven));
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-grid_upper", &upperGiven));
  PetscCall(grid.SetFromOptions(comm));
  // Default folder: next to the input, named after it (particles_000400_analysis).
  const std::filesystem::path in(input), dir = in.parent_path() / (in.stem().string() + "_analysis");
  PetscCall(analysis.SetFromOptions(comm, {"packing", "coordination", "pores", "surface", "segregation"}, dir.string()));
  if (help) PetscFunctionReturn(0);
  if (input.empty()) VofdemInputError(comm, "option -analysis_input is missing: name the particles_<step>.h5 file to analyse");
  PetscCall(vofdem::CheckUnusedOptions(comm));
  vofdem::analysis::Spheres s;
  PetscCall(vofdem::PowderAnalysis::Read(comm, input, &s));
  PetscCall(analysis.SetUp());
  vofdem::analysis::Window box;
  for (int d = 0; d < 3; ++d) {
    s.periodic[d] = grid.Periodic(d), s.lower[d] = grid.Lower()[d], s.upper[d] = grid.Upper()[d];
    box.lo[d] = grid.Lower()[d], box.hi[d] = grid.Upper()[d];
    if (lowerGiven || upperGiven) continue;
    box.lo[d] = HUGE_VAL, box.hi[d] = -HUGE_VAL;
    for (size_t i = 0; i < s.Size(); ++i) box.lo[d] = std::min(box.lo[d], s.x[3 * i + d] - s.r[i]), box.hi[d] = std::max(box.hi[d], s.x[3 * i + d] + s.r[i]);
  }
  PetscCall(analysis.Run(s, box, input));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}
