// Hertz-Mindlin normal contact (docs/physics.md P3), the Rayleigh time step (P9) and the elastic Hertz
// contact duration used to verify them (docs/verification.md D1). Pure inline functions: they run inside
// the per-contact loops and are unit-tested on their own.
#pragma once

#include <petscsys.h>

#include <algorithm>
#include <cmath>

// Functions of the per-contact loops that must be inlined there.
#if defined(__GNUC__)
#define VOFDEM_HOT_INLINE inline __attribute__((always_inline))
#else
#define VOFDEM_HOT_INLINE inline
#endif

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

namespace vofdem::hertz {

// 1/G* = 2(2-nu_i)(1+nu_i)/E_i + 2(2-nu_j)(1+nu_j)/E_j   (P3)
inline PetscReal EffectiveShearModulus(PetscReal Ei, PetscReal nui, PetscReal Ej, PetscReal nuj) {
  return 1.0 / (2 * (2 - nui) * (1 + nui) / Ei + 2 * (2 - nuj) * (1 + nuj) / Ej);
}

// Material constants of one pair of materials (or a material and a wall).
struct PairMaterial {
  PetscReal Estar = 0, Gstar = 0;
  PetscReal beta  = 0;  // ln(e)/sqrt(ln^2 e + pi^2) <= 0
  PetscReal mu    = 0;  // sliding friction
  bool      limitForce = false;  // no tension from damping: F_n never below min(0, the elastic force)
  PetscReal w = 0;               // work of adhesion (JKR, P6), J/m^2
  // Derived once: gamma_n = k5 sqrt(S_n m*), S_t = tStiff S_n, gamma_t = tOverN gamma_n (P3).
  PetscReal k5 = 0, tStiff = 0, tOverN = 0;
};

inline PairMaterial MakePairMaterial(PetscReal Ei, PetscReal nui, PetscReal Ej, PetscReal nuj, PetscReal e, PetscReal mu, bool limitForce = false,
                                     PetscReal w = 0) {
  PairMaterial c{EffectiveModulus(Ei, nui, Ej, nuj), EffectiveShearModulus(Ei, nui, Ej, nuj), DampingRatio(e), mu, limitForce, w};
  // gamma_n = -2 sqrt(5/6) beta sqrt(S_n m*); S_t / S_n = 8 G* / (2 E*) whether S_n = 2 E* sqrt(R* delta)
  // (Hertz) or 2 E* a (JKR).
  c.k5     = -2 * std::sqrt(5.0 / 6.0) * c.beta;
  c.tStiff = 4 * c.Gstar / c.Estar;
  c.tOverN = std::sqrt(c.tStiff);
  return c;
}

// The normal elastic law at one instant: the elastic force (repulsive > 0), the normal contact
// stiffness S_n, and what adds to F_n in the Coulomb limit.
struct NormalLaw {
  PetscReal Fel, Sn, frictionOffset;
};

// Hertz (P3): F = (4/3) E* sqrt(R*) delta^1.5 = (2/3) S_n delta, S_n = 2 E* sqrt(R* delta).
inline NormalLaw HertzNormal(const PairMaterial &c, PetscReal delta, PetscReal Rstar) {
  const PetscReal Sn = 2 * c.Estar * std::sqrt(Rstar * delta);
  return {2.0 / 3.0 * Sn * delta, Sn, 0};
}

// The overlap at which a JKR bond breaks under displacement control: -(3/4) (pi^2 w^2 R* / E*^2)^(1/3) (P6).
inline PetscReal JkrBreakOverlap(const PairMaterial &c, PetscReal Rstar) {
  return -0.75 * std::cbrt(PETSC_PI * PETSC_PI * c.w * c.w * Rstar / (c.Estar * c.Estar));
}

// The JKR contact radius at zero load, a0 = (9 pi w R*^2 / (2 E*))^(1/3) (P6): a resting bond is this wide
// whatever gravity does, so its stiffness S_n = 2 E* a0 does not vanish as a Hertz contact's does.
inline PetscReal JkrZeroLoadRadius(const PairMaterial &c, PetscReal Rstar) { return std::cbrt(9 * PETSC_PI * c.w * Rstar * Rstar / (2 * c.Estar)); }

// The stability of velocity Verlet for spheres held by contacts. The stiffest mode is a cluster
// spinning one way: each contact's tangential spring k_t = S_t and dashpot gamma_t = |k5| sqrt(m* S_t)
// (P3) resist the slip of both surfaces, (R_i + R_j) w per contact (R_i w against a wall), averaged over
// the contact directions (2/3), against I = 0.4 m R_i^2: w^2 = sum f k_t / m and a damping rate c = sum
// f gamma_t / m over the contacts, f = (5/3)(1 + R_j/R_i) (10/3 for equal spheres, 5/3 at a wall). For a
// whole packing these sums are Gershgorin's bound on the largest eigenvalue of its spin modes, so the
// sphere with the smallest step bounds them all. SpinContact adds one contact of stiffness S_n and m* to
// a sphere of mass m; SpinStep is the largest dt for which the leapfrog recurrence of that damped
// oscillator (damping at the half-step velocity, as the contact loop has it) is stable:
// w^2 dt^2 + 2 c dt < 4.
//  - Hertz contacts stiffen with their load (S_n = 2 E* sqrt(R* delta)), which the Rayleigh time (P9)
//    does not see: at the bottom of a 55 d bed of soft spheres (E 5 MPa, e 0.3, overlaps to 2 % of d)
//    0.3 T_R is beyond this bound, and the lowest spheres kept spinning at 100 rad/s (Dem's contact step
//    limit measures it from the contacts as they are).
//  - A JKR bond is stiff at zero load (JkrSpinBond): a soft, strongly adhesive powder with low restitution
//    at the Rayleigh step never came to rest (E 1e7 Pa, w 0.1 J/m^2, e 0.3, R 0.1 mm at 0.3 T_R: kinetic
//    energy ~1e-10 J in a 100-sphere pile for ever).
inline void SpinContact(const PairMaterial &c, PetscReal Sn, PetscReal mstar, PetscReal m, PetscReal radiusRatio, PetscReal *w2, PetscReal *rate) {
  const PetscReal kt = c.tStiff * Sn, f = 5.0 / 3.0 * (1 + radiusRatio);
  *w2 += f * kt / m;
  *rate += f * std::abs(c.k5) * std::sqrt(mstar * kt) / m;
}
inline PetscReal SpinStep(PetscReal w2, PetscReal rate) { return w2 > 0 ? (std::sqrt(rate * rate + 4 * w2) - rate) / w2 : PETSC_MAX_REAL; }
// One JKR bond at zero load (equal spheres, or a sphere and a wall).
inline void JkrSpinBond(const PairMaterial &c, PetscReal Rstar, PetscReal mstar, PetscReal m, bool wall, PetscReal *w2, PetscReal *rate) {
  SpinContact(c, 2 * c.Estar * JkrZeroLoadRadius(c, Rstar), mstar, m, wall ? 0 : 1, w2, rate);
}

// What JKR needs of a pair besides its overlap, fixed by the material and R*: sqrt(a_c), k = sqrt(2 pi
// w/E*), 1/R*, sqrt(8 pi w E*) and the break overlap. The neighbour list's pairs keep them
// (Dem::jkrPairs_): two cube roots per contact and step were 9 % of a settling tungsten powder's run.
struct JkrPair {
  PetscReal sc = 0, k = 0, invR = 0, pull = 0, breakOverlap = 0;
};
inline JkrPair JkrConstants(const PairMaterial &c, PetscReal Rstar) {
  const PetscReal ac = std::cbrt(PETSC_PI * c.w * Rstar * Rstar / (8 * c.Estar));
  return {std::sqrt(ac), std::sqrt(2 * PETSC_PI * c.w / c.Estar), 1 / Rstar, std::sqrt(8 * PETSC_PI * c.w * c.Estar), JkrBreakOverlap(c, Rstar)};
}

// JKR (P6): delta = a^2/R* - sqrt(2 pi w a / E*), F = 4 E* a^3/(3 R*) - sqrt(8 pi w E* a^3), S_n = 2 E* a.
// The contact radius is found on the stable branch a >= a_c = (pi w R*^2 / (8 E*))^(1/3), where delta(a)
// rises (a_c is its minimum), by Halley's method in s = sqrt(a): f(s) = s^4/R* - k s - delta is convex
// in s too, and an iteration needs no square root and one division. From the previous step's a
// (history) or from a_c. The iteration stops on its own error estimate: after a step h the error left
// is about C h^3, C = f''^2/(4 f'^2) + f'''/(6 f') (cubic convergence), and once that is below 1e-15 s
// the step is the last. In a settling tungsten pile (D7) the overlap moves by ~0.2 % of itself per
// step: 2.0 iterations per contact, where Newton's method stopping on a step below 1e-13 s took 3.4
// (the last only confirming), and the pair loop spent a third of its time here; the radii agree with
// the fully converged ones to 1.4e-15 relative. Friction is bounded by mu (F_n + 2 F_c), F_c = 1.5 pi
// w R* (Thornton and Yin 1991).
inline NormalLaw JkrNormal(const PairMaterial &c, const JkrPair &j, PetscReal delta, PetscReal Rstar, PetscReal *a) {
  const PetscReal sc = j.sc, k = j.k, iR = j.invR;
  PetscReal       s  = std::sqrt(std::max(*a, 1.001 * sc * sc));
  for (int it = 0; it < 60; ++it) {
    const PetscReal s2 = s * s, f = s2 * s2 * iR - k * s - delta, df = 4 * s2 * s * iR - k, d2 = 12 * s2 * iR;
    PetscReal       next = 2 * s;  // at a_c or left of it (round-off): move right
    bool            done = false;
    if (df > 0) {
      // Halley's step 2 f f' / (2 f'^2 - f f''). Right of the root it can overshoot past a_c; Newton's
      // step from there stays right of the root (f convex and rising), so it is taken instead.
      const PetscReal den = 2 * df * df - f * d2, h = den > 0 ? 2 * f * df / den : 0;
      if (den > 0 && s - h >= sc) {
        const PetscReal ah = std::abs(h);
        // C |h|^3 <= 1e-15 s, C = (f''^2/4 + f''' f'/6) / f'^2 with f''' = 24 s/R*, multiplied out by f'^2 > 0.
        done = (0.25 * d2 * d2 + 4 * s * iR * df) * ah * ah * ah <= 1e-15 * s * df * df;
        next = s - h;
      } else {
        next = s - f / df;
      }
    }
    if (next < sc) next = sc;
    done = done || std::abs(next - s) <= 1e-13 * s;
    s    = next;
    if (done) break;
  }
  const PetscReal x = s * s, s3 = x * s;
  *a = x;
  return {4.0 / 3.0 * c.Estar * s3 * s3 * iR - j.pull * s3, 2 * c.Estar * x, 3 * PETSC_PI * c.w * Rstar};
}
inline NormalLaw JkrNormal(const PairMaterial &c, PetscReal delta, PetscReal Rstar, PetscReal *a) { return JkrNormal(c, JkrConstants(c, Rstar), delta, Rstar, a); }

// Linear spring-dashpot (P4): F = k_n delta with constant stiffnesses k_n, k_t = ratio k_n. The
// damping -2 beta sqrt(k m*) then gives the restitution e exactly (no sqrt(5/6): that factor belongs
// to Hertz' stiffness growing with the overlap).
inline PairMaterial MakeLinearMaterial(PetscReal e, PetscReal mu, PetscReal tangentialRatio, bool limitForce = false) {
  PairMaterial c{0, 0, DampingRatio(e), mu, limitForce, 0};
  c.k5     = -2 * c.beta;
  c.tStiff = tangentialRatio;
  c.tOverN = std::sqrt(tangentialRatio);
  return c;
}

inline NormalLaw LinearNormal(PetscReal kn, PetscReal delta) { return {kn * delta, kn, 0}; }

// Turns a spring into the plane normal to n keeping its length. When n has not turned measurably
// the length factor rounds to 1, and the square root is skipped (it sits on the contact loop's
// critical path).
inline void ProjectKeepingLength(PetscReal s[3], const PetscReal n[3]) {
  const PetscReal old2 = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
  if (old2 == 0) return;
  const PetscReal sn = s[0] * n[0] + s[1] * n[1] + s[2] * n[2];
  for (int d = 0; d < 3; ++d) s[d] -= sn * n[d];
  if (sn * sn <= 1e-16 * old2) return;
  const PetscReal new2 = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
  if (new2 > 0) {
    const PetscReal f = std::sqrt(old2 / new2);
    for (int d = 0; d < 3; ++d) s[d] *= f;
  }
}

// One Hertz-Mindlin contact (P3). Inputs: the normal law at the overlap, unit normal n pointing from the partner
// to this particle, R* and m*, the relative velocity of this particle's surface against the
// partner's at the contact point (vrel), the step dt, and the tangential spring xi (history, m),
// which is updated. Output: the force on this particle (the partner gets minus it) and its
// tangential part Ft, from which each side's torque is -R n x Ft. Returns the normal force F_n.
// Without limitForce the damping is not clipped (D1 needs that to give the input restitution) and
// F_n turns slightly attractive as a contact ends. Friction needs compression: the Coulomb limit is
// mu max(F_n, 0), never mu |F_n| (which made friction act under tension: the oblique impact's
// friction impulse came out 6.7 % above mu times the normal impulse).
// The old spring is turned into the current tangent plane keeping its length and extended by
// v_t dt. Coulomb's law holds for the whole tangential force, spring plus damping: when
// |F_t| > mu max(F_n, 0) the force is scaled down to that limit and the spring reset to carry all of it,
// xi = -F_t / S_t. Two common alternatives failed the oblique impact in gross sliding
// (docs/verification.md D2): resetting the spring to -(F_t + gamma_t v_t)/S_t (LAMMPS) leaves it pointing
// backwards early in a contact, where gamma_t v_t alone exceeds the cap, and the friction impulse
// fell 7 % short of mu times the normal impulse; capping only the spring part and adding damping
// while sticking (LIGGGHTS) let |F_t| exceed mu |F_n| and the impulse came out 16 % too large.
// law: the normal elastic law at this overlap (HertzNormal or JkrNormal); sqrtMstar: sqrt(m*)
// (constant for a pair, so callers cache it).
// Forced inline: called once per contact from the hot loops, where GCC otherwise keeps it a call
// (5.8 % more instructions per step on the benchmark bed).
VOFDEM_HOT_INLINE PetscReal Contact(const PairMaterial &c, const NormalLaw &law, const PetscReal n[3], PetscReal sqrtMstar, const PetscReal vrel[3], PetscReal dt,
                         PetscReal xi[3], PetscReal F[3], PetscReal Ft[3]) {
  const PetscReal Sn = law.Sn, St = c.tStiff * Sn;
  const PetscReal gn = c.k5 * sqrtMstar * std::sqrt(Sn), gt = gn * c.tOverN;  // gamma_n, gamma_t (P3)
  const PetscReal vn = vrel[0] * n[0] + vrel[1] * n[1] + vrel[2] * n[2];      // > 0 separating
  PetscReal       Fn = law.Fel - gn * vn;
  if (c.limitForce) Fn = std::max(Fn, std::min(law.Fel, (PetscReal)0));
  PetscReal       vt[3];
  for (int d = 0; d < 3; ++d) vt[d] = vrel[d] - vn * n[d];
  ProjectKeepingLength(xi, n);
  for (int d = 0; d < 3; ++d) {
    xi[d] += vt[d] * dt;
    Ft[d] = -St * xi[d] - gt * vt[d];
  }
  const PetscReal ft2 = Ft[0] * Ft[0] + Ft[1] * Ft[1] + Ft[2] * Ft[2], cap = c.mu * std::max(Fn + law.frictionOffset, (PetscReal)0);
  if (ft2 > cap * cap) {  // sliding
    const PetscReal s = cap / std::sqrt(ft2), invSt = St > 0 ? 1 / St : 0;
    for (int d = 0; d < 3; ++d) {
      Ft[d] *= s;
      xi[d] = -Ft[d] * invSt;
    }
  }
  for (int d = 0; d < 3; ++d) F[d] = Fn * n[d] + Ft[d];
  return Fn;
}

}  // namespace vofdem::hertz

namespace vofdem::hertz {

// Energy stored in the normal Hertz spring: the integral of (4/3) E* sqrt(R*) delta^1.5, i.e.
// (8/15) E* sqrt(R*) delta^2.5 = (4/15) S_n delta^2 with S_n = 2 E* sqrt(R* delta) (P3; counted in
// the energy balance of docs/verification.md D4).
inline PetscReal ElasticEnergy(PetscReal Sn, PetscReal delta) { return 4.0 / 15.0 * Sn * delta * delta; }

}  // namespace vofdem::hertz

namespace vofdem::hertz {

// Rolling resistance (P5), chosen per scene and bound outside the contact loops.
enum class Rolling { None, ConstantTorque, Epsd, Epsd2 };

// The normal load that bounds the rolling torque, mu_r R* N (P5). With adhesion (JKR) a resting
// contact carries almost no net normal force, so the choice decides whether bonded contacts resist
// rolling at all:
//  - Compression: N = max(F_n, 0), the net force in compression only;
//  - Magnitude: N = |F_n|, P5's formula as written (seed 001's model), tension resists too;
//  - Adhesion: N = max(F_n + 2 F_c, 0), the load of the sliding limit (Thornton and Yin 1991).
// Without adhesion the three differ only where damping pulls as a contact ends.
enum class RollingLoad { Compression, Magnitude, Adhesion };

struct RollingParams {
  PetscReal   mu    = 0;    // rolling friction coefficient mu_r
  PetscReal   eta   = 0.3;  // EPSD: viscous damping as a fraction of critical (Ai et al. 2011)
  RollingLoad load  = RollingLoad::Compression;
  bool        twist = true;  // EPSD: the spring-dashpot resists the twist about n too (RollingTorque)
};

// N of RollingLoad from the net normal force and the law's friction offset 2 F_c (NormalLaw).
inline PetscReal RollingNormalLoad(RollingLoad load, PetscReal Fn, PetscReal offset) {
  return load == RollingLoad::Magnitude ? std::abs(Fn) : load == RollingLoad::Adhesion ? std::max(Fn + offset, (PetscReal)0) : std::max(Fn, (PetscReal)0);
}

// Rolling torque on this particle (the partner gets minus it) from the relative angular velocity
// wrel = w_this - w_partner. Fn: the net normal force and offset: the law's friction offset (2 F_c with
// JKR), which p.load turns into the bounding load N; kn: the secant normal stiffness F_n,elastic/delta
// (as in LIGGGHTS), Ir: the equivalent moment of inertia about the contact, spring: the rolling spring
// (history, N m), updated; turn: the rotation of n since the last step (axis times angle; nullptr: n
// has not turned, as at a box face).
//  - ConstantTorque: M = -mu_r R* N w/|w|, the classic model, w without the twist about n; it chatters
//    around w = 0.
//  - Epsd (Ai et al. 2011, model C): spring k_r = 2.25 k_n mu_r^2 R*^2 with dM = -k_r w dt, capped at
//    mu_r R* N, plus damping -eta 2 sqrt(I_r k_r) w while not at the cap; holds a pile at rest. With
//    p.twist (the default) w is the whole relative rotation, the twist about n included, and the spring
//    turns with n (by turn) instead of being projected into the tangent plane. Without it, a sphere that
//    rolling resistance holds in place with its contacts' normals (nearly) on one line -- on a face with
//    one neighbour above or beside it, or one sphere hanging from another -- is free to spin about that
//    line: neither spring nor damper sees the spin, only its leak through the normals' tilt. In a settled
//    100-sphere JKR pile three such spheres kept spinning back and forth at up to 80 rad/s with ~1e-12 J
//    between them to t = 0.4 s; damping the twist alone left them creeping (1e-17 J), as the static
//    rolling moments of the tilted contacts kept a steady torque about the line (test dem/epsd_rest;
//    docs/physics.md P5).
//  - Epsd2 (LIGGGHTS' epsd2): the spring and cap of Epsd without the twist, without damping.
template <Rolling model>
VOFDEM_HOT_INLINE void RollingTorque(const RollingParams &p, PetscReal Fn, PetscReal offset, PetscReal kn, PetscReal Rstar, PetscReal Ir, const PetscReal n[3],
                          const PetscReal wrel[3], PetscReal dt, PetscReal spring[3], PetscReal M[3], const PetscReal *turn = nullptr) {
  M[0] = M[1] = M[2] = 0;
  if constexpr (model == Rolling::None) return;
  const bool      twist = model == Rolling::Epsd && p.twist;
  const PetscReal wn    = twist ? 0 : wrel[0] * n[0] + wrel[1] * n[1] + wrel[2] * n[2];
  PetscReal       w[3];
  for (int d = 0; d < 3; ++d) w[d] = wrel[d] - wn * n[d];
  const PetscReal Mmax = p.mu * Rstar * RollingNormalLoad(p.load, Fn, offset);
  if constexpr (model == Rolling::ConstantTorque) {
    const PetscReal wmag = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    if (wmag > 0)
      for (int d = 0; d < 3; ++d) M[d] = -Mmax * w[d] / wmag;
  } else {
    if (!twist) {
      ProjectKeepingLength(spring, n);  // as the tangential spring
    } else if (turn) {
      // The spring turns with the normal, its rolling and twisting parts kept: s += turn x s, then its
      // length back (first order in the angle, as ProjectKeepingLength is).
      const PetscReal old2 = spring[0] * spring[0] + spring[1] * spring[1] + spring[2] * spring[2];
      const PetscReal c[3] = {turn[1] * spring[2] - turn[2] * spring[1], turn[2] * spring[0] - turn[0] * spring[2], turn[0] * spring[1] - turn[1] * spring[0]};
      const PetscReal c2   = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
      if (c2 > 1e-32 * old2) {
        for (int d = 0; d < 3; ++d) spring[d] += c[d];
        const PetscReal new2 = spring[0] * spring[0] + spring[1] * spring[1] + spring[2] * spring[2], f = std::sqrt(old2 / new2);
        for (int d = 0; d < 3; ++d) spring[d] *= f;
      }
    }
    const PetscReal kr = 2.25 * kn * p.mu * p.mu * Rstar * Rstar;
    for (int d = 0; d < 3; ++d) spring[d] -= kr * w[d] * dt;
    const PetscReal s2 = spring[0] * spring[0] + spring[1] * spring[1] + spring[2] * spring[2];
    const bool      full = s2 > Mmax * Mmax;
    if (full) {
      const PetscReal s = Mmax / std::sqrt(s2);
      for (int d = 0; d < 3; ++d) spring[d] *= s;
    }
    if (model == Rolling::Epsd && !full) {
      const PetscReal damp = p.eta * 2 * std::sqrt(Ir * kr);
      for (int d = 0; d < 3; ++d) M[d] = spring[d] - damp * w[d];
    } else {
      for (int d = 0; d < 3; ++d) M[d] = spring[d];
    }
  }
}

}  // namespace vofdem::hertz

namespace vofdem::hertz {

// Van der Waals attraction between a sphere pair or a sphere and a wall (P7, Hamaker):
// |F| = A R* / (6 z^2) for the gap z >= z0, held at its value at z0 below that (contact included),
// zero from the range cut-off on. The largest attraction A R* / (6 z0^2) equals 2 pi w R* with
// w = A / (12 pi z0^2). Returns the magnitude of the attraction.
struct VanDerWaals {
  PetscReal hamaker = 0;      // A, J
  PetscReal minGap  = 0;      // z0, m
  PetscReal range   = 0;      // cut-off gap, m
};

inline PetscReal VdwAttraction(const VanDerWaals &v, PetscReal gap, PetscReal Rstar) {
  if (gap >= v.range) return 0;
  const PetscReal z = std::max(gap, v.minGap);
  return v.hamaker * Rstar / (6 * z * z);
}

}  // namespace vofdem::hertz


namespace vofdem::hertz {

// SJKR, LIGGGHTS' "cohesion sjkr" (P6, for cross-checks with LIGGGHTS): an attraction F = k A while
// the spheres overlap, k the cohesion energy density (J/m^3) and A the area of the circle where the
// undeformed spheres intersect: A = -pi/4 (d-Ri-Rj)(d+Ri-Rj)(d-Ri+Rj)(d+Ri+Rj)/d^2 for two spheres
// at distance d, and pi (2 R delta - delta^2) for a sphere cut by a plane. As LIGGGHTS' default
// (tangential_reduce off), the friction limit sees the normal force reduced by the attraction.
inline PetscReal SjkrPairArea(PetscReal ri, PetscReal rj, PetscReal d) {
  return -0.25 * PETSC_PI * (d - ri - rj) * (d + ri - rj) * (d - ri + rj) * (d + ri + rj) / (d * d);
}
inline PetscReal SjkrWallArea(PetscReal r, PetscReal delta) { return PETSC_PI * (2 * r * delta - delta * delta); }

// Lubrication (P8): f = 6 pi mu R_eff^2 v_n / h across a gap h between the cut-offs (a wall has
// R_eff = R); below the inner cut-off h is held at it, beyond the outer one the force is zero.
// Acts only across a gap (not in contact: the contact's damping takes over there). Returns the
// coefficient c of f = -c v_n (v_n > 0 separating), 0 outside the range.
struct Lubrication {
  PetscReal viscosity = 0;  // mu, Pa s; 0: off
  PetscReal minGap    = 0;  // m
  PetscReal maxGap    = 0;  // m
};

inline PetscReal LubricationCoefficient(const Lubrication &l, PetscReal gap, PetscReal Reff) {
  if (gap <= 0 || gap >= l.maxGap) return 0;
  return 6 * PETSC_PI * l.viscosity * Reff * Reff / std::max(gap, l.minGap);
}

}  // namespace vofdem::hertz
