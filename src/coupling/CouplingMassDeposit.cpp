// The fluid's reaction to explicit particle forces, shared by face mass (Coupling.hpp, docs/physics.md F5).
#include "vofdem/coupling/Coupling.hpp"
#include "vofdem/grid/FaceMass.hpp"

namespace vofdem {

// The fluid's share -F (F5) of the particle forces in massForce_ (the capillary force; with the implicit fluid
// side of the drag also f_vm's m_a Du/Dt) is given in proportion to the mass of the faces the kernel covers, not
// to the kernel weight alone: the contact line pulls on the interface, and a kernel share in the gas (1000 times
// lighter than water) would accelerate it to metres per second in a few steps. Face J gets the acceleration a_J = G w_J/V_c, w_J the kernel's normalised weights
// (those of every deposit), G = -F/Mbar, Mbar = sum_J w_J M_J the kernel average of the faces'
// (eps rho)_f as the flow's predictor forms it (Project): the fluid's momentum changes by
// sum_J M_J V_c a_J dt = G Mbar dt = -F dt exactly. massWork_[d] is scratch, created on the first call.
PetscErrorCode Coupling::DepositByFaceMass(int d, const ParticleArrays &a, LocalField &eps, LocalField &rho, PetscReal *source) {
  PetscFunctionBeginUser;
  const StaggeredGrid &sg   = flow_->Staggered();
  const PetscReal     *h    = sg.Base().Spacing();
  const PetscReal      Vc   = h[0] * h[1] * h[2];
  if (!massWork_[d]) PetscCall(VecDuplicate(faceEps_[d], &massWork_[d]));
  Vec work = massWork_[d];
  PetscCall(FaceMass(sg, d, eps, rho, 1, work));  // wall faces take no deposit
  capMass_.resize(a.n);
  capShare_.resize(a.n);
  PetscCall(avg_.Average(d, work, nullptr, a.n, a.x, H_.data(), capMass_.data(), 1, false));
  for (PetscInt p = 0; p < a.n; ++p) {
    capShare_[p] = capMass_[p] > 0 ? -massForce_[3 * p + d] / capMass_[p] : 0;
    *source -= massForce_[3 * p + d];
  }
  PetscCall(VecSet(work, 0));
  PetscCall(avg_.Deposit(d, a.n, a.x, H_.data(), capShare_.data(), 1, work));
  PetscCall(VecAXPY(accel_[d], 1 / Vc, work));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
