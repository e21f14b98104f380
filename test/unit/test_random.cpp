#include "vofdem/base/Random.hpp"

#include <gtest/gtest.h>

using vofdem::random::Uniform;

TEST(Random, DependsOnlyOnSeedKeyAndStream) {
  EXPECT_EQ(Uniform(7, 100, 2), Uniform(7, 100, 2));
  EXPECT_NE(Uniform(7, 100, 2), Uniform(8, 100, 2));
  EXPECT_NE(Uniform(7, 100, 2), Uniform(7, 101, 2));
  EXPECT_NE(Uniform(7, 100, 2), Uniform(7, 100, 1));
}

TEST(Random, UniformOnUnitInterval) {
  double sum = 0, sum2 = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double u = Uniform(12345, i, 0);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sum2 += u * u;
  }
  EXPECT_NEAR(sum / n, 0.5, 0.005);                        // mean 1/2, sigma_mean ~ 6.5e-4
  EXPECT_NEAR(sum2 / n - (sum / n) * (sum / n), 1.0 / 12, 0.002);  // variance 1/12
}
