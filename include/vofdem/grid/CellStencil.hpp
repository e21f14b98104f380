// What the cell-centred transports (the passive scalar, the energy's sweeps) share on the staggered grid:
// van Leer's limited face value and the ghost cells outside a non-periodic box.
#pragma once

#include "vofdem/grid/StaggeredGrid.hpp"

#include <cmath>

namespace vofdem {

// The van Leer limiter phi(r) = (r + |r|)/(1 + |r|): phi(r) in [0, 2], TVD.
inline PetscReal VanLeer(PetscReal r) { return (r + std::fabs(r)) / (1 + std::fabs(r)); }

// A cell value at a face from the upwind side: up2, up1 the two upwind cells (up1 next to the face), down the
// downwind one. Bounded by up1 and down.
inline PetscReal VanLeerFaceValue(PetscReal up2, PetscReal up1, PetscReal down) {
  const PetscReal dd = down - up1, du = up1 - up2;
  if (dd == 0) return up1;
  return up1 + 0.5 * VanLeer(du / dd) * dd;
}

// Outside a non-periodic box, every ghost cell of c (a local vector of sg.Cells()) takes the value of its
// nearest interior cell, direction by direction (so edges and corners do too): zero gradient.
PetscErrorCode FillNearestOutside(const StaggeredGrid &sg, LocalField &c);

}  // namespace vofdem
