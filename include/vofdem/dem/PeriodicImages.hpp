// Periodic images of the particles' box (-grid_periodic). An image is the box shifted by
// (sx Lx, sy Ly, sz Lz), s in {-1, 0, 1} and 0 in directions that are not periodic; it is named by
// the code (sx+1) + 3 (sy+1) + 9 (sz+1), so 13 is "no shift" and 26 - k the opposite of k.
//
// Particles are wrapped back into the box only at neighbour-list rebuilds, right before migration
// (DMSwarmMigrate deletes particles outside the box, and the swarm's vertex DMDA must stay
// non-periodic: docs/petsc-notes.md); the reference positions of the rebuild rule are reset by that
// migration, so a wrap never looks like a jump of one box length. Between rebuilds a particle may
// stand up to half the skin outside the box in a periodic direction.
//
// A pair across a seam is evaluated as dx = (x_a - x_b) + shift, with both positions as their
// owners hold them, so the two ranks that hold either end (or one rank holding both, each seeing the
// other's image) compute the same bits, as for pairs across rank boundaries.
#pragma once

#include "vofdem/dem/NeighbourList.hpp"
#include "vofdem/grid/Grid.hpp"

#include <vector>

namespace vofdem {

class PeriodicImages {
public:
  static constexpr int kNone = 13, kCount = 27;
  static int           Opposite(int k) { return kCount - 1 - k; }

  void SetUp(const Grid &grid);
  bool Any() const { return any_; }
  bool Periodic(int d) const { return periodic_[d]; }
  PetscReal Length(int d) const { return length_[d]; }
  // The shift of image k; zero in the directions that are not periodic.
  const PetscReal *Shift(int k) const { return shift_[k]; }
  // Whether image k exists: no shift in a direction that is not periodic.
  bool Valid(int k) const { return valid_[k]; }

  // Moves the n positions x (x,y,z each) that lie outside the box in a periodic direction back in
  // by one box length; returns how many moved.
  PetscInt Wrap(PetscInt n, PetscReal *x) const;

  // Input check: a contact must see only one image of each partner, so every periodic length must
  // be at least twice the neighbour cut-off; and DMSwarmMigrate reaches only neighbouring ranks, so a
  // particle that wraps must land on a neighbour: at most 2 ranks along a periodic direction.
  PetscErrorCode Check(MPI_Comm comm, PetscReal cutoff, const char *cutoffText) const;
  PetscErrorCode CheckRanks(const Grid &grid) const;

  // The image code of each pair of the list (lower id "a" first, indices below nLocal local, the
  // others ghosts with image codes ghostImage): the shift to add to x_a - x_b.
  static void PairImages(const NeighbourList &list, PetscInt nLocal, const unsigned char *ghostImage, std::vector<unsigned char> *pairImage);

private:
  bool      any_ = false, periodic_[3] = {false, false, false}, valid_[kCount] = {};
  PetscReal lower_[3] = {0, 0, 0}, upper_[3] = {0, 0, 0}, length_[3] = {0, 0, 0};
  PetscReal shift_[kCount][3] = {};
};

}  // namespace vofdem
