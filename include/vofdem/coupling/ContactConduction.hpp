// Heat conduction between touching particles (docs/physics.md P11's contact term): through the contact of radius a
// (Hertz's, or JKR's while bonded; Dem::TouchingPairs) the pair exchanges
//   Q_ij = G_ij (T_j - T_i),  G_ij = 4 k_i k_j / (k_i + k_j) sqrt(A_c),  A_c = pi a^2.
// Each pair relaxes exactly over the step with the capacities C = m dh/dT (latent heat included) held:
//   Q = (T_j - T_i) (1 - exp(-G dt (1/C_i + 1/C_j))) / (1/C_i + 1/C_j)  into i, the same out of j,
// from the temperatures at the step's start (explicit across a particle's contacts). The step is cut into n equal
// sub-steps (the same n on every rank) when dt sum_j G_ij / C_i passes 1/2 for some particle. What one particle
// gains its partner loses to the bit: a pair across ranks is evaluated by both from the same numbers (lower id
// first), each keeping its own particle's share. The box faces and walls conduct nothing (no wall temperature).
#pragma once

#include "vofdem/dem/Dem.hpp"
#include "vofdem/energy/ThermalMaterial.hpp"

#include <vector>

namespace vofdem {

class ContactConduction {
public:
  struct StepSummary {
    PetscReal power    = 0;  // W: sum over pairs of |Q|/dt, all ranks
    PetscInt  contacts = 0;  // touching pairs, all ranks
    PetscInt  substeps = 0;
  };
  // Collective: the step dt of the local particles' enthalpy and temperature (a: the swarm's arrays, held by the
  // caller); heat (J into each local particle) is added to `conducted`.
  PetscErrorCode Step(MPI_Comm comm, const Dem &dem, const std::vector<ThermalMaterial> &materials, ParticleArrays &a, PetscReal dt, PetscReal *conducted);
  const StepSummary &Last() const { return last_; }

private:
  std::vector<PetscReal>              values_, ghost_, heat_, load_;
  std::vector<Dem::TouchingPair>      pairs_;
  StepSummary                         last_;
};

}  // namespace vofdem
