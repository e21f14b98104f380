// Energy.hpp: the Darcy term of the mushy zone and the solid metal (docs/physics.md F2), as the rates per face that
// the flow takes implicitly (Flow::SetFaceDamping), and the liquid share of each cell for the surface forces.
//
// The momentum equation per unit volume carries -D_c s^2/((1 - s)^3 + D_cs) U with s = alpha (1 - f_l) the
// solid metal fraction: zero in gas and in liquid metal, D_c/D_cs where the metal is all solid. Divided by
// the face density the flow divides by (rho_f from the harmonic mean of 1/rho, FaceProperties.hpp), it is a
// relaxation rate toward rest, taken implicitly: any constant is stable at any step. Metal that is all solid
// (f_l = 0; only the linear law reaches it) in a cell at least -energy_freeze_alpha full is held at rest
// exactly (rate +inf): the cell leaves the pressure equation and its faces keep u = 0, so solid metal does
// not creep at the finite D_c/D_cs (a Marangoni stress on a solid surface would otherwise move it).
#include "vofdem/energy/Energy.hpp"

#include "vofdem/grid/CellStencil.hpp"
#include "vofdem/grid/FaceProperties.hpp"

#include <cmath>
#include <limits>

namespace vofdem {

PetscErrorCode Energy::MushyDrag(Vec rate[3], Vec liquid) {
  const StaggeredGrid &sg = *sg_;
  LocalField           S, R, A, T, M, C;
  PetscInt             s[3], n[3];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evMushy_, 0, 0, 0, 0));
  if (!sLocal_) {
    PetscCall(DMCreateLocalVector(sg.Cells(), &sLocal_));
    PetscCall(VecDuplicate(sLocal_, &rhoLocal_));
    PetscCall(DMCreateGlobalVector(sg.Cells(), &sGlobal_));
    PetscCall(VecDuplicate(sGlobal_, &rhoGlobal_));
  }
  // 1. Each owned cell: its solid metal fraction s (-1: held), density and liquid share.
  const Vec alpha = interfaceAlpha_();
  PetscCall(sg.GetGlobal(3, sGlobal_, &S));
  PetscCall(sg.GetGlobal(3, rhoGlobal_, &R));
  PetscCall(sg.GetGlobal(3, alpha, &A));
  PetscCall(sg.GetGlobal(3, T_, &T));  // T_ has the cells' layout (Energy::TransportSweep copies it likewise)
  PetscCall(sg.GetGlobal(3, liquid, &M));
  PetscInt held = 0;
  sg.Owned(3, s, n);
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscReal a = std::min((PetscReal)1, std::max((PetscReal)0, PetscRealPart(A.at(i, j, k))));
        const PetscReal f = metal_.MeltFraction(PetscRealPart(T.at(i, j, k)));
        const bool      h = holdSolid_ && a > 0 && a >= freezeAlpha_ && f == 0;
        held += h;
        S.at(i, j, k) = h ? -1 : a * (1 - f);
        R.at(i, j, k) = a * metal_.density + (1 - a) * gas_.density;
        M.at(i, j, k) = a > 0 ? f : 1;
      }
  PetscCall(sg.RestoreGlobal(3, liquid, &M));
  PetscCall(sg.RestoreGlobal(3, T_, &T));
  PetscCall(sg.RestoreGlobal(3, alpha, &A));
  PetscCall(sg.RestoreGlobal(3, rhoGlobal_, &R));
  PetscCall(sg.RestoreGlobal(3, sGlobal_, &S));
  PetscCallMPI(MPI_Allreduce(&held, &heldCells_, 1, MPIU_INT, MPI_SUM, comm_));
  // 2. Ghosts: the neighbours' values across ranks and periodic faces, the nearest cell's outside the box.
  for (int v = 0; v < 2; ++v) {
    const Vec local = v ? rhoLocal_ : sLocal_;
    PetscCall(DMGlobalToLocal(sg.Cells(), v ? rhoGlobal_ : sGlobal_, INSERT_VALUES, local));
    PetscCall(sg.GetLocal(3, local, &C));
    PetscCall(FillNearestOutside(sg, C));
    PetscCall(sg.RestoreLocal(3, local, &C));
  }
  // 3. The owned faces: +inf beside a held cell, else the Carman-Kozeny rate at the mean s.
  const PetscReal inf = std::numeric_limits<PetscReal>::infinity();
  PetscCall(sg.GetLocal(3, sLocal_, &S));
  PetscCall(sg.GetLocal(3, rhoLocal_, &R));
  for (int d = 0; d < 3; ++d) {
    LocalField F;
    PetscCall(sg.GetGlobal(d, rate[d], &F));
    sg.Owned(d, s, n);
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
          PetscInt q[3] = {i, j, k}, p[3] = {i, j, k};
          p[d] -= 1;
          const PetscReal sL = PetscRealPart(S.at(p)), sR = PetscRealPart(S.at(q));
          if (sL < 0 || sR < 0) {
            F.at(i, j, k) = inf;
            continue;
          }
          const PetscReal sf = 0.5 * (sL + sR), open = 1 - sf;
          const PetscReal rhoF = 1 / FaceBeta(1 / PetscRealPart(R.at(p)), 1 / PetscRealPart(R.at(q)));
          F.at(i, j, k) = sf > 0 ? mushyConstant_ * sf * sf / ((open * open * open + mushyEpsilon_) * rhoF) : 0;
        }
    PetscCall(sg.RestoreGlobal(d, rate[d], &F));
  }
  PetscCall(sg.RestoreLocal(3, rhoLocal_, &R));
  PetscCall(sg.RestoreLocal(3, sLocal_, &S));
  PetscCall(PetscLogEventEnd(evMushy_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
