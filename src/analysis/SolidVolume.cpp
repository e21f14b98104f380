// Solid volume inside a window or a cutting ring, clump overlaps counted once (SolidVolume.hpp).
#include "vofdem/analysis/SolidVolume.hpp"

#include "vofdem/analysis/PowderMetrics.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace vofdem::analysis {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The shifts of a body at c (every point within `reach` of c in each direction) whose periodic
// images may reach into [lo, hi] (shift 0 always); f gets the image's centre.
template <typename F>
void ForImages(const Spheres &s, const double c[3], double reach, const double lo[3], const double hi[3], F &&f) {
  double shifts[3][3];
  int    counts[3];
  for (int d = 0; d < 3; ++d) {
    counts[d] = 0;
    shifts[d][counts[d]++] = 0;
    if (!s.periodic[d]) continue;
    const double L = s.upper[d] - s.lower[d];
    for (double sh : {-L, L})
      if (c[d] + sh + reach > lo[d] && c[d] + sh - reach < hi[d]) shifts[d][counts[d]++] = sh;
  }
  for (int a = 0; a < counts[0]; ++a)
    for (int b = 0; b < counts[1]; ++b)
      for (int e = 0; e < counts[2]; ++e) {
        const double p[3] = {c[0] + shifts[0][a], c[1] + shifts[1][b], c[2] + shifts[2][e]};
        f(p);
      }
}

// A box window as a region: exact sphere volumes, and a midpoint lattice of columns over the part of
// a box [lo, hi]'s footprint inside the window (aligned to that rectangle: no cell is cut).
struct BoxRegion {
  const Window &w;
  const double *Lo() const { return w.lo; }
  const double *Hi() const { return w.hi; }
  double        Z0() const { return w.lo[2]; }
  double        Z1() const { return w.hi[2]; }
  double        Sphere(const double c[3], double r) const { return SphereBoxVolume(c, r, w.lo, w.hi); }
  bool          Misses(const double lo[3], const double hi[3]) const {
    for (int d = 0; d < 3; ++d)
      if (!(hi[d] > w.lo[d] && lo[d] < w.hi[d])) return true;
    return false;
  }
  bool Holds(const double lo[3], const double hi[3]) const {
    for (int d = 0; d < 3; ++d)
      if (lo[d] < w.lo[d] || hi[d] > w.hi[d]) return false;
    return true;
  }
  // Integral of col(x, y) over the footprint of [lo, hi] inside the window: lattice spacing at most
  // h, and at least n points along each side (a small window is resolved as finely as a clump).
  template <typename F>
  double Columns(const double lo[3], const double hi[3], double h, int n, F &&col) const {
    const double x0 = std::max(lo[0], w.lo[0]), x1 = std::min(hi[0], w.hi[0]), y0 = std::max(lo[1], w.lo[1]), y1 = std::min(hi[1], w.hi[1]);
    if (!(x1 > x0) || !(y1 > y0)) return 0;
    const int    nx = std::max(n, (int)std::ceil((x1 - x0) / h)), ny = std::max(n, (int)std::ceil((y1 - y0) / h));
    const double dx = (x1 - x0) / nx, dy = (y1 - y0) / ny;
    double       sum = 0;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) sum += col(x0 + (i + 0.5) * dx, y0 + (j + 0.5) * dy);
    return sum * dx * dy;
  }
};

// A ring as a region: exact sphere volumes, and a polar midpoint lattice about the ring's axis over
// the part of a box's footprint inside the annulus (aligned to the ring's circles).
struct RingRegion {
  const Ring &g;
  double      lo[3], hi[3];
  explicit RingRegion(const Ring &ring) : g(ring), lo{ring.x - ring.outer, ring.y - ring.outer, ring.z0}, hi{ring.x + ring.outer, ring.y + ring.outer, ring.z1} {}
  const double *Lo() const { return lo; }
  const double *Hi() const { return hi; }
  double        Z0() const { return g.z0; }
  double        Z1() const { return g.z1; }
  double        Sphere(const double c[3], double r) const { return SphereRingVolume(c, r, g); }
  // Nearest and farthest distance of the rectangle [lo, hi] (x, y) from the axis.
  void Distances(const double l[3], const double u[3], double *nearest, double *farthest) const {
    const double nx = std::clamp(g.x, l[0], u[0]) - g.x, ny = std::clamp(g.y, l[1], u[1]) - g.y;
    const double fx = std::max(std::fabs(l[0] - g.x), std::fabs(u[0] - g.x)), fy = std::max(std::fabs(l[1] - g.y), std::fabs(u[1] - g.y));
    *nearest = std::hypot(nx, ny), *farthest = std::hypot(fx, fy);
  }
  bool Misses(const double l[3], const double u[3]) const {
    double n, f;
    Distances(l, u, &n, &f);
    return !(u[2] > g.z0 && l[2] < g.z1) || n >= g.outer || f <= g.inner;
  }
  bool Holds(const double l[3], const double u[3]) const {
    double n, f;
    Distances(l, u, &n, &f);
    return l[2] >= g.z0 && u[2] <= g.z1 && f <= g.outer && n >= g.inner;
  }
  template <typename F>
  double Columns(const double l[3], const double u[3], double h, int n, F &&col) const {
    // The rectangle's circumscribed circle (centre c, radius rho) bounds the radii and angles.
    const double cx = 0.5 * (l[0] + u[0]) - g.x, cy = 0.5 * (l[1] + u[1]) - g.y, rho = 0.5 * std::hypot(u[0] - l[0], u[1] - l[1]);
    const double D = std::hypot(cx, cy), r0 = std::max(g.inner, D - rho), r1 = std::min(g.outer, D + rho);
    if (!(r1 > r0)) return 0;
    double t0 = 0, t1 = 2 * kPi;
    if (D > rho) {
      const double half = std::asin(rho / D), tc = std::atan2(cy, cx);
      t0 = tc - half, t1 = tc + half;
    }
    const int    nr = std::max(n, (int)std::ceil((r1 - r0) / h)), nt = std::max(n, (int)std::ceil((t1 - t0) * r1 / h));
    const double dr = (r1 - r0) / nr, dt = (t1 - t0) / nt;
    double       sum = 0;
    for (int j = 0; j < nt; ++j) {
      const double t = t0 + (j + 0.5) * dt, ct = std::cos(t), st = std::sin(t);
      for (int i = 0; i < nr; ++i) {
        const double r = r0 + (i + 0.5) * dr, x = g.x + r * ct, y = g.y + r * st;
        if (x < l[0] || x > u[0] || y < l[1] || y > u[1]) continue;
        sum += r * col(x, y);
      }
    }
    return sum * dr * dt;
  }
};

}  // namespace

ClumpUnions::ClumpUnions(const Spheres &s, int resolution) : resolution_(std::max(1, resolution)), loose_(s.Size(), 1) {
  if (s.clump.empty()) return;
  std::map<std::int64_t, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < s.Size(); ++i)
    if (s.clump[i] >= 0) groups[s.clump[i]].push_back(i);
  start_.push_back(0);
  for (const auto &[id, members] : groups) {
    if (members.size() < 2) continue;  // a one-sphere clump is a sphere
    const std::size_t first = members[0], b = member_.size(), n = members.size();
    double            lo[3], hi[3], lensLo[3], lensHi[3], rmax = 0;
    for (int d = 0; d < 3; ++d) lo[d] = lensLo[d] = HUGE_VAL, hi[d] = lensHi[d] = -HUGE_VAL;
    for (std::size_t i : members) {
      loose_[i] = 0, member_.push_back(i), radius_.push_back(s.r[i]), lens_.push_back(0), rmax = std::max(rmax, s.r[i]);
      for (int d = 0; d < 3; ++d) {  // the minimum image of the first member
        double e = s.x[3 * i + d] - s.x[3 * first + d];
        if (s.periodic[d]) e -= (s.upper[d] - s.lower[d]) * std::round(e / (s.upper[d] - s.lower[d]));
        centre_.push_back(s.x[3 * first + d] + e);
        lo[d] = std::min(lo[d], centre_.back() - s.r[i]), hi[d] = std::max(hi[d], centre_.back() + s.r[i]);
      }
    }
    for (std::size_t p = b; p < b + n; ++p)
      for (std::size_t q = p + 1; q < b + n; ++q) {
        const double *a = &centre_[3 * p], *e = &centre_[3 * q];
        if (!(std::hypot(a[0] - e[0], a[1] - e[1], a[2] - e[2]) < radius_[p] + radius_[q])) continue;
        lens_[p] = lens_[q] = 1;
        for (int d = 0; d < 3; ++d)  // the lens lies in both spheres' boxes
          lensLo[d] = std::min(lensLo[d], std::max(a[d] - radius_[p], e[d] - radius_[q])), lensHi[d] = std::max(lensHi[d], std::min(a[d] + radius_[p], e[d] + radius_[q]));
      }
    start_.push_back(member_.size());
    box_.insert(box_.end(), lo, lo + 3), box_.insert(box_.end(), hi, hi + 3);
    lensBox_.insert(lensBox_.end(), lensLo, lensLo + 3), lensBox_.insert(lensBox_.end(), lensHi, lensHi + 3);
    step_.push_back(2 * rmax / resolution_);
    maxMembers_ = std::max(maxMembers_, n);
  }
  // The whole overlap of each clump: the quadrature over its lenses' box.
  std::vector<double> scratch;
  const double        zero[3] = {0, 0, 0};
  overlap_.assign(Count(), 0);
  for (std::size_t c = 0; c < Count(); ++c) {
    if (!HasLens(c)) continue;
    Window w;
    for (int d = 0; d < 3; ++d) w.lo[d] = lensBox_[6 * c + d], w.hi[d] = lensBox_[6 * c + 3 + d];
    overlap_[c] = Quadrature(c, zero, BoxRegion{w}, &scratch);
  }
}

double ClumpUnions::UnionVolume(std::size_t c) const {
  double sum = -overlap_[c];
  for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) sum += 4.0 / 3.0 * kPi * radius_[k] * radius_[k] * radius_[k];
  return sum;
}

template <class Region>
double ClumpUnions::Quadrature(std::size_t c, const double shift[3], const Region &g, std::vector<double> *scratch) const {
  // The members in a lens, moved by the shift: x, y, z, r each.
  scratch->resize(6 * maxMembers_);
  double *m = scratch->data(), *iv = m + 4 * maxMembers_;  // iv: chords (lo, hi), kept sorted by lo
  int     n = 0;
  for (std::size_t k = start_[c]; k < start_[c + 1]; ++k)
    if (lens_[k]) {
      for (int d = 0; d < 3; ++d) m[4 * n + d] = centre_[3 * k + d] + shift[d];
      m[4 * n + 3] = radius_[k], ++n;
    }
  const double za = g.Z0(), zb = g.Z1();
  // (sum of the chords' lengths in [za, zb]) - (length of their union) at the column (x, y).
  auto column = [&](double x, double y) {
    int    count = 0;
    double sum   = 0;
    for (int k = 0; k < n; ++k) {
      const double dx = x - m[4 * k], dy = y - m[4 * k + 1], q = m[4 * k + 3] * m[4 * k + 3] - dx * dx - dy * dy;
      if (!(q > 0)) continue;
      const double h = std::sqrt(q), a = std::max(za, m[4 * k + 2] - h), b = std::min(zb, m[4 * k + 2] + h);
      if (!(b > a)) continue;
      int p = count++;
      for (; p > 0 && iv[2 * (p - 1)] > a; --p) iv[2 * p] = iv[2 * (p - 1)], iv[2 * p + 1] = iv[2 * (p - 1) + 1];
      iv[2 * p] = a, iv[2 * p + 1] = b, sum += b - a;
    }
    if (count < 2) return 0.0;
    double joined = 0, lo = iv[0], hi = iv[1];
    for (int p = 1; p < count; ++p) {
      if (iv[2 * p] > hi) joined += hi - lo, lo = iv[2 * p], hi = iv[2 * p + 1];
      else hi = std::max(hi, iv[2 * p + 1]);
    }
    return sum - (joined + hi - lo);
  };
  double lo[3], hi[3];
  for (int d = 0; d < 3; ++d) lo[d] = lensBox_[6 * c + d] + shift[d], hi[d] = lensBox_[6 * c + 3 + d] + shift[d];
  return g.Columns(lo, hi, step_[c], resolution_, column);
}

template <class Region>
double ClumpUnions::Overlap(std::size_t c, const double shift[3], const Region &g, std::vector<double> *scratch) const {
  if (!HasLens(c)) return 0;
  double lo[3], hi[3];
  for (int d = 0; d < 3; ++d) lo[d] = lensBox_[6 * c + d] + shift[d], hi[d] = lensBox_[6 * c + 3 + d] + shift[d];
  if (g.Misses(lo, hi)) return 0;
  if (g.Holds(lo, hi)) return overlap_[c];
  return Quadrature(c, shift, g, scratch);
}

template <class Region>
double ClumpUnions::InsideOf(const Spheres &s, const Region &g) const {
  double              solid = 0;
  std::vector<double> scratch;
  for (std::size_t i = 0; i < s.Size(); ++i)
    if (loose_[i]) ForImages(s, &s.x[3 * i], s.r[i], g.Lo(), g.Hi(), [&](const double p[3]) { solid += g.Sphere(p, s.r[i]); });
  for (std::size_t c = 0; c < Count(); ++c) {
    const double *lo = &box_[6 * c], *hi = lo + 3;
    const double  mid[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
    const double  reach  = 0.5 * std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    ForImages(s, mid, reach, g.Lo(), g.Hi(), [&](const double p[3]) {
      const double shift[3] = {p[0] - mid[0], p[1] - mid[1], p[2] - mid[2]};
      for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) {
        const double q[3] = {centre_[3 * k] + shift[0], centre_[3 * k + 1] + shift[1], centre_[3 * k + 2] + shift[2]};
        solid += g.Sphere(q, radius_[k]);
      }
      solid -= Overlap(c, shift, g, &scratch);
    });
  }
  return solid;
}

double ClumpUnions::Inside(const Spheres &s, const Window &w) const { return InsideOf(s, BoxRegion{w}); }
double ClumpUnions::Inside(const Spheres &s, const Ring &g) const { return InsideOf(s, RingRegion(g)); }

}  // namespace vofdem::analysis
