// The projection's coefficient when the predictor takes a linear drag implicitly (Flow::SetFaceRelaxation,
// docs/physics.md F5): the velocity correction of a face that relaxes at rate c is
// u = u* - dt/(1 + dt c) (1/rho)_f G phi, since the drag acts on the correction as on the rest of the
// velocity. A projection that ignores the 1/(1 + dt c) asks the pressure for only a 1/(1 + dt c) share
// of the gradient that balances the drag each step, so a dense bed (dt c ~ 100) builds its pressure
// drop over hundreds of steps (ex34). The steady state does not depend on the coefficient (phi = 0 there);
// how fast it is reached does. The factor is taken per cell, so that the Poisson operator (harmonic means of
// cell values) and the correction stay one operator and div(eps u) = 0 holds exactly; with c the mean of
// the cell's six face rates, bounded as follows.
//
// The pressure is incremental (p += phi), so a face whose true response T = 1/(1 + dt c_f) exceeds the
// response A the operator assumes there sees phi too large by T/A; the next predictor corrects it, and
// the error of the drop is multiplied by 1 - T/A per step. Where a cell's face rates differ much (a
// narrow kernel: -coupling_kernel unresolved, whose particles give their K to their own cell's faces
// only, or a truncated kernel narrower than the cell; the rim of a bed), the mean puts T/A above 2 at
// the weak faces and the drop flips sign from step to step and grows (measured: a fixed bed at cell 3 d,
// unresolved, 763 Pa of spread around 62 Pa; ex34 unresolved_*). So c_cell <= gamma c_f + (gamma - 1)/dt for
// every face f the correction moves, gamma = 1.5: A >= T/gamma at each of the cell's faces, hence at their
// harmonic means, and the error factor stays in [-0.5, 1). Within a uniform bed the bound is inactive
// (the default packed bed's drop: 27.707 -> 27.707 Pa after 200 steps). Taking c_cell = min c_f
// (gamma = 1) never overshoots, but the faces it under-asks converge over hundreds of steps. Another
// flip, of d(eps)/dt in the continuity and the particles' pressure force, is not this one: a relay where
// eps jumps as a particle crosses a face (the centred rule; the divided rule is continuous since e9e281d;
// results/c2-packed-bed.md).
#include "vofdem/flow/Flow.hpp"

#include <cmath>

namespace vofdem {

namespace {
const PetscReal kGain = 1.5;  // gamma: the largest T/A allowed at any face (see above)
}

void Flow::SetFaceDamping(Vec c[3]) {
  for (int d = 0; d < 3; ++d) damping_[d] = c ? c[d] : nullptr;
  if (implicitViscosity_) viscous_.SetDamping(c);  // implicit in the predictor's matrix (else split after it)
  pressure_.AllowHeldCells(c ? 1 / density_ : 0);  // held cells' identity rows, scaled like the flow's own phase
}

PetscErrorCode Flow::DragProjectionCoefficient(PetscReal dt) {
  LocalField c[3], b, out;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  if (!dragBeta_) {
    PetscCall(VecDuplicate(beta_, &dragBeta_));
    PetscCall(VecDuplicate(betaLocal_, &dragBetaLocal_));
    for (int d = 0; d < 3; ++d) PetscCall(DMCreateLocalVector(sg_.Face(d), &rateLocal_[d]));
    if (damping_[0])
      for (int d = 0; d < 3; ++d) PetscCall(DMCreateLocalVector(sg_.Face(d), &dampLocal_[d]));
  }
  // The rate of each face: the relaxation's plus the damping's (SetFaceDamping; +inf: held at rest).
  for (int d = 0; d < 3; ++d) {
    if (relaxRate_[d]) PetscCall(DMGlobalToLocal(sg_.Face(d), relaxRate_[d], INSERT_VALUES, rateLocal_[d]));
    else PetscCall(VecSet(rateLocal_[d], 0));
    if (damping_[d]) {
      PetscCall(DMGlobalToLocal(sg_.Face(d), damping_[d], INSERT_VALUES, dampLocal_[d]));
      PetscCall(VecAXPY(rateLocal_[d], 1, dampLocal_[d]));
    }
    PetscCall(sg_.GetLocal(d, rateLocal_[d], &c[d]));
  }
  // Box faces that keep their prescribed velocity (all but periodic and outflow) take no correction.
  const PetscInt *N = grid_->Cells();
  bool            fixed[6];
  for (int f = 0; f < 6; ++f) fixed[f] = !grid_->Periodic(f / 2) && bc_.Face(f).type != FlowBoundaryType::Outflow;
  PetscCall(sg_.GetGlobal(3, beta_, &b));
  PetscCall(sg_.GetGlobal(3, dragBeta_, &out));
  sg_.Owned(3, s, n);
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        // Held faces (rate +inf, SetFaceDamping) take no correction whatever the coefficient: they are left out of
        // the mean and the bound. A cell whose movable faces are all held gets 0: it leaves the pressure equation.
        PetscReal mean = 0, sum = 0, least = PETSC_MAX_REAL;
        int       counted = 0, movable = 0, held = 0;
        for (int d = 0; d < 3; ++d)
          for (int side = 0; side < 2; ++side) {
            PetscInt q[3] = {i, j, k};
            q[d] += side;
            const PetscReal r     = PetscRealPart(c[d].at(q));
            const bool      moved = !(fixed[2 * d + side] && q[d] == (side ? N[d] : 0));  // faces the correction moves
            if (std::isinf(r)) {
              held += moved;
              continue;
            }
            mean += r / 6, sum += r, ++counted;
            if (moved) least = std::min(least, r), ++movable;
          }
        if (!movable && held) {
          out.at(i, j, k) = 0;
          continue;
        }
        if (counted < 6) mean = sum / counted;  // the mean of the faces not held
        const PetscReal rate = std::min(mean, kGain * least + (kGain - 1) / dt);
        out.at(i, j, k) = PetscRealPart(b.at(i, j, k)) / (1 + dt * rate);
      }
  PetscCall(sg_.RestoreGlobal(3, dragBeta_, &out));
  PetscCall(sg_.RestoreGlobal(3, beta_, &b));
  for (int d = 0; d < 3; ++d) PetscCall(sg_.RestoreLocal(d, rateLocal_[d], &c[d]));
  PetscCall(DMGlobalToLocal(sg_.Cells(), dragBeta_, INSERT_VALUES, dragBetaLocal_));
  PetscCall(bc_.FillCellGhosts(sg_, dragBetaLocal_));
  PetscCall(pressure_.SetCoefficient(dragBeta_, "flow: eps/(rho (1 + dt c))"));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
