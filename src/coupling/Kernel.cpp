#include "vofdem/coupling/Kernel.hpp"

#include <vector>

namespace vofdem {
namespace kernel {

// Oseen's angular factor J(a) of Kernel.hpp (a series for small a, where the closed form cancels).
static double OseenJ(double a) {
  if (a < 1e-2) return 4.0 / 3.0 - 4.0 / 15.0 * a * a + 4.0 / 35.0 * a * a * a * a;
  const double I0 = 2 * std::atan(a) / a;
  return I0 * (1 + 1 / (a * a)) - 2 / (a * a);
}

// Quadrature of Kernel.hpp's formula at H = 1: the normalised transform g^(k) = int g r^2 sin(kr)/(kr) dr
// / int g r^2 dr by Simpson's rule over [0, rc], then int |g^|^2 J dk by Simpson's rule in x up to
// k = 80 with k = 80 x^2, which resolves J's change near k = Re_H even at small Re_H; |g^|^2 has
// fallen below 1e-9 of its peak by k = 80 for these kernels (the truncated Gaussian's jump makes g^
// decay as 1/k^2 only: its tail beyond adds ~ 1e-7 relative).
std::vector<double> SelfDisturbanceTable(Shape s, double truncation, const std::vector<double> &ReH) {
  std::vector<double> out(ReH.size(), 0.0);
  if (CellBased(s) || s == Shape::Linear) return out;
  const double rc = Cutoff(s, 1.0, truncation);
  const int    M  = 800, K = 4000;  // even
  std::vector<double> r(M + 1), gw(M + 1), g2(K + 1);
  double       mass = 0;
  for (int i = 0; i <= M; ++i) {
    r[i] = rc * i / M;
    const double simpson = (i == 0 || i == M) ? 1 : (i % 2 ? 4 : 2);
    gw[i] = simpson * Weight(s, r[i] * r[i], 1.0, rc * (1 + 1e-15)) * r[i] * r[i];
    mass += gw[i];
  }
  const double kmax = 80;
  for (int j = 0; j <= K; ++j) {
    const double k = kmax * (double)j * j / ((double)K * K);
    double       gh = 0;
    for (int i = 0; i <= M; ++i) {
      const double kr = k * r[i];
      gh += gw[i] * (kr < 1e-8 ? 1 - kr * kr / 6 : std::sin(kr) / kr);
    }
    gh /= mass;
    g2[j] = gh * gh;
  }
  for (size_t q = 0; q < ReH.size(); ++q) {
    double integral = 0;
    for (int j = 1; j <= K; ++j) {  // the point k = 0 has dk/dx = 0
      const double x = (double)j / K, k = kmax * x * x, simpson = j == K ? 1 : (j % 2 ? 4 : 2);
      // J(W/(nu k)) with W/nu = Re_H at H = 1.
      integral += simpson * g2[j] * OseenJ(ReH[q] / k) * 2 * kmax * x;
    }
    out[q] = integral / K / 3 / (4 * M_PI * M_PI);
  }
  return out;
}

}  // namespace kernel
}  // namespace vofdem
