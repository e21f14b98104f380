// PLIC geometry (Plic.hpp): volumes against a direct count, the inverse, limits of vanishing normal
// components, sub-box fractions.
#include "vofdem/vof/Plic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace vofdem;

namespace {

// Fraction of the unit cube with n.x <= alpha by the midpoint rule on an m^3 lattice.
double CountVolume(const double n[3], double alpha, int m) {
  long inside = 0;
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) inside += n[0] * (i + 0.5) / m + n[1] * (j + 0.5) / m + n[2] * (k + 0.5) / m <= alpha;
  return (double)inside / ((double)m * m * m);
}

}  // namespace

TEST(Plic, VolumeMatchesCountForRandomPlanes) {
  std::mt19937_64                        rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int t = 0; t < 40; ++t) {
    const double n[3] = {u(rng), u(rng), u(rng)};
    double       lo = 0, hi = 0;
    for (double c : n) (c < 0 ? lo : hi) += c;
    const double alpha = lo + (hi - lo) * (0.5 + 0.45 * u(rng));
    EXPECT_NEAR(plic::Volume(n, alpha), CountVolume(n, alpha, 200), 2e-3) << "plane " << t;
  }
}

TEST(Plic, KnownVolumes) {
  const double diag[3] = {1, 1, 1};
  EXPECT_NEAR(plic::Volume(diag, 1.0 / 3), 1.0 / 162, 1e-15);  // corner tetrahedron (1/3)^3 / 6
  EXPECT_NEAR(plic::Volume(diag, 1.5), 0.5, 1e-15);
  const double axis[3] = {0, 0, 2};
  EXPECT_NEAR(plic::Volume(axis, 0.6), 0.3, 1e-15);
  const double tilted[3] = {1, 1, 0};  // 2-D: triangle of legs 0.5
  EXPECT_NEAR(plic::Volume(tilted, 0.5), 0.125, 1e-15);
  const double down[3] = {0, -1, 0};  // fluid above y = 0.25
  EXPECT_NEAR(plic::Volume(down, -0.25), 0.75, 1e-15);
}

TEST(Plic, InverseRoundTripsToRoundOff) {
  std::mt19937_64                        rng(11);
  std::uniform_real_distribution<double> u(-1, 1), f(0, 1);
  for (int t = 0; t < 2000; ++t) {
    double n[3] = {u(rng), u(rng), u(rng)};
    // Components from exactly 0 down to 1e-14 of the others: the cases that cancel in the textbook formula.
    if (t % 4 == 1) n[t % 3] = 0;
    if (t % 4 == 2) n[t % 3] *= 1e-14;
    if (t % 4 == 3) n[(t + 1) % 3] *= 1e-9, n[t % 3] *= 1e-12;
    const double v = t % 10 == 0 ? 1e-13 * f(rng) : f(rng);
    const double a = plic::Alpha(n, v);
    EXPECT_NEAR(plic::Volume(n, a), v, 4e-16) << "case " << t;
  }
}

TEST(Plic, VolumeIsContinuousAsAComponentVanishes) {
  const double alphas[] = {0.1, 0.3, 0.45, 0.5, 0.62, 0.9};
  for (double a : alphas)
    for (double eps : {1e-4, 1e-8, 1e-12, 1e-15}) {
      const double n0[3] = {0.3, 0.7, 0}, n1[3] = {0.3, 0.7, eps};
      EXPECT_NEAR(plic::Volume(n1, a + 0.5 * eps), plic::Volume(n0, a), 2 * eps + 1e-15);
    }
}

TEST(Plic, BoxFractionOfASlab) {
  const double n[3] = {1, 0, 0};  // fluid in x <= 0.4
  const double lo[3] = {0.2, 0, 0}, hi[3] = {0.6, 1, 1};
  EXPECT_NEAR(plic::BoxFraction(n, 0.4, lo, hi), 0.5, 1e-15);
  const double lo2[3] = {0.5, 0, 0}, hi2[3] = {1, 1, 1};
  EXPECT_EQ(plic::BoxFraction(n, 0.4, lo2, hi2), 0.0);
}

TEST(Plic, ReducedNormalGivesTheSameNumbers) {
  std::mt19937_64                        rng(5);
  std::uniform_real_distribution<double> u(-1, 1), f(0, 1);
  for (int t = 0; t < 500; ++t) {
    double n[3] = {u(rng), u(rng), u(rng)};
    if (t % 3 == 1) n[t % 3] = 0;
    const plic::ReducedNormal r = plic::Reduce(n);
    const double              v = f(rng), a = u(rng);
    EXPECT_EQ(plic::Alpha(r, v), plic::Alpha(n, v)) << "case " << t;
    EXPECT_EQ(plic::Volume(r, a), plic::Volume(n, a)) << "case " << t;
  }
}

// The 27 fractions of the block around a cell cut by the plane n.x = c (cell units, centre cell [0,1]^3).
void CutBlock(const double n[3], double c, double block[27]) {
  const plic::ReducedNormal r = plic::Reduce(n);
  for (int z = -1, i = 0; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x, ++i) block[i] = plic::Volume(r, c - (n[0] * x + n[1] * y + n[2] * z));
}

TEST(Plic, ElviraRecoversAPlane) {
  // Planes within slope 1/2 of an axis (every 3-cell column along it holds the whole transition when the
  // plane passes near the centre): ELVIRA's normal is the plane's, whatever the fluid side.
  std::mt19937_64                        rng(17);
  std::uniform_real_distribution<double> s(-0.45, 0.45), f(0.3, 0.7), noise(-0.2, 0.2);
  int                                    youngsOff = 0;
  for (int t = 0; t < 200; ++t) {
    const int d = t % 3, sign = (t / 3) % 2 ? 1 : -1;
    double    n[3];
    for (int e = 0; e < 3; ++e) n[e] = e == d ? sign : s(rng);
    const double c = plic::Alpha(n, f(rng));
    double       block[27], young[3], out[3];
    CutBlock(n, c, block);
    for (int e = 0; e < 3; ++e) young[e] = n[e] + (e == d ? 0 : noise(rng));  // a rough first guess, the fluid side right
    plic::Elvira(block, young, out);
    const double scale = out[d] / n[d];
    for (int e = 0; e < 3; ++e) EXPECT_NEAR(out[e], scale * n[e], 1e-12) << "case " << t << " component " << e;
    // Youngs' (1,2,1)-weighted gradient of the same block is not exact for a tilted plane
    double       g[3] = {0, 0, 0};
    const double w[3] = {1, 2, 1};
    auto         at   = [&](int x, int y, int z) { return block[9 * (z + 1) + 3 * (y + 1) + (x + 1)]; };
    for (int c = -1; c <= 1; ++c)
      for (int b = -1; b <= 1; ++b) {
        g[0] -= w[b + 1] * w[c + 1] * (at(1, b, c) - at(-1, b, c));
        g[1] -= w[b + 1] * w[c + 1] * (at(b, 1, c) - at(b, -1, c));
        g[2] -= w[b + 1] * w[c + 1] * (at(b, c, 1) - at(b, c, -1));
      }
    double worst = 0;
    for (int e = 0; e < 3; ++e) worst = std::max(worst, std::fabs(g[e] / g[d] - n[e] / n[d]));
    youngsOff += worst > 1e-3;
  }
  EXPECT_GT(youngsOff, 100) << "Youngs' normal was within 1e-3 of the plane's in most cases: the test does not tell ELVIRA from it";
}

