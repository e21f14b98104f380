// The permeability laws of the Darcy seepage (docs/physics.md (F11); seed 004 table 3): the intrinsic
// permeability k (m^2) of a packing from its fluid fraction (porosity) eps, one row per law. A new law is a
// function in PermeabilityLaws.cpp and one row of kLaws; -darcy_permeability_law, its help and the error for
// an unknown name follow from the table (NamedTable.hpp). Seed 004 writes some rows as the hydraulic
// conductivity k rho_w g/mu (m/s); here every row is the intrinsic k, and the module divides by mu.
#pragma once

#include <petscsys.h>

namespace vofdem::permeability {

// What a law may read: the grain size (D, D10 or d of the row), the reference state of the evolving law,
// the fluid and, for Ergun's inertial term, the local superficial (Darcy) speed |q|.
struct Parameters {
  PetscReal diameter = 1e-3;     // m, -darcy_diameter
  PetscReal k0 = 1e-10;          // m^2, -darcy_reference_permeability
  PetscReal eps0 = 0.4;          // -, -darcy_reference_fluid_fraction
  PetscReal density = 1000;      // kg/m^3, -darcy_density
  PetscReal viscosity = 1e-3;    // Pa s, -darcy_viscosity
};

using Law = PetscReal (*)(const Parameters &p, PetscReal eps, PetscReal speed);

struct Row {
  const char *name;
  const char *summary;
  Law         k;
  bool        nonlinear;  // k depends on the speed |q|: the solve iterates (Picard)
};

// Kozeny-Carman, (1/180) eps^3/(1-eps)^2 D^2, eps capped at 0.7 (seed 004 table 3, row 1).
PetscReal KozenyCarman180(const Parameters &p, PetscReal eps, PetscReal speed);
// Kozeny-Carman with the effective size D10, D10^2 eps^3/(150 (1-eps)^2) (row 2, as intrinsic permeability).
PetscReal KozenyCarman150(const Parameters &p, PetscReal eps, PetscReal speed);
// The evolving form k0 (eps/eps0)^3 ((1-eps0)/(1-eps))^2 (row 3).
PetscReal Evolving(const Parameters &p, PetscReal eps, PetscReal speed);
// Ergun: d^2 eps^3 / ((1-eps) (150 (1-eps) + 1.75 rho |q| d/mu)) (row 5, as intrinsic permeability; the
// inertial term makes the head loss quadratic in the speed).
PetscReal Ergun(const Parameters &p, PetscReal eps, PetscReal speed);

inline constexpr Row kLaws[] = {
  {"kozenycarman", "(1/180) eps^3/(1-eps)^2 D^2, eps capped at 0.7; D = -darcy_diameter", KozenyCarman180, false},
  {"kozenycarman_d10", "D10^2 eps^3/(150 (1-eps)^2), also Ergun's viscous (slow-flow) limit; D10 = -darcy_diameter", KozenyCarman150, false},
  {"evolving", "k0 (eps/eps0)^3 ((1-eps0)/(1-eps))^2; k0, eps0 = -darcy_reference_permeability, -darcy_reference_fluid_fraction", Evolving, false},
  {"ergun", "Ergun with its inertial term, d^2 eps^3/((1-eps)(150 (1-eps) + 1.75 rho |q| d/mu)); nonlinear, solved by Picard iterations", Ergun, true},
};

}  // namespace vofdem::permeability
