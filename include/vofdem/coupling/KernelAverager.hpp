// Kernel averaging and projection between particles and the MAC grid (PHYSICS.md K1-K3).
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
// matrices (notes/petsc-3.18.md). Unresolved mode: the cell that contains the particle (for faces,
// the two faces of that cell along the component), CFD-DEM's "centre" limit.
#pragma once

#include "vofdem/coupling/Kernel.hpp"
#include "vofdem/flow/StaggeredGrid.hpp"

#include <vector>

namespace vofdem {

class KernelAverager {
public:
  struct Settings {
    kernel::Shape shape      = kernel::Shape::Smooth;
    PetscReal     truncation = 1.5;  // cut-off of the truncated Gaussian, in widths H
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
  // summed into their owners).
  PetscErrorCode Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, const PetscReal *value, PetscInt stride, Vec out);
  // out[p*stride] = sum_J f_J c_J w_pJ / sum_J c_J w_pJ over the points of location loc within the
  // cut-off, c = weight (a global vector of the same location; nullptr: 1). Wall faces take part
  // (their velocity is the wall's) unless `walls` is false (a pressure gradient there is not
  // computed). Collective (ghost update).
  PetscErrorCode Average(int loc, Vec field, Vec weight, PetscInt n, const PetscReal *x, const PetscReal *H, PetscReal *out, PetscInt stride, bool walls = true);
  // Several fields of one location at once (the kernel weights, the costly part, are computed once per
  // particle): value[f] into out[f], or field[f] (weighted by weight[f], walls[f]) into out[f].
  PetscErrorCode Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, PetscInt nf, const PetscReal *const value[], PetscInt stride, Vec out[]);
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
  bool           Gather(int loc, const PetscReal x[3], PetscReal H, Points &pts) const;
  // Gather for particle p; the tent's points (Linear) are remembered per location and particle and reused while
  // the particle's x and H are those they were gathered for (a coupled step deposits and reads at the same
  // positions: one gather instead of two). Bitwise the same as Gather.
  bool           GatherAt(int loc, PetscInt p, const PetscReal x[3], PetscReal H, Points &pts);
  void           SizeTent(int loc, PetscInt n);  // room for n particles in tent_[loc] (Linear only)
  struct TentCache {  // per particle: x, H; the gather's outcome (0 none, 1 ok, 2 failed); up to 8 points
    std::vector<PetscReal> key;     // 4 per particle
    std::vector<char>      state;
    std::vector<char>      n;
    std::vector<PetscInt>  offsets;  // 8 per particle
    std::vector<PetscReal> raw;      // 8 per particle
    std::vector<char>      wall;     // 8 per particle
    std::vector<PetscReal> sums;     // sumAll, sumInner
  };
  TentCache tent_[4];
  bool           Normalise(int loc, const PetscReal x[3], const Points &pts, bool inner, std::vector<PetscInt> &offsets, std::vector<PetscReal> &weights) const;
  PetscErrorCode LocalVectors(int loc, size_t count);
  PetscErrorCode Layout(int loc, DM *dm) const;

  const StaggeredGrid *sg_ = nullptr;
  Settings             settings_;
  PetscInt             width_ = 1;
  DM                   dm_[4] = {nullptr, nullptr, nullptr, nullptr};  // wide-ghost DMDAs per location
  Vec                  local_[4] = {nullptr, nullptr, nullptr, nullptr};
  std::vector<Vec>     pool_[4];  // local vectors of the multi-field Deposit and Average, per location
  PetscInt             gs_[4][3] = {}, gm_[4][3] = {};  // ghosted corners of each location
  Points                     points_;  // scratch, reused: no allocation per particle
  std::vector<PetscInt>      offsets_, offsetsInner_;
  std::vector<PetscReal>     weights_, weightsInner_;
  std::vector<PetscScalar *> arrays_;
  std::vector<PetscReal>     values_, num_, den_;  // per field, reused
};

}  // namespace vofdem
