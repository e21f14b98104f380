// Grid fields of the flow for ParaView (-flow_output_every N): every N steps one HDF5 file
// flow_<step>.h5 in -output_dir with cell-centred velocity (the mean of the two faces of each
// cell), pressure, density and, with solids, the solid mask, in natural (z, y, x) ordering whatever
// the rank count; flow.xmf indexes them as a temporal collection of uniform grids (rewritten
// atomically at each output, Xdmf.hpp).
#include "vofdem/flow/Flow.hpp"

#include "vofdem/base/Runtime.hpp"
#include "vofdem/io/TextFile.hpp"

#include <petscviewerhdf5.h>

#include <cstdio>

namespace vofdem {

PetscErrorCode Flow::SetOutputDir(const std::string &dir) {
  PetscFunctionBeginUser;
  if (dir.empty() && outputEvery_ > 0) VofdemInputError(grid_->Comm(), "option -flow_output_every needs -output_dir (the folder for the files)");
  outputDir_ = dir;
  PetscFunctionReturn(0);
}

XdmfEntry Flow::OutputEntry(PetscInt step, PetscReal time) const {
  XdmfEntry e;
  e.time = time, e.step = step;
  char file[64];
  std::snprintf(file, sizeof file, "flow_%08d.h5", (int)step);
  e.file = file;
  for (int d = 0; d < 3; ++d) {
    e.cells[d]   = grid_->Cells()[d];
    e.origin[d]  = grid_->Lower()[d];
    e.spacing[d] = grid_->Spacing()[d];
  }
  e.attributes = {{"velocity", "/velocity", 3, true}, {"pressure", "/flow_pressure", 1, true}, {"density", "/flow_density", 1, true}};
  if (solid_.Any()) e.attributes.push_back({"solid", "/flow_solid", 1, true});
  for (Vec v : outputExtra_) {
    const char *name = nullptr;
    PetscObjectGetName((PetscObject)v, &name);
    e.attributes.push_back({name, std::string("/") + name, 1, true});
  }
  return e;
}

PetscErrorCode Flow::WriteOutput(PetscInt step, PetscReal time) {
  PetscViewer viewer;
  LocalField  u[3];
  PetscInt    s[3], n[3];

  PetscFunctionBeginUser;
  if (outputEvery_ <= 0 || step % outputEvery_) PetscFunctionReturn(0);
  if (!velocityDM_) {
    PetscCall(DMDACreateCompatibleDMDA(sg_.Cells(), 3, &velocityDM_));
    PetscCall(DMCreateGlobalVector(velocityDM_, &cellVelocity_));
    PetscCall(PetscObjectSetName((PetscObject)cellVelocity_, "velocity"));
  }
  // Cell-centred velocity from the current faces (the ghosted copies are refreshed here: the next
  // step refreshes them again, so the run is unchanged by writing).
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMGlobalToLocal(sg_.Face(d), u_[d], INSERT_VALUES, uLocal_[d]));
    PetscCall(sg_.GetLocal(d, uLocal_[d], &u[d]));
  }
  PetscScalar *v;
  PetscCall(VecGetArray(cellVelocity_, &v));
  sg_.Owned(3, s, n);
  for (PetscInt k = s[2], c = 0; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i, ++c)
        for (int d = 0; d < 3; ++d) {
          PetscInt q[3] = {i, j, k};
          const PetscScalar lo = u[d].at(q);
          q[d] += 1;
          v[3 * c + d] = 0.5 * (lo + u[d].at(q));
        }
  PetscCall(VecRestoreArray(cellVelocity_, &v));
  for (int d = 0; d < 3; ++d) PetscCall(sg_.RestoreLocal(d, uLocal_[d], &u[d]));

  const XdmfEntry e = OutputEntry(step, time);
  PetscCall(PetscViewerHDF5Open(grid_->Comm(), (outputDir_ + "/" + e.file).c_str(), FILE_MODE_WRITE, &viewer));
  PetscCall(VecView(cellVelocity_, viewer));
  PetscCall(VecView(p_, viewer));
  PetscCall(VecView(rho_, viewer));
  if (solid_.Any()) PetscCall(VecView(solid_.Cells(), viewer));
  for (Vec x : outputExtra_) PetscCall(VecView(x, viewer));
  PetscCall(PetscViewerDestroy(&viewer));

  outputEntries_.push_back(e);
  PetscCall(WriteTextFile(grid_->Comm(), outputDir_ + "/flow.xmf", XdmfIndexText("flow", outputEntries_), "option -flow_output_every"));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
