// Kernel averaging and projection between particles and the MAC grid (docs/physics.md K1-K3).
//  - Deposit (K3): a particle's value (volume, a force component, heat) is shared among the grid
//    points of one staggered location (cells, or the faces of one velocity component) within the
//    kernel's cut-off, with weights normalised over the points that take part, so the grid total
//    equals the particle total to round-off, next to walls (points outside the box, and the wall
//    faces, whose velocity the boundary conditions set, do not take part) and across ranks (the
//    contributions to ghost points are added to their owners).
//  - Average (K1, K2): the kernel-weighted mean of a grid field at a particle, optionally weighted
//    by a second field (the fluid fraction eps, K1; no weight for pressure and velocity gradients, K2).
// Grid points are found by index arithmetic, not by search: the support of a particle at x is the
// index box around (x - lower)/h. The local vectors come from DMDAs with the staggered locations'
// ownership ranges and a BOX ghost layer wide enough for the cut-off plus the distance a particle
// may stray outside its rank's box between migrations; these wide DMDAs carry vectors only, never
// matrices (docs/petsc-notes.md). Unresolved mode: the cell that contains the particle (for faces,
// the two faces of that cell along the component), CFD-DEM's "centre" limit.
#pragma once

#include "vofdem/coupling/Kernel.hpp"
#include "vofdem/grid/StaggeredGrid.hpp"

#include <vector>

namespace vofdem {

class KernelAverager {
public:
  struct Settings {
    kernel::Shape shape      = kernel::Shape::Smooth;
    PetscReal     truncation = 1.5;  // cut-off of the truncated Gaussian, in widths H
    const char   *owner      = "coupling";  // whose options set the kernel (-<owner>_kernel_width), for the input errors
  };

  // maxCutoff: the largest support radius any particle will use (m; ignored when unresolved);
  // margin: how far a particle may lie outside its rank's box (m). Collective.
  PetscErrorCode SetUp(const StaggeredGrid &sg, const Settings &s, PetscReal maxCutoff, PetscReal margin);
  PetscErrorCode Destroy();
  const Settings &GetSettings() const { return settings_; }
  PetscInt        GhostWidth() const { return width_; }
  PetscReal       Cutoff(PetscReal H) const { return kernel::Cutoff(settings_.shape, H, settings_.truncation); }

  // out (a global vector of location loc: 0-2 faces, 3 cells) += the particles' values value[p*stride]
  // shared by the kernel of width H[p] around x[3p..3p+2]. Collective (ghost contributions are
  // summed into their owners). The wall faces of a face location's own direction take no share unless
  // `walls` (the particle forces: a wall face's half control volume takes its share, Coupling.cpp).
  // Points excluded by SetExcludedCells take no share unless `excluded` is true (the heat, which solid metal takes).
  PetscErrorCode Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, const PetscReal *value, PetscInt stride, Vec out, bool walls = false, bool excluded = false);
  // out[p*stride] = sum_J f_J c_J w_pJ / sum_J c_J w_pJ over the points of location loc within the
  // cut-off, c = weight (a global vector of the same location; nullptr: 1). Wall faces take part
  // (their velocity is the wall's) unless `walls` is false. With walls, a wall face counts for the
  // half control volume it has: the tent's and the unresolved mode's weights give it that by
  // themselves (a hat function is cut in half at the box face); a point-sampled kernel (smooth,
  // truncated) gives it half its weight. Collective (ghost update).
  PetscErrorCode Average(int loc, Vec field, Vec weight, PetscInt n, const PetscReal *x, const PetscReal *H, PetscReal *out, PetscInt stride, bool walls = true);
  // Several fields of one location at once (the kernel weights, the costly part, are computed once per
  // particle): value[f] into out[f], or field[f] (weighted by weight[f], walls[f]) into out[f].
  PetscErrorCode Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, PetscInt nf, const PetscReal *const value[], PetscInt stride, Vec out[], bool walls = false,
                         bool excluded = false);
  // Cells a deposit leaves out (KernelAveragerExcluded.cpp): `cells` (the cells' layout; > 0.5: excluded, e.g. solid
  // metal the flow holds at rest; nullptr: none) and the faces beside them. A particle's share is normalised over the
  // points of its support that remain, so its total still reaches the grid to round-off; one whose support is all
  // excluded deposits as without the mask. Averages read every point. Collective; returns the count of cells.
  PetscErrorCode SetExcludedCells(Vec cells, PetscInt *count = nullptr);
  PetscErrorCode Average(int loc, PetscInt nf, const Vec field[], const Vec weight[], const bool walls[], PetscInt n, const PetscReal *x, const PetscReal *H, PetscReal *const out[],
                         PetscInt stride);

private:
  struct Points {  // a particle's support: n local offsets, raw weights, wall-face flags; weight sums
    std::vector<PetscInt>  offsets;  // sized for the largest index box seen, n in use
    std::vector<PetscReal> raw;
    std::vector<char>      wall;
    std::vector<PetscReal> dx2;  // (x index - particle)^2 h^2 along the box's x range
    size_t                 n      = 0;
    PetscReal              sumAll = 0, sumInner = 0;
  };
  bool Gather(int loc, const PetscReal x[3], PetscReal H, Points &pts) const;
  // Divided shape (KernelAveragerDivided.cpp): the cells (and faces) the 32 cubes of a sphere of radius R overlap.
  bool GatherDivided(int loc, const PetscReal x[3], PetscReal R, Points &pts) const;
  // One point of a gather: local offset, raw weight, wall flag; the weight counted in the sums (wall faces apart).
  static void Append(PetscInt at, PetscReal w, bool onWall, PetscInt *off, PetscReal *raw, char *wall, size_t &m, PetscReal &sumAll, PetscReal &sumInner) {
    off[m]  = at;
    raw[m]  = w;
    wall[m] = onWall;
    ++m;
    sumAll += w;
    if (!onWall) sumInner += w;
  }
  // The tent's (Linear) 2 x 2 x 2 points (fewer at the box's faces) with their raw weights, written to
  // off/raw/wall; false if they leave this rank's ghosted region (the generic path, Gather).
  bool GatherTent(int loc, const PetscReal x[3], PetscInt *off, PetscReal *raw, char *wall, size_t &m, PetscReal &sumAll, PetscReal &sumInner) const;
  // A support as the generic Deposit and Average loops read it: local offsets, wall-face flags, and the
  // weights normalised over all points (wAll = raw/sumAll) and over the points off the wall faces (wInner =
  // raw/sumInner, 0 on a wall face).
  struct Span {
    const PetscInt  *offsets = nullptr;
    const PetscReal *wAll = nullptr, *wInner = nullptr;
    const char      *wall = nullptr;
    size_t           n      = 0;
    PetscReal        sumAll = 0, sumInner = 0;
  };
  // Gather into points_ and the weights asked for (needAll, needInner; with a sum of zero none) into wAll_, wInner_.
  bool Support(int loc, const PetscReal x[3], PetscReal H, bool needAll, bool needInner, Span &span);
  // The tent (Linear) of particle p on location loc, separable (KernelAveragerTent.cpp): per direction one or
  // two points and their factors normalised per direction, so that the weights g_x g_y g_z sum to one over the
  // points that take part (a tent's weight sum factorises: the same normalisation as the generic path's, K3,
  // to round-off), and the same with the wall faces of the location's own direction left out (deposits,
  // pressure-gradient reads). The directions' indices and factors are remembered per particle for all four
  // locations while x is the same (a coupled step deposits and reads at the same positions). False if the tent
  // leaves the ghosted region; okAll/okInner false when a normalisation has nothing to share (then the generic
  // path's nearest-point rule applies).
  struct TentSpan {
    PetscInt  base;        // local offset of the lowest point
    PetscInt  n[3];        // points per direction
    PetscInt  stride[3];   // local offset steps per direction
    PetscReal g[3][2];     // factors, all points
    PetscReal gi[3][2];    // factors, the own direction's wall faces left out
    bool      okAll, okInner;
  };
  struct TentAxes {  // per direction e and numbering v (0 cells, 1 faces normal to e)
    PetscReal s[3][2];        // x's continuous index
    PetscInt  below[3][2];    // the index below it
    PetscReal g[3][2][2];     // the factors of the points below and above, normalised
  };
  void TentAxesAt(const PetscReal x[3], TentAxes &a) const;
  bool TentAt(int loc, PetscInt p, const PetscReal x[3], TentSpan &t);
  void SizeTent(PetscInt n);  // room for n particles in the tent cache (Linear only)
  std::vector<PetscReal> tentKey_;    // x per particle, 3
  std::vector<char>      tentState_;  // 0 none, 1 remembered
  std::vector<TentAxes>  tentAxes_;
  // The normalised weights of one use of a support (wall faces left out when `inner`); the nearest point if
  // the kernel, narrower than the point spacing, missed every point. False if that leaves the ghosted region.
  bool Normalise(int loc, const PetscReal x[3], const Span &span, bool inner, std::vector<PetscInt> &offsets, std::vector<PetscReal> &weights) const;
  PetscErrorCode LocalVectors(int loc, size_t count);
  PetscErrorCode Layout(int loc, DM *dm) const;

  const StaggeredGrid *sg_ = nullptr;
  Settings             settings_;
  PetscInt             width_ = 1;
  DM                   dm_[4] = {nullptr, nullptr, nullptr, nullptr};  // wide-ghost DMDAs per location
  Vec                  local_[4] = {nullptr, nullptr, nullptr, nullptr};
  std::vector<Vec>     pool_[4];  // local vectors of the multi-field Deposit and Average, per location
  PetscInt             gs_[4][3] = {}, gm_[4][3] = {};  // ghosted corners of each location
  std::vector<char>    excluded_[4];      // per location, over its ghosted box: 1 if a deposit leaves the point out
  bool                 excluding_ = false;  // some point is excluded on some rank
  Points                     points_;  // scratch, reused: no allocation per particle
  std::vector<PetscInt>      offsets_, offsetsInner_;
  std::vector<PetscReal>     weights_, weightsInner_;
  std::vector<PetscReal>     wAll_, wInner_;  // normalised weights of a non-tent support (Support)
  std::vector<PetscScalar *> arrays_;
  std::vector<PetscReal>     values_;  // per field, reused
};

}  // namespace vofdem
