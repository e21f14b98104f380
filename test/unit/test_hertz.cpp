// Hertz normal contact (docs/physics.md P3) checked against a direct integration of the impact ODE:
// the formulas must give the elastic contact time of Hertz theory and the input restitution.
#include "vofdem/dem/HertzMindlin.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace h = vofdem::hertz;

namespace {

struct Outcome {
  double restitution, contactTime;
};

// Sphere-wall impact at speed v0 through hertz::Contact (the kernel the module uses), integrated
// with small velocity-Verlet steps; the wall normal is +z, the sphere approaches along -z.
Outcome Impact(double e, double v0) {
  const double R = 1e-3, rho = 2500, E = 1e8, nu = 0.28;
  const double m = rho * 4.0 / 3.0 * M_PI * R * R * R;
  const auto   c = h::MakePairMaterial(E, nu, E, nu, e, 0.5);
  const double tc = h::HertzContactTime(m, R, h::EffectiveModulus(E, nu, E, nu), v0);
  const double dt = tc / 20000, n[3] = {0, 0, 1};
  double       x = 0, v = v0, t = 0;  // x: overlap, v: approach speed
  double       a = 0;
  do {
    v -= 0.5 * dt * a;
    x += dt * v;
    t += dt;
    a = 0;
    if (x > 0) {
      double vrel[3] = {0, 0, -v}, xi[3] = {0, 0, 0}, F[3], Ft[3];
      h::Contact(c, h::HertzNormal(c, x, R), n, std::sqrt(m), vrel, dt, xi, F, Ft);
      a = F[2] / m;
    }
    v -= 0.5 * dt * a;
  } while (x > 0);
  return {-v / v0, t};
}

}  // namespace

TEST(Hertz, EffectiveQuantitiesOfWallsAndEqualSpheres) {
  EXPECT_DOUBLE_EQ(h::EffectiveRadius(2.0, 0), 2.0);
  EXPECT_DOUBLE_EQ(h::EffectiveRadius(2.0, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(h::EffectiveMass(3.0, 3.0), 1.5);
  EXPECT_DOUBLE_EQ(h::EffectiveModulus(1e8, 0.0, 1e8, 0.0), 0.5e8);
  EXPECT_DOUBLE_EQ(h::DampingRatio(1.0), 0.0);
  EXPECT_LT(h::DampingRatio(0.5), 0.0);
}

TEST(Hertz, RayleighTimeMatchesHandValue) {
  // T_R = pi R sqrt(rho/G)/(0.1631 nu + 0.8766), G = E/(2(1+nu)) = 3.90625e7 Pa for E 1e8, nu 0.28.
  const double expected = M_PI * 1e-3 * std::sqrt(2500 / 3.90625e7) / (0.1631 * 0.28 + 0.8766);
  EXPECT_NEAR(h::RayleighTime(1e-3, 2500, 1e8, 0.28), expected, 1e-15);
  EXPECT_NEAR(h::RayleighTime(1e-3, 2500, 1e8, 0.28), 2.7251e-5, 1e-9);
}

TEST(Hertz, ElasticContactTimeMatchesHertzTheory) {
  const Outcome o = Impact(1.0, 0.5);
  EXPECT_NEAR(o.restitution, 1.0, 1e-6);
  const double R = 1e-3, m = 2500 * 4.0 / 3.0 * M_PI * 1e-9, Es = h::EffectiveModulus(1e8, 0.28, 1e8, 0.28);
  EXPECT_NEAR(o.contactTime / h::HertzContactTime(m, R, Es, 0.5), 1.0, 0.002);
}

TEST(Hertz, DampingGivesTheInputRestitutionAtAnySpeed) {
  for (double e : {0.3, 0.6, 0.9})
    for (double v0 : {0.05, 0.5, 5.0}) EXPECT_NEAR(Impact(e, v0).restitution / e, 1.0, 0.02) << "e " << e << " v0 " << v0;
}

// JKR (P6): the contact radius returned for an overlap solves delta = a^2/R* - sqrt(2 pi w a/E*) on the
// stable branch, from any starting radius (none, a smaller or a larger one); the force is
// 4 E* a^3/(3 R*) - sqrt(8 pi w E* a^3), at zero overlap with a^3 = 2 pi w R*^2/E* and F = -(4/3) pi w R*.
TEST(Jkr, ContactRadiusSolvesTheOverlapRelationFromAnyStart) {
  const double R = 5e-6, E = 3.4e9, nu = 0.28, w = 3e-4;
  const auto   c     = h::MakePairMaterial(E, nu, E, nu, 0.5, 0.3, false, w);
  const double Es    = c.Estar, k = std::sqrt(2 * M_PI * w / Es);
  const double ac    = std::cbrt(M_PI * w * R * R / (8 * Es));
  const double dmin  = ac * ac / R - k * std::sqrt(ac);  // the lowest overlap of the stable branch
  const auto   delta = [&](double a) { return a * a / R - k * std::sqrt(a); };
  for (double f : {0.999, 0.9, 0.5, 0.0, -0.5, -2.0, -20.0, -200.0}) {
    const double d = f * dmin;  // from just above the minimum to compressions 200 times its depth
    for (double start : {0.0, 0.5 * ac, 3 * ac, 100 * ac}) {
      double     a   = start;
      const auto law = h::JkrNormal(c, d, R, &a);
      ASSERT_GE(a, ac * (1 - 1e-14));
      EXPECT_NEAR(delta(a), d, 1e-12 * std::fabs(dmin)) << "overlap " << d << ", start " << start;
      EXPECT_NEAR(law.Fel, 4 * Es * a * a * a / (3 * R) - std::sqrt(8 * M_PI * w * Es * a * a * a), 1e-12 * 1.5 * M_PI * w * R);
      EXPECT_DOUBLE_EQ(law.Sn, 2 * Es * a);
    }
  }
  double a = 0;
  EXPECT_NEAR(h::JkrNormal(c, 0.0, R, &a).Fel, -4.0 / 3.0 * M_PI * w * R, 1e-12 * M_PI * w * R);
  EXPECT_NEAR(a * a * a, 2 * M_PI * w * R * R / Es, 1e-12 * 2 * M_PI * w * R * R / Es);
  // The largest tension, -1.5 pi w R* at a^3 = 9 pi w R*^2/(8 E*), and -(5/6) pi w R* where the bond
  // breaks under displacement control (a_c, the lowest overlap).
  const double af = std::cbrt(9 * M_PI * w * R * R / (8 * Es));
  a = 0;
  EXPECT_NEAR(h::JkrNormal(c, delta(af), R, &a).Fel, -1.5 * M_PI * w * R, 1e-12 * M_PI * w * R);
  a = 0;
  EXPECT_NEAR(h::JkrNormal(c, dmin, R, &a).Fel, -5.0 / 6.0 * M_PI * w * R, 1e-6 * M_PI * w * R);
}

// The rolling cap mu_r R* N (P5) on a JKR contact held at zero net force (F_n = 0, the resting
// bonded contact of an adhesive pile) and on one in tension: compression counts no load, magnitude
// |F_n|, adhesion F_n + 2 F_c with 2 F_c = 3 pi w R* (the friction offset of JkrNormal).
TEST(Rolling, CapLoadOfABondedContact) {
  const double R = 5e-6, E = 3.4e9, nu = 0.28, w = 3e-4, mu = 0.0315;
  const auto   c = h::MakePairMaterial(E, nu, E, nu, 0.5, 0.3, false, w);
  double       a = 0;
  const double a0 = std::cbrt(9 * M_PI * w * R * R / (2 * c.Estar));  // zero net force: 4 E* a^3/(3 R) = sqrt(8 pi w E* a^3)
  const double d0 = a0 * a0 / R - std::sqrt(2 * M_PI * w * a0 / c.Estar);
  const auto   law = h::JkrNormal(c, d0, R, &a);
  EXPECT_NEAR(law.Fel, 0.0, 1e-10 * M_PI * w * R);
  EXPECT_DOUBLE_EQ(law.frictionOffset, 3 * M_PI * w * R);
  const double n[3] = {0, 0, 1}, wrel[3] = {1.0, 0, 0}, Fc2 = law.frictionOffset;
  for (double Fn : {0.0, -0.4 * Fc2, 0.7 * Fc2}) {
    for (auto load : {h::RollingLoad::Compression, h::RollingLoad::Magnitude, h::RollingLoad::Adhesion}) {
      const h::RollingParams p{mu, 0.3, load, true};
      double                 spring[3] = {0, 0, 0}, M[3];
      h::RollingTorque<h::Rolling::ConstantTorque>(p, Fn, Fc2, 1.0, R, 1.0, n, wrel, 1e-8, spring, M);
      const double N = load == h::RollingLoad::Magnitude ? std::fabs(Fn) : load == h::RollingLoad::Adhesion ? Fn + Fc2 : std::max(Fn, 0.0);
      EXPECT_DOUBLE_EQ(M[0], -mu * R * N) << "load " << (int)load << ", F_n " << Fn;
      EXPECT_EQ(M[1], 0.0);
      EXPECT_EQ(M[2], 0.0);
    }
  }
  // Without adhesion (offset 0) adhesion and compression agree.
  EXPECT_EQ(h::RollingNormalLoad(h::RollingLoad::Adhesion, -1.0, 0.0), h::RollingNormalLoad(h::RollingLoad::Compression, -1.0, 0.0));
}

// EPSD's spring-dashpot (P5) on a relative spin about n, the twist: with p.twist it winds up against it
// (dM = -k_r w dt, plus the damping) and stays along n; rolling only (twist 0, as epsd2) it sees nothing.
// And the spring turns with the normal: a rolling moment across a contact whose n turns by 1e-3 rad
// stays across it and keeps its length.
TEST(Rolling, EpsdResistsTheTwistAndTurnsWithTheNormal) {
  const double R = 1e-4, kn = 30, Ir = 1e-16, dt = 1e-6, mu = 0.1, kr = 2.25 * kn * mu * mu * R * R;
  const double n[3] = {0, 0, 1}, wrel[3] = {0, 0, 2.0}, N = 1e-5;  // a load far from the cap
  for (bool twist : {true, false}) {
    const h::RollingParams p{mu, 0.3, h::RollingLoad::Compression, twist};
    double                 spring[3] = {0, 0, 0}, M[3];
    h::RollingTorque<h::Rolling::Epsd>(p, N, 0, kn, R, Ir, n, wrel, dt, spring, M);
    EXPECT_EQ(M[0], 0.0);
    EXPECT_EQ(M[1], 0.0);
    if (twist) {
      EXPECT_DOUBLE_EQ(spring[2], -kr * 2.0 * dt);
      EXPECT_DOUBLE_EQ(M[2], -kr * 2.0 * dt - 0.3 * 2 * std::sqrt(Ir * kr) * 2.0);
    } else {
      EXPECT_EQ(M[2], 0.0);
    }
    h::RollingTorque<h::Rolling::Epsd2>(p, N, 0, kn, R, Ir, n, wrel, dt, spring, M);
    EXPECT_EQ(M[2], spring[2]);  // epsd2: the projection drops what was along n, and the twist is not seen
    EXPECT_EQ(M[2], 0.0);
  }
  const double th = 1e-3, turned[3] = {std::sin(th), 0, std::cos(th)}, turn[3] = {0, th, 0}, still[3] = {0, 0, 0};
  const h::RollingParams p{mu, 0.3, h::RollingLoad::Compression, true};
  double                 spring[3] = {1e-12, 0, 0}, M[3];
  h::RollingTorque<h::Rolling::Epsd>(p, N, 0, kn, R, Ir, turned, still, dt, spring, M, turn);
  EXPECT_NEAR(spring[0] * turned[0] + spring[2] * turned[2], 0.0, 1e-18);  // across the new n to O(th^2)
  EXPECT_NEAR(std::hypot(spring[0], spring[2]), 1e-12, 1e-24);
}

// SpinStep is the stability bound of the leapfrog recurrence of a damped oscillator with the damping
// at the half-step velocity, x_{n+1} - x_n = (1 - c dt)(x_n - x_{n-1}) - w^2 dt^2 x_n: bounded just below
// it, growing just above, for weak and strong damping. And a zero-load JKR contact is a0 wide: the
// contact radius JkrNormal finds at zero overlap force.
TEST(Jkr, SpinStepIsTheLeapfrogStabilityBound) {
  auto grows = [](double w2, double c, double dt) {
    double xm = 1, x = 1 + 1e-3;
    for (int n = 0; n < 20000; ++n) {
      const double next = x + (1 - c * dt) * (x - xm) - w2 * dt * dt * x;
      xm = x, x = next;
      if (std::abs(x) > 1e6) return true;
    }
    return false;
  };
  for (double c : {0.0, 1e2, 1e4, 1e5}) {
    const double w2 = 1e8, dt = h::SpinStep(w2, c);
    EXPECT_NEAR(w2 * dt * dt + 2 * c * dt, 4.0, 1e-12);
    EXPECT_FALSE(grows(w2, c, 0.99 * dt)) << "c " << c;
    EXPECT_TRUE(grows(w2, c, 1.01 * dt)) << "c " << c;
  }
  const auto   c = h::MakePairMaterial(1e7, 0.28, 1e7, 0.28, 0.3, 0.5, false, 0.1);
  const double R = 5e-5;
  double       a = 0;
  const double a0 = h::JkrZeroLoadRadius(c, R);
  // Zero net force at the overlap of a0: delta = a0^2/R - sqrt(2 pi w a0/E*).
  const double d0 = a0 * a0 / R - std::sqrt(2 * M_PI * c.w * a0 / c.Estar);
  EXPECT_NEAR(h::JkrNormal(c, d0, R, &a).Fel, 0.0, 1e-9 * M_PI * c.w * R);
  EXPECT_NEAR(a, a0, 1e-10 * a0);
}

// SpinContact is the Gershgorin row sum of the spin modes: for a uniform spin w of a sphere and its
// neighbours, a contact's tangential spring stretches by (R_i + R_j) w, averaged over the contact's
// directions (2/3), and acts on I = 0.4 m R_i^2 at the lever R_i; at a wall (R_j = 0) half as much.
TEST(Spin, ContactIsTheUniformSpinRowSum) {
  const auto   c = h::MakePairMaterial(5e6, 0.28, 5e6, 0.28, 0.3, 0.5);
  const double Ri = 5e-4, Rj = 1e-3, m = 1e-6, mstar = 0.8e-6, Sn = 200;
  double       w2 = 0, rate = 0;
  h::SpinContact(c, Sn, mstar, m, Rj / Ri, &w2, &rate);
  const double kt = c.tStiff * Sn, gt = std::abs(c.k5) * std::sqrt(mstar * kt), I = 0.4 * m * Ri * Ri;
  EXPECT_NEAR(w2, 2.0 / 3.0 * kt * Ri * (Ri + Rj) / I, 1e-12 * w2);
  EXPECT_NEAR(rate, 2.0 / 3.0 * gt * Ri * (Ri + Rj) / I, 1e-12 * rate);
  double ww2 = 0, wrate = 0, ew2 = 0, erate = 0;
  h::SpinContact(c, Sn, mstar, m, 0, &ww2, &wrate);
  h::SpinContact(c, Sn, mstar, m, 1, &ew2, &erate);
  EXPECT_NEAR(ww2, 0.5 * ew2, 1e-12 * ew2);
  EXPECT_NEAR(wrate, 0.5 * erate, 1e-12 * erate);
}
