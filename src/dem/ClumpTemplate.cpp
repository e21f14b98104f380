// Mass properties of a clump template: the union of overlapping spheres (ClumpTemplate.hpp, P10).
#include "vofdem/dem/ClumpTemplate.hpp"

#include "vofdem/base/GaussLegendre.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

namespace vofdem {

namespace {

// sum over pieces between sorted breakpoints in [a, b] of the smoothed Gauss rule applied to f.
template <typename F>
void Pieces(std::vector<double> breaks, double a, double b, const std::vector<double> &gx, const std::vector<double> &gw, F &&f) {
  breaks.push_back(a), breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double lo = std::max(a, breaks[k]), hi = std::min(b, breaks[k + 1]);
    if (!(hi > lo)) continue;
    for (size_t i = 0; i < gx.size(); ++i) {
      const double s = gx[i];
      f(lo + (hi - lo) * s * s * (3 - 2 * s), (hi - lo) * gw[i] * 6 * s * (1 - s));
    }
  }
}

// The circle where the surfaces of two spheres meet: centre, radius, and two unit vectors u, v of its
// plane. False when the surfaces do not meet.
struct Circle {
  double c[3], rho, u[3], v[3];
};
bool Intersection(const ClumpSphere &a, const ClumpSphere &b, Circle *k) {
  double n[3] = {b.x[0] - a.x[0], b.x[1] - a.x[1], b.x[2] - a.x[2]};
  const double d = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(d > std::fabs(a.r - b.r)) || !(d < a.r + b.r)) return false;
  for (double &e : n) e /= d;
  const double t = (d * d + a.r * a.r - b.r * b.r) / (2 * d);
  k->rho         = std::sqrt(std::max(0.0, a.r * a.r - t * t));
  for (int i = 0; i < 3; ++i) k->c[i] = a.x[i] + t * n[i];
  // u: the unit vector of the coordinate axis least aligned with n, made normal to n; v = n x u.
  int m = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(n[i]) < std::fabs(n[m])) m = i;
  double u[3] = {0, 0, 0};
  u[m]        = 1;
  const double un = u[0] * n[0] + u[1] * n[1] + u[2] * n[2];
  for (int i = 0; i < 3; ++i) u[i] -= un * n[i];
  const double ul = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (int i = 0; i < 3; ++i) k->u[i] = u[i] / ul;
  k->v[0] = n[1] * k->u[2] - n[2] * k->u[1], k->v[1] = n[2] * k->u[0] - n[0] * k->u[2], k->v[2] = n[0] * k->u[1] - n[1] * k->u[0];
  return true;
}

}  // namespace

void SymmetricEigen(int n, const PetscReal *A, PetscReal *values, PetscReal *vectors) {
  // Cyclic Jacobi rotations on a copy; vectors accumulate the rotations (columns).
  std::vector<double> a(n * n), v(n * n, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a[i * n + j] = 0.5 * (A[i * n + j] + A[j * n + i]);
  for (int i = 0; i < n; ++i) v[i * n + i] = 1;
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0, diag = 0;
    for (int i = 0; i < n; ++i) {
      diag += a[i * n + i] * a[i * n + i];
      for (int j = i + 1; j < n; ++j) off += a[i * n + j] * a[i * n + j];
    }
    if (off == 0 || off <= 1e-30 * diag) break;
    for (int p = 0; p < n - 1; ++p)
      for (int q = p + 1; q < n; ++q) {
        if (a[p * n + q] == 0) continue;
        const double theta = (a[q * n + q] - a[p * n + p]) / (2 * a[p * n + q]);
        const double t     = (theta >= 0 ? 1 : -1) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < n; ++k) {  // A <- A J (columns p, q)
          const double akp = a[k * n + p], akq = a[k * n + q];
          a[k * n + p] = c * akp - s * akq, a[k * n + q] = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {  // A <- J^T A (rows p, q)
          const double apk = a[p * n + k], aqk = a[q * n + k];
          a[p * n + k] = c * apk - s * aqk, a[q * n + k] = s * apk + c * aqk;
        }
        for (int k = 0; k < n; ++k) {
          const double vkp = v[k * n + p], vkq = v[k * n + q];
          v[k * n + p] = c * vkp - s * vkq, v[k * n + q] = s * vkp + c * vkq;
        }
      }
  }
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int i, int j) { return a[i * n + i] < a[j * n + j]; });
  for (int c = 0; c < n; ++c) {
    values[c] = a[order[c] * n + order[c]];
    for (int k = 0; k < n; ++k) vectors[k * n + c] = v[k * n + order[c]];
  }
}

void SymmetricEigen3(const PetscReal A[9], PetscReal values[3], PetscReal vectors[9]) {
  SymmetricEigen(3, A, values, vectors);
  // Right-handed: third column = first x second.
  const PetscReal *e = vectors;
  const PetscReal  cx = e[3] * e[7] - e[6] * e[4], cy = e[6] * e[1] - e[0] * e[7], cz = e[0] * e[4] - e[3] * e[1];
  if (cx * e[2] + cy * e[5] + cz * e[8] < 0)
    for (int k = 0; k < 3; ++k) vectors[3 * k + 2] = -vectors[3 * k + 2];
}

void ClumpTemplate::Compute(int nodes) {
  nodes = std::max(nodes, 2);
  std::vector<double> gx, gw;
  GaussLegendre01(nodes, &gx, &gw);
  // Moments of the union: m[0] = V, m[1..3] = int x, y, z, m[4..9] = int xx, yy, zz, xy, xz, yz.
  double              m[10] = {0};
  double              xlo = HUGE_VAL, xhi = -HUGE_VAL;
  std::vector<double> xb;
  for (const auto &s : spheres) xlo = std::min(xlo, s.x[0] - s.r), xhi = std::max(xhi, s.x[0] + s.r), xb.push_back(s.x[0] - s.r), xb.push_back(s.x[0] + s.r);
  // Where two spheres' chords start to overlap (over their intersection circle) the integrand has a
  // kink: the circles' x extents are breakpoints in x, their points at each x breakpoints in y.
  std::vector<Circle> circles;
  for (size_t i = 0; i < spheres.size(); ++i)
    for (size_t j = i + 1; j < spheres.size(); ++j) {
      Circle k;
      if (!Intersection(spheres[i], spheres[j], &k)) continue;
      circles.push_back(k);
      const double ext = k.rho * std::hypot(k.u[0], k.v[0]);
      xb.push_back(k.c[0] - ext), xb.push_back(k.c[0] + ext);
    }
  std::vector<std::pair<double, double>> chords;
  Pieces(xb, xlo, xhi, gx, gw, [&](double x, double wx) {
    std::vector<double> yb;
    double              ylo = HUGE_VAL, yhi = -HUGE_VAL;
    for (const auto &s : spheres) {
      const double q = s.r * s.r - (x - s.x[0]) * (x - s.x[0]);
      if (q <= 0) continue;
      const double rho = std::sqrt(q);
      yb.push_back(s.x[1] - rho), yb.push_back(s.x[1] + rho), ylo = std::min(ylo, s.x[1] - rho), yhi = std::max(yhi, s.x[1] + rho);
    }
    if (!(yhi > ylo)) return;
    for (const Circle &k : circles) {  // c_x + rho (cos t u_x + sin t v_x) = x
      const double A = k.u[0], B = k.v[0], K = std::hypot(A, B), q = (x - k.c[0]) / k.rho;
      if (!(K > 0) || std::fabs(q) > K) continue;
      const double t0 = std::atan2(B, A), dt = std::acos(std::clamp(q / K, -1.0, 1.0));
      for (double t : {t0 + dt, t0 - dt}) yb.push_back(k.c[1] + k.rho * (std::cos(t) * k.u[1] + std::sin(t) * k.v[1]));
    }
    Pieces(yb, ylo, yhi, gx, gw, [&](double y, double wy) {
      chords.clear();
      for (const auto &s : spheres) {
        const double q = s.r * s.r - (x - s.x[0]) * (x - s.x[0]) - (y - s.x[1]) * (y - s.x[1]);
        if (q > 0) chords.emplace_back(s.x[2] - std::sqrt(q), s.x[2] + std::sqrt(q));
      }
      std::sort(chords.begin(), chords.end());
      double       l = 0, z1 = 0, z2 = 0;  // int dz, z dz, z^2 dz over the union of the chords
      const double w = wx * wy;
      for (size_t k = 0; k < chords.size();) {
        double a = chords[k].first, b = chords[k].second;
        for (++k; k < chords.size() && chords[k].first <= b; ++k) b = std::max(b, chords[k].second);
        l += b - a, z1 += 0.5 * (b * b - a * a), z2 += (b * b * b - a * a * a) / 3;
      }
      m[0] += w * l, m[1] += w * x * l, m[2] += w * y * l, m[3] += w * z1;
      m[4] += w * x * x * l, m[5] += w * y * y * l, m[6] += w * z2, m[7] += w * x * y * l, m[8] += w * x * z1, m[9] += w * y * z1;
    });
  });
  volume = m[0];
  for (int d = 0; d < 3; ++d) centroid[d] = m[1 + d] / volume;
  // Second moments about the centroid, then I = tr(S) 1 - S.
  const double *c     = centroid;
  const double  S[9] = {m[4] - volume * c[0] * c[0], m[7] - volume * c[0] * c[1], m[8] - volume * c[0] * c[2],
                        m[7] - volume * c[0] * c[1], m[5] - volume * c[1] * c[1], m[9] - volume * c[1] * c[2],
                        m[8] - volume * c[0] * c[2], m[9] - volume * c[1] * c[2], m[6] - volume * c[2] * c[2]};
  const double  tr   = S[0] + S[4] + S[8];
  for (int k = 0; k < 9; ++k) inertia[k] = (k % 4 == 0 ? tr : 0) - S[k];
  SymmetricEigen3(inertia, principal, axes);
  body.assign(3 * spheres.size(), 0);
  boundingRadius = 0;
  for (size_t k = 0; k < spheres.size(); ++k) {
    const double r[3] = {spheres[k].x[0] - c[0], spheres[k].x[1] - c[1], spheres[k].x[2] - c[2]};
    double       len2 = 0;
    for (int a = 0; a < 3; ++a) {  // body = axes^T r
      body[3 * k + a] = axes[a] * r[0] + axes[3 + a] * r[1] + axes[6 + a] * r[2];
      len2 += body[3 * k + a] * body[3 * k + a];
    }
    boundingRadius = std::max(boundingRadius, std::sqrt(len2) + spheres[k].r);
  }
}

}  // namespace vofdem
