#include "vofdem/coupling/Kernel.hpp"

#include <vector>

namespace vofdem {
namespace kernel {

// Quadrature of Kernel.hpp's formula: the normalised transform g^(k) = int g r^2 sin(kr)/(kr) dr /
// int g r^2 dr by Simpson's rule over [0, rc], then int |g^|^2 dk by Simpson's rule up to 80/H,
// where |g^|^2 has fallen below 1e-9 of its peak for these kernels (the truncated Gaussian's jump
// makes g^ decay as 1/k^2 only: its tail beyond 80/H adds ~ 1e-7 relative).
double SelfDisturbanceCoefficient(Shape s, double H, double truncation) {
  if (s == Shape::Unresolved) return 0;
  const double rc = Cutoff(s, H, truncation);
  const int    M  = 800, K = 4000;  // even
  std::vector<double> r(M + 1), gw(M + 1);
  double       mass = 0;
  for (int i = 0; i <= M; ++i) {
    r[i] = rc * i / M;
    const double simpson = (i == 0 || i == M) ? 1 : (i % 2 ? 4 : 2);
    gw[i] = simpson * Weight(s, r[i] * r[i], H, rc * (1 + 1e-15)) * r[i] * r[i];
    mass += gw[i];
  }
  const double kmax = 80 / H;
  double       integral = 0;
  for (int j = 0; j <= K; ++j) {
    const double k = kmax * j / K;
    double       gh = 0;
    for (int i = 0; i <= M; ++i) {
      const double kr = k * r[i];
      gh += gw[i] * (kr < 1e-8 ? 1 - kr * kr / 6 : std::sin(kr) / kr);
    }
    gh /= mass;
    const double simpson = (j == 0 || j == K) ? 1 : (j % 2 ? 4 : 2);
    integral += simpson * gh * gh;
  }
  integral *= kmax / K / 3;
  return integral / (3 * M_PI * M_PI);
}

}  // namespace kernel
}  // namespace vofdem
