// The diffusion smoothing's matrix I - tau sum_e D_e d^2/dx_e^2 (DiffusionSmoother.hpp) applied without
// storing it: a MATSHELL whose product is the 7-point stencil on a DMDA of stencil width 1. The assembled
// AIJ matrix reads 7 values and 7 column indices per row; the stencil reads the field and one coefficient
// per direction, so the Chebyshev iterations (the smoothing's cost) run about twice as fast. The same rows
// as DiffusionSmoother::Assemble: zero flux through walls (the neighbour beyond is left out, and its share
// of the diagonal with it), periodic where the grid is, identity rows on the wall faces of a velocity
// component. The products equal the assembled matrix's to round-off (the terms are summed in another order).
#pragma once

#include <petscdmda.h>
#include <petscmat.h>

#include <vector>

namespace vofdem {

class DiffusionOperator {
public:
  // dm: the location's DMDA (stencil width 1); a[e] = tau D_e/h_e^2; lo/hi[e]: the first and last index
  // along e of the points the smoothing acts on (others are identity rows; periodic: the whole range).
  PetscErrorCode Create(DM dm, const PetscReal a[3], const PetscInt lo[3], const PetscInt hi[3], const bool periodic[3], Mat *shell);
  PetscErrorCode Destroy();

private:
  static PetscErrorCode Mult(Mat A, Vec x, Vec y);

  DM                     dm_    = nullptr;
  Vec                    local_ = nullptr;
  PetscReal              a_[3]  = {0, 0, 0};
  PetscInt               lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0};
  bool                   periodic_[3] = {false, false, false};
  bool                   ghosted_     = true;  // the local vector has ghost points (else x is read in place)
  PetscInt               s_[3] = {0, 0, 0}, n_[3] = {0, 0, 0}, gs_[3] = {0, 0, 0}, gm_[3] = {0, 0, 0};
  std::vector<PetscReal> zeros_;  // a row of zeros standing in for a neighbour row beyond a wall
};

}  // namespace vofdem
