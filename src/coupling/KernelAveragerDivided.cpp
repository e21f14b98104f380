// The divided shape of KernelAverager (-coupling_kernel divided, Kernel.hpp): unresolved CFD-DEM with the particle's
// volume shared among the cells it overlaps instead of given whole to the cell of its centre (CFDEM's "divided" void
// fraction model). With a few particles per cell the centred rule makes eps jump by a sphere's volume whenever a centre
// crosses a face, which a packed bed at cell 2 d shows as a noisy pressure drop (results/c2-packed-bed.md). Here the
// sphere is 32 equal cubes of side R/2, and each cube's volume goes to the cells it overlaps in proportion to the
// overlap: eps is a continuous (piecewise linear) function of the particle's position. (CFDEM gives each sample point
// whole to the cell of its centre; then eps still jumps, by a 32nd of the volume, whenever a point crosses a face, and
// d(eps)/dt in the continuity turns a particle rattling by nanometres across a face into a pressure impulse that
// pushes it back: a relay, which held a packed bed in a 3-cycle of its drop, 106 / 118 / 111 Pa; results/c2-packed-bed.md.)
// The same weights serve the force deposit and the reads, so K3's conservation and the adjointness of deposit and
// read hold as in the unresolved mode.
#include "vofdem/coupling/KernelAverager.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace {

// Sample points of a unit sphere, each standing for an equal volume: the centres of the cubes of side 1/2 of the
// lattice (+-1/4, +-3/4)^3 that lie inside it (eight with all coordinates +-1/4, 24 with one +-3/4): symmetric about
// the three axes, so a sphere centred in a cell gives it all its volume and one centred on a face gives each side half.
constexpr int kPoints = 32;
struct Samples {
  PetscReal p[kPoints][3];
  Samples() {
    int n = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 4; ++c) {
          const PetscReal o[3] = {-0.75 + 0.5 * a, -0.75 + 0.5 * b, -0.75 + 0.5 * c};
          if (o[0] * o[0] + o[1] * o[1] + o[2] * o[2] > 1) continue;
          for (int e = 0; e < 3; ++e) p[n][e] = o[e];
          ++n;
        }
  }
};
const Samples kSamples;

// The fraction of [lo, hi] (in cells) inside cell c.
inline PetscReal Overlap(PetscReal lo, PetscReal hi, PetscInt c) { return (std::min(hi, (PetscReal)(c + 1)) - std::max(lo, (PetscReal)c)) / (hi - lo); }

}  // namespace

bool KernelAverager::GatherDivided(int loc, const PetscReal x[3], PetscReal R, Points &pts) const {
  const Grid      &grid = sg_->Base();
  const PetscReal *h    = grid.Spacing();
  PetscReal        lo[kPoints][3], hi[kPoints][3];  // each cube's extent along each axis, in cells
  PetscInt         q0[3], q1[3];
  PetscInt         wallAt[2] = {PETSC_MIN_INT, PETSC_MIN_INT};  // the wall-face indices along loc (as Gather)
  for (int e = 0; e < 3; ++e) {
    const PetscInt Nc = grid.Cells()[e];
    PetscReal      c  = (x[e] - grid.Lower()[e]) / h[e];  // in cells
    if (grid.Periodic(e)) {  // the image nearest this rank's points (as Gather)
      const PetscReal s = c - (loc == e ? 0 : 0.5), mid = gs_[loc][e] + 0.5 * gm_[loc][e];
      if (s - mid > 0.5 * Nc) c -= Nc;
      else if (s - mid < -0.5 * Nc) c += Nc;
    } else if (loc == e) wallAt[0] = 0, wallAt[1] = sg_->Points(loc, e) - 1;
    const PetscReal half = 0.25 * R / h[e];  // half the cube's side R/2
    q0[e] = PETSC_MAX_INT, q1[e] = PETSC_MIN_INT;
    for (int p = 0; p < kPoints; ++p) {
      const PetscReal at = c + R * kSamples.p[p][e] / h[e];
      lo[p][e] = at - half, hi[p][e] = at + half;
      PetscInt c0 = (PetscInt)std::floor(lo[p][e]), c1 = (PetscInt)std::floor(hi[p][e]);
      if (!grid.Periodic(e)) c0 = std::min(std::max(c0, (PetscInt)0), Nc - 1), c1 = std::min(std::max(c1, (PetscInt)0), Nc - 1);
      q0[e] = std::min(q0[e], c0);
      q1[e] = std::max(q1[e], loc == e ? c1 + 1 : c1);  // a cell's two faces along its own direction
    }
    if (q0[e] < gs_[loc][e] || q1[e] >= gs_[loc][e] + gm_[loc][e]) return false;
  }
  const PetscInt nx = q1[0] - q0[0] + 1, ny = q1[1] - q0[1] + 1, box = nx * ny * (q1[2] - q0[2] + 1);
  if (pts.raw.size() < (size_t)box) {  // grown once, reused
    pts.offsets.resize(box);
    pts.raw.resize(box);
    pts.wall.resize(box);
  }
  if (pts.dx2.size() < (size_t)box) pts.dx2.resize(box);
  PetscReal *w = pts.dx2.data();  // the box's weights (dx2 is the kernel shapes' scratch)
  std::fill(w, w + box, 0.0);
  const PetscInt step = loc == 0 ? 1 : loc == 1 ? nx : nx * ny;  // to a cell's upper face along loc
  const PetscInt *N = grid.Cells();
  auto            clampCell = [&](int e, PetscInt c) { return grid.Periodic(e) ? c : std::min(std::max(c, (PetscInt)0), N[e] - 1); };
  for (int p = 0; p < kPoints; ++p) {
    // The cube's share of each cell it overlaps: the product of the overlaps along the axes (a cell beyond a
    // wall gives its share to the cell at the wall, as a point beyond it went to that cell).
    PetscInt c0[3], c1[3];
    for (int e = 0; e < 3; ++e) c0[e] = (PetscInt)std::floor(lo[p][e]), c1[e] = (PetscInt)std::floor(hi[p][e]);
    if (c0[0] == c1[0] && c0[1] == c1[1] && c0[2] == c1[2]) {  // inside one cell: most cubes when cells are larger than R/2
      const PetscInt at = (clampCell(0, c0[0]) - q0[0]) + nx * ((clampCell(1, c0[1]) - q0[1]) + ny * (clampCell(2, c0[2]) - q0[2]));
      w[at] += 1;
      if (loc != 3) w[at + step] += 1;  // the unresolved rule per cube: both faces of its cell along loc
      continue;
    }
    for (PetscInt k = c0[2]; k <= c1[2]; ++k) {
      const PetscReal fz = Overlap(lo[p][2], hi[p][2], k);
      if (fz <= 0) continue;
      for (PetscInt j = c0[1]; j <= c1[1]; ++j) {
        const PetscReal fy = Overlap(lo[p][1], hi[p][1], j);
        if (fy <= 0) continue;
        for (PetscInt i = c0[0]; i <= c1[0]; ++i) {
          const PetscReal fx = Overlap(lo[p][0], hi[p][0], i);
          if (fx <= 0) continue;
          const PetscInt  at = (clampCell(0, i) - q0[0]) + nx * ((clampCell(1, j) - q0[1]) + ny * (clampCell(2, k) - q0[2]));
          const PetscReal f  = fx * fy * fz;
          w[at] += f;
          if (loc != 3) w[at + step] += f;
        }
      }
    }
  }
  const PetscInt sy = gm_[loc][0], sz = gm_[loc][0] * gm_[loc][1];
  PetscReal      all = 0, inner = 0;
  size_t         m = 0;
  for (PetscInt k = q0[2]; k <= q1[2]; ++k)
    for (PetscInt j = q0[1]; j <= q1[1]; ++j) {
      const bool     rowWall = (loc == 1 && (j == wallAt[0] || j == wallAt[1])) || (loc == 2 && (k == wallAt[0] || k == wallAt[1]));
      const PetscInt base    = (j - gs_[loc][1]) * sy + (k - gs_[loc][2]) * sz - gs_[loc][0];
      for (PetscInt i = q0[0]; i <= q1[0]; ++i) {
        const PetscReal wi = w[(i - q0[0]) + nx * ((j - q0[1]) + ny * (k - q0[2]))];
        if (wi > 0) Append(base + i, wi, rowWall || (loc == 0 && (i == wallAt[0] || i == wallAt[1])), pts.offsets.data(), pts.raw.data(), pts.wall.data(), m, all, inner);
      }
    }
  pts.n = m, pts.sumAll = all, pts.sumInner = inner;
  return true;
}

}  // namespace vofdem
