// The laws of a particle's heat exchange with the fluid around it (docs/physics.md P11, F9), as pure functions
// (ParticleHeat.hpp applies them to the swarm; the Nusselt number of F10 is heat::Nusselt, DragLaws.hpp): the inverse
// of the particle material's enthalpy h(T) (with latent heat, ThermalMaterial.hpp), and one step of P11 without the
// beam and contacts against a fluid temperature held over the step.
#pragma once

#include "vofdem/energy/ThermalMaterial.hpp"

#include <cmath>

namespace vofdem {
namespace heat {

inline constexpr PetscReal kStefanBoltzmann = 5.670374419e-8;  // W/(m^2 K^4)

// The temperature T with m.Enthalpy(T) = h (h increases strictly with T: cp > 0): Newton on the apparent
// capacity from `guess`, safeguarded by bisection in a bracket that is widened until it holds h; to round-off.
PetscReal TemperatureOf(const ThermalMaterial &m, PetscReal h, PetscReal guess);

// One step of length dt of docs/physics.md (P11) for one particle without the beam and the contacts:
//   C_p dT/dt = A [h_c (Tbar - T) + e sigma (Tbar^4 - T^4)] = A G(T) (Tbar - T),  G = h_c + e sigma (Tbar^2 + T^2)(Tbar + T),
// against the fluid it reads, Tbar, which answers with the capacity C_g (J/K; <= 0: a reservoir) to what it receives
// (F9): the pair relaxes to its common temperature exactly, for G and C_p held over the step,
//   Q = C (Tbar - T0) (1 - exp(-A G dt / C)),  1/C = 1/C_p + 1/C_g,
// with G at the step's mean temperature and C_p the secant capacity m (h(T1) - h0)/(T1 - T0) (latent heat included),
// the end temperature T1 solved (false position between T0 and Tbar) so that the particle's enthalpy change is Q. Neither side passes the pair's common temperature, so the step is stable for any dt, however short the
// particle's time constant C_p/(A G) (Q -> C (Tbar - T0)); for C_g -> infinity it is the exponential of the linear law.
// Returns Q (J, into the particle; what the fluid loses) and the particle's new enthalpy and temperature.
struct StepResult {
  PetscReal heat = 0, h = 0, T = 0;
};
StepResult Step(const ThermalMaterial &m, PetscReal mass, PetscReal area, PetscReal hc, PetscReal emissivity, PetscReal Tbar, PetscReal gasCapacity, PetscReal h0, PetscReal T0,
                PetscReal dt);

}  // namespace heat
}  // namespace vofdem
