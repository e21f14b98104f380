// A phase of the energy equation, metal or gas (docs/physics.md F3, F7, M; docs/modules/energy.md):
// density, heat capacity and conductivity (numbers, or tables of temperature), and for a metal its solidus,
// liquidus, latent heat, melt-fraction law, boiling point; emissivity and absorptivity of its surface.
// Read from config/materials/<name>.yaml (ReadThermalMaterial); every value a file gives states its source
// there. The enthalpy per mass, h(T) = int_{T_ref}^{T} cp dT + f_l(T) L (T_ref a choice: only differences of
// h enter), is exact for a piecewise-linear cp table.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace vofdem {

// A property as a function of temperature: one value, or a piecewise-linear table (constant beyond its ends).
struct PropertyTable {
  std::vector<PetscReal> T, v;  // K, ascending; the property
  // One value inline (the cells' loops call these per cell and step), a table out of line: the same arithmetic.
  PetscReal At(PetscReal t) const { return v.size() == 1 ? v[0] : TableAt(t); }
  PetscReal Integral(PetscReal a, PetscReal b) const { return v.size() == 1 ? v[0] * (b - a) : TableIntegral(a, b); }  // int_a^b v dT, exact
  bool      Constant() const { return v.size() == 1; }
  bool      Valid() const { return !v.empty(); }
  PetscReal Min() const;

private:
  PetscReal TableAt(PetscReal t) const;
  PetscReal TableIntegral(PetscReal a, PetscReal b) const;
};

enum class MeltLaw { Linear, Erf };  // F3: clamp((T - T_s)/(T_l - T_s), 0, 1), or seed 000's erf form

struct ThermalMaterial {
  std::string   name, path;
  PetscReal     density = -1;                 // kg/m^3
  PropertyTable cp, k;                        // J/(kg K), W/(m K)
  bool          metal = false;                // has solidus and liquidus
  PetscReal     solidus = -1, liquidus = -1;  // K
  PetscReal     latentHeat   = 0;             // J/kg
  PetscReal     boilingPoint = -1;            // K (< 0: not given)
  PetscReal     emissivity   = 0;             // of its surface, -
  PetscReal     absorptivity = -1;            // of a laser at its surface, - (< 0: not given)
  MeltLaw       melt = MeltLaw::Linear;
  PetscReal     referenceTemperature = 0;  // K: where h = 0 (only differences of h enter; a reference near the field's
                                           // temperatures keeps E's round-off to that of the differences)

  PetscReal MeltFraction(PetscReal T) const;   // f_l, 0 for a gas
  PetscReal MeltSlope(PetscReal T) const;      // d f_l / dT
  PetscReal Enthalpy(PetscReal T) const;       // h(T), J/kg
  PetscReal Sensible(PetscReal T) const { return cp.Integral(referenceTemperature, T); }  // int_{T_ref}^T cp dT, J/kg
  PetscReal MeltInverse(PetscReal f) const;    // the T with f_l(T) = f, for 0 < f < 1
  PetscReal Capacity(PetscReal T) const { return cp.At(T) + latentHeat * MeltSlope(T); }  // dh/dT
};

// Reads a material file (io/NumberMapping.hpp) into m. Keys: density, specific_heat, conductivity (numbers
// or [[T, value], ...] tables), solidus, liquidus, latent_heat, boiling_point, emissivity, absorptivity,
// melt_law (0 linear, 1 erf); the particle keys of config/materials (youngs_modulus, ...) are left to the DEM.
// False with a one-line message naming the file and what is wrong. Values missing from the file keep those
// passed in (the energy module checks that every needed one is set, from the file or its options).
bool ReadThermalMaterial(const std::string &path, bool metal, ThermalMaterial *m, std::string *message);

}  // namespace vofdem
