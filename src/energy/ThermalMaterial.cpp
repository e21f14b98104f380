// ThermalMaterial.hpp: properties, the melt fraction (docs/physics.md F3) and the enthalpy h(T) (F7).
#include "vofdem/energy/ThermalMaterial.hpp"

#include "vofdem/io/NumberMapping.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace vofdem {

PetscReal PropertyTable::TableAt(PetscReal t) const {
  if (t <= T.front()) return v.front();
  if (t >= T.back()) return v.back();
  const size_t i = std::upper_bound(T.begin(), T.end(), t) - T.begin();  // T[i-1] <= t < T[i]
  const PetscReal w = (t - T[i - 1]) / (T[i] - T[i - 1]);
  return v[i - 1] + w * (v[i] - v[i - 1]);
}

PetscReal PropertyTable::Min() const { return *std::min_element(v.begin(), v.end()); }

// int_a^b of the piecewise-linear table: constant beyond the ends, trapezoids (exact) between nodes.
PetscReal PropertyTable::TableIntegral(PetscReal a, PetscReal b) const {
  if (a > b) return -TableIntegral(b, a);
  PetscReal sum = 0, lo = a;
  auto      piece = [&](PetscReal x0, PetscReal x1) { sum += 0.5 * (At(x0) + At(x1)) * (x1 - x0); };
  for (size_t i = 0; i < T.size() && lo < b; ++i) {
    if (T[i] <= lo) continue;
    const PetscReal hi = std::min(T[i], b);
    piece(lo, hi);
    lo = hi;
  }
  if (lo < b) piece(lo, b);
  return sum;
}

PetscReal ThermalMaterial::MeltFraction(PetscReal T) const {
  if (!metal) return 0;
  if (melt == MeltLaw::Linear) return std::min((PetscReal)1, std::max((PetscReal)0, (T - solidus) / (liquidus - solidus)));
  return 0.5 * (1 + std::erf(4 / (liquidus - solidus) * (T - 0.5 * (liquidus + solidus))));
}

PetscReal ThermalMaterial::MeltSlope(PetscReal T) const {
  if (!metal) return 0;
  const PetscReal w = liquidus - solidus;
  if (melt == MeltLaw::Linear) return (T > solidus && T < liquidus) ? 1 / w : 0;
  const PetscReal x = 4 / w * (T - 0.5 * (liquidus + solidus));
  return 4 / w / std::sqrt(PETSC_PI) * std::exp(-x * x);
}

PetscReal ThermalMaterial::Enthalpy(PetscReal T) const { return Sensible(T) + latentHeat * MeltFraction(T); }

PetscReal ThermalMaterial::MeltInverse(PetscReal f) const {
  if (melt == MeltLaw::Linear) return solidus + f * (liquidus - solidus);
  PetscReal lo = solidus - 4 * (liquidus - solidus), hi = liquidus + 4 * (liquidus - solidus);  // erf: f_l(lo) < 1e-40
  for (int i = 0; i < 200 && hi - lo > 4 * PETSC_MACHINE_EPSILON * hi; ++i) {
    const PetscReal mid = 0.5 * (lo + hi);
    (MeltFraction(mid) < f ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

namespace {

bool Table(const NumberMapping &map, const std::string &path, const char *key, PropertyTable *t, std::string *message) {
  auto it = map.find(key);
  if (it == map.end()) return true;
  const NumberEntry &e = it->second;
  const std::string  where = path + ":" + std::to_string(e.line) + ": " + key;
  t->T.clear(), t->v.clear();
  if (e.IsNumber() || (e.rows.size() == 1 && e.rows[0].size() == 1)) {
    t->v = {e.rows[0][0]};
  } else {
    for (const auto &r : e.rows) {
      if (r.size() != 2) return *message = where + ": a table is a list of [temperature, value] rows", false;
      if (!t->T.empty() && !(r[0] > t->T.back())) return *message = where + ": the temperatures of the table must increase", false;
      t->T.push_back(r[0]), t->v.push_back(r[1]);
    }
  }
  for (PetscReal v : t->v)
    if (!(v > 0)) return *message = where + ": must be positive", false;
  return true;
}

}  // namespace

bool ReadThermalMaterial(const std::string &path, bool metal, ThermalMaterial *m, std::string *message) {
  NumberMapping map;
  if (!ReadNumberMapping(path, &map, message)) return false;
  static const std::set<std::string> known = {"density", "specific_heat", "conductivity", "solidus", "liquidus", "latent_heat", "boiling_point",
                                              "emissivity", "absorptivity", "melt_law", "viscosity", "surface_tension", "surface_tension_slope",
                                              // particle keys, read by the DEM (-dem_type_<t>_material)
                                              "youngs_modulus", "poisson_ratio", "restitution", "friction", "rolling_friction", "surface_energy"};
  for (const auto &kv : map)
    if (!known.count(kv.first)) return *message = path + ":" + std::to_string(kv.second.line) + ": unknown key '" + kv.first + "'", false;
  ThermalMaterial out = *m;
  out.path  = path;
  out.metal = metal;
  auto number = [&](const char *key, PetscReal *v, PetscReal lo, PetscReal hi, bool loOpen) {
    auto it = map.find(key);
    if (it == map.end()) return true;
    if (!it->second.IsNumber()) return *message = path + ":" + std::to_string(it->second.line) + ": " + key + ": expected one number", false;
    const PetscReal x = it->second.rows[0][0];
    if (!((loOpen ? x > lo : x >= lo) && x <= hi)) {
      std::ostringstream s;
      s << path << ":" << it->second.line << ": " << key << " = " << x << " is out of range " << (loOpen ? "(" : "[") << lo << ", " << hi << "]";
      return *message = s.str(), false;
    }
    *v = x;
    return true;
  };
  PetscReal law = out.melt == MeltLaw::Erf ? 1 : 0;
  if (!number("density", &out.density, 0, PETSC_MAX_REAL, true) || !Table(map, path, "specific_heat", &out.cp, message) ||
      !Table(map, path, "conductivity", &out.k, message) || !number("solidus", &out.solidus, 0, PETSC_MAX_REAL, true) ||
      !number("liquidus", &out.liquidus, 0, PETSC_MAX_REAL, true) || !number("latent_heat", &out.latentHeat, 0, PETSC_MAX_REAL, false) ||
      !number("boiling_point", &out.boilingPoint, 0, PETSC_MAX_REAL, true) || !number("emissivity", &out.emissivity, 0, 1, false) ||
      !number("absorptivity", &out.absorptivity, 0, 1, false) || !number("melt_law", &law, 0, 1, false))
    return false;
  out.melt = law > 0.5 ? MeltLaw::Erf : MeltLaw::Linear;
  *m = out;
  return true;
}

}  // namespace vofdem
