// The normal law of the scene's contact model at one overlap, shared by the pair loop, the box
// faces and the other walls: Hertz (P3), linear (P4), JKR with its contact radius and bond flag kept
// in the contact's history (P6), and SJKR's attraction k A added by the caller (it needs the
// geometry: two spheres or a sphere and a plane).
#pragma once

#include "vofdem/dem/HertzMindlin.hpp"
#include "vofdem/dem/NeighbourList.hpp"

namespace vofdem {

// Cohesion models, a template argument of the contact loops.
// kBond: the ordinary normal law where spheres overlap, and the bonds of Bonds.hpp beside it (P13).
inline constexpr int kNoCohesion = 0, kJkr = 1, kSjkr = 2, kBond = 3;

template <int COH, bool LIN>
inline hertz::NormalLaw NormalLawAt(const hertz::PairMaterial &c, PetscReal kLinear, PetscReal delta, PetscReal Rstar, PetscReal *history, const hertz::JkrPair *jkr = nullptr) {
  if constexpr (COH == kJkr) {
    history[kJkrBonded] = 1;
    return jkr ? hertz::JkrNormal(c, *jkr, delta, Rstar, &history[kJkrRadius]) : hertz::JkrNormal(c, delta, Rstar, &history[kJkrRadius]);
  } else if constexpr (LIN) {
    return hertz::LinearNormal(kLinear, delta);
  } else {
    return hertz::HertzNormal(c, delta, Rstar);
  }
}

}  // namespace vofdem
