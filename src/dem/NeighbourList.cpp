#include "vofdem/dem/NeighbourList.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

PetscErrorCode NeighbourList::Build(PetscInt nLocal, const PetscReal *xLocal, const PetscReal *rLocal, const PetscReal *mLocal,
                                    const PetscInt64 *idLocal, PetscInt nGhost, const PetscReal *xGhost, const PetscReal *rGhost,
                                    const PetscReal *mGhost, const PetscInt64 *idGhost, PetscReal cutoff, PetscReal skin,
                                    const PetscReal lo[3], const PetscReal hi[3], const PairTags &tags) {
  PetscFunctionBeginUser;
  const PetscInt n = nLocal + nGhost;
  PetscInt       nc[3];
  PetscReal      origin[3], inv[3];
  // Cells as wide as the reach of the smallest pair, 2 r_min + skin, but not below a quarter of the
  // cut-off 2 r_max + skin: with one size they are the cut-off wide and the stencil is 3x3x3; in a
  // polydisperse bed a small sphere then searches only the cells it can reach (r_i + r_max + skin)
  // instead of 27 cells sized for the largest pair, which hold many small spheres each.
  PetscReal rMin = PETSC_MAX_REAL;
  for (PetscInt p = 0; p < nLocal; ++p) rMin = std::min(rMin, rLocal[p]);
  for (PetscInt g = 0; g < nGhost; ++g) rMin = std::min(rMin, rGhost[g]);
  const PetscReal rMax  = 0.5 * (cutoff - skin);
  const PetscReal width = n ? std::min(cutoff, std::max(2 * rMin + skin, 0.25 * cutoff)) : cutoff;
  for (int d = 0; d < 3; ++d) {
    origin[d]           = lo[d] - cutoff;
    const PetscReal len = hi[d] - lo[d] + 2 * cutoff;
    nc[d]               = std::max<PetscInt>(1, std::min<PetscInt>((PetscInt)(len / width), 1024));  // cells at least `width` wide
    inv[d]              = nc[d] / len;
  }
  auto pos = [&](PetscInt p) { return p < nLocal ? &xLocal[3 * p] : &xGhost[3 * (p - nLocal)]; };
  auto cellOf = [&](const PetscReal *x, PetscInt c[3]) {
    for (int d = 0; d < 3; ++d) c[d] = std::min(nc[d] - 1, std::max<PetscInt>(0, (PetscInt)((x[d] - origin[d]) * inv[d])));
  };
  // Only the block of that lattice that holds particles is stored: a dilute scene (a pour, a stream
  // into a box) would otherwise clear and sum some 300,000 empty cells at every rebuild. The cells are
  // the same, so the lists are too, pair for pair and in the same order.
  PetscInt cmin[3] = {0, 0, 0}, cmax[3] = {0, 0, 0}, ns[3];
  for (PetscInt p = 0; p < n; ++p) {
    PetscInt c[3];
    cellOf(pos(p), c);
    for (int d = 0; d < 3; ++d) {
      cmin[d] = p ? std::min(cmin[d], c[d]) : c[d];
      cmax[d] = p ? std::max(cmax[d], c[d]) : c[d];
    }
  }
  for (int d = 0; d < 3; ++d) ns[d] = cmax[d] - cmin[d] + 1;
  // Counting sort of particles by cell (CSR: cellStart_, order_).
  const PetscInt ncell = ns[0] * ns[1] * ns[2];
  cellStart_.assign(ncell + 1, 0);
  cellOf_.resize(n);
  order_.resize(n);
  for (PetscInt p = 0; p < n; ++p) {
    PetscInt c[3];
    cellOf(pos(p), c);
    cellOf_[p] = (c[0] - cmin[0]) + ns[0] * ((c[1] - cmin[1]) + ns[1] * (c[2] - cmin[2]));
    ++cellStart_[cellOf_[p] + 1];
  }
  for (PetscInt c = 0; c < ncell; ++c) cellStart_[c + 1] += cellStart_[c];
  auto rad = [&](PetscInt p) { return p < nLocal ? rLocal[p] : rGhost[p - nLocal]; };
  // Positions and radii copied in cell order too: the candidates of a cell are then read from one
  // stretch of memory, not gathered from the local and ghost arrays (the gather was most of Build).
  packed_.resize(n);
  {
    std::vector<PetscInt> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (PetscInt p = 0; p < n; ++p) {
      const PetscInt k = fill[cellOf_[p]]++;
      const PetscReal *x = pos(p);
      order_[k]  = p;
      packed_[k] = {x[0], x[1], x[2], rad(p)};
    }
  }
  first.clear();
  second.clear();
  const bool clumped = tags.clumpLocal != nullptr;
  for (PetscInt i = 0; i < nLocal; ++i) {
    const PetscReal *xi = pos(i), ri = rLocal[i] + skin;
    const PetscInt64 clumpI = clumped ? tags.clumpLocal[i] : -1;
    PetscInt         c[3], span[3];
    cellOf(xi, c);
    // Stencil half-width in cells: a partner within r_i + r_max + skin lies at most ceil(reach / width) cells away.
    for (int d = 0; d < 3; ++d) span[d] = std::max<PetscInt>(1, (PetscInt)std::ceil((ri + rMax) * inv[d]));
    // The cells of a row along x are consecutive, and so are their particles in order_: one range per
    // row (the per-cell loop over mostly empty small cells was most of Build's time).
    const PetscInt x0 = std::max(cmin[0], c[0] - span[0]) - cmin[0], x1 = std::min(cmax[0], c[0] + span[0]) - cmin[0];
    for (PetscInt dz = -span[2]; dz <= span[2]; ++dz)
      for (PetscInt dy = -span[1]; dy <= span[1]; ++dy) {
        const PetscInt cy = c[1] + dy, cz = c[2] + dz;
        if (cy < cmin[1] || cz < cmin[2] || cy > cmax[1] || cz > cmax[2]) continue;
        const PetscInt row = ns[0] * ((cy - cmin[1]) + ns[1] * (cz - cmin[2]));
        for (PetscInt k = cellStart_[row + x0], end = cellStart_[row + x1 + 1]; k < end; ++k) {
          const PetscInt j = order_[k];
          if (j < nLocal && j <= i) continue;  // each local pair once; ghost pairs from the local side
          if (clumped && clumpI >= 0 && clumpI == (j < nLocal ? tags.clumpLocal[j] : tags.clumpGhost[j - nLocal])) continue;  // one rigid body (P10)
          const PetscReal *xj = packed_[k].data();
          const PetscReal  ex = xi[0] - xj[0], ey = xi[1] - xj[1], ez = xi[2] - xj[2], c = ri + xj[3];
          if (ex * ex + ey * ey + ez * ez < c * c) {
            first.push_back(i);
            second.push_back(j);
          }
        }
      }
  }
  spring.assign(kSpringWidth * first.size(), 0);
  touching.assign(first.size(), 0);
  rstar.resize(first.size());
  sqrtMstar.resize(first.size());
  material.assign(first.size(), 0);
  for (size_t k = 0; k < first.size(); ++k) {
    // Lower global id first (see the header).
    const PetscInt64 idi = idLocal[first[k]], idj = second[k] < nLocal ? idLocal[second[k]] : idGhost[second[k] - nLocal];
    if (idi > idj) std::swap(first[k], second[k]);
    const PetscInt  i = first[k], j = second[k];
    const PetscReal ri = i < nLocal ? rLocal[i] : rGhost[i - nLocal], mi = i < nLocal ? mLocal[i] : mGhost[i - nLocal];
    const PetscReal rj = j < nLocal ? rLocal[j] : rGhost[j - nLocal], mj = j < nLocal ? mLocal[j] : mGhost[j - nLocal];
    rstar[k]     = ri * rj / (ri + rj);
    sqrtMstar[k] = std::sqrt(mi * mj / (mi + mj));
    if (tags.typeLocal) {
      const PetscInt ti = i < nLocal ? tags.typeLocal[i] : tags.typeGhost[i - nLocal], tj = j < nLocal ? tags.typeLocal[j] : tags.typeGhost[j - nLocal];
      material[k] = ti * tags.typeCount + tj;
    }
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
