// A uniform grid over a triangle mesh (in the mesh's reference frame) that tells which triangles a
// point may be within `reach` of: each cell lists, in increasing index order, the triangles whose
// closest point to the cell's centre is within reach + the cell's half diagonal. Any triangle within
// reach of a point of the cell is then listed (triangle inequality), so a search through the cell's
// list finds exactly what a search through all triangles finds, in the same order. The candidate
// search of the mesh walls (WallSet::BuildCandidates) used to test every particle near the mesh's
// bounding box against every triangle: O(particles x triangles) per rebuild, 9 % of a funnel run's
// time with 576 triangles.
#pragma once

#include <petscsys.h>

#include <vector>

namespace vofdem {

class TriangleBins {
public:
  // corner: 9 coordinates per triangle; lo, hi: the mesh's bounding box; reach: the largest distance
  // a query will ask about (the bins must be built again for a larger one).
  void Build(const PetscReal *corner, PetscInt triangles, const PetscReal lo[3], const PetscReal hi[3], PetscReal reach);
  PetscReal Reach() const { return reach_; }
  // The triangles that may lie within Reach() of x (a point in the box grown by Reach()): [*begin, *end).
  void Near(const PetscReal x[3], const PetscInt **begin, const PetscInt **end) const {
    int c[3];
    for (int d = 0; d < 3; ++d) {
      const int i = (int)((x[d] - lo_[d]) / h_[d]);
      c[d]        = i < 0 ? 0 : i >= n_[d] ? n_[d] - 1 : i;
    }
    const size_t cell = ((size_t)c[2] * n_[1] + c[1]) * n_[0] + c[0];
    *begin = items_.data() + start_[cell], *end = items_.data() + start_[cell + 1];
  }

private:
  PetscReal             lo_[3] = {0, 0, 0}, h_[3] = {1, 1, 1}, reach_ = -1;
  int                   n_[3] = {1, 1, 1};
  std::vector<PetscInt> start_, items_;
};

}  // namespace vofdem
