// A uniform cell hash of spheres in a box for "does a new sphere overlap any stored one?" queries
// in O(1) expected time: cells at least the largest diameter wide, so a sphere can only touch the
// spheres of its own and the 26 neighbouring cells. Used by the random fill and by insertion.
// Spheres outside the box are clamped into its border cells (still found, just less selectively).
// Along a periodic direction of the domain (SetPeriodic) spheres also meet across its faces: a query
// near a face is repeated at its image one period away (the stored spheres are not copied).
#pragma once

#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vofdem {

class SphereHash {
public:
  // Box [lo, hi]; cells at least `minCell` wide, and at most about `maxCells` of them in all.
  void Reset(const PetscReal lo[3], const PetscReal hi[3], PetscReal minCell, double maxCells) {
    double volume = 1;
    for (int d = 0; d < 3; ++d) volume *= std::max(hi[d] - lo[d], minCell);
    const PetscReal cell = std::max(minCell, (PetscReal)std::cbrt(volume / std::max(1.0, maxCells)));
    for (int d = 0; d < 3; ++d) {
      lo_[d]   = lo[d];
      n_[d]    = std::max(1, (int)std::floor((hi[d] - lo[d]) / cell));
      inv_[d]  = n_[d] / std::max(hi[d] - lo[d], (PetscReal)1e-300);
    }
    head_.assign((size_t)n_[0] * n_[1] * n_[2], -1);
    next_.clear(), x_.clear(), r_.clear();
    for (int d = 0; d < 3; ++d) period_[d] = 0;
    rMax_ = 0, outside_ = 0;
  }
  // After Reset: direction d of the domain is periodic with faces lo and hi (the hash's own box must
  // then hold the stored spheres on both sides, within a query's reach of the faces).
  void SetPeriodic(int d, PetscReal lo, PetscReal hi) { faceLo_[d] = lo, period_[d] = hi - lo; }
  void Reserve(size_t n) { next_.reserve(n), x_.reserve(3 * n), r_.reserve(n); }
  void Add(const PetscReal x[3], PetscReal r) {
    const size_t c = CellOf(x);
    rMax_          = std::max(rMax_, r);
    for (int d = 0; d < 3; ++d)  // how far a stored centre lies past a periodic face (moved since its last wrap)
      if (period_[d] > 0) outside_ = std::max({outside_, faceLo_[d] - x[d], x[d] - faceLo_[d] - period_[d]});
    next_.push_back(head_[c]);
    head_[c] = (PetscInt)r_.size();
    x_.insert(x_.end(), x, x + 3);
    r_.push_back(r);
  }
  // True when a sphere at x with radius r would overlap a stored one (touching does not count).
  bool Overlaps(const PetscReal x[3], PetscReal r) const {
    if (!(period_[0] > 0 || period_[1] > 0 || period_[2] > 0)) return OverlapsAt(x, r);
    // The query's images within reach (r + the largest stored radius + how far a stored centre lies
    // past a face) of a periodic face: up to 3 per direction, 27 in all.
    const PetscReal reach = r + rMax_ + outside_;
    PetscReal       shifts[3][3];
    int             count[3];
    for (int d = 0; d < 3; ++d) {
      shifts[d][0] = 0, count[d] = 1;
      if (!(period_[d] > 0)) continue;
      if (x[d] - faceLo_[d] < reach) shifts[d][count[d]++] = period_[d];
      if (faceLo_[d] + period_[d] - x[d] < reach) shifts[d][count[d]++] = -period_[d];
    }
    for (int k = 0; k < count[2]; ++k)
      for (int j = 0; j < count[1]; ++j)
        for (int i = 0; i < count[0]; ++i) {
          const PetscReal y[3] = {x[0] + shifts[0][i], x[1] + shifts[1][j], x[2] + shifts[2][k]};
          if (OverlapsAt(y, r)) return true;
        }
    return false;
  }
  size_t Size() const { return r_.size(); }

private:
  bool OverlapsAt(const PetscReal x[3], PetscReal r) const {
    int c[3];
    for (int d = 0; d < 3; ++d) c[d] = Index(x, d);
    for (int k = std::max(0, c[2] - 1); k <= std::min(n_[2] - 1, c[2] + 1); ++k)
      for (int j = std::max(0, c[1] - 1); j <= std::min(n_[1] - 1, c[1] + 1); ++j)
        for (int i = std::max(0, c[0] - 1); i <= std::min(n_[0] - 1, c[0] + 1); ++i)
          for (PetscInt s = head_[((size_t)k * n_[1] + j) * n_[0] + i]; s >= 0; s = next_[s]) {
            const PetscReal dx = x[0] - x_[3 * s], dy = x[1] - x_[3 * s + 1], dz = x[2] - x_[3 * s + 2], rs = r + r_[s];
            if (dx * dx + dy * dy + dz * dz < rs * rs) return true;
          }
    return false;
  }
  int    Index(const PetscReal x[3], int d) const { return std::clamp((int)std::floor((x[d] - lo_[d]) * inv_[d]), 0, n_[d] - 1); }
  size_t CellOf(const PetscReal x[3]) const { return ((size_t)Index(x, 2) * n_[1] + Index(x, 1)) * n_[0] + Index(x, 0); }

  PetscReal              lo_[3] = {0, 0, 0}, inv_[3] = {1, 1, 1};
  PetscReal              faceLo_[3] = {0, 0, 0}, period_[3] = {0, 0, 0};  // periodic directions (period 0: not)
  PetscReal              rMax_ = 0, outside_ = 0;                        // largest stored radius; furthest stored centre past a periodic face
  int                    n_[3]  = {1, 1, 1};
  std::vector<PetscInt>  head_, next_;
  std::vector<PetscReal> x_, r_;
};

}  // namespace vofdem
