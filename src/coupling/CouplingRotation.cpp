// The fluid's rotation at the particles and the forces that come from it (Coupling.hpp step 3; RotationLaws.hpp,
// docs/physics.md P1, K2): the velocity derivatives on the grid, and per particle the Magnus lift and the rotational drag.
#include "vofdem/coupling/Coupling.hpp"

#include <cmath>

namespace vofdem {

// du_d/dx_e at the faces of component d, for the two e != d. Along e those faces sit at cell centres, so the
// central difference over two cells is centred on the face itself; at a wall of e (no neighbour beyond it) the
// one-sided difference. The curl at a particle is then the kernel average of these (K2: unweighted, like the
// pressure gradient), computed only with -coupling_lift or -coupling_rotational_drag.
PetscErrorCode Coupling::VelocityGradients() {
  LocalField U, G;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  const StaggeredGrid &sg = flow_->Staggered();
  const Grid          &g  = sg.Base();
  const PetscReal     *h  = g.Spacing();
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMGlobalToLocal(sg.Face(d), flow_->Velocity(d), INSERT_VALUES, faceLocal_[d]));
    PetscCall(sg.GetLocal(d, faceLocal_[d], &U));
    sg.Owned(d, s, n);
    for (int k = 0; k < 2; ++k) {
      const int      e = (d + 1 + k) % 3;
      const PetscInt N = sg.Points(d, e);
      const bool     wall = !g.Periodic(e);
      PetscCall(sg.GetGlobal(d, gradU_[d][k], &G));
      for (PetscInt kk = s[2]; kk < s[2] + n[2]; ++kk)
        for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
          for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
            PetscInt q[3] = {i, j, kk}, lo[3] = {i, j, kk}, hi[3] = {i, j, kk};
            PetscReal span = 2 * h[e];
            lo[e] -= 1, hi[e] += 1;
            if (wall && q[e] == 0) lo[e] = q[e], span = h[e];
            if (wall && q[e] == N - 1) hi[e] = q[e], span = lo[e] == q[e] ? 0 : h[e];
            G.at(q) = span > 0 ? (PetscRealPart(U.at(hi)) - PetscRealPart(U.at(lo))) / span : 0;
          }
      PetscCall(sg.RestoreGlobal(d, gradU_[d][k], &G));
    }
    PetscCall(sg.RestoreLocal(d, faceLocal_[d], &U));
  }
  PetscFunctionReturn(0);
}

void Coupling::RotationForces(ParticleArrays &a, PetscInt p, const PetscReal *g, const PetscReal uf[3], PetscReal rho, PetscReal mu, PetscReal F[3]) const {
  // Half the vorticity, g[3c + e] = du_c/dx_e.
  const PetscReal Of[3] = {0.5 * (g[7] - g[5]), 0.5 * (g[2] - g[6]), 0.5 * (g[3] - g[1])};
  const PetscReal d = 2 * a.radius[p];
  PetscReal       Om[3], w[3];
  for (int c = 0; c < 3; ++c) Om[c] = a.omega[3 * p + c] - Of[c], w[c] = a.v[3 * p + c] - uf[c];
  rotation::LiftForce(lift_, d, rho, mu, Om, w, F);
  const PetscReal om = std::sqrt(Om[0] * Om[0] + Om[1] * Om[1] + Om[2] * Om[2]);
  a.fluidRotationalDrag[p] = rotationalDrag_ ? rotation::RotationalDragCoefficient(d, rho, mu, om, rotationalDragDennis_) : 0;
  for (int c = 0; c < 3; ++c) a.fluidRotation[3 * p + c] = Of[c];
}

}  // namespace vofdem
