// What the particle module writes for ParaView and reports as analysis (DemOutput.cpp):
// particles (-dem_output_every) and the contact network (-dem_contacts_every) as HDF5 files with
// one XDMF index each in the run's -output_dir, and the Love-Weber stress over a box region
// (-dem_stress_lower/-dem_stress_upper) as monitor columns.
#pragma once

#include "vofdem/io/Xdmf.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace vofdem {

struct DemOutputSettings {
  PetscInt    particlesEvery = 0, contactsEvery = 0;  // steps; 0 = never
  PetscReal   stressLower[3] = {0, 0, 0}, stressUpper[3] = {0, 0, 0};
  PetscBool   stress = PETSC_FALSE;                   // a stress region was given
  PetscBool   stressKinetic = PETSC_FALSE;            // add the kinetic part sum m v (x) v
  std::string dir;                                     // -output_dir
  std::vector<XdmfEntry> particleEntries, contactEntries;

  PetscErrorCode SetFromOptions(MPI_Comm comm);
  static XdmfEntry ParticleEntry(PetscInt step, PetscReal time, PetscInt N);
  static XdmfEntry ContactEntry(PetscInt step, PetscReal time, PetscInt M);
  // Whether the contact forces of the evaluation at step `step` are needed.
  bool NeedsContacts(PetscInt step) const {
    return stress || (particlesEvery > 0 && step % particlesEvery == 0) || (contactsEvery > 0 && step % contactsEvery == 0);
  }
};

}  // namespace vofdem
