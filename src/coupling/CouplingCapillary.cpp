// The particles' wettability at the free surface (Coupling.hpp, -coupling_contact_angle; issue 9,
// docs/physics.md P1): Princen's capillary force (Capillary.hpp) from the kernel averages of the liquid
// fraction alpha and of its gradient at each particle. The fluid receives -F with the other explicit
// forces (F5, Coupling::Project).
#include "vofdem/coupling/Coupling.hpp"

#include <cmath>

namespace vofdem {

// Princen's F_n as the DEM's surface-force law (SurfaceForce.hpp): params = (sigma N/m, theta rad).
static PetscReal PrincenLaw(PetscReal R, PetscReal s, const PetscReal *params) {
  return capillary::PrincenForce(R, params[0], params[1], s);
}

PetscErrorCode Coupling::SetFreeSurface(Vec alpha, PetscReal sigma) {
  PetscFunctionBeginUser;
  freeSurface_ = true;
  sigma_       = sigma;
  if (!contactAngleSet_ || !(sigma > 0)) PetscFunctionReturn(0);  // no force: nothing to average
  alpha_ = alpha;
  SurfaceForce princen;
  princen.law       = PrincenLaw;
  princen.params[0] = sigma;
  princen.params[1] = contactAngle_ * PETSC_PI / 180;
  dem_->SetSurfaceForce(princen);
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

// Capillary.hpp: n = -grad alpha/|grad alpha| (from the liquid into the gas) and the centre's height above the
// interface s = -H F^-1(alpha_avg), stored as the plane (n, c) with s = n.x + c through the particle's position
// now: the DEM kicks evaluate Princen's force F_n n at the particle's current height on it (Dem::SetSurfaceForce;
// held at one height over the fluid step the stiff force pumps the particle's oscillation). Where the kernel
// sees no interface (|grad alpha| H below 1e-6, against about 1/2 at an interface) n = 0: no force.
void Coupling::SurfacePlane(PetscReal H, PetscReal alphaAvg, const PetscReal grad[3], const PetscReal x[3], PetscReal plane[4]) const {
  const PetscReal g = std::sqrt(grad[0] * grad[0] + grad[1] * grad[1] + grad[2] * grad[2]);
  plane[0] = plane[1] = plane[2] = plane[3] = 0;
  if (!(g * H > 1e-6)) return;
  const PetscReal s = -H * marginal_.Coordinate(alphaAvg);
  plane[3]          = s;
  for (int c = 0; c < 3; ++c) {
    plane[c] = -grad[c] / g;
    plane[3] -= plane[c] * x[c];
  }
}

}  // namespace vofdem
