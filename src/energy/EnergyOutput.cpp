// Energy.hpp: ParaView files of the energy equation (-energy_output_every N): every N steps energy_<step>.h5 in
// -output_dir with the temperature, the melt fraction alpha f and the metal fraction alpha, cell-centred in
// natural (z, y, x) ordering; energy.xmf indexes them (rewritten atomically at each output, io/Xdmf.hpp).
#include "vofdem/energy/Energy.hpp"

#include "vofdem/base/Runtime.hpp"
#include "vofdem/io/TextFile.hpp"

#include <petscviewerhdf5.h>

#include <cstdio>

namespace vofdem {

PetscErrorCode Energy::SetOutputDir(const std::string &dir) {
  PetscFunctionBeginUser;
  if (dir.empty() && outputEvery_ > 0) VofdemInputError(comm_, "option -energy_output_every needs -output_dir (the folder for the files)");
  outputDir_ = dir;
  PetscFunctionReturn(0);
}

XdmfEntry Energy::OutputEntry(PetscInt step, PetscReal time) const {
  XdmfEntry e;
  char      file[64];

  e.time = time, e.step = step;
  std::snprintf(file, sizeof file, "energy_%08d.h5", (int)step);
  e.file = file;
  for (int d = 0; d < 3; ++d) e.cells[d] = grid_->Cells()[d], e.origin[d] = grid_->Lower()[d], e.spacing[d] = grid_->Spacing()[d];
  e.attributes = {{"temperature", "/energy_temperature", 1, true}, {"melt_fraction", "/energy_melt_fraction", 1, true}, {"metal_fraction", "/energy_metal_fraction", 1, true}};
  return e;
}

PetscErrorCode Energy::WriteOutput(PetscInt step, PetscReal time) {
  PetscViewer viewer;

  PetscFunctionBeginUser;
  if (outputEvery_ <= 0 || step % outputEvery_) PetscFunctionReturn(0);
  const XdmfEntry e = OutputEntry(step, time);
  PetscCall(PetscViewerHDF5Open(comm_, (outputDir_ + "/" + e.file).c_str(), FILE_MODE_WRITE, &viewer));
  PetscCall(VecView(T_, viewer));
  PetscCall(VecView(MeltFraction(), viewer));
  PetscCall(VecView(alpha_, viewer));
  PetscCall(PetscViewerDestroy(&viewer));
  outputEntries_.push_back(e);
  PetscCall(WriteTextFile(comm_, outputDir_ + "/energy.xmf", XdmfIndexText("energy", outputEntries_), "option -energy_output_every"));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
