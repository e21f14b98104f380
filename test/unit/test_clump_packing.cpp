// Packing density of rigid clumps (SolidVolume.hpp): the union of a clump's overlapping members
// inside a window or cutting ring, counted once. Known answers: two overlapping spheres (the lens in
// closed form) in a large box, cut in half by a window plane, a ring through the lens holding no
// member centre, a clump across a periodic face; a dense packing of five-sphere clumps never above 1
// in small rings and windows (the earlier V_union / sum V_members weighting gave up to 1.8 there),
// and against a brute-force point count.
#include "vofdem/analysis/PowderMetrics.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace vofdem::analysis;

namespace {
const double kPi = 3.14159265358979323846;
const double S   = 1e-5;  // length scale of the tests, m (the grains' size)
// The largest error of the quadrature of a lens at the default resolution 64, relative to the lens's
// volume (measured here: SolidVolume.hpp).
const double kLens64 = 5e-4;
double SphereVolume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }
// The lens where two spheres of radii a, b with centres d apart overlap.
double LensVolume(double a, double b, double d) { return kPi * (a + b - d) * (a + b - d) * (d * d + 2 * d * (a + b) - 3 * (a - b) * (a - b)) / (12 * d); }

Spheres TwoSphereClump(const double c0[3], double r0, const double c1[3], double r1) {
  Spheres s;
  s.Add(c0[0], c0[1], c0[2], r0), s.Add(c1[0], c1[1], c1[2], r1);
  s.clump = {7, 7};
  return s;
}

Window Box(double lo, double hi) {
  Window w;
  for (int d = 0; d < 3; ++d) w.lo[d] = lo, w.hi[d] = hi;
  return w;
}

// The solid volume of the spheres inside the window, counted as the earlier code did: each member's
// volume inside it times V_union / sum V_members of its clump (exact V_union given).
double WeightedVolume(const Spheres &s, const Window &w, double weight) {
  double v = 0;
  for (std::size_t i = 0; i < s.Size(); ++i) v += weight * SphereBoxVolume(&s.x[3 * i], s.r[i], w.lo, w.hi);
  return v;
}
}  // namespace

TEST(ClumpPacking, TwoSpheresInLargeBoxAreTheirUnion) {
  // Radii 1 and 0.8 with centres 1.2 apart, tilted in x-y; equal radii 1 along z (the lens's rim is a
  // circle across the lattice); equal radii 1 along x (its rim stands upright).
  const double cases[3][5] = {{1, 0.8, 0.6, 0.8, 0}, {1, 1, 0, 0, 1}, {1, 1, 1, 0, 0}};  // radii, direction
  for (const auto &k : cases) {
    const double a = k[0] * S, b = k[1] * S, d = 1.2 * S, c0[3] = {0.1 * S, 0.2 * S, 0.3 * S};
    const double c1[3] = {c0[0] + d * k[2], c0[1] + d * k[3], c0[2] + d * k[4]};
    const Spheres s    = TwoSphereClump(c0, a, c1, b);
    const double  lens = LensVolume(a, b, d), exact = SphereVolume(a) + SphereVolume(b) - lens;
    const Window  w    = Box(-5 * S, 5 * S);
    // The error of the column quadrature of the lens, at each resolution (SolidVolume.hpp states them).
    for (int n : {16, 32, 64, 128, 256}) {
      const ClumpUnions u(s, n);
      ASSERT_EQ(u.Count(), 1u);
      const double err = std::fabs(u.UnionVolume(0) - exact) / lens;
      std::printf("radii %g %g along (%g %g %g), resolution %3d: union volume error %.2e of the lens (%.2e of the union)\n", k[0], k[1], k[2], k[3], k[4], n, err, err * lens / exact);
      EXPECT_NEAR(u.Inside(s, w), u.UnionVolume(0), 1e-13 * exact);  // the lenses inside the box: the whole overlap
      EXPECT_LT(err, n == 16 ? 6e-3 : n == 32 ? 2.5e-3 : n == 64 ? kLens64 : n == 128 ? 1e-4 : 4e-5) << "resolution " << n;
    }
    EXPECT_NEAR(PackingDensity(s, w) * w.Volume(), exact, kLens64 * lens);
  }
  // Members not overlapping (centres 2.5 apart): exact, no quadrature.
  const double  c0[3] = {0, 0, 0}, far[3] = {2.5 * S, 0, 0};
  const Spheres apart = TwoSphereClump(c0, S, far, S);
  const Window  w     = Box(-5 * S, 5 * S);
  EXPECT_NEAR(PackingDensity(apart, w) * w.Volume(), 2 * SphereVolume(S), 1e-13 * SphereVolume(S));
  EXPECT_NEAR(ClumpUnions(apart).UnionVolume(0), 2 * SphereVolume(S), 1e-13 * SphereVolume(S));
}

TEST(ClumpPacking, WindowPlaneHalvesASymmetricClump) {
  // Two equal spheres with centres 1.2 apart along each axis in turn; the window's plane through the
  // middle (normal to the axis: the lens is cut across; or containing the axis) holds half the union.
  const double r = 1 * S, h = 0.6 * S, lens = LensVolume(r, r, 2 * h), full = 2 * SphereVolume(r) - lens;
  for (int axis = 0; axis < 3; ++axis)
    for (int plane = 0; plane < 3; ++plane) {
      double c0[3] = {0.2 * S, -0.1 * S, 0.4 * S}, c1[3] = {c0[0], c0[1], c0[2]};
      c0[axis] -= h, c1[axis] += h;
      const Spheres s = TwoSphereClump(c0, r, c1, r);
      Window        w = Box(-5 * S, 5 * S);
      w.lo[plane]     = c0[plane] + (c1[plane] - c0[plane]) / 2;
      EXPECT_NEAR(PackingDensity(s, w) * w.Volume(), full / 2, kLens64 * lens) << "axis " << axis << " plane " << plane;
      // The two halves sum to the whole.
      Window other     = Box(-5 * S, 5 * S);
      other.hi[plane]  = w.lo[plane];
      const ClumpUnions u(s);
      EXPECT_NEAR(u.Inside(s, w) + u.Inside(s, other), full, 2 * kLens64 * lens) << "axis " << axis << " plane " << plane;
    }
}

TEST(ClumpPacking, RingThroughTheLensHoldsNoCentre) {
  // Two equal spheres on the ring's axis at z = -0.6 and 0.6; the ring's heights |z| <= 0.3 hold
  // neither centre. Column at distance q from the axis: the chords' half length is
  // h = sqrt(1 - q^2); inside |z| <= 0.3 the union is 0.6 long for h >= 0.6 (the chords meet),
  // 2 (h - 0.3) for 0.3 < h < 0.6, empty below.
  const double r = 1 * S, c0[3] = {2 * S, 3 * S, -0.6 * S}, c1[3] = {2 * S, 3 * S, 0.6 * S};
  const Spheres s = TwoSphereClump(c0, r, c1, r);
  Ring          g;
  g.x = 2 * S, g.y = 3 * S, g.z0 = -0.3 * S, g.z1 = 0.3 * S;
  // Ring radius 0.3: solid throughout (h >= 0.95), packing 1 (the weighting gave 2 - lens / V = 1.79).
  g.outer = 0.3 * S;
  const auto rings = SampleRings(s, {g}, std::vector<int>{0, -1});
  EXPECT_EQ(rings[0].centres, 0);
  EXPECT_NEAR(rings[0].packing, 1, 1e-12);
  // Ring radius 0.9: 2 pi [0.6 * 0.8^2 / 2 + int_0.8^0.9 q 2 (sqrt(1 - q^2) - 0.3) dq] (S^3).
  g.outer         = 0.9 * S;
  const double I  = 2 * (std::pow(1 - 0.64, 1.5) - std::pow(1 - 0.81, 1.5)) / 3 - 0.3 * (0.81 - 0.64);
  const double V  = 2 * kPi * (0.6 * 0.64 / 2 + I) * S * S * S;
  const double in = SampleRings(s, {g}, std::vector<int>{0, -1})[0].packing * g.Volume();
  EXPECT_NEAR(in, V, kLens64 * LensVolume(r, r, 1.2 * S));
  // A ring beside the axis, through the lens only (its axis 0.5 off): between the members' own
  // volumes in it and their sum, and self-convergent.
  g.x += 0.5 * S, g.outer = 0.25 * S;
  double own[2];
  for (int k = 0; k < 2; ++k) own[k] = SphereRingVolume(&s.x[3 * k], r, g);
  const double v64 = ClumpUnions(s, 64).Inside(s, g), v512 = ClumpUnions(s, 512).Inside(s, g);
  EXPECT_GT(v64, std::max(own[0], own[1]));
  EXPECT_LT(v64, own[0] + own[1]);
  EXPECT_NEAR(v64, v512, kLens64 * (own[0] + own[1] - v512));
}

TEST(ClumpPacking, ClumpAcrossAPeriodicFace) {
  // The clump of the first test with its members wrapped to both ends of a box periodic in x and y.
  const double r = 1 * S, L = 8 * S;
  const double lens = LensVolume(r, 0.8 * r, 1.2 * S), full = SphereVolume(r) + SphereVolume(0.8 * r) - lens;
  const double c0[3] = {0.3 * S, 0.2 * S, 4 * S}, c1[3] = {L - 0.42 * S, L - 0.76 * S, 4 * S};  // 1.2 apart across the corner
  ASSERT_NEAR(std::hypot(c0[0] + L - c1[0], c0[1] + L - c1[1]), 1.2 * S, 1e-15);
  Spheres s = TwoSphereClump(c0, r, c1, 0.8 * r);
  s.periodic[0] = s.periodic[1] = true;
  for (int d = 0; d < 3; ++d) s.lower[d] = 0, s.upper[d] = L;
  const ClumpUnions u(s);
  EXPECT_NEAR(u.UnionVolume(0), full, kLens64 * lens);
  // The box, and a window across the faces: the whole clump once (in the box its images' lenses are
  // cut by the faces: quadratures of the pieces).
  EXPECT_NEAR(u.Inside(s, Box(0, L)), full, 2 * kLens64 * lens);
  Window across = Box(-2 * S, 2 * S);
  across.lo[2] = 0, across.hi[2] = L;
  EXPECT_NEAR(u.Inside(s, across), u.UnionVolume(0), 1e-13 * full);
  // A window that cuts the lens at x = 0, and its complement in the box.
  Window left = Box(0, L), right = Box(0, L);
  left.lo[0] = -3 * S, left.hi[0] = 0, right.hi[0] = L - 3 * S;
  EXPECT_NEAR(u.Inside(s, left) + u.Inside(s, right), full, 3 * kLens64 * lens);
  // A ring across the corner through the lens.
  Ring g;
  g.x = 0, g.y = 0, g.outer = 0.6 * S, g.z0 = 0, g.z1 = L;
  const double v = u.Inside(s, g);
  EXPECT_NEAR(v, ClumpUnions(s, 512).Inside(s, g), kLens64 * lens);
  EXPECT_LT(v, g.Volume());
}

TEST(ClumpPacking, SphereLargerThanTheRing) {
  // A ring inside one sphere (on or off its centre) is full: packing 1; half in it, about half.
  Spheres s;
  s.Add(0, 0, 0, 10 * S);
  Ring g;
  g.outer = 1.5 * S, g.z0 = -2 * S, g.z1 = 3 * S;
  for (double x : {0.0, 4 * S, -7 * S}) {
    g.x = x, g.y = 0.5 * x;
    EXPECT_NEAR(SampleRings(s, {g}, {0})[0].packing, 1, 1e-12) << "axis at " << x;
  }
  g.z0 = 9.9 * S, g.z1 = 10.1 * S, g.x = g.y = 0;  // across the pole: the cap above z = 9.9 (base radius 1.41 < 1.5)
  const double cap = kPi * 0.01 * S * S * (30 - 0.1) * S / 3;
  EXPECT_NEAR(SampleRings(s, {g}, {0})[0].packing * g.Volume(), cap, 1e-12 * cap);
}

TEST(ClumpPacking, DenseClumpPackingNeverAboveOne) {
  // Five-sphere clumps (the shape of regolith4, scaled to reach 0.5 cell from the base's centre) on a
  // 4 x 4 x 4 periodic cubic lattice, each turned differently: clumps nearly touch, none overlaps
  // another (overlaps of different particles count twice, as for loose spheres). Small rings and
  // windows everywhere, many inside a clump.
  const double tmpl[5][4] = {{0, 0, 0, 1}, {0.6, 0, 0, 0.65}, {-0.5, 0.4, 0, 0.6}, {0, -0.5, 0.45, 0.55}, {0, 0.1, -0.75, 0.5}};
  const int    n = 4;
  const double a = 2 * S, k0 = 1 / 1.26;  // the template reaches 1.257 base radii
  Spheres      s;
  for (int d = 0; d < 3; ++d) s.periodic[d] = true, s.lower[d] = 0, s.upper[d] = n * a;
  long id = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i, ++id) {
        const double t = 0.7 * id, u = 1.3 * id, ct = std::cos(t), st = std::sin(t), cu = std::cos(u), su = std::sin(u);
        for (const auto &m : tmpl) {
          // Rotation about z by t, then about x by u.
          const double x = ct * m[0] - st * m[1], y = st * m[0] + ct * m[1], z = m[2];
          const double p[3] = {x, cu * y - su * z, su * y + cu * z};
          s.Add((i + 0.5) * a + k0 * p[0] * S, (j + 0.5) * a + k0 * p[1] * S, (k + 0.5) * a + k0 * p[2] * S, k0 * m[3] * S);
          s.clump.push_back(id);
        }
      }
  const ClumpUnions u(s);
  ASSERT_EQ(u.Count(), (std::size_t)(n * n * n));
  double sumMembers = 0;
  for (const auto &m : tmpl) sumMembers += SphereVolume(k0 * m[3] * S);
  const double weight = u.UnionVolume(0) / sumMembers;
  // The whole box: every clump once (the neighbours' overlaps counted twice, as for loose spheres).
  double unions = 0;
  for (std::size_t c = 0; c < u.Count(); ++c) unions += u.UnionVolume(c);
  EXPECT_NEAR(u.Inside(s, Box(0, n * a)), unions, 1e-12 * unions);
  double highest = 0, highestWeighted = 0;
  long   regions = 0;
  for (double size : {0.1, 0.3, 0.7}) {
    for (int p = 0; p < 12; ++p)
      for (int q = 0; q < 12; ++q) {
        const double x = (p + 0.31) * n * a / 12, y = (q + 0.17) * n * a / 12, z = (0.4 + 0.05 * p) * a;
        Ring         g;
        g.x = x, g.y = y, g.outer = size * S, g.z0 = z, g.z1 = z + 2 * size * S;
        highest = std::max(highest, u.Inside(s, g) / g.Volume());
        Window w;
        w.lo[0] = x, w.lo[1] = y, w.lo[2] = z;
        for (int d = 0; d < 3; ++d) w.hi[d] = w.lo[d] + 2 * size * S;
        highest         = std::max(highest, u.Inside(s, w) / w.Volume());
        highestWeighted = std::max(highestWeighted, WeightedVolume(s, w, weight) / w.Volume());
        regions += 2;
      }
  }
  std::printf("%ld regions: highest packing %.6f (the weighting of members: %.4f)\n", regions, highest, highestWeighted);
  EXPECT_LE(highest, 1 + kLens64);  // the quadrature's error, relative to a region inside a lens
  EXPECT_GT(highest, 0.999);  // some region lies inside a clump
  EXPECT_GT(highestWeighted, 1.2);  // what this test would have caught

  // One window over a few clumps against a brute-force count of points (160^3, each in any sphere).
  Window w;
  w.lo[0] = 0.3 * a, w.lo[1] = 0.9 * a, w.lo[2] = 1.2 * a;
  for (int d = 0; d < 3; ++d) w.hi[d] = w.lo[d] + 1.1 * a;
  const int                m  = 160;
  long                     in = 0;
  std::vector<std::size_t> near;  // the spheres that reach into the window
  for (std::size_t c = 0; c < s.Size(); ++c) {
    bool reach = true;
    for (int d = 0; d < 3; ++d) reach = reach && s.x[3 * c + d] + s.r[c] > w.lo[d] && s.x[3 * c + d] - s.r[c] < w.hi[d];
    if (reach) near.push_back(c);
  }
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const double x[3] = {w.lo[0] + (i + 0.5) / m * 1.1 * a, w.lo[1] + (j + 0.5) / m * 1.1 * a, w.lo[2] + (k + 0.5) / m * 1.1 * a};
        for (std::size_t c : near) {
          double d2 = 0;
          for (int d = 0; d < 3; ++d) d2 += (x[d] - s.x[3 * c + d]) * (x[d] - s.x[3 * c + d]);  // no image needed: the window is inside the box
          if (d2 < s.r[c] * s.r[c]) {
            ++in;
            break;
          }
        }
      }
  const double brute = (double)in / ((double)m * m * m), phi = PackingDensity(s, w);
  std::printf("window over a few clumps: packing %.6f, brute-force count %.6f\n", phi, brute);
  EXPECT_NEAR(phi, brute, 3e-3);
}
