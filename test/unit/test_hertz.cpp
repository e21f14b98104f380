// Hertz normal contact (PHYSICS.md P3) checked against a direct integration of the impact ODE:
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
