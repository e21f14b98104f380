// A force that a fluid's free surface puts on a particle, handed to the DEM by whoever models the fluid
// (the coupling's capillary force, src/coupling/CouplingCapillary.cpp). The DEM knows no fluid: it only
// knows that, if a law is set, every half kick adds F_n(R, s) n along the particle's fluid_surface_plane
// n.x + c = s (ParticleSwarm.hpp), at the particle's current height s; the force is stiff, so it is
// evaluated per kick rather than held over a fluid step (Dem.cpp, HalfKick).
#pragma once

#include <petscsys.h>

namespace vofdem {

struct SurfaceForce {
  // F_n (N, along n) on a sphere of radius R (m) whose centre is s (m) above the surface; params as set.
  using Law = PetscReal (*)(PetscReal R, PetscReal s, const PetscReal *params);
  Law       law       = nullptr;  // nullptr: no surface force
  PetscReal params[4] = {0, 0, 0, 0};
};

}  // namespace vofdem
