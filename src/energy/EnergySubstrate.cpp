// Energy.hpp: a substrate moving under a fixed beam (-energy_substrate_velocity; docs/modules/energy.md). Without a
// flow the box's contents (metal and gas, alpha uniform along the motion) move at the velocity v in x and y; each step
// begins with one explicit sweep per direction of the enthalpy, as the interface's sweeps move it (F7 a),
//   E' = E - dt/h (Phi_P - Phi_M),  Phi = v [alpha rho_m h_m(T_f, f_up) + (1 - alpha) rho_g h_g(T_f)],
// T_f the van Leer face temperature from the upwind side, the inflow face at the cells' initial temperature and an
// outflow face at the donor's. What crosses the box's faces joins the account. T, f then follow from E'. With BDF2 the
// history E^{n-1} takes the same sweep (its T, f from its E), so that the scheme's three levels stand in the beam's frame
// at the same material points (a semi-Lagrangian BDF2); backward Euler needs E^n alone.
#include "vofdem/energy/Energy.hpp"

#include "vofdem/base/Runtime.hpp"
#include "vofdem/grid/CellStencil.hpp"

#include <petscdmda.h>

#include <algorithm>
#include <cmath>

namespace vofdem {

PetscErrorCode Energy::SetUpSubstrate() {
  const PetscInt  *n = grid_->Cells();
  const PetscInt  *lx, *ly, *lz;
  PetscInt         px, py, pz;

  PetscFunctionBeginUser;
  if (!SubstrateMoving()) PetscFunctionReturn(0);
  // The cells' layout with two ghosts (the van Leer stencil): global vectors of dm_ and wide_ are the same.
  PetscCall(DMDAGetInfo(dm_, nullptr, nullptr, nullptr, nullptr, &px, &py, &pz, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(dm_, &lx, &ly, &lz));
  PetscCall(DMDACreate3d(comm_, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_STAR, n[0], n[1], n[2], px, py, pz, 1, 2, lx, ly, lz, &wide_));
  PetscCall(DMSetUp(wide_));
  PetscCall(DMCreateGlobalVector(wide_, &wideGlobal_));
  PetscCall(DMCreateLocalVector(wide_, &wideT_));
  PetscCall(VecDuplicate(wideT_, &wideF_));
  PetscCall(VecDuplicate(T_, &Tinflow_));
  PetscCall(VecDuplicate(T_, &Told_));
  PetscCall(VecDuplicate(T_, &Fold_));
  PetscCall(VecCopy(T_, Tinflow_));  // the initial field (SetInitial): what enters through the upstream faces
  PetscFunctionReturn(0);
}

PetscReal Energy::SubstrateStepLimit() const {
  PetscReal limit = 0;
  for (int d = 0; d < 2; ++d)
    if (substrateVelocity_[d] != 0) {
      const PetscReal l = substrateCfl_ * grid_->Spacing()[d] / std::fabs(substrateVelocity_[d]);
      limit             = limit > 0 ? std::min(limit, l) : l;
    }
  return limit;
}

// One sweep along d of the field E (cells' T and f as given, ghosted through wide_); its inflow through the box's
// faces (J, this rank's) is added to *entered.
PetscErrorCode Energy::SweepSubstrate(int d, PetscReal dt, Vec Evec, Vec Tvec, Vec Fvec, PetscReal *entered) {
  const PetscReal *h = grid_->Spacing();
  const PetscInt  *n = grid_->Cells();
  const PetscReal  V = h[0] * h[1] * h[2], rm = metal_.density, rg = gas_.density, L = metal_.latentHeat, v = substrateVelocity_[d];
  PetscInt         s[3], m[3];
  PetscScalar   ***T, ***F, ***E, ***al, ***Ti;

  PetscFunctionBeginUser;
  PetscCall(DMDAGetCorners(dm_, &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  PetscCall(VecCopy(Tvec, wideGlobal_));
  PetscCall(DMGlobalToLocal(wide_, wideGlobal_, INSERT_VALUES, wideT_));
  PetscCall(VecCopy(Fvec, wideGlobal_));
  PetscCall(DMGlobalToLocal(wide_, wideGlobal_, INSERT_VALUES, wideF_));
  PetscCall(DMDAVecGetArrayRead(wide_, wideT_, &T));
  PetscCall(DMDAVecGetArrayRead(wide_, wideF_, &F));
  PetscCall(DMDAVecGetArray(dm_, Evec, &E));
  PetscCall(DMDAVecGetArrayRead(dm_, alpha_, &al));
  PetscCall(DMDAVecGetArrayRead(dm_, Tinflow_, &Ti));
  const int      sgn = v > 0 ? 1 : -1;
  const PetscInt N   = n[d];
  // dt/h times the enthalpy flux through face q (between cells q-1 and q along d) of the line at (x, y, z), `own` the
  // owned cell beside it: the upwind cell's alpha (uniform along the motion), van Leer's T from the upwind side.
  auto flux = [&](PetscInt q, PetscInt x, PetscInt y, PetscInt z, PetscInt own) {
    auto            at  = [&](PetscScalar ***A, PetscInt i) { return d == 0 ? A[z][y][i] : A[z][i][x]; };
    const PetscInt  up1 = sgn > 0 ? q - 1 : q, up2 = up1 - sgn, down = up1 + sgn;
    PetscReal       t, f;
    if (up1 < 0 || up1 >= N) t = at(Ti, own), f = metal_.MeltFraction(t);  // the inflow face: the initial temperature
    else if (down < 0 || down >= N) t = at(T, up1), f = at(F, up1);        // the outflow face: the donor's
    else {
      const PetscInt u2 = std::min(N - 1, std::max((PetscInt)0, up2));
      t = VanLeerFaceValue(at(T, u2), at(T, up1), at(T, down)), f = at(F, up1);
    }
    const PetscReal a = at(al, own);
    return v * dt / h[d] * (a * rm * (metal_.Sensible(t) + L * f) + (1 - a) * rg * gas_.Sensible(t));
  };
  for (PetscInt z = s[2]; z < s[2] + m[2]; ++z)
    for (PetscInt o = s[1 - d]; o < s[1 - d] + m[1 - d]; ++o) {
      const PetscInt y0 = d == 0 ? o : 0, x0 = d == 0 ? 0 : o, lo = s[d], hi = s[d] + m[d];
      PetscReal      below = flux(lo, x0, y0, z, lo);
      if (lo == 0) *entered += below * V;
      for (PetscInt q = lo; q < hi; ++q) {
        const PetscReal above = flux(q + 1, x0, y0, z, q);
        if (d == 0) E[z][y0][q] -= above - below;
        else E[z][q][x0] -= above - below;
        if (q + 1 == N) *entered -= above * V;
        below = above;
      }
    }
  PetscCall(DMDAVecRestoreArrayRead(dm_, Tinflow_, &Ti));
  PetscCall(DMDAVecRestoreArrayRead(dm_, alpha_, &al));
  PetscCall(DMDAVecRestoreArray(dm_, Evec, &E));
  PetscCall(DMDAVecRestoreArrayRead(wide_, wideF_, &F));
  PetscCall(DMDAVecRestoreArrayRead(wide_, wideT_, &T));
  PetscFunctionReturn(0);
}

// T and f of the field E (alpha unchanged), T as the guess.
PetscErrorCode Energy::TemperatureOf(Vec Evec, Vec Tvec, Vec Fvec) {
  PetscInt       s[3], m[3];
  PetscScalar ***T, ***F, ***E, ***al;

  PetscFunctionBeginUser;
  PetscCall(DMDAGetCorners(dm_, &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  PetscCall(DMDAVecGetArray(dm_, Tvec, &T));
  PetscCall(DMDAVecGetArray(dm_, Fvec, &F));
  PetscCall(DMDAVecGetArrayRead(dm_, Evec, &E));
  PetscCall(DMDAVecGetArrayRead(dm_, alpha_, &al));
  for (PetscInt z = s[2]; z < s[2] + m[2]; ++z)
    for (PetscInt y = s[1]; y < s[1] + m[1]; ++y)
      for (PetscInt x = s[0]; x < s[0] + m[0]; ++x) {
        T[z][y][x] = CellTemperature(E[z][y][x], al[z][y][x], T[z][y][x]);
        F[z][y][x] = metal_.MeltFraction(T[z][y][x]);
      }
  PetscCall(DMDAVecRestoreArrayRead(dm_, alpha_, &al));
  PetscCall(DMDAVecRestoreArrayRead(dm_, Evec, &E));
  PetscCall(DMDAVecRestoreArray(dm_, Fvec, &F));
  PetscCall(DMDAVecRestoreArray(dm_, Tvec, &T));
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::MoveSubstrate(PetscReal dt, bool history) {
  PetscFunctionBeginUser;
  if (history) PetscCall(VecCopy(T_, Told_));  // the guess of E^{n-1}'s temperature
  for (int d = 0; d < 2; ++d) {
    if (substrateVelocity_[d] == 0) continue;
    PetscCall(SweepSubstrate(d, dt, E_, T_, F_, &advected_));
    PetscCall(TemperatureOf(E_, T_, F_));
    if (history) {
      PetscCall(TemperatureOf(Eold_, Told_, Fold_));
      PetscCall(SweepSubstrate(d, dt, Eold_, Told_, Fold_, &advectedOld_));
    }
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
