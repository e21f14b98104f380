// HeatExchange.hpp: the inverse of h(T) and one exchange step of a particle (docs/physics.md P11, F9).
#include "vofdem/coupling/HeatExchange.hpp"

#include <algorithm>

namespace vofdem {
namespace heat {

PetscReal TemperatureOf(const ThermalMaterial &m, PetscReal h, PetscReal guess) {
  PetscReal T = guess > 0 ? guess : 300, lo = T, hi = T;
  // A bracket [lo, hi] with h(lo) <= h <= h(hi).
  for (PetscReal step = 1; m.Enthalpy(lo) > h && lo > 1e-3; step *= 2) lo = std::max((PetscReal)1e-3, lo - step);
  for (PetscReal step = 1; m.Enthalpy(hi) < h && hi < 1e7; step *= 2) hi += step;
  for (int it = 0; it < 100; ++it) {
    const PetscReal r = m.Enthalpy(T) - h;
    if (r == 0) return T;
    if (r > 0) hi = T;
    else lo = T;
    const PetscReal c = m.Capacity(T);
    PetscReal       next = c > 0 ? T - r / c : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket (a kink of f_l): bisect
    if (std::fabs(next - T) <= 1e-15 * T || hi - lo <= 1e-15 * hi) return next;
    T = next;
  }
  return T;
}

StepResult Step(const ThermalMaterial &m, PetscReal mass, PetscReal area, PetscReal hc, PetscReal emissivity, PetscReal Tbar, PetscReal gasCapacity, PetscReal h0, PetscReal T0,
                PetscReal dt) {
  StepResult r;
  r.h = h0, r.T = T0;
  if (!(dt > 0) || Tbar == T0) return r;
  // The heat Q(T1) the pair's relaxation gives for an end temperature T1 (G at the mean, the secant capacity).
  auto heatFor = [&](PetscReal T1) {
    const PetscReal Tm  = 0.5 * (T0 + T1);
    const PetscReal G   = area * (hc + emissivity * kStefanBoltzmann * (Tbar * Tbar + Tm * Tm) * (Tbar + Tm));  // W/K
    const PetscReal Cp  = std::fabs(T1 - T0) > 1e-9 * T0 ? mass * (m.Enthalpy(T1) - h0) / (T1 - T0) : mass * m.Capacity(T0);  // J/K
    const PetscReal inv = 1 / Cp + (gasCapacity > 0 ? 1 / gasCapacity : 0);
    return (Tbar - T0) * -std::expm1(-G * dt * inv) / inv;
  };
  // T1 with m (h(T1) - h0) = Q(T1): F changes sign between T0 and Tbar (Q is at most C_p (Tbar - T0)); Illinois false position.
  auto F = [&](PetscReal T1) { return mass * (m.Enthalpy(T1) - h0) - heatFor(T1); };
  PetscReal a = T0, b = Tbar, Fa = F(a), Fb = F(b);
  PetscReal T1 = b;
  int       side = 0;
  for (int it = 0; it < 200 && Fa != 0 && Fb != 0; ++it) {
    T1 = (a * Fb - b * Fa) / (Fb - Fa);
    if (!(T1 > std::min(a, b) && T1 < std::max(a, b))) T1 = 0.5 * (a + b);
    const PetscReal Fc = F(T1);
    if (Fc == 0 || std::fabs(b - a) <= 1e-14 * std::fabs(T1)) break;
    if ((Fc > 0) == (Fb > 0)) {
      b = T1, Fb = Fc;
      if (side == -1) Fa *= 0.5;
      side = -1;
    } else {
      a = T1, Fa = Fc;
      if (side == 1) Fb *= 0.5;
      side = 1;
    }
  }
  if (Fa == 0) T1 = a;
  // The particle takes exactly Q; its temperature follows from its enthalpy.
  r.heat = heatFor(T1);
  r.h    = h0 + r.heat / mass;
  r.T    = TemperatureOf(m, r.h, T1);
  return r;
}

}  // namespace heat
}  // namespace vofdem
