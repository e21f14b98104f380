// Prescribed divergence-free MAC velocities for interface tests (docs/verification.md V1, V2): a 2-D
// stream function psi(x, y) sampled at the cell corners gives face velocities
//   u = (psi(x_i, y_j+1) - psi(x_i, y_j)) / hy,  v = -(psi(x_i+1, y_j) - psi(x_i, y_j)) / hx,  w = 0,
// whose discrete divergence is zero to round-off in every cell (the differences telescope).
#pragma once

#include "vofdem/grid/StaggeredGrid.hpp"

namespace vofdem {

using StreamFunction = PetscReal (*)(void *ctx, PetscReal x, PetscReal y);

// u[d]: global vectors of sg.Face(d); their previous values are overwritten.
PetscErrorCode FillFromStreamFunction(const StaggeredGrid &sg, StreamFunction psi, void *ctx, Vec u[3]);

}  // namespace vofdem
