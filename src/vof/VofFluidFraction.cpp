// Particles in the VOF module's fluid (Vof.hpp SetFluidFraction; docs/physics.md F1b): the ghosted copies of
// eps and of its change over the step that the sweeps read.
#include "vofdem/vof/Vof.hpp"

namespace vofdem {

// eps_ and epsChange_ are global vectors of the flow's cell DMDA, whose layout is da_'s (the same
// ownership ranges, one dof): copied into a global vector of da_ and scattered with da_'s 4-wide ghosts;
// boundary layers by zero gradient, as alpha's (the face means there multiply a zero wall velocity).
PetscErrorCode Vof::FluidFractionGhosts() {
  PetscFunctionBeginUser;
  if (!cellScratch_) {
    PetscCall(DMCreateGlobalVector(da_, &cellScratch_));
    PetscCall(DMCreateLocalVector(da_, &epsLocal_));
    PetscCall(DMCreateLocalVector(da_, &changeLocal_));
  }
  const Vec from[2] = {eps_, epsChange_}, to[2] = {epsLocal_, changeLocal_};
  for (int k = 0; k < 2; ++k) {
    if (from[k]) PetscCall(VecCopy(from[k], cellScratch_));
    else PetscCall(VecSet(cellScratch_, 0));  // no change given: eps constant over the step
    PetscCall(DMGlobalToLocal(da_, cellScratch_, INSERT_VALUES, to[k]));
    PetscCall(MirrorBoundary(to[k]));
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
