// FaceMass.hpp: (eps rho)_f at the owned faces of one component.
#include "vofdem/grid/FaceMass.hpp"

#include "vofdem/grid/FaceProperties.hpp"

namespace vofdem {

PetscErrorCode FaceMass(const StaggeredGrid &sg, int d, LocalField &eps, LocalField &rho, PetscReal scale, Vec out) {
  LocalField M;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  PetscCall(sg.GetGlobal(d, out, &M));
  sg.Owned(d, s, n);
  const PetscInt last = sg.Points(d, d) - 1;
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        PetscInt q[3] = {i, j, k}, cm[3] = {i, j, k};
        if (!sg.Base().Periodic(d) && (q[d] == 0 || q[d] == last)) {
          M.at(q) = 0;
          continue;
        }
        cm[d] -= 1;
        const PetscReal eL = PetscRealPart(eps.at(cm)), eR = PetscRealPart(eps.at(q));
        M.at(q) = scale * FaceAverage(eL, eR, eL / PetscRealPart(rho.at(cm)), eR / PetscRealPart(rho.at(q))).EpsRho();
      }
  PetscCall(sg.RestoreGlobal(d, out, &M));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
