// The projection's coefficient when the predictor takes a linear drag implicitly (Flow::SetFaceRelaxation,
// PHYSICS.md F5): the velocity correction of a face that relaxes at rate c is
// u = u* - dt/(1 + dt c) (1/rho)_f G phi, since the drag acts on the correction as on the rest of the
// velocity. A projection that ignores the 1/(1 + dt c) asks the pressure for only a 1/(1 + dt c) share
// of the gradient that balances the drag each step, so a dense bed (dt c ~ 100) builds its pressure
// drop over hundreds of steps (ex34). The steady state does not depend on the coefficient (phi = 0 there);
// how fast it is reached does. The factor is taken per cell, with c the mean of its six faces' rates,
// so that the Poisson operator (harmonic means of cell values) and the correction stay one operator and
// div(eps u) = 0 holds exactly.
#include "vofdem/flow/Flow.hpp"

namespace vofdem {

PetscErrorCode Flow::DragProjectionCoefficient(PetscReal dt) {
  LocalField c[3], b, out;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  if (!dragBeta_) {
    PetscCall(VecDuplicate(beta_, &dragBeta_));
    PetscCall(VecDuplicate(betaLocal_, &dragBetaLocal_));
    for (int d = 0; d < 3; ++d) PetscCall(DMCreateLocalVector(sg_.Face(d), &rateLocal_[d]));
  }
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMGlobalToLocal(sg_.Face(d), relaxRate_[d], INSERT_VALUES, rateLocal_[d]));
    PetscCall(sg_.GetLocal(d, rateLocal_[d], &c[d]));
  }
  PetscCall(sg_.GetGlobal(3, beta_, &b));
  PetscCall(sg_.GetGlobal(3, dragBeta_, &out));
  sg_.Owned(3, s, n);
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        PetscReal rate = 0;
        for (int d = 0; d < 3; ++d) {
          PetscInt q[3] = {i, j, k};
          rate += PetscRealPart(c[d].at(q));
          q[d] += 1;
          rate += PetscRealPart(c[d].at(q));
        }
        out.at(i, j, k) = PetscRealPart(b.at(i, j, k)) / (1 + dt * rate / 6);
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
