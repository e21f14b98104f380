// ParticleBeam.hpp: the beam's rays and the particles that take them (docs/physics.md P11, F8).
#include "vofdem/coupling/ParticleBeam.hpp"

#include <petscdmda.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace vofdem {

PetscErrorCode ParticleBeam::Trace(PetscReal t, PetscInt n, const PetscReal *x, const PetscReal *r, PetscReal *power, std::vector<PetscReal> *taken) {
  const PetscReal *h = grid_->Spacing(), *lo = grid_->Lower();
  const PetscInt  *N = grid_->Cells();
  PetscInt         s[3], m[3];
  PetscMPIInt      rank;

  PetscFunctionBeginUser;
  PetscCall(DMDAGetCorners(grid_->CellDM(), &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  PetscCallMPI(MPI_Comm_rank(grid_->Comm(), &rank));
  taken->assign((size_t)m[0] * m[1], 0);
  std::fill(power, power + n, 0);
  intercepted_ = absorbed_ = 0, rays_ = 0;
  const PetscReal P = laser_->On() ? laser_->Power(t) : 0;
  PetscReal       rmin = PETSC_MAX_REAL;
  for (PetscInt p = 0; p < n; ++p) rmin = std::min(rmin, r[p]);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &rmin, 1, MPIU_REAL, MPI_MIN, grid_->Comm()));
  if (P == 0 || rmin == PETSC_MAX_REAL) PetscFunctionReturn(0);  // no beam, or no particle anywhere
  // The columns within 3 R of the centre, and the rays' sub-grid: ns per cell edge.
  const PetscReal R = laser_->Radius();
  PetscReal       cx, cy;
  laser_->Centre(t, &cx, &cy);
  PetscInt c0[2], c1[2];
  const PetscReal centre[2] = {cx, cy};
  for (int d = 0; d < 2; ++d) {
    c0[d] = std::max((PetscInt)0, (PetscInt)std::floor((centre[d] - 3 * R - lo[d]) / h[d]));
    c1[d] = std::min(N[d], (PetscInt)std::ceil((centre[d] + 3 * R - lo[d]) / h[d]));  // exclusive
    if (c1[d] <= c0[d]) PetscFunctionReturn(0);  // the beam's support misses the box
  }
  PetscInt ns = raysPerCell_;
  if (ns <= 0) ns = (PetscInt)std::ceil(16 * std::max(h[0], h[1]) / std::min(rmin, R));
  const PetscInt cols = (c1[0] - c0[0]) * (c1[1] - c0[1]);
  ns = std::max((PetscInt)1, std::min(ns, (PetscInt)std::floor(std::sqrt((PetscReal)(1 << 22) / cols))));  // at most ~4e6 rays
  const PetscInt  NX = (c1[0] - c0[0]) * ns, NY = (c1[1] - c0[1]) * ns;
  const PetscReal hs[2] = {h[0] / ns, h[1] / ns}, x0 = lo[0] + c0[0] * h[0], y0 = lo[1] + c0[1] * h[1];
  // Only the rays some particle's disc reaches take part: the block of the rays' sub-grid that holds every rank's
  // footprints (the union's bounding box), so the exchange below is the stream's size, not the beam's (3 R around
  // the centre, 7e5 rays in config/scenes/nozzle-track-reduced.yaml, where the dense exchange was the particle heat's
  // largest cost on 2 ranks). The rays outside it have no hit.
  auto footprint = [&](PetscInt p, PetscInt *i0, PetscInt *i1, PetscInt *j0, PetscInt *j1) {
    const PetscReal px = x[3 * p], py = x[3 * p + 1], rp = r[p];
    *i0 = std::max((PetscInt)0, (PetscInt)std::floor((px - rp - x0) / hs[0] - 0.5)), *i1 = std::min(NX, (PetscInt)std::ceil((px + rp - x0) / hs[0] + 0.5));
    *j0 = std::max((PetscInt)0, (PetscInt)std::floor((py - rp - y0) / hs[1] - 0.5)), *j1 = std::min(NY, (PetscInt)std::ceil((py + rp - y0) / hs[1] + 0.5));
  };
  PetscInt box[4] = {NX, NY, 0, 0};  // lowest i, j (as minima), then -highest i1, j1 (as minima of the negatives)
  for (PetscInt p = 0; p < n; ++p) {
    PetscInt i0, i1, j0, j1;
    footprint(p, &i0, &i1, &j0, &j1);
    if (i1 <= i0 || j1 <= j0) continue;
    box[0] = std::min(box[0], i0), box[1] = std::min(box[1], j0), box[2] = std::min(box[2], -i1), box[3] = std::min(box[3], -j1);
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, box, 4, MPIU_INT, MPI_MIN, grid_->Comm()));
  const PetscInt bi0 = box[0], bj0 = box[1], BX = -box[2] - bi0, BY = -box[3] - bj0;
  if (BX <= 0 || BY <= 0) PetscFunctionReturn(0);  // no disc over the beam's rays
  rays_ = BX * BY;
  hit_.assign((size_t)rays_, Hit{-DBL_MAX, (int)rank});
  owner_.assign((size_t)rays_, -1);
  cover_.assign((size_t)rays_, 0);
  // This rank's particles: over each ray the disc reaches, its highest point there (the centre's height at the
  // disc's rim) and the share of the ray's square inside the disc, c = clamp((r - rho)/w + 1/2, 0, 1) with w the
  // square's width across the rim (second order in the ray's size: the binary test of the centre was first order).
  for (PetscInt p = 0; p < n; ++p) {
    const PetscReal px = x[3 * p], py = x[3 * p + 1], pz = x[3 * p + 2], rp = r[p];
    PetscInt        i0, i1, j0, j1;
    footprint(p, &i0, &i1, &j0, &j1);
    for (PetscInt j = j0; j < j1; ++j) {
      const PetscReal dy = y0 + (j + 0.5) * hs[1] - py;
      for (PetscInt i = i0; i < i1; ++i) {
        const PetscReal dx = x0 + (i + 0.5) * hs[0] - px, d2 = dx * dx + dy * dy, rho = std::sqrt(d2);
        const PetscReal w = rho > 0 ? (hs[0] * std::fabs(dx) + hs[1] * std::fabs(dy)) / rho : hs[0];
        const PetscReal c = std::min((PetscReal)1, std::max((PetscReal)0, (rp - rho) / w + 0.5));
        if (c <= 0) continue;
        const double top = pz + std::sqrt(std::max((PetscReal)0, rp * rp - d2));
        const size_t k   = (size_t)((j - bj0) * BX + (i - bi0));
        if (top > hit_[k].z) hit_[k].z = top, owner_[k] = p, cover_[k] = c;
      }
    }
  }
  // The block's columns (ns x ns rays each): those where several ranks have a disc need the highest hit over the
  // ranks (a MAXLOC over their rays); in the others the one rank with a disc there decides alone. So the exchange is
  // the rays of the shared columns only (the columns along a rank boundary the stream crosses), and the sums of what
  // the winners took per column.
  const PetscInt ci0 = bi0 / ns, cj0 = bj0 / ns, nci = (bi0 + BX - 1) / ns - ci0 + 1, ncj = (bj0 + BY - 1) / ns - cj0 + 1;
  auto           column = [&](PetscInt i, PetscInt j) { return (size_t)((j / ns - cj0) * nci + (i / ns - ci0)); };
  std::vector<PetscInt> shared((size_t)nci * ncj, 0);
  for (PetscInt j = bj0; j < bj0 + BY; ++j)
    for (PetscInt i = bi0; i < bi0 + BX; ++i)
      if (owner_[(size_t)((j - bj0) * BX + (i - bi0))] >= 0) shared[column(i, j)] = 1;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, shared.data(), (int)shared.size(), MPIU_INT, MPI_SUM, grid_->Comm()));
  std::vector<size_t> sharedRays;  // block indices of the shared columns' rays, in one order on every rank
  for (PetscInt j = bj0; j < bj0 + BY; ++j)
    for (PetscInt i = bi0; i < bi0 + BX; ++i)
      if (shared[column(i, j)] > 1) sharedRays.push_back((size_t)((j - bj0) * BX + (i - bi0)));
  const size_t ns2 = sharedRays.size();
  std::vector<Hit> mineHit(ns2);
  best_.resize(ns2);
  for (size_t q = 0; q < ns2; ++q) mineHit[q] = hit_[sharedRays[q]];
  if (ns2) PetscCallMPI(MPI_Allreduce(mineHit.data(), best_.data(), (int)ns2, MPI_DOUBLE_INT, MPI_MAXLOC, grid_->Comm()));
  for (size_t q = 0; q < ns2; ++q)
    if (best_[q].rank != rank) owner_[sharedRays[q]] = -1;  // another rank's disc is higher there
  // Each ray's power, separable: P/4 [erf]_x [erf]_y over its square; what this rank's winners take, per column.
  const PetscReal        sq = std::sqrt((PetscReal)2) / R;
  std::vector<PetscReal> ex((size_t)NX), ey((size_t)NY);
  for (PetscInt i = 0; i < NX; ++i) ex[(size_t)i] = ErfDifference(sq * (x0 + i * hs[0] - cx), sq * (x0 + (i + 1) * hs[0] - cx));
  for (PetscInt j = 0; j < NY; ++j) ey[(size_t)j] = ErfDifference(sq * (y0 + j * hs[1] - cy), sq * (y0 + (j + 1) * hs[1] - cy));
  std::vector<PetscReal> sums((size_t)nci * ncj + 2, 0);  // per block column what was taken; then intercepted, absorbed
  for (PetscInt j = bj0; j < bj0 + BY; ++j)
    for (PetscInt i = bi0; i < bi0 + BX; ++i) {
      const size_t   k = (size_t)((j - bj0) * BX + (i - bi0));
      const PetscInt p = owner_[k];
      if (p < 0) continue;  // no disc of this rank wins this ray
      const PetscReal pr = cover_[k] * 0.25 * P * ex[(size_t)i] * ey[(size_t)j];  // what the highest disc takes
      sums[column(i, j)] += pr;
      sums[sums.size() - 2] += pr;
      power[p] += eta_ * pr;
      sums[sums.size() - 1] += eta_ * pr;
    }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums.data(), (int)sums.size(), MPIU_REAL, MPI_SUM, grid_->Comm()));
  intercepted_ = sums[sums.size() - 2], absorbed_ = sums[sums.size() - 1];
  for (PetscInt cj = 0; cj < ncj; ++cj)
    for (PetscInt ci = 0; ci < nci; ++ci) {
      const PetscInt gx = c0[0] + ci0 + ci, gy = c0[1] + cj0 + cj;
      if (gx >= s[0] && gx < s[0] + m[0] && gy >= s[1] && gy < s[1] + m[1]) (*taken)[(size_t)((gy - s[1]) * m[0] + (gx - s[0]))] += sums[(size_t)(cj * nci + ci)];
    }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
