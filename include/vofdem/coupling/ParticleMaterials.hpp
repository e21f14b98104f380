// The particles' thermal material per DEM type (-physics with dem and energy; docs/modules/coupling.md): each type
// named by -dem_types takes -coupling_heat_type_<name>_material FILE|NAME (default: -coupling_heat_material) and
// -coupling_heat_type_<name>_specific_heat (a constant cp replacing the material's; seed 000's third four-particle
// scene gives one pair cp 1390) and -coupling_heat_type_<name>_initial_temperature (default:
// -coupling_heat_initial_temperature). Checked here: a positive specific heat; with melting on, a solidus below the
// liquidus and the liquidus below the boiling point (the melt criterion must be reachable before boiling).
#pragma once

#include "vofdem/energy/ThermalMaterial.hpp"

#include <string>
#include <vector>

namespace vofdem {

struct ParticleTypeHeat {
  std::string name;              // the DEM type's
  std::string material;          // "" : the particles' common material
  PetscReal   specificHeat = -1;  // J/(kg K), < 0: the material's
  PetscReal   initialTemperature = -1;  // K, < 0: the common one
};

// Reads the per-type options of the types named (collective, inside no options block).
PetscErrorCode ReadParticleTypeHeat(MPI_Comm comm, const std::vector<std::string> &typeNames, std::vector<ParticleTypeHeat> *types);

// A material file (config/materials/NAME.yaml or a path) read for `option`; unchecked (BuildParticleMaterials checks).
PetscErrorCode ReadParticleMaterial(MPI_Comm comm, const std::string &option, const std::string &name, ThermalMaterial *m);

// One material per type from the common one and the per-type options; one clear line and exit on bad input.
// emissivity >= 0 replaces a per-type file's (-coupling_heat_emissivity, or 0 without radiation); conduction: every
// type needs a positive conductivity (-coupling_heat_contact_conduction).
PetscErrorCode BuildParticleMaterials(MPI_Comm comm, const ThermalMaterial &common, const std::vector<ParticleTypeHeat> &types, bool melting, bool conduction, PetscReal emissivity,
                                      std::vector<ThermalMaterial> *materials);

}  // namespace vofdem
