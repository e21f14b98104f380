// Binning of a triangle mesh for the mesh walls' candidate search (TriangleBins.hpp).
#include "vofdem/dem/TriangleBins.hpp"

#include "vofdem/dem/WallGeometry.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

void TriangleBins::Build(const PetscReal *corner, PetscInt triangles, const PetscReal lo[3], const PetscReal hi[3], PetscReal reach) {
  reach_ = reach;
  // Cells about twice the reach (a particle's neighbourhood), at most 64 per direction.
  PetscReal extent = 0;
  for (int d = 0; d < 3; ++d) lo_[d] = lo[d] - reach, extent = std::max(extent, hi[d] - lo[d] + 2 * reach);
  const PetscReal target = std::max(2 * reach, extent / 64);
  PetscReal       halfDiagonal2 = 0;
  for (int d = 0; d < 3; ++d) {
    const PetscReal len = hi[d] - lo[d] + 2 * reach;
    n_[d]               = std::max(1, std::min(64, (int)std::ceil(len / target)));
    h_[d]               = len > 0 ? len / n_[d] : 1;  // a flat mesh with no reach: one layer of cells
    halfDiagonal2 += 0.25 * h_[d] * h_[d];
  }
  // (a hair more than the half diagonal: a point on a cell's face may round into its neighbour)
  const PetscReal       within = reach + std::sqrt(halfDiagonal2) * (1 + 1e-9);
  const size_t          cells  = (size_t)n_[0] * n_[1] * n_[2];
  std::vector<PetscInt> count(cells + 1, 0);
  // Two sweeps over the same (triangle, cell) pairs: count, then fill; triangles in increasing order.
  auto sweep = [&](auto &&take) {
    for (PetscInt t = 0; t < triangles; ++t) {
      const PetscReal *c = &corner[9 * t];
      int              c0[3], c1[3];
      for (int d = 0; d < 3; ++d) {
        const PetscReal a = std::min({c[d], c[3 + d], c[6 + d]}) - within, b = std::max({c[d], c[3 + d], c[6 + d]}) + within;
        c0[d] = std::max(0, (int)std::floor((a - lo_[d]) / h_[d]));
        c1[d] = std::min(n_[d] - 1, (int)std::floor((b - lo_[d]) / h_[d]));
      }
      for (int k = c0[2]; k <= c1[2]; ++k)
        for (int j = c0[1]; j <= c1[1]; ++j)
          for (int i = c0[0]; i <= c1[0]; ++i) {
            const PetscReal x[3] = {lo_[0] + (i + 0.5) * h_[0], lo_[1] + (j + 0.5) * h_[1], lo_[2] + (k + 0.5) * h_[2]};
            PetscReal       q[3];
            int             which;
            wall::ClosestOnTriangle(c, c + 3, c + 6, x, q, &which);
            const PetscReal s[3] = {x[0] - q[0], x[1] - q[1], x[2] - q[2]};
            if (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] <= within * within) take(((size_t)k * n_[1] + j) * n_[0] + i, t);
          }
    }
  };
  sweep([&](size_t cell, PetscInt) { ++count[cell + 1]; });
  for (size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
  start_ = count;
  items_.assign((size_t)start_[cells], 0);
  sweep([&](size_t cell, PetscInt t) { items_[(size_t)count[cell]++] = t; });
}

}  // namespace vofdem
