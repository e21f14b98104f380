// Gauss-Legendre nodes and weights on [0, 1], by Newton's method on P_n from the usual cosine guess
// (Golub-Welsch is not needed for the small n used: the clump templates' and the analysis's
// quadratures). Exact for polynomials of degree 2n - 1.
#pragma once

#include <cmath>
#include <vector>

namespace vofdem {

inline void GaussLegendre01(int n, std::vector<double> *x, std::vector<double> *w) {
  const double pi = 3.14159265358979323846;
  x->resize(n), w->resize(n);
  for (int i = 0; i < n; ++i) {
    double t = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = p2;
      }
      dp              = n * (t * p1 - p0) / (t * t - 1);
      const double dt = p1 / dp;
      t -= dt;
      if (std::fabs(dt) < 1e-16) break;
    }
    (*x)[i] = 0.5 * (1 - t), (*w)[i] = 1.0 / ((1 - t * t) * dp * dp);  // 2/((1-t^2)P'^2), halved for [0,1]
  }
}

}  // namespace vofdem
