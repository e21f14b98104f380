// A separable discrete Gaussian on one staggered location of the grid: the explicit alternative to the
// diffusion in DiffusionSmoother (docs/physics.md K1, K3). v <- G_z G_y G_x v, each G_e a 1-D convolution
// with 2 R_e + 1 taps g_t ~ exp(-(t h_e)^2 / (2 b^2)), normalised to sum 1, b chosen so that the taps'
// discrete variance sum_t (t h_e)^2 g_t is exactly the spread asked for (variances add under
// convolution, so tent deposit + filter has the kernel's variance to round-off, not only on average
// over a long pseudo-time as backward Euler). R_e = ceil(3 sqrt(spread)/h_e) (GaussianFilter.cpp: why 3).
// Why: at cell/d 0.5 the diffusion needs ~30 Chebyshev sweeps per pseudo-step (its spectrum grows as
// (b/h)^2); the filter costs 3 (2R + 1) multiply-adds per point and three ghost updates, no reductions.
// Walls: the active range of each direction (all points; for a velocity component along its own walled
// direction, the faces 1..N-2: the wall faces keep their value and take nothing) is folded onto itself by
// mirrors half a spacing beyond its ends, as often as the taps reach (a narrow box). Each tap lands on
// exactly one point, so every column of G_e sums to one (conservation, K3) and G_e is symmetric (the
// images of j seen from i are those of i seen from j): deposit and average stay adjoint.
// Periodic directions wrap through the DMDA's ghosts. Ghost width max_e R_e on vectors only; a rank
// must hold at least that many points along every direction that is split or periodic.
#pragma once

#include <petscdmda.h>

#include <vector>

namespace vofdem {

class GaussianFilter {
public:
  // location: the location's DMDA (its global vectors are filtered); spread[e]: the variance to add
  // (m^2; <= 0: no filtering along e); lo/hi: the active index range per direction. Collective.
  PetscErrorCode SetUp(DM location, const PetscReal h[3], const PetscReal spread[3], const PetscInt lo[3], const PetscInt hi[3], const bool periodic[3]);
  PetscErrorCode Destroy();
  // v <- G v (v: a global vector of the location). Collective.
  PetscErrorCode Apply(Vec v);
  // The same where only part of it is needed, with the planes (z indices, inclusive) given alike on all
  // ranks: v is zero outside inPlanes, and the result is wanted on outPlanes only. Where the
  // layout allows it (z and y neither split nor periodic, all three directions filtered) the x and y passes
  // run only on the planes the z pass reads and the z pass only on outPlanes: the points there are bitwise those
  // of Apply(v); elsewhere v keeps what it had, partly filtered (zero where the whole result is zero, i.e.
  // outPlanes covering inPlanes widened by the z taps). Otherwise the whole Apply. inPlanes empty (first >
  // last): nothing to do.
  PetscErrorCode Apply(Vec v, const PetscInt inPlanes[2], const PetscInt outPlanes[2]);
  // Whether Apply(v, in, out) restricts the work for this layout.
  bool           Restricts() const { return !needGhosts_[1] && !needGhosts_[2] && !periodic_[2] && R_[0] > 0 && R_[1] > 0 && R_[2] > 0; }
  PetscInt       Radius(int e) const { return R_[e]; }

  // Whether SetUp would accept this layout: every rank holds at least max_e R_e points along each
  // direction that is split or periodic.
  static bool Fits(DM location, const PetscReal h[3], const PetscReal spread[3], const bool periodic[3]);
  // The 2R + 1 taps for spacing h and variance `spread` (R = 0, {1}, when spread <= 0).
  static std::vector<PetscReal> Taps(PetscReal h, PetscReal spread);

private:
  PetscInt Fold(int e, PetscInt j) const {
    if (periodic_[e]) return j;
    while (j < lo_[e] || j > hi_[e]) j = j < lo_[e] ? 2 * lo_[e] - 1 - j : 2 * hi_[e] + 1 - j;
    return j;
  }

  DM                     dm_    = nullptr;  // star stencil of width max R_e, the location's ownership
  Vec                    local_ = nullptr;  // ghosted (directions split across ranks or periodic)
  Vec                    copy_  = nullptr;  // a plain copy (the others)
  bool                   needGhosts_[3] = {false, false, false};
  std::vector<const PetscScalar *> rows_;    // the 2R + 1 source rows of one output row
  std::vector<PetscScalar> ext_;             // one row and R images or ghosts each side (x pass)
  // The x pass's ghosts when x is split or periodic: R_x values at each end of every owned row, exchanged
  // with the x neighbours directly (a ghost update of the DMDA would also copy the whole vector).
  PetscMPIInt              xNeighbour_[2] = {MPI_PROC_NULL, MPI_PROC_NULL};  // left, right
  std::vector<PetscScalar> haloSend_[2], haloRecv_[2];                      // [row * R_x + t]
  PetscErrorCode           ExchangeXHalo(Vec v, const PetscInt s[3], const PetscInt n[3]);
  std::vector<PetscReal> taps_[3];
  PetscInt               R_[3] = {0, 0, 0}, lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0};
  bool                   periodic_[3] = {false, false, false};
};

}  // namespace vofdem
