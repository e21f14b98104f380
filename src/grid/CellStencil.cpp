// CellStencil.hpp: ghost cells outside the box.
#include "vofdem/grid/CellStencil.hpp"

#include <algorithm>

namespace vofdem {

PetscErrorCode FillNearestOutside(const StaggeredGrid &sg, LocalField &c) {
  const Grid &grid = sg.Base();
  PetscInt    gs[3], gm[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetGhostCorners(sg.Cells(), &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  // Direction by direction, the ghost slabs beyond the box's faces (a pass reads only cells inside the box along
  // its direction, so the order within a pass does not matter; corners take the later directions' values).
  for (int d = 0; d < 3; ++d) {
    if (grid.Periodic(d)) continue;
    const PetscInt n = grid.Cells()[d];
    for (int side = 0; side < 2; ++side) {
      PetscInt lo[3] = {gs[0], gs[1], gs[2]}, hi[3] = {gs[0] + gm[0], gs[1] + gm[1], gs[2] + gm[2]};
      if (side == 0) hi[d] = std::min(hi[d], (PetscInt)0);
      else lo[d] = std::max(lo[d], n);
      const PetscInt from = side == 0 ? 0 : n - 1;
      if (lo[d] >= hi[d] || from < gs[d] || from >= gs[d] + gm[d]) continue;  // no slab here, or its source is not in this rank's box
      for (PetscInt k = lo[2]; k < hi[2]; ++k)
        for (PetscInt j = lo[1]; j < hi[1]; ++j)
          for (PetscInt i = lo[0]; i < hi[0]; ++i) {
            PetscInt q[3] = {i, j, k}, src[3] = {i, j, k};
            src[d] = from;
            c.at(q) = c.at(src);
          }
    }
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
