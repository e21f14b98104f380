#include "vofdem/vof/Plic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vofdem {
namespace plic {

namespace {

// Volume under m.x = a in the unit cube for sorted m1 <= m2 <= m3, m1 + m2 + m3 = 1, a in [0, 1/2]
// (the other half by symmetry). Inclusion-exclusion: 6 m1 m2 m3 V = a^3 - sum (a - m_i)_+^3 + ...;
// each piece below divides only by components that bound the term it divides, so nothing cancels
// when m1 (or m2) tends to 0. dV/da comes with it, for the Newton inverse.
void HalfVolume(double m1, double m2, double m3, double a, double *v, double *dv) {
  const double m12 = m1 + m2;
  if (a < m1) {  // a corner tetrahedron
    *v  = a * a * a / (6 * m1 * m2 * m3);
    *dv = a * a / (2 * m1 * m2 * m3);
  } else if (a < m2) {  // m1 <= a: a^3 - (a - m1)^3 = m1 (a^2 + a (a - m1) + (a - m1)^2)
    *v  = (a * (a - m1) + m1 * m1 / 3) / (2 * m2 * m3);
    *dv = (2 * a - m1) / (2 * m2 * m3);
  } else if (a < std::min(m12, m3)) {  // also (a - m2)^3 cut off, with a - m2 < m1
    const double u = a - m2, b = a - m1;
    *v  = (a * a + a * b + b * b) / (6 * m2 * m3) - (u / m1) * u * u / (6 * m2 * m3);
    *dv = (2 * a - m1) / (2 * m2 * m3) - (u / m1) * u / (2 * m2 * m3);
  } else if (m12 <= m3) {  // the plane crosses the four edges along the m3 axis: a prism
    *v  = (a - 0.5 * m12) / m3;
    *dv = 1 / m3;
  } else {  // m3 <= a < m12: also (a - m3)^3; here a - m2 and a - m3 are below m1
    const double b = a - m1, u2 = a - m2, u3 = a - m3;
    *v  = ((a * a + a * b + b * b) - (u2 / m1) * u2 * u2 - (u3 / m1) * u3 * u3) / (6 * m2 * m3);
    *dv = ((2 * a - m1) - (u2 / m1) * u2 - (u3 / m1) * u3) / (2 * m2 * m3);
  }
}

// Normalises n: flips negative components (x_i -> 1 - x_i), divides by the sum, sorts. Returns the
// sum s and the shift: n.x <= alpha  <=>  m.x' <= (alpha - shift)/s.
double Normalise(const double n[3], double m[3], double *shift) {
  double s = 0;
  *shift   = 0;
  for (int i = 0; i < 3; ++i) {
    m[i] = std::fabs(n[i]);
    s += m[i];
    if (n[i] < 0) *shift += n[i];
  }
  if (s > 0)
    for (int i = 0; i < 3; ++i) m[i] /= s;
  std::sort(m, m + 3);
  return s;
}

double UnitVolume(const double m[3], double a) {
  if (a <= 0) return 0;
  if (a >= 1) return 1;
  double v, dv;
  if (a <= 0.5) {
    HalfVolume(m[0], m[1], m[2], a, &v, &dv);
    return v;
  }
  HalfVolume(m[0], m[1], m[2], 1 - a, &v, &dv);
  return 1 - v;
}

// Inverse on [0, 1/2] for v in [0, 1/2].
double HalfAlpha(const double m[3], double v) {
  double lo = 0, hi = 0.5, a;
  // Start from the prism (the middle piece), clamped into the bracket.
  a = std::min(std::max(m[2] * v + 0.5 * (m[0] + m[1]), 0.0), 0.5);
  for (int it = 0; it < 100; ++it) {
    double f, df;
    HalfVolume(m[0], m[1], m[2], a, &f, &df);
    f -= v;
    if (f == 0) return a;
    if (f > 0) hi = a;
    else lo = a;
    double next = df > 0 ? a - f / df : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - a) <= 4e-16 * std::max(a, 1e-300) || hi - lo <= 1e-16) return next;
    a = next;
  }
  return a;
}

}  // namespace

ReducedNormal Reduce(const double n[3]) {
  ReducedNormal r;
  r.sum = Normalise(n, r.m, &r.shift);
  return r;
}

double Volume(const ReducedNormal &r, double alpha) {
  if (!(r.sum > 0)) return alpha >= 0 ? 1 : 0;
  return UnitVolume(r.m, (alpha - r.shift) / r.sum);
}

double Alpha(const ReducedNormal &r, double v) {
  if (!(r.sum > 0)) return 0;
  double a;
  if (v <= 0) a = 0;
  else if (v >= 1) a = 1;
  else if (v <= 0.5) a = HalfAlpha(r.m, v);
  else a = 1 - HalfAlpha(r.m, 1 - v);
  return a * r.sum + r.shift;
}

double Volume(const double n[3], double alpha) { return Volume(Reduce(n), alpha); }

double Alpha(const double n[3], double v) { return Alpha(Reduce(n), v); }

double BoxFraction(const double n[3], double alpha, const double lo[3], const double hi[3]) {
  double nb[3], a = alpha;
  for (int i = 0; i < 3; ++i) {
    nb[i] = n[i] * (hi[i] - lo[i]);
    a -= n[i] * lo[i];
  }
  return Volume(nb, a);
}

// For each direction d the interface faces (Youngs' component at least half the largest: columns
// within slope 2 of the normal; columns more nearly along the interface do not hold its transition),
// the 3-cell column sums along d over the 3 x 3 transverse block give backward, central and forward
// slopes in each transverse direction: 9 planes per direction, and Youngs' plane besides. Each plane,
// put through the centre cell at its fraction, is extended over the block (the neighbour at offset o is
// the unit cube shifted by o: the plane's constant moves by m.o); the least-squares misfit picks one.
// Unlike Youngs, it takes the one-sided slope at the tip of a filament, where a centred difference
// reaches across to the other side.
void Elvira(const double block[27], const double young[3], double n[3]) {
  const double v = block[13];
  auto         at = [&](const int o[3]) { return block[9 * (o[2] + 1) + 3 * (o[1] + 1) + (o[0] + 1)]; };
  auto         misfit = [&](const double m[3], double limit) {
    const ReducedNormal r = Reduce(m);
    const double        c = Alpha(r, v);
    double              err = 0;
    int                 o[3];
    for (o[2] = -1; o[2] <= 1 && err < limit; ++o[2])
      for (o[1] = -1; o[1] <= 1; ++o[1])
        for (o[0] = -1; o[0] <= 1; ++o[0]) {
          const double e = Volume(r, c - (m[0] * o[0] + m[1] * o[1] + m[2] * o[2])) - at(o);
          err += e * e;
        }
    return err;
  };
  double bestErr = misfit(young, std::numeric_limits<double>::infinity());
  for (int e = 0; e < 3; ++e) n[e] = young[e];
  const double ymax = std::max({std::fabs(young[0]), std::fabs(young[1]), std::fabs(young[2])});
  for (int d = 0; d < 3; ++d) {
    if (young[d] == 0 || std::fabs(young[d]) < 0.5 * ymax) continue;
    const int sign = young[d] > 0 ? 1 : -1, t1 = (d + 1) % 3, t2 = (d + 2) % 3;
    double    H[3][3];  // column sums along d at transverse offsets (t1, t2)
    for (int b = -1; b <= 1; ++b)
      for (int c = -1; c <= 1; ++c) {
        int o[3];
        o[t1] = b, o[t2] = c, H[b + 1][c + 1] = 0;
        for (o[d] = -1; o[d] <= 1; ++o[d]) H[b + 1][c + 1] += at(o);
      }
    const double s1[3] = {H[1][1] - H[0][1], 0.5 * (H[2][1] - H[0][1]), H[2][1] - H[1][1]};
    const double s2[3] = {H[1][1] - H[1][0], 0.5 * (H[1][2] - H[1][0]), H[1][2] - H[1][1]};
    for (int i1 = 0; i1 < 3; ++i1)
      for (int i2 = 0; i2 < 3; ++i2) {
        if ((i1 != 1 && s1[i1] == s1[1]) || (i2 != 1 && s2[i2] == s2[1])) continue;  // the same plane as a central one
        // the surface x_d = H(x_t): the normal (-dH/dt, 1) times the fluid's side, the transverse part
        // the same for either side (H counts fluid from that side's end)
        double m[3];
        m[d] = sign, m[t1] = -s1[i1], m[t2] = -s2[i2];
        const double err = misfit(m, bestErr);
        if (err < bestErr) {
          bestErr = err;
          for (int e = 0; e < 3; ++e) n[e] = m[e];
        }
      }
  }
}

}  // namespace plic
}  // namespace vofdem
