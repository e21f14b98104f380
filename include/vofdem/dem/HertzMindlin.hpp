// Hertz-Mindlin normal contact (PHYSICS.md P3), the Rayleigh time step (P9) and the elastic Hertz
// contact duration used to verify them (VERIFICATION.md D1). Pure inline functions: they run inside
// the per-contact loops and are unit-tested on their own.
#pragma once

#include <petscsys.h>

#include <cmath>

namespace vofdem::hertz {

// 1/R* = 1/R_i + 1/R_j; a wall is a sphere of infinite radius (pass 0 for "infinite").
inline PetscReal EffectiveRadius(PetscReal ri, PetscReal rj) { return rj <= 0 ? ri : ri * rj / (ri + rj); }

// 1/m* = 1/m_i + 1/m_j; a wall has infinite mass (pass 0 for "infinite").
inline PetscReal EffectiveMass(PetscReal mi, PetscReal mj) { return mj <= 0 ? mi : mi * mj / (mi + mj); }

// 1/E* = (1-nu_i^2)/E_i + (1-nu_j^2)/E_j   (P3)
inline PetscReal EffectiveModulus(PetscReal Ei, PetscReal nui, PetscReal Ej, PetscReal nuj) {
  return 1.0 / ((1 - nui * nui) / Ei + (1 - nuj * nuj) / Ej);
}

// beta = ln(e)/sqrt(ln^2(e) + pi^2)   (P3); 0 for e = 1 (no damping)
inline PetscReal DampingRatio(PetscReal e) {
  const PetscReal l = std::log(e);
  return l / std::sqrt(l * l + PETSC_PI * PETSC_PI);
}

// Precomputed constants of one normal contact pair type.
struct NormalContact {
  PetscReal kHertz;   // (4/3) E* sqrt(R*): F_elastic = kHertz * delta^1.5
  PetscReal dampPre;  // -2 sqrt(5/6) beta sqrt(2 E* sqrt(R*) m*): gamma_n = dampPre * delta^(1/4)
};

inline NormalContact MakeNormalContact(PetscReal Estar, PetscReal Rstar, PetscReal mstar, PetscReal e) {
  const PetscReal sqrtR = std::sqrt(Rstar);
  return {4.0 / 3.0 * Estar * sqrtR, -2.0 * std::sqrt(5.0 / 6.0) * DampingRatio(e) * std::sqrt(2.0 * Estar * sqrtR * mstar)};
}

// Normal force magnitude along the contact normal (positive = repulsive) for overlap delta > 0 and
// normal relative velocity vn (negative while approaching):
// F_n = (4/3) E* sqrt(R*) delta^1.5 - gamma_n vn, gamma_n = -2 sqrt(5/6) beta sqrt(S_n m*),
// S_n = 2 E* sqrt(R* delta)   (P3). The damping part is not clipped (VERIFICATION.md D1).
inline PetscReal NormalForce(const NormalContact &c, PetscReal delta, PetscReal vn) {
  const PetscReal q = std::sqrt(std::sqrt(delta));  // delta^(1/4)
  return c.kHertz * delta * q * q - c.dampPre * q * vn;
}

// Rayleigh time T_R = pi R sqrt(rho/G) / (0.1631 nu + 0.8766), G = E / (2 (1 + nu))   (P9)
inline PetscReal RayleighTime(PetscReal R, PetscReal rho, PetscReal E, PetscReal nu) {
  const PetscReal G = E / (2 * (1 + nu));
  return PETSC_PI * R * std::sqrt(rho / G) / (0.1631 * nu + 0.8766);
}

// Elastic Hertz contact duration t_c = 2.87 (m*^2 / (R* E*^2 v))^(1/5) for impact speed v (D1).
inline PetscReal HertzContactTime(PetscReal mstar, PetscReal Rstar, PetscReal Estar, PetscReal v) {
  return 2.87 * std::pow(mstar * mstar / (Rstar * Estar * Estar * v), 0.2);
}

}  // namespace vofdem::hertz
