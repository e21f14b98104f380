// CellStencil.hpp: ghost cells outside the box.
#include "vofdem/grid/CellStencil.hpp"

namespace vofdem {

PetscErrorCode FillNearestOutside(const StaggeredGrid &sg, LocalField &c) {
  const Grid &grid = sg.Base();
  PetscInt    gs[3], gm[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetGhostCorners(sg.Cells(), &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  for (int d = 0; d < 3; ++d) {
    if (grid.Periodic(d)) continue;
    const PetscInt n = grid.Cells()[d];
    for (PetscInt k = gs[2]; k < gs[2] + gm[2]; ++k)
      for (PetscInt j = gs[1]; j < gs[1] + gm[1]; ++j)
        for (PetscInt i = gs[0]; i < gs[0] + gm[0]; ++i) {
          PetscInt q[3] = {i, j, k};
          if (q[d] >= 0 && q[d] < n) continue;
          PetscInt src[3] = {i, j, k};
          src[d]          = q[d] < 0 ? 0 : n - 1;
          bool inside     = true;
          for (int e = 0; e < 3; ++e) inside = inside && src[e] >= gs[e] && src[e] < gs[e] + gm[e];
          if (inside) c.at(q) = c.at(src);
        }
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
