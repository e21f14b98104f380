// Bounded second-order advection (TVD, flux-limited): the value carried through a control-volume
// face, reconstructed from the upwind cell C, the cell U upwind of it and the downwind cell D,
//     u_f = u_C + psi(r)/2 (u_D - u_C),   r = (u_C - u_U)/(u_D - u_C),
// with psi one of the classical limiters (Sweby's TVD region; all second order where the solution
// is smooth and not at an extremum). Central (psi = 1) is second order but unbounded; upwind (psi = 0)
// bounded but first order. Chosen by -flow_advection.
#pragma once

#include <petscsys.h>

#include <cmath>

namespace vofdem {

enum class Limiter { Upwind, Central, Minmod, VanLeer, MC, Superbee, Koren };

template <Limiter L>
inline PetscReal LimitedFace(PetscReal uU, PetscReal uC, PetscReal uD) {
  const PetscReal dD = uD - uC, dU = uC - uU;
  if constexpr (L == Limiter::Upwind) return uC;
  else if constexpr (L == Limiter::Central) return uC + 0.5 * dD;
  else if constexpr (L == Limiter::VanLeer) {
    // psi = 2r/(1+r): u_f = u_C + dU dD/(dU + dD), one division; zero at an extremum (dU dD <= 0).
    const PetscReal p = dU * dD;
    return p > 0 ? uC + p / (dU + dD) : uC;
  } else {
    if (dD * dU <= 0) return uC;  // extremum (or flat): first order, no new extrema
    const PetscReal r = dU / dD;   // > 0 here
    PetscReal       psi;
    if constexpr (L == Limiter::Minmod) psi = std::fmin(r, 1.0);
    else if constexpr (L == Limiter::MC) psi = std::fmin(std::fmin(2 * r, 0.5 * (1 + r)), 2.0);
    else if constexpr (L == Limiter::Superbee) psi = std::fmax(std::fmin(2 * r, 1.0), std::fmin(r, 2.0));
    else psi = std::fmin(std::fmin(2 * r, (1 + 2 * r) / 3), 2.0);  // Koren
    return uC + 0.5 * psi * dD;
  }
}

}  // namespace vofdem
