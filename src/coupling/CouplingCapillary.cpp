// The particles' wettability at the free surface (Coupling.hpp, -coupling_contact_angle; issue 9,
// PHYSICS.md P1): Princen's capillary force (Capillary.hpp) from the kernel averages of the liquid
// fraction alpha and of its gradient at each particle. The fluid receives -F with the other explicit
// forces (F5, Coupling::Project).
#include "vofdem/coupling/Coupling.hpp"

#include <cmath>

namespace vofdem {

PetscErrorCode Coupling::SetFreeSurface(Vec alpha, PetscReal sigma) {
  PetscFunctionBeginUser;
  freeSurface_ = true;
  sigma_       = sigma;
  if (!contactAngleSet_ || !(sigma > 0)) PetscFunctionReturn(0);  // no force: nothing to average
  alpha_ = alpha;
  marginal_.Build(kernel_.shape, kernel_.truncation);
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecDuplicate(faceEps_[d], &gradAlpha_[d]));
    PetscCall(VecSet(gradAlpha_[d], 0));
  }
  PetscFunctionReturn(0);
}

// d alpha/dx_d at the inner faces, (alpha_R - alpha_L)/h (K2: averaged without weight, wall faces left out).
PetscErrorCode Coupling::AlphaGradient() {
  LocalField A, G;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  const StaggeredGrid &sg = flow_->Staggered();
  const PetscReal     *h  = sg.Base().Spacing();
  PetscCall(DMGlobalToLocal(sg.Cells(), alpha_, INSERT_VALUES, cellLocal_));
  PetscCall(sg.GetLocal(3, cellLocal_, &A));
  for (int d = 0; d < 3; ++d) {
    PetscCall(sg.GetGlobal(d, gradAlpha_[d], &G));
    sg.Owned(d, s, n);
    const PetscInt last = sg.Points(d, d) - 1;
    const bool     wall = !sg.Base().Periodic(d);
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
          PetscInt q[3] = {i, j, k}, cm[3] = {i, j, k};
          cm[d] -= 1;
          if (wall && (q[d] == 0 || q[d] == last)) G.at(q) = 0;
          else G.at(q) = (A.at(q) - A.at(cm)) / h[d];
        }
    PetscCall(sg.RestoreGlobal(d, gradAlpha_[d], &G));
  }
  PetscCall(sg.RestoreLocal(3, cellLocal_, &A));
  PetscFunctionReturn(0);
}

// Capillary.hpp: n = -grad alpha/|grad alpha| (from the liquid into the gas), the centre's height above
// the interface s = -H F^-1(alpha_avg), F = Princen's F_n along n. Where the kernel sees no interface
// (|grad alpha| H below 1e-6, against about 1/2 at an interface) there is no force.
// The force is held over the coming fluid step (the DEM sub-steps) and it is stiff (dF/ds = 2 pi sigma
// at a floating equilibrium: a 1 mm sphere oscillates with a period of about 10 ms). Taken at the step's
// start it pumps energy into that oscillation: for F = -k s the step maps (s, v) with determinant
// 1 + (omega dt)^2/2, a growth of 1.6 per period at 20 steps per period (seen in ex41). Taken at the
// mid-step height predicted with the particle's velocity, s + (v.n) dt/2, the map has determinant 1 and
// is stable for omega dt < 2; dt is the step just taken, the coming one's estimate.
void Coupling::CapillaryForce(PetscReal R, PetscReal H, PetscReal alphaAvg, const PetscReal grad[3], const PetscReal v[3], PetscReal dt, PetscReal f[3]) const {
  const PetscReal g = std::sqrt(grad[0] * grad[0] + grad[1] * grad[1] + grad[2] * grad[2]);
  f[0] = f[1] = f[2] = 0;
  if (!(g * H > 1e-6)) return;
  const PetscReal vn = -(v[0] * grad[0] + v[1] * grad[1] + v[2] * grad[2]) / g;
  const PetscReal s  = -H * marginal_.Coordinate(alphaAvg) + 0.5 * dt * vn;
  const PetscReal Fn = capillary::PrincenForce(R, sigma_, contactAngle_ * PETSC_PI / 180, s);
  for (int c = 0; c < 3; ++c) f[c] = -Fn * grad[c] / g;
}

}  // namespace vofdem

namespace vofdem {

// The fluid's share of the capillary force, -F (F5), is given in proportion to the mass of the faces
// the kernel covers, not to the kernel weight alone: the contact line pulls on the interface, and a
// kernel share in the gas (1000 times lighter than water) would accelerate it to metres per second
// in a few steps. Face J gets the acceleration a_J = G w_J/V_c, w_J the kernel's normalised weights
// (those of every deposit), G = -F/Mbar, Mbar = sum_J w_J M_J the kernel average of the faces'
// (eps rho)_f as the flow's predictor forms it (Project): the fluid's momentum changes by
// sum_J M_J V_c a_J dt = G Mbar dt = -F dt exactly. gradAlpha_[d] is the scratch vector (Average
// recomputes it).
PetscErrorCode Coupling::DepositCapillary(int d, const ParticleArrays &a, LocalField &eps, LocalField &rho, PetscReal *source) {
  LocalField M;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  const StaggeredGrid &sg   = flow_->Staggered();
  const PetscReal     *h    = sg.Base().Spacing();
  const PetscReal      Vc   = h[0] * h[1] * h[2];
  Vec                  work = gradAlpha_[d];
  PetscCall(sg.GetGlobal(d, work, &M));
  sg.Owned(d, s, n);
  const PetscInt last = sg.Points(d, d) - 1;
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        PetscInt q[3] = {i, j, k}, cm[3] = {i, j, k};
        if (!sg.Base().Periodic(d) && (q[d] == 0 || q[d] == last)) {
          M.at(q) = 0;  // wall faces take no deposit
          continue;
        }
        cm[d] -= 1;
        const PetscReal eL = PetscRealPart(eps.at(cm)), eR = PetscRealPart(eps.at(q));
        const PetscReal bL = eL / PetscRealPart(rho.at(cm)), bR = eR / PetscRealPart(rho.at(q));
        const PetscReal eF = 0.5 * (eL + eR), bF = 2 * bL * bR / (bL + bR);
        M.at(q) = eF * eF / bF;
      }
  PetscCall(sg.RestoreGlobal(d, work, &M));
  capMass_.resize(a.n);
  capShare_.resize(a.n);
  PetscCall(avg_.Average(d, work, nullptr, a.n, a.x, H_.data(), capMass_.data(), 1, false));
  for (PetscInt p = 0; p < a.n; ++p) {
    capShare_[p] = capMass_[p] > 0 ? -capForce_[3 * p + d] / capMass_[p] : 0;
    *source -= capForce_[3 * p + d];
  }
  PetscCall(VecSet(work, 0));
  PetscCall(avg_.Deposit(d, a.n, a.x, H_.data(), capShare_.data(), 1, work));
  PetscCall(VecAXPY(accel_[d], 1 / Vc, work));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
