// Capillary.hpp: the kernel's interface marginal and Princen's force.
#include "vofdem/coupling/Capillary.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {
namespace capillary {

// m(t) = 2 pi G(|t|), G(r) = int_r^rc w(r') r' dr', by the trapezoidal rule on 16 sub-intervals of the
// table's spacing (accumulated from rc inward); F by the trapezoidal rule on the table, normalised by its
// last value. The grid is symmetric about t = 0 with N even, so F(0) = 1/2 and F(-t) = 1 - F(t) to
// round-off.
void Marginal::Build(kernel::Shape shape, double truncation) {
  const int N = 4000, sub = 16;
  rc_ = kernel::Cutoff(shape, 1.0, truncation);
  F_.assign(N + 1, 0.0);
  if (!(rc_ > 0)) return;
  dt_ = 2 * rc_ / N;
  std::vector<double> G(N / 2 + 1, 0.0);  // at r_j = j dt
  const double        wrc = rc_ * (1 + 1e-15), hs = dt_ / sub;
  auto                f = [&](double r) { return kernel::Weight(shape, r * r, 1.0, wrc) * r; };
  for (int j = N / 2 - 1; j >= 0; --j) {
    double sum = 0;
    for (int q = 0; q < sub; ++q) {
      const double a = j * dt_ + q * hs;
      sum += 0.5 * hs * (f(a) + f(std::min(a + hs, rc_)));
    }
    G[j] = G[j + 1] + sum;
  }
  auto m = [&](int k) { return 2 * M_PI * G[std::abs(k - N / 2)]; };
  for (int k = 1; k <= N; ++k) F_[k] = F_[k - 1] + 0.5 * dt_ * (m(k - 1) + m(k));
  const double total = F_[N];
  for (double &v : F_) v /= total;
}

double Marginal::Fraction(double t) const {
  const int N = (int)F_.size() - 1;
  if (t <= -rc_) return 0;
  if (t >= rc_) return 1;
  const double x = (t + rc_) / dt_;
  const int    k = std::min((int)x, N - 1);
  const double f = x - k;
  return (1 - f) * F_[k] + f * F_[k + 1];
}

double Marginal::Coordinate(double alpha) const {
  const int N = (int)F_.size() - 1;
  if (alpha <= 0) return -rc_;
  if (alpha >= 1) return rc_;
  int lo = 0, hi = N;  // F_[lo] < alpha <= F_[hi]
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (F_[mid] < alpha) lo = mid;
    else hi = mid;
  }
  const double dF = F_[hi] - F_[lo];
  const double f  = dF > 0 ? (alpha - F_[lo]) / dF : 0.5;
  return -rc_ + (lo + f) * dt_;
}

double PrincenForce(double R, double sigma, double theta, double s) {
  if (!(std::fabs(s) < R)) return 0;
  const double beta = std::acos(s / R);
  return -2 * M_PI * R * sigma * std::sin(beta) * std::sin(beta + theta);
}

}  // namespace capillary
}  // namespace vofdem
