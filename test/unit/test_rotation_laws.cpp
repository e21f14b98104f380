// Magnus lift and rotational drag (RotationLaws.hpp; docs/physics.md P1) against values computed separately from the
// papers' formulas (Python, written from the equations as Loth & Dorgan 2009 quote them, not from this code):
// Oesterle & Bui Dinh (1998) C_L = 0.45 + (Re_r/Re_p - 0.45) exp(-0.05684 Re_r^0.4 Re_p^0.3), Rubinow & Keller (1961)
// C_L = Re_r/Re_p, i.e. F = pi a^3 rho Omega x (v - u); torque -pi mu d^3 Omega (Rubinow & Keller), times
// 1 + (5/(64 pi)) Re_r^0.6 (Dennis et al. 1980 as fitted by Loth 2008).
#include "vofdem/coupling/RotationLaws.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace vofdem;
using rotation::Lift;

TEST(RotationLaws, LiftCoefficientsAgainstHandComputedValues) {
  EXPECT_DOUBLE_EQ(rotation::LiftCoefficient(Lift::RubinowKeller, 1, 2), 2.0);
  EXPECT_DOUBLE_EQ(rotation::LiftCoefficient(Lift::RubinowKeller, 50, 100), 2.0);
  // 0.45 + 1.55 exp(-0.05684 x 2^0.4) = 0.45 + 1.55 x 0.927744 = 1.8880012
  EXPECT_NEAR(rotation::LiftCoefficient(Lift::Oesterle, 1, 2), 1.8880012107734572, 1e-13);
  EXPECT_NEAR(rotation::LiftCoefficient(Lift::Oesterle, 50, 100), 0.9360501346667973, 1e-13);
  EXPECT_NEAR(rotation::LiftCoefficient(Lift::Oesterle, 10, 5), 0.49029100571031964, 1e-13);
  // Oesterle's tends to Rubinow-Keller's at vanishing Reynolds numbers.
  EXPECT_NEAR(rotation::LiftCoefficient(Lift::Oesterle, 1e-6, 2e-6) / 2.0, 1.0, 1e-3);
  EXPECT_EQ(rotation::LiftCoefficient(Lift::None, 1, 2), 0.0);
}

TEST(RotationLaws, LiftForceMagnitudeAndDirection) {
  // d = 1 mm, water, a sphere moving along +x at 0.01 m/s through still fluid, spinning at 20 rad/s about +z (backspin
  // for that motion: its top surface moves backwards, with the stream it sees): lifted along +y by
  // pi a^3 rho omega V = pi x 1.25e-10 x 1000 x 20 x 0.01 = 7.853981634e-8 N.
  const double d = 1e-3, rho = 1000, mu = 1e-3, Om[3] = {0, 0, 20}, w[3] = {0.01, 0, 0};
  double       F[3];
  rotation::LiftForce(Lift::RubinowKeller, d, rho, mu, Om, w, F);
  EXPECT_NEAR(F[0], 0, 1e-24);
  EXPECT_NEAR(F[1], 7.853981633974483e-08, 1e-20);
  EXPECT_NEAR(F[2], 0, 1e-24);
  // Oesterle at Re_p = 10, Re_r = 20: (pi/8) d^2 rho C_L |w|^2 along +y, C_L = 0.45 + 1.55 exp(-0.05684 20^0.4 10^0.3).
  const double CL = 0.45 + (2 - 0.45) * std::exp(-0.05684 * std::pow(20.0, 0.4) * std::pow(10.0, 0.3));
  rotation::LiftForce(Lift::Oesterle, d, rho, mu, Om, w, F);
  EXPECT_NEAR(F[1], M_PI / 8 * d * d * rho * CL * 0.01 * 0.01, 1e-20);
  // Reversed spin, reversed lift; no spin or no slip, no lift; the force is normal to w and Omega.
  const double Om2[3] = {3, -4, 12}, w2[3] = {-0.02, 0.005, 0.01};
  rotation::LiftForce(Lift::Oesterle, d, rho, mu, Om2, w2, F);
  EXPECT_NEAR(F[0] * w2[0] + F[1] * w2[1] + F[2] * w2[2], 0, 1e-22);
  EXPECT_NEAR(F[0] * Om2[0] + F[1] * Om2[1] + F[2] * Om2[2], 0, 1e-18);
  const double zero[3] = {0, 0, 0};
  rotation::LiftForce(Lift::Oesterle, d, rho, mu, zero, w, F);
  EXPECT_EQ(F[0] * F[0] + F[1] * F[1] + F[2] * F[2], 0.0);
  rotation::LiftForce(Lift::RubinowKeller, d, rho, mu, Om, zero, F);
  EXPECT_EQ(F[0] * F[0] + F[1] * F[1] + F[2] * F[2], 0.0);
}

TEST(RotationLaws, RotationalDrag) {
  const double d = 1e-3, rho = 1000, mu = 1e-3;
  EXPECT_NEAR(rotation::RotationalDragCoefficient(d, rho, mu, 50, false), M_PI * 1e-12, 1e-27);
  // Re_r = rho d^2 |Omega|/mu = 100 at |Omega| = 100 rad/s: factor 1 + (5/(64 pi)) 100^0.6 = 1.3941306
  EXPECT_NEAR(rotation::RotationalDragCoefficient(d, rho, mu, 100, true) / (M_PI * 1e-12), 1.3941306028951264, 1e-13);
  Lift        law;
  EXPECT_TRUE(rotation::ParseLift("oesterle", &law));
  EXPECT_EQ(law, Lift::Oesterle);
  EXPECT_FALSE(rotation::ParseLift("saffman", &law));
}
