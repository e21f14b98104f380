#include "vofdem/analysis/Geometry.hpp"

#include "vofdem/base/GaussLegendre.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <vector>

namespace vofdem::analysis {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Gauss-Legendre nodes and weights on [0, 1] (base/GaussLegendre.hpp), computed once per n.
struct GaussLegendre {
  std::vector<double> x, w;
  explicit GaussLegendre(int n) { GaussLegendre01(n, &x, &w); }
};

const GaussLegendre &Rule(int n) {
  static std::deque<GaussLegendre> rules;  // a deque: references stay valid as it grows
  for (const auto &g : rules)
    if ((int)g.x.size() == n) return g;
  rules.emplace_back(n);
  return rules.back();
}

// Integral of area(z) over [za, zb], split at the breakpoints, with the end-smoothing substitution.
double IntegrateSlices(double za, double zb, std::vector<double> breaks, int nodes, const std::function<double(double)> &area) {
  if (!(zb > za)) return 0;
  breaks.push_back(za), breaks.push_back(zb);
  std::sort(breaks.begin(), breaks.end());
  const GaussLegendre &g   = Rule(nodes);
  double               sum = 0;
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = std::max(breaks[k], za), b = std::min(breaks[k + 1], zb);
    if (!(b > a)) continue;
    double piece = 0;
    for (int i = 0; i < nodes; ++i) {
      const double s = g.x[i];
      piece += g.w[i] * 6 * s * (1 - s) * area(a + (b - a) * s * s * (3 - 2 * s));
    }
    sum += (b - a) * piece;
  }
  return sum;
}

// Heights z where the slice radius sqrt(r^2 - (z - cz)^2) equals dist.
void AddBreaks(double cz, double r, double dist, std::vector<double> *breaks) {
  const double q = r * r - dist * dist;
  if (q > 0) breaks->push_back(cz - std::sqrt(q)), breaks->push_back(cz + std::sqrt(q));
}

// Area of {x^2 + y^2 <= rho^2, x <= X, y <= Y}.
double Quadrant(double rho, double X, double Y) {
  if (!(rho > 0)) return 0;
  const double x = std::clamp(X, -rho, rho);
  if (x <= -rho || Y <= -rho) return 0;
  // P(t) = integral of sqrt(rho^2 - u^2) du from 0 to t
  auto P = [rho](double t) {
    t = std::clamp(t, -rho, rho);
    return 0.5 * (t * std::sqrt(std::max(0.0, rho * rho - t * t)) + rho * rho * std::asin(t / rho));
  };
  if (Y >= rho) return 2 * (P(x) - P(-rho));
  // Columns |u| < w are cut by y = Y (height Y + s(u)); outside, the column is whole (2 s(u)) when
  // Y >= 0, empty when Y < 0.
  const double w   = std::sqrt(rho * rho - Y * Y);
  double       sum = 0;
  if (Y >= 0) sum += 2 * (P(std::min(-w, x)) - P(-rho));
  if (x > -w) {
    const double b = std::min(w, x);
    sum += Y * (b + w) + P(b) - P(-w);
  }
  if (Y >= 0 && x > w) sum += 2 * (P(x) - P(w));
  return sum;
}

}  // namespace

double DiscRectangleArea(double rho, double x0, double x1, double y0, double y1) {
  if (!(x1 > x0) || !(y1 > y0)) return 0;
  return Quadrant(rho, x1, y1) - Quadrant(rho, x0, y1) - Quadrant(rho, x1, y0) + Quadrant(rho, x0, y0);
}

double DiscDiscArea(double a, double b, double d) {
  if (!(a > 0) || !(b > 0) || d >= a + b) return 0;
  if (d <= std::fabs(a - b)) return kPi * std::min(a, b) * std::min(a, b);
  const double ca = std::clamp((d * d + a * a - b * b) / (2 * d * a), -1.0, 1.0);
  const double cb = std::clamp((d * d + b * b - a * a) / (2 * d * b), -1.0, 1.0);
  const double k  = (-d + a + b) * (d + a - b) * (d - a + b) * (d + a + b);
  return a * a * std::acos(ca) + b * b * std::acos(cb) - 0.5 * std::sqrt(std::max(0.0, k));
}

double SphereBoxVolume(const double c[3], double r, const double lo[3], const double hi[3], int nodes) {
  for (int d = 0; d < 3; ++d)
    if (c[d] + r <= lo[d] || c[d] - r >= hi[d]) return 0;
  const double x0 = lo[0] - c[0], x1 = hi[0] - c[0], y0 = lo[1] - c[1], y1 = hi[1] - c[1];
  // Whole sphere inside: skip the quadrature (most spheres of a window).
  if (x0 <= -r && x1 >= r && y0 <= -r && y1 >= r && lo[2] <= c[2] - r && hi[2] >= c[2] + r) return 4.0 / 3.0 * kPi * r * r * r;
  std::vector<double> breaks;
  for (double dx : {x0, x1}) AddBreaks(c[2], r, dx, &breaks);
  for (double dy : {y0, y1}) AddBreaks(c[2], r, dy, &breaks);
  for (double dx : {x0, x1})
    for (double dy : {y0, y1}) AddBreaks(c[2], r, std::hypot(dx, dy), &breaks);
  return IntegrateSlices(std::max(lo[2], c[2] - r), std::min(hi[2], c[2] + r), breaks, nodes, [&](double z) {
    const double rho = std::sqrt(std::max(0.0, r * r - (z - c[2]) * (z - c[2])));
    return DiscRectangleArea(rho, x0, x1, y0, y1);
  });
}

double Ring::Volume() const { return kPi * (outer * outer - inner * inner) * (z1 - z0); }

bool Ring::Contains(const double p[3]) const {
  const double d2 = (p[0] - x) * (p[0] - x) + (p[1] - y) * (p[1] - y);
  return p[2] >= z0 && p[2] <= z1 && d2 <= outer * outer && d2 >= inner * inner;
}

double SphereRingVolume(const double c[3], double r, const Ring &ring, int nodes) {
  const double D = std::hypot(c[0] - ring.x, c[1] - ring.y);
  if (D - r >= ring.outer || c[2] + r <= ring.z0 || c[2] - r >= ring.z1) return 0;
  std::vector<double> breaks;
  for (double R : {ring.inner, ring.outer})
    if (R > 0) AddBreaks(c[2], r, D + R, &breaks), AddBreaks(c[2], r, std::fabs(D - R), &breaks);
  return IntegrateSlices(std::max(ring.z0, c[2] - r), std::min(ring.z1, c[2] + r), breaks, nodes, [&](double z) {
    const double rho = std::sqrt(std::max(0.0, r * r - (z - c[2]) * (z - c[2])));
    return DiscDiscArea(rho, ring.outer, D) - (ring.inner > 0 ? DiscDiscArea(rho, ring.inner, D) : 0.0);
  });
}

}  // namespace vofdem::analysis
