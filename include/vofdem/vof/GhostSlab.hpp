// The ghost layers of a ghosted DMDA extent that lie beyond one face of the box (only those this rank
// has): the index box [lo, hi) for the face `face` = 2 d + side (side 0: below index 0; 1: at N[d] and
// above). Used wherever the VOF fills ghosts face by face (walls, contact angles, open faces).
#pragma once

#include <petscsys.h>

#include <algorithm>

namespace vofdem {

inline void GhostSlabBeyondFace(int face, const PetscInt gs[3], const PetscInt gm[3], const PetscInt N[3], PetscInt lo[3], PetscInt hi[3]) {
  const int d = face / 2;
  for (int e = 0; e < 3; ++e) lo[e] = gs[e], hi[e] = gs[e] + gm[e];
  if (face % 2 == 0) hi[d] = std::min(hi[d], (PetscInt)0);
  else lo[d] = std::max(lo[d], N[d]);
}

}  // namespace vofdem
