// Dem::TouchingPairs (Dem.hpp): the touching pairs of the neighbour list at given positions, for what a coupling
// moves through the contacts.
#include "vofdem/dem/Dem.hpp"

#include <cmath>

namespace vofdem {

PetscErrorCode Dem::TouchingPairs(int width, const PetscReal *values, std::vector<PetscReal> *ghostValues, std::vector<TouchingPair> *pairs) const {
  ParticleArrays a;

  PetscFunctionBeginUser;
  PetscCall(swarm_.GetArrays(&a));
  const PetscInt   n = a.n;
  const PetscReal *x = a.x;
  // One message: the owners' positions as they are now, then the values.
  const int              w = 3 + width;
  std::vector<PetscReal> packed((size_t)w * n), ghost;
  for (PetscInt p = 0; p < n; ++p) {
    for (int e = 0; e < 3; ++e) packed[(size_t)w * p + e] = x[3 * p + e];
    for (int e = 0; e < width; ++e) packed[(size_t)w * p + 3 + e] = values[(size_t)width * p + e];
  }
  PetscCall(halo_.SendValues(w, packed.data(), &ghost));
  const PetscInt ng = halo_.Count();
  PetscCheck((PetscInt)ghost.size() == w * ng, PETSC_COMM_SELF, PETSC_ERR_PLIB, "touching pairs: %zu values for %" PetscInt_FMT " ghosts", ghost.size() / w, ng);
  ghostValues->resize((size_t)width * ng);
  for (PetscInt g = 0; g < ng; ++g)
    for (int e = 0; e < width; ++e) (*ghostValues)[(size_t)width * g + e] = ghost[(size_t)w * g + 3 + e];
  auto position = [&](PetscInt j) { return j < n ? &x[3 * j] : &ghost[(size_t)w * (j - n)]; };
  pairs->clear();
  const PeriodicImages &images = halo_.Images();
  for (size_t k = 0; k < list_.Size(); ++k) {
    const PetscInt   ia = list_.first[k], ib = list_.second[k];
    const PetscReal *xa = position(ia), *xb = position(ib), *sh = images.Shift(pairImage_[k]);
    const PetscReal  dx[3] = {(xa[0] - xb[0]) + sh[0], (xa[1] - xb[1]) + sh[1], (xa[2] - xb[2]) + sh[2]};
    const PetscReal  dist2 = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
    const PetscReal  rsum = (ia < n ? a.radius[ia] : halo_.radius[ia - n]) + (ib < n ? a.radius[ib] : halo_.radius[ib - n]);
    const PetscReal *spring = &list_.spring[kSpringWidth * k];
    if (jkr_ && list_.touching[k] && spring[kJkrBonded] != 0 && spring[kJkrRadius] > 0) pairs->push_back({ia, ib, spring[kJkrRadius]});
    else if (dist2 < rsum * rsum) pairs->push_back({ia, ib, std::sqrt(list_.rstar[k] * (rsum - std::sqrt(dist2)))});
  }
  PetscCall(swarm_.RestoreArrays(&a));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
