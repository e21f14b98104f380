#include "vofdem/vof/StreamFunction.hpp"

namespace vofdem {

PetscErrorCode FillFromStreamFunction(const StaggeredGrid &sg, StreamFunction psi, void *ctx, Vec u[3]) {
  PetscFunctionBeginUser;
  const Grid      &grid = sg.Base();
  const PetscReal *h = grid.Spacing(), *lo = grid.Lower();
  for (int d = 0; d < 3; ++d) {
    LocalField f;
    PetscInt   s[3], n[3];
    sg.Owned(d, s, n);
    PetscCall(sg.GetGlobal(d, u[d], &f));
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
          const PetscReal x0 = lo[0] + i * h[0], y0 = lo[1] + j * h[1];
          PetscReal       v  = 0;
          if (d == 0) v = (psi(ctx, x0, y0 + h[1]) - psi(ctx, x0, y0)) / h[1];
          else if (d == 1) v = -(psi(ctx, x0 + h[0], y0) - psi(ctx, x0, y0)) / h[0];
          f.at(i, j, k) = v;
        }
    PetscCall(sg.RestoreGlobal(d, u[d], &f));
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
