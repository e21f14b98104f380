// KernelAverager::SetExcludedCells (KernelAverager.hpp): the cells and faces a deposit leaves out.
#include "vofdem/coupling/KernelAverager.hpp"

namespace vofdem {

PetscErrorCode KernelAverager::SetExcludedCells(Vec cells, PetscInt *count) {
  PetscInt mine = 0, all = 0;

  PetscFunctionBeginUser;
  if (!cells) {
    for (auto &e : excluded_) e.clear();
    excluding_ = false;
    if (count) *count = 0;
    PetscFunctionReturn(0);
  }
  Vec local;
  PetscCall(DMGetLocalVector(dm_[3], &local));
  PetscCall(DMGlobalToLocal(dm_[3], cells, INSERT_VALUES, local));  // the same ownership as the flow's cells
  const PetscScalar *c;
  PetscCall(VecGetArrayRead(local, &c));
  const PetscInt *cs = gs_[3], *cm = gm_[3];
  // Cell (i, j, k) in global indices (periodic ghosts as the DMDA numbers them), 0 outside the ghosted box.
  auto cell = [&](PetscInt i, PetscInt j, PetscInt k) -> bool {
    if (i < cs[0] || j < cs[1] || k < cs[2] || i >= cs[0] + cm[0] || j >= cs[1] + cm[1] || k >= cs[2] + cm[2]) return false;
    return PetscRealPart(c[(i - cs[0]) + (j - cs[1]) * cm[0] + (k - cs[2]) * cm[0] * cm[1]]) > 0.5;
  };
  for (int loc = 0; loc < 4; ++loc) {
    const PetscInt *s = gs_[loc], *m = gm_[loc];
    std::vector<char> &e = excluded_[loc];
    e.assign((size_t)m[0] * m[1] * m[2], 0);
    for (PetscInt k = s[2]; k < s[2] + m[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + m[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + m[0]; ++i) {
          // A face (loc = its direction) lies between the cells below and above it along loc: out if either is.
          const bool out = loc == 3 ? cell(i, j, k) : cell(i, j, k) || cell(i - (loc == 0), j - (loc == 1), k - (loc == 2));
          e[(size_t)(i - s[0]) + (size_t)(j - s[1]) * m[0] + (size_t)(k - s[2]) * m[0] * m[1]] = out;
        }
  }
  PetscCall(VecRestoreArrayRead(local, &c));
  PetscCall(DMRestoreLocalVector(dm_[3], &local));
  {  // owned cells only, for the count
    const PetscScalar *g;
    PetscInt           n;
    PetscCall(VecGetLocalSize(cells, &n));
    PetscCall(VecGetArrayRead(cells, &g));
    for (PetscInt q = 0; q < n; ++q) mine += PetscRealPart(g[q]) > 0.5;
    PetscCall(VecRestoreArrayRead(cells, &g));
  }
  PetscCallMPI(MPI_Allreduce(&mine, &all, 1, MPIU_INT, MPI_SUM, sg_->Base().Comm()));
  excluding_ = all > 0;
  if (!excluding_)
    for (auto &e : excluded_) e.clear();
  if (count) *count = all;
  PetscFunctionReturn(0);
}

}  // namespace vofdem
