// The pieces of the capillary force (Capillary.hpp; docs/physics.md P1, -coupling_contact_angle): the kernel's
// interface marginal F against closed forms written from the kernels' definitions (Kernel.hpp), its
// symmetry and inversion, and Princen's force at the checks of Capillary.hpp.
#include "vofdem/coupling/Capillary.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace vofdem;

namespace {
// Smooth kernel (1 - r^2/rc^2)^4: m(t) = 2 pi int_|t|^rc w r dr = (pi rc^2/5) (1 - t^2/rc^2)^5, so with
// u = t/rc, F(u) = P(u)/P(1), P(u) = int_-1^u (1 - x^2)^5 dx = sum_k C(5,k) (-1)^k (u^(2k+1) + 1)/(2k+1).
double SmoothF(double t) {
  const double rc = std::sqrt(8.0), u = t / rc;
  const double C[6] = {1, 5, 10, 10, 5, 1};
  auto         P = [&](double x) {
    double s = 0;
    for (int k = 0; k <= 5; ++k) s += C[k] * (k % 2 ? -1 : 1) * (std::pow(x, 2 * k + 1) + 1) / (2 * k + 1);
    return s;
  };
  return P(u) / P(1);
}
// Truncated Gaussian exp(-r^2/2) cut at c: m(t) = 2 pi (exp(-t^2/2) - exp(-c^2/2)), whose integral from -c
// to t is sqrt(pi/2) (erf(t/sqrt 2) + erf(c/sqrt 2)) - exp(-c^2/2) (t + c) (times 2 pi).
double TruncatedF(double t, double c) {
  auto I = [&](double x) { return std::sqrt(M_PI / 2) * (std::erf(x / std::sqrt(2.0)) + std::erf(c / std::sqrt(2.0))) - std::exp(-c * c / 2) * (x + c); };
  return I(t) / I(c);
}
}  // namespace

TEST(Capillary, MarginalAgainstClosedForms) {
  capillary::Marginal smooth, trunc;
  smooth.Build(kernel::Shape::Smooth, 1.5);
  trunc.Build(kernel::Shape::Truncated, 1.5);
  EXPECT_NEAR(smooth.Cutoff(), std::sqrt(8.0), 1e-15);
  EXPECT_NEAR(trunc.Cutoff(), 1.5, 1e-15);
  for (double t = -3; t <= 3; t += 0.125) {
    EXPECT_NEAR(smooth.Fraction(t), std::fabs(t) < std::sqrt(8.0) ? SmoothF(t) : (t < 0 ? 0 : 1), 2e-6) << "t = " << t;
    EXPECT_NEAR(trunc.Fraction(t), std::fabs(t) < 1.5 ? TruncatedF(t, 1.5) : (t < 0 ? 0 : 1), 2e-6) << "t = " << t;
  }
}

TEST(Capillary, MarginalSymmetryAndInversion) {
  for (kernel::Shape s : {kernel::Shape::Smooth, kernel::Shape::Truncated}) {
    capillary::Marginal F;
    F.Build(s, 1.3);
    EXPECT_NEAR(F.Fraction(0), 0.5, 1e-14);
    EXPECT_NEAR(F.Coordinate(0.5), 0, 1e-12);
    EXPECT_EQ(F.Fraction(-10), 0);
    EXPECT_EQ(F.Fraction(10), 1);
    EXPECT_EQ(F.Coordinate(0), -F.Cutoff());
    EXPECT_EQ(F.Coordinate(1), F.Cutoff());
    for (double t = -0.9 * F.Cutoff(); t < 0.9 * F.Cutoff(); t += 0.0731) {  // the tails are flat: F^-1 is ill-conditioned there
      EXPECT_NEAR(F.Fraction(-t), 1 - F.Fraction(t), 1e-13) << "t = " << t;
      EXPECT_NEAR(F.Coordinate(F.Fraction(t)), t, 1e-9) << "t = " << t;  // round trip
      EXPECT_GT(F.Fraction(t + 0.01), F.Fraction(t));
    }
  }
}

TEST(Capillary, PrincenForceChecks) {
  const double R = 0.5e-3, sigma = 0.072, scale = 2 * M_PI * R * sigma, deg = M_PI / 180;
  // A neutral sphere (90 deg) floats centred; none beyond the contact band.
  EXPECT_NEAR(capillary::PrincenForce(R, sigma, 90 * deg, 0), 0, 1e-15 * scale);
  EXPECT_EQ(capillary::PrincenForce(R, sigma, 120 * deg, R), 0);
  EXPECT_EQ(capillary::PrincenForce(R, sigma, 120 * deg, -1.01 * R), 0);
  // 120 deg: equilibrium at beta = 60 deg, centre R/2 above; restoring either side, stiffness 2 pi sigma.
  EXPECT_NEAR(capillary::PrincenForce(R, sigma, 120 * deg, R / 2), 0, 1e-14 * scale);
  EXPECT_LT(capillary::PrincenForce(R, sigma, 120 * deg, 0.6 * R), 0);
  EXPECT_GT(capillary::PrincenForce(R, sigma, 120 * deg, 0.4 * R), 0);
  const double ds = 1e-4 * R, k = -(capillary::PrincenForce(R, sigma, 120 * deg, R / 2 + ds) - capillary::PrincenForce(R, sigma, 120 * deg, R / 2 - ds)) / (2 * ds);
  EXPECT_NEAR(k, 2 * M_PI * sigma, 1e-6 * 2 * M_PI * sigma);
  // At the centre (beta = 90 deg): -2 pi R sigma cos(theta) (sin(90 + theta) = cos theta).
  EXPECT_NEAR(capillary::PrincenForce(R, sigma, 120 * deg, 0), scale * 0.5, 1e-12 * scale);
  // The largest force toward the gas is the detachment force 2 pi R sigma sin^2(theta/2), at beta = 180 deg - theta/2;
  // theta = 0 pulls the sphere into the liquid everywhere in the band.
  for (double theta : {30.0, 90.0, 120.0, 150.0}) {
    double best = 0;
    for (int i = 1; i < 20000; ++i) best = std::max(best, capillary::PrincenForce(R, sigma, theta * deg, R * (-1 + i / 10000.0)));
    EXPECT_NEAR(best, scale * std::pow(std::sin(theta * deg / 2), 2), 1e-6 * scale) << "theta = " << theta;
    EXPECT_NEAR(capillary::PrincenForce(R, sigma, theta * deg, R * std::cos((180 - theta / 2) * deg)), scale * std::pow(std::sin(theta * deg / 2), 2), 1e-12 * scale);
  }
  for (int i = 1; i < 100; ++i) EXPECT_LE(capillary::PrincenForce(R, sigma, 0, R * (-1 + i / 50.0)), 0);
}
