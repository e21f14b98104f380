// The bonded-particle law (docs/physics.md (P13); seed 004 section 2.3.2 eqs 16-19, Potyondy & Cundall 2004):
// a parallel bond is an elastic cylinder of radius R = lambda min(r_a, r_b) between two spheres, with normal
// and shear stiffness per area kn, ks (Pa/m); its force and moment are built up in increments of the relative
// motion and kept in the bond's history, and the bond breaks, for good, when the largest tensile stress
// sigma = -F_n/A + |M_s| R/I or the largest shear stress tau = |F_s|/A + |M_n| R/J passes its strength.
// A contact bond is the same springs at the contact point without the moments, its strengths forces.
// Pure inline functions: they run inside the pair loop (DemContacts.cpp) and are tested through the app
// (test/dem/test_bond_break.py, examples/ex56_bonded_beam.cpp).
#pragma once

#include "vofdem/dem/HertzMindlin.hpp"

#include <petscsys.h>

#include <cmath>

namespace vofdem::bond {

// History of one bond, as seen from the lower id ("a"), the normal n from b to a:
// kState (1 intact, 0 none), F_n (N, compression positive), F_s (N, on a, x,y,z), M_n (N m, twist about n, on a),
// M_s (N m, bending, on a, x,y,z), and the normal of the last evaluation (x,y,z).
inline constexpr int kWidth = 12;
inline constexpr int kState = 0, kFn = 1, kFs = 2, kMn = 5, kMs = 6, kNormal = 9;

struct Params {
  PetscReal lambda  = 1;     // bond radius / smaller sphere radius
  PetscReal kn = 0, ks = 0;  // normal and shear stiffness per area, Pa/m
  PetscReal tensile = 0, shear = 0;  // strengths: Pa (parallel bond), N (contact bond)
  bool      moments = true;  // parallel bond; false: contact bond (no moments, strengths as forces)
};

// The bond's cross-section: radius, area, moment of inertia and polar moment (P13).
struct Section {
  PetscReal R, A, I, J;
};
VOFDEM_HOT_INLINE Section SectionOf(const Params &p, PetscReal ra, PetscReal rb) {
  const PetscReal R = p.lambda * (ra < rb ? ra : rb), R2 = R * R;
  return {R, PETSC_PI * R2, 0.25 * PETSC_PI * R2 * R2, 0.5 * PETSC_PI * R2 * R2};
}

// The largest tensile and shear stress of the bond (eqs 18-19); for a contact bond the tensile and shear forces.
struct Load {
  PetscReal sigma, tau;
};
VOFDEM_HOT_INLINE Load LoadOf(const Params &p, const Section &s, const PetscReal *h) {
  const PetscReal fs = std::sqrt(h[kFs] * h[kFs] + h[kFs + 1] * h[kFs + 1] + h[kFs + 2] * h[kFs + 2]);
  if (!p.moments) return {-h[kFn], fs};
  const PetscReal ms = std::sqrt(h[kMs] * h[kMs] + h[kMs + 1] * h[kMs + 1] + h[kMs + 2] * h[kMs + 2]);
  return {-h[kFn] / s.A + ms * s.R / s.I, fs / s.A + std::abs(h[kMn]) * s.R / s.J};
}

// A new bond at normal n: no force, no moment.
inline void Make(const PetscReal n[3], PetscReal *h) {
  for (int e = 0; e < kWidth; ++e) h[e] = 0;
  h[kState] = 1;
  for (int e = 0; e < 3; ++e) h[kNormal + e] = n[e];
}

// Turns a vector of the old contact plane with the pair: by n_old x n (the normal's turn) and by the spin about n,
// then drops what is left along n (it stays in the contact plane).
VOFDEM_HOT_INLINE void Turn(const PetscReal t[3], const PetscReal n[3], PetscReal *v) {
  const PetscReal c[3] = {t[1] * v[2] - t[2] * v[1], t[2] * v[0] - t[0] * v[2], t[0] * v[1] - t[1] * v[0]};
  for (int e = 0; e < 3; ++e) v[e] += c[e];
  const PetscReal vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
  for (int e = 0; e < 3; ++e) v[e] -= vn * n[e];
}

// One evaluation of an intact bond (eqs 16-17 as increments): n from b to a, du the contact points' relative
// displacement over the step (a against b), dtheta = (w_a - w_b) dt, spin = the pair's mean spin about n times
// dt. Updates the history h, returns the stresses after the update in *load; true when the bond broke (then
// h is cleared and the bond gives no force).
VOFDEM_HOT_INLINE bool Update(const Params &p, const Section &s, const PetscReal n[3], const PetscReal du[3], const PetscReal dtheta[3], PetscReal spin,
                              PetscReal *h, Load *load) {
  const PetscReal *n0   = &h[kNormal];
  const PetscReal  t[3] = {n0[1] * n[2] - n0[2] * n[1] + spin * n[0], n0[2] * n[0] - n0[0] * n[2] + spin * n[1], n0[0] * n[1] - n0[1] * n[0] + spin * n[2]};
  Turn(t, n, &h[kFs]);
  if (p.moments) Turn(t, n, &h[kMs]);
  const PetscReal dun = du[0] * n[0] + du[1] * n[1] + du[2] * n[2], dtn = dtheta[0] * n[0] + dtheta[1] * n[1] + dtheta[2] * n[2];
  h[kFn] -= p.kn * s.A * dun;  // approaching (dun < 0): more compression
  for (int e = 0; e < 3; ++e) h[kFs + e] -= p.ks * s.A * (du[e] - dun * n[e]);
  if (p.moments) {
    h[kMn] -= p.ks * s.J * dtn;
    for (int e = 0; e < 3; ++e) h[kMs + e] -= p.kn * s.I * (dtheta[e] - dtn * n[e]);
  }
  for (int e = 0; e < 3; ++e) h[kNormal + e] = n[e];
  *load = LoadOf(p, s, h);
  if (load->sigma >= p.tensile || load->tau >= p.shear) {
    for (int e = 0; e < kWidth; ++e) h[e] = 0;
    return true;
  }
  return false;
}

}  // namespace vofdem::bond
