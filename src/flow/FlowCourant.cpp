// The flow's convective rate (1/s) for the time step and the monitor (Flow.hpp; docs/modules/flow.md, time step).
//
// -flow_courant box (the measure before 2026-12-04): the largest |u_d| of the box per direction, then their sum over d (one number per box; the
//   extremes of the three components may lie far apart).
// -flow_courant cell (the default): per cell, the faster of its two d-faces' normal velocities per direction, summed over d, then
//   the largest cell. This is the local Courant number AB2's advection sees in each cell (OpenFOAM's is the mean of
//   the two faces, 0.5 sum_f |phi_f| / V), and never larger than the box's.
// When the momentum is moved elsewhere (the VOF's sweeps, one direction at a time) the sum over d becomes a maximum,
// and both measures are the same number. A moving wall or an inflow counts with its velocity in either measure.
#include "vofdem/flow/Flow.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

PetscErrorCode Flow::ConvectiveRate(bool ownAdvection, PetscReal *rate) {
  const PetscReal *h = grid_->Spacing();
  PetscReal        boundaryRate = 0, boxRate = 0;

  PetscFunctionBeginUser;
  PetscReal boundary[3] = {0, 0, 0};  // a moving wall or an inflow moves the fluid next to it
  for (int d = 0; d < 3; ++d)
    for (int f = 0; f < 6; ++f) boundary[d] = std::fmax(boundary[d], std::fabs(bc_.Face(f).velocity[d]));
  for (int d = 0; d < 3; ++d) boundaryRate = ownAdvection ? boundaryRate + boundary[d] / h[d] : std::fmax(boundaryRate, boundary[d] / h[d]);
  if (courant_ == CourantMeasure::Box || !ownAdvection) {
    for (int d = 0; d < 3; ++d) {
      PetscReal m;
      PetscCall(VecNorm(u_[d], NORM_INFINITY, &m));
      const PetscReal r = std::fmax(m, boundary[d]) / h[d];
      boxRate           = ownAdvection ? boxRate + r : std::fmax(boxRate, r);
    }
    *rate = boxRate;
    PetscFunctionReturn(0);
  }
  LocalField u[3];
  PetscInt   s[3], n[3];
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMGlobalToLocal(sg_.Face(d), u_[d], INSERT_VALUES, uLocal_[d]));
    PetscCall(sg_.GetLocal(d, uLocal_[d], &u[d]));
  }
  sg_.Owned(3, s, n);
  const PetscReal ih[3] = {1 / h[0], 1 / h[1], 1 / h[2]};
  PetscReal       worst = 0;
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
      const PetscScalar *ux = &u[0].at(s[0], j, k), *uy = &u[1].at(s[0], j, k), *uz = &u[2].at(s[0], j, k);
      const PetscInt     sy = u[1].stride[1], sz = u[2].stride[2];
      for (PetscInt i = 0; i < n[0]; ++i) {
        const PetscReal r = std::fmax(std::fabs(ux[i]), std::fabs(ux[i + 1])) * ih[0] + std::fmax(std::fabs(uy[i]), std::fabs(uy[i + sy])) * ih[1] +
                            std::fmax(std::fabs(uz[i]), std::fabs(uz[i + sz])) * ih[2];
        worst = std::fmax(worst, r);
      }
    }
  for (int d = 0; d < 3; ++d) PetscCall(sg_.RestoreLocal(d, uLocal_[d], &u[d]));
  PetscCall(MPIU_Allreduce(&worst, rate, 1, MPIU_REAL, MPIU_MAX, grid_->Comm()));
  *rate = std::fmax(*rate, boundaryRate);
  PetscFunctionReturn(0);
}

}  // namespace vofdem
