// The permeability laws of seed 004 table 3 (Permeability.hpp; docs/physics.md (F11)), as intrinsic
// permeability in m^2. eps is the cell's fluid fraction, already held below 1 by the module
// (-darcy_max_fluid_fraction), so that no law divides by zero.
#include "vofdem/darcy/Permeability.hpp"

#include <algorithm>

namespace vofdem::permeability {

PetscReal KozenyCarman180(const Parameters &p, PetscReal eps, PetscReal) {
  const PetscReal e = std::min(eps, (PetscReal)0.7);  // the table's cap: k(0.7) above eps 0.7
  return e * e * e / ((1 - e) * (1 - e)) * p.diameter * p.diameter / 180;
}

PetscReal KozenyCarman150(const Parameters &p, PetscReal eps, PetscReal) {
  return p.diameter * p.diameter * eps * eps * eps / (150 * (1 - eps) * (1 - eps));
}

PetscReal Evolving(const Parameters &p, PetscReal eps, PetscReal) {
  const PetscReal r = eps / p.eps0, s = (1 - p.eps0) / (1 - eps);
  return p.k0 * r * r * r * s * s;
}

PetscReal Ergun(const Parameters &p, PetscReal eps, PetscReal speed) {
  const PetscReal d = p.diameter;
  return d * d * eps * eps * eps / ((1 - eps) * (150 * (1 - eps) + 1.75 * p.density * speed * d / p.viscosity));
}

}  // namespace vofdem::permeability
