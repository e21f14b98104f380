// Size distributions (SizeDistribution.hpp): samples against the truncated laws' analytic moments,
// the analytic moments against a numerical integral of the truncated density, cut-offs respected.
#include "vofdem/base/Random.hpp"
#include "vofdem/dem/RandomFill.hpp"
#include "vofdem/dem/SphereHash.hpp"
#include "vofdem/dem/SizeDistribution.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

using vofdem::SizeDistribution;

namespace {

// Sample mean and variance of n radii must lie within 4 standard errors of the analytic ones; the
// standard error of the variance uses the sample's fourth central moment.
void CheckSamples(const SizeDistribution &s, int n = 200000) {
  double sum = 0, sum2 = 0;
  std::vector<double> r(n);
  for (int i = 0; i < n; ++i) {
    r[i] = s.Radius(vofdem::random::Uniform(99, i, 6));
    ASSERT_GE(r[i], s.MinRadius());
    ASSERT_LE(r[i], s.MaxRadius());
    sum += r[i];
  }
  const double mean = sum / n;
  double       m4   = 0;
  for (double x : r) sum2 += (x - mean) * (x - mean), m4 += std::pow(x - mean, 4);
  const double var = sum2 / (n - 1);
  m4 /= n;
  EXPECT_NEAR(mean, s.Mean(), 4 * std::sqrt(s.Variance() / n)) << s.Describe();
  EXPECT_NEAR(var, s.Variance(), 4 * std::sqrt((m4 - var * var) / n)) << s.Describe();
}

// k-th moment of a density on [a, b] by the composite Simpson rule, normalised by its integral.
double NumericMoment(const std::function<double(double)> &pdf, double a, double b, int k) {
  const int m = 20000;
  const double h = (b - a) / m;
  double       num = 0, den = 0;
  for (int i = 0; i <= m; ++i) {
    const double x = a + i * h, w = (i == 0 || i == m) ? 1 : (i % 2 ? 4 : 2);
    num += w * pdf(x) * std::pow(x, k), den += w * pdf(x);
  }
  return num / den;
}

}  // namespace

TEST(SizeDistribution, UniformMomentsAndCutoffs) {
  SizeDistribution s;
  s.SetUniform(1e-4, 3e-4);
  EXPECT_NEAR(s.Mean(), 2e-4, 1e-18);
  EXPECT_NEAR(s.Variance(), 4e-8 / 12, 1e-20);
  CheckSamples(s);
}

TEST(SizeDistribution, TruncatedNormal) {
  SizeDistribution s;
  const double mu = 50e-6, sd = 15e-6, lo = 30e-6, hi = 100e-6;  // asymmetric cut: the mean shifts up
  s.SetNormal(mu, sd, lo, hi);
  auto pdf = [&](double x) { return std::exp(-0.5 * std::pow((x - mu) / sd, 2)); };
  EXPECT_NEAR(s.Mean(), NumericMoment(pdf, lo, hi, 1), 1e-9 * mu);
  EXPECT_NEAR(s.Mean() * s.Mean() + s.Variance(), NumericMoment(pdf, lo, hi, 2), 1e-9 * mu * mu);
  EXPECT_NEAR(s.MeanCube(), NumericMoment(pdf, lo, hi, 3), 1e-9 * mu * mu * mu);
  EXPECT_GT(s.Mean(), mu);  // the lower cut removes more of the left tail
  CheckSamples(s);
}

TEST(SizeDistribution, TruncatedLognormal) {
  SizeDistribution s;
  const double m = 40e-6, sd = 20e-6, lo = 15e-6, hi = 80e-6;
  s.SetLognormal(m, sd, lo, hi);
  const double sig = std::sqrt(std::log(1 + sd * sd / (m * m))), mu = std::log(m) - 0.5 * sig * sig;
  auto pdf = [&](double x) { return std::exp(-0.5 * std::pow((std::log(x) - mu) / sig, 2)) / x; };
  EXPECT_NEAR(s.Mean(), NumericMoment(pdf, lo, hi, 1), 1e-9 * m);
  EXPECT_NEAR(s.Mean() * s.Mean() + s.Variance(), NumericMoment(pdf, lo, hi, 2), 1e-9 * m * m);
  EXPECT_NEAR(s.MeanCube(), NumericMoment(pdf, lo, hi, 3), 1e-9 * m * m * m);
  CheckSamples(s);
  // Without effective cut-offs the parent's mean and standard deviation come back.
  SizeDistribution wide;
  wide.SetLognormal(m, sd, 1e-9, 1);
  EXPECT_NEAR(wide.Mean(), m, 1e-6 * m);
  EXPECT_NEAR(std::sqrt(wide.Variance()), sd, 1e-6 * sd);
}

// Mass fractions w_i become number fractions n_i ~ w_i / r_i^3: equal masses of r and r/2 are one
// large sphere to eight small ones.
TEST(SizeDistribution, DiscreteNumberFractionsFromMassFractions) {
  SizeDistribution s;
  s.SetDiscrete({1e-3, 5e-4}, {0.5, 0.5});
  const int n = 200000;
  int       large = 0;
  for (int i = 0; i < n; ++i) large += s.Radius(vofdem::random::Uniform(5, i, 6)) == 1e-3;
  const double p = 1.0 / 9;
  EXPECT_NEAR((double)large / n, p, 4 * std::sqrt(p * (1 - p) / n));
  EXPECT_NEAR(s.Mean(), p * 1e-3 + (1 - p) * 5e-4, 1e-15);
  CheckSamples(s);
}

TEST(NormalInverse, RoundTrip) {
  for (double x : {-6.0, -2.5, -0.3, 0.0, 0.7, 3.0, 5.5}) EXPECT_NEAR(vofdem::normal::InverseCdfIn(vofdem::normal::Cdf(x), -10, 10), x, 1e-8);
}

// Random fill: no overlaps, everything inside, the volume fraction reached, and the result is a
// function of the seed only.
TEST(RandomFill, NoOverlapsInsideAndFractionReached) {
  SizeDistribution s;
  s.SetUniform(2e-4, 4e-4);
  vofdem::RandomFillRequest req;
  for (int d = 0; d < 3; ++d) req.lower[d] = 0, req.upper[d] = 0.006;
  req.fraction = 0.2;
  req.seed     = 3;
  vofdem::RandomFillResult res, again;
  vofdem::RandomFill(s, req, &res);
  ASSERT_TRUE(res.complete);
  EXPECT_GE(res.fraction, 0.2);
  const size_t n = res.radius.size();
  double       solid = 0;
  for (size_t i = 0; i < n; ++i) {
    const double *x = &res.x[3 * i], r = res.radius[i];
    solid += 4.0 / 3.0 * M_PI * r * r * r;
    for (int d = 0; d < 3; ++d) ASSERT_TRUE(x[d] - r >= 0 && x[d] + r <= 0.006);
    for (size_t j = 0; j < i; ++j) {  // brute force: independent of the cell hash
      const double *y = &res.x[3 * j];
      const double  d2 = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) + (x[2] - y[2]) * (x[2] - y[2]);
      ASSERT_GE(d2, (r + res.radius[j]) * (r + res.radius[j])) << i << " overlaps " << j;
    }
  }
  EXPECT_NEAR(solid / (0.006 * 0.006 * 0.006), res.fraction, 1e-12);
  vofdem::RandomFill(s, req, &again);
  EXPECT_EQ(res.x, again.x);
  // Too dense: the fill stops incomplete below the target.
  req.fraction = 0.5;
  req.attempts = 200;
  vofdem::RandomFill(s, req, &again);
  EXPECT_FALSE(again.complete);
  EXPECT_LT(again.fraction, 0.5);
}

// A fill across a periodic direction: centres reach the faces (no radius-wide gap at the seam) and no
// two spheres overlap through the faces either (minimum-image distances, brute force). Without the
// periodic hash a pair across the seam is not seen (checked on the hash below).
TEST(RandomFill, PeriodicDirectionsHaveNoSeam) {
  SizeDistribution s;
  s.SetUniform(2e-4, 4e-4);
  vofdem::RandomFillRequest req;
  const double L = 0.006;
  for (int d = 0; d < 3; ++d) req.lower[d] = 0, req.upper[d] = L;
  req.periodic[0] = req.periodic[1] = true;  // x and y periodic, z walls
  req.fraction    = 0.25;
  req.seed        = 5;
  auto overlapsAcross = [&](const vofdem::RandomFillResult &res) {
    int          pairs = 0;
    const size_t n     = res.radius.size();
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < i; ++j) {
        double d2 = 0;
        for (int d = 0; d < 3; ++d) {
          double dx = res.x[3 * i + d] - res.x[3 * j + d];
          if (d < 2) dx -= L * std::round(dx / L);
          d2 += dx * dx;
        }
        const double rs = res.radius[i] + res.radius[j];
        pairs += d2 < rs * rs * (1 - 1e-12);
      }
    return pairs;
  };
  vofdem::RandomFillResult res;
  vofdem::RandomFill(s, req, &res);
  ASSERT_TRUE(res.complete);
  EXPECT_EQ(overlapsAcross(res), 0);
  double nearFace[2] = {1, 1};  // the closest centre to x = 0 and to y = 0, in radii of that sphere
  for (size_t i = 0; i < res.radius.size(); ++i) {
    const double *x = &res.x[3 * i], r = res.radius[i];
    for (int d = 0; d < 2; ++d) ASSERT_TRUE(x[d] >= 0 && x[d] < L);
    ASSERT_TRUE(x[2] - r >= 0 && x[2] + r <= L);  // the walls keep the margin
    for (int d = 0; d < 2; ++d) nearFace[d] = std::min({nearFace[d], x[d] / r, (L - x[d]) / r});
  }
  EXPECT_LT(nearFace[0], 0.2);  // centres closer to the faces than a radius: no gap
  EXPECT_LT(nearFace[1], 0.2);
  // The hash itself on pairs placed across the seam: without SetPeriodic they do not meet.
  vofdem::SphereHash hash;
  const PetscReal lo[3] = {0, 0, 0}, hi[3] = {L, L, L}, a[3] = {1e-4, 3e-3, 3e-3}, b[3] = {L - 1e-4, 3e-3, 3e-3};
  hash.Reset(lo, hi, 8e-4, 1000);
  hash.Add(a, 3e-4);
  EXPECT_FALSE(hash.Overlaps(b, 3e-4));  // 5.8 mm apart in the box
  hash.Reset(lo, hi, 8e-4, 1000);
  hash.SetPeriodic(0, 0, L);
  hash.Add(a, 3e-4);
  EXPECT_TRUE(hash.Overlaps(b, 3e-4));  // 0.2 mm apart across the face x = 0
  const PetscReal c[3] = {L - 1e-4, 3e-3 + 7e-4, 3e-3};
  EXPECT_FALSE(hash.Overlaps(c, 3e-4));  // across the face but 0.73 mm apart
  const PetscReal past[3] = {-2e-4, 1e-3, 1e-3}, near[3] = {L - 2e-4, 1e-3, 1e-3};
  hash.Add(past, 2e-4);  // a centre that moved past the face since its last wrap
  EXPECT_TRUE(hash.Overlaps(near, 2e-4));  // 0.4 mm from its image, radii 0.4 mm
}
