// Contact forces of one evaluation, kept only when output or analysis needs them (particle output,
// contact network, stress): the contact loop stores the total force F and its tangential part F_t
// of each touching contact in the slot of its neighbour-list pair or wall candidate. Off (the
// default), the loop pays one predictable branch per contact and nothing is stored.
#pragma once

#include <petscsys.h>

#include <algorithm>
#include <vector>

namespace vofdem {

struct ContactRecord {
  static constexpr int kWidth = 6;  // F x,y,z on the first (lower id) particle, then F_t x,y,z
  bool                   on = false;
  std::vector<PetscReal> pair, wall;  // kWidth per pair of the list / per wall candidate; zero if not touching

  // Before the loops (outside them: no allocation per contact once the sizes settle).
  void Reset(size_t pairs, size_t walls) {
    pair.assign(kWidth * pairs, 0);
    wall.assign(kWidth * walls, 0);
  }
  static void Store(PetscReal *slot, const PetscReal F[3], const PetscReal Ft[3]) {
    std::copy(F, F + 3, slot);
    std::copy(Ft, Ft + 3, slot + 3);
  }
};

}  // namespace vofdem
