// A volume moved between two cells of the grid, as the rank owning `cell` sees it: dv > 0 cell volumes of a phase
// from `other` into `cell` (and as much of the other phase back), dv < 0 the reverse. `other` is a neighbour and
// may lie in a (periodic) ghost layer. The VOF's redistribution reports its moves so (vof/Vof.hpp); what moves
// with the phases (the energy) follows them.
#pragma once

#include <petscsys.h>

namespace vofdem {

struct CellMove {
  PetscInt  cell[3], other[3];  // global cell indices
  PetscReal dv;
};

}  // namespace vofdem
