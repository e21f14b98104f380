// Powder-bed metrics (src/analysis) on constructed packings with known answers: exact sphere volumes
// in boxes and rings, a simple-cubic lattice (density pi/6, coordination 6), one sphere under a ray
// grid, a two-size layer with known segregation, cones of known angle, Delaunay tetrahedra.
#include "vofdem/analysis/PowderMetrics.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace vofdem::analysis;

namespace {
const double kPi = 3.14159265358979323846;
double SphereVolume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

// Simple-cubic lattice of n^3 spheres of radius r, spacing a, first centre at a/2 (periodic box [0, n a]^3).
Spheres CubicLattice(int n, double r, double a, bool periodic) {
  Spheres s;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) s.Add((i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a, r);
  for (int d = 0; d < 3; ++d) s.periodic[d] = periodic, s.lower[d] = 0, s.upper[d] = n * a;
  return s;
}
}  // namespace

TEST(AnalysisGeometry, SphereInBoxExactCases) {
  const double r = 2e-5, c[3] = {1e-4, 2e-4, 3e-4}, V = SphereVolume(r);
  const double big = 1;
  const double lo[3] = {-big, -big, -big}, hi[3] = {big, big, big};
  EXPECT_NEAR(SphereBoxVolume(c, r, lo, hi), V, 1e-13 * V);
  // An octant: the box's corner at the centre.
  const double loO[3] = {c[0], c[1], c[2]};
  EXPECT_NEAR(SphereBoxVolume(c, r, loO, hi), V / 8, 1e-12 * V);
  // A quarter: an edge through the centre.
  const double loQ[3] = {c[0], -big, c[2]};
  EXPECT_NEAR(SphereBoxVolume(c, r, loQ, hi), V / 4, 1e-12 * V);
  // A cap of height h above the plane z = c + (r - h): pi h^2 (3r - h) / 3.
  for (double h : {0.1 * r, 0.5 * r, 1.3 * r, 1.9 * r}) {
    const double loC[3] = {-big, -big, c[2] + r - h};
    EXPECT_NEAR(SphereBoxVolume(c, r, loC, hi), kPi * h * h * (3 * r - h) / 3, 1e-12 * V) << "h/r " << h / r;
  }
  // A slab through the sphere with the x-y window cutting the discs off-centre (no closed form):
  // 24 nodes per piece agree with 64 to 1e-12 of the sphere volume.
  const double loS[3] = {c[0] - 0.3 * r, c[1] + 0.45 * r, c[2] - 0.8 * r}, hiS[3] = {c[0] + 0.7 * r, c[1] + 2 * r, c[2] + 0.2 * r};
  EXPECT_NEAR(SphereBoxVolume(c, r, loS, hiS, 24), SphereBoxVolume(c, r, loS, hiS, 64), 1e-12 * V);
  // The eight octants of an off-centre split sum to the sphere.
  const double m[3] = {c[0] + 0.37 * r, c[1] - 0.61 * r, c[2] + 0.13 * r};
  double       sum  = 0;
  for (int o = 0; o < 8; ++o) {
    double l[3], u[3];
    for (int d = 0; d < 3; ++d) l[d] = (o >> d) & 1 ? m[d] : -big, u[d] = (o >> d) & 1 ? big : m[d];
    sum += SphereBoxVolume(c, r, l, u);
  }
  EXPECT_NEAR(sum, V, 1e-12 * V);
}

TEST(AnalysisGeometry, DiscAreas) {
  const double rho = 1.5;
  EXPECT_NEAR(DiscRectangleArea(rho, -2, 2, -2, 2), kPi * rho * rho, 1e-14);
  EXPECT_NEAR(DiscRectangleArea(rho, 0, 2, 0, 2), kPi * rho * rho / 4, 1e-14);
  // A segment cut by x >= 1: rho^2 acos(1/rho) - sqrt(rho^2 - 1).
  EXPECT_NEAR(DiscRectangleArea(rho, 1, 2, -2, 2), rho * rho * std::acos(1 / rho) - std::sqrt(rho * rho - 1), 1e-14);
  EXPECT_NEAR(DiscRectangleArea(rho, -2, 2, -2, -1), rho * rho * std::acos(1 / rho) - std::sqrt(rho * rho - 1), 1e-14);
  EXPECT_NEAR(DiscDiscArea(1, 3, 0.5), kPi, 1e-14);
  EXPECT_NEAR(DiscDiscArea(1, 1, 2.0), 0, 1e-14);
  // Two unit discs one radius apart: 2 pi/3 - sqrt(3)/2.
  EXPECT_NEAR(DiscDiscArea(1, 1, 1), 2 * kPi / 3 - std::sqrt(3.0) / 2, 1e-14);
}

TEST(AnalysisGeometry, SphereInRing) {
  const double r = 1e-5, c[3] = {0, 0, 0}, V = SphereVolume(r);
  Ring         g;
  g.outer = 1, g.z0 = -1, g.z1 = 1;
  EXPECT_NEAR(SphereRingVolume(c, r, g), V, 1e-12 * V);
  // Outside a coaxial cylinder of radius a: (4 pi / 3) (r^2 - a^2)^(3/2).
  for (double a : {0.2 * r, 0.7 * r}) {
    g.inner = a;
    EXPECT_NEAR(SphereRingVolume(c, r, g), 4 * kPi / 3 * std::pow(r * r - a * a, 1.5), 1e-12 * V);
  }
  // Cut by a ring wall off the axis: inside plus outside is the whole sphere.
  Ring in, out;
  in.x = out.x = 0.6 * r, in.y = out.y = -0.2 * r, in.outer = 0.9 * r, out.inner = 0.9 * r, out.outer = 1;
  in.z0 = out.z0 = -1, in.z1 = out.z1 = 0.4 * r;
  const double below = kPi * std::pow(1.4 * r, 2) * (3 * r - 1.4 * r) / 3;  // cap of height 1.4 r under z = 0.4 r
  EXPECT_NEAR(SphereRingVolume(c, r, in) + SphereRingVolume(c, r, out), below, 1e-12 * V);
}

TEST(AnalysisMetrics, SimpleCubicDensityAndCoordination) {
  const double r = 1e-5, a = 2 * r;
  Spheres      s = CubicLattice(6, r, a, true);
  // Any window of whole lattice cells holds pi/6, wherever it starts (spheres cut exactly).
  Window w;
  const double off[3] = {0.37 * a, 0.11 * a, 0.59 * a}, n[3] = {3, 2, 4};
  for (int d = 0; d < 3; ++d) w.lo[d] = off[d], w.hi[d] = off[d] + n[d] * a;
  EXPECT_NEAR(PackingDensity(s, w), kPi / 6, 1e-11);
  // Periodic images count: a window across the box face.
  for (int d = 0; d < 3; ++d) w.lo[d] = -0.5 * a, w.hi[d] = 1.5 * a;
  EXPECT_NEAR(PackingDensity(s, w), kPi / 6, 1e-11);
  // Touching spheres: six contacts within a gap tolerance, none without one when not overlapping.
  for (int z : CoordinationNumbers(s, 1e-9 * r)) EXPECT_EQ(z, 6);
  Spheres apart = CubicLattice(6, r, a * (1 + 1e-6), true);
  for (int z : CoordinationNumbers(apart, 0)) EXPECT_EQ(z, 0);
  // Overlapping by 1e-6 of a diameter, not periodic: 6 inside, 3 at corners.
  Spheres squeezed = CubicLattice(5, r, a * (1 - 1e-6), false);
  const std::vector<int> zc = CoordinationNumbers(squeezed, 0);
  long hist[7] = {0};
  for (int z : zc) ++hist[z];
  EXPECT_EQ(hist[6], 27);   // interior 3^3
  EXPECT_EQ(hist[5], 54);   // faces 6 * 3^2
  EXPECT_EQ(hist[4], 36);   // edges 12 * 3
  EXPECT_EQ(hist[3], 8);    // corners
  // A ring of radius r on the lattice column x = y = a/2 over z in [-a/2, 3a/2].
  const std::vector<Ring> rings = RingsAlongX(w, 1, 0.5 * a);
  const auto res = SampleRings(s, rings, CoordinationNumbers(s, 1e-9 * r));
  EXPECT_EQ(res[0].ring.x, 0.5 * a);
  EXPECT_EQ(res[0].centres, 2);  // the column x = y = a/2 at z = a/2 and 3a/2 (ends closed)
  EXPECT_NEAR(res[0].coordination, 6, 1e-12);
  // The ring of radius r holds its column only: one whole sphere and two halves (one a periodic
  // image) in a cylinder of height 4r: (8/3) pi r^3 / (4 pi r^3).
  EXPECT_NEAR(res[0].packing, 2.0 / 3.0, 1e-11);
}

TEST(AnalysisMetrics, SingleSphereUnderRays) {
  // A sphere resting on the substrate z = 0: over the disc r < R the height is R + sqrt(R^2 - r^2).
  // Continuous answers over the square of side 4R: mean (5/3) pi R^3 / A, second moment (17/6) pi R^4 / A.
  const double R = 1e-5, L = 4 * R, A = L * L;
  Spheres      s;
  s.Add(0, 0, R, R);
  Window w;
  w.lo[0] = w.lo[1] = -2 * R, w.hi[0] = w.hi[1] = 2 * R, w.lo[2] = 0, w.hi[2] = 2 * R;
  const Surface surf = CastRays(s, w, R / 100, 0.0);
  EXPECT_EQ(surf.nx, 400);
  EXPECT_EQ(surf.ny, 400);
  const double mean = 5.0 / 3.0 * kPi * R * R * R / A, m2 = 17.0 / 6.0 * kPi * R * R * R * R / A;
  EXPECT_NEAR(surf.mean, mean, 2e-3 * mean);
  EXPECT_NEAR(surf.saStd, std::sqrt(m2 - mean * mean), 2e-3 * std::sqrt(m2 - mean * mean));
  EXPECT_NEAR((double)surf.hits, kPi * R * R / (R * R / 1e4), 2e-3 * kPi * 1e4);
  // The top of the sphere is the highest ray; a sphere outside the window's z range is not seen.
  double top = 0;
  for (double z : surf.z) top = std::max(top, z);
  EXPECT_NEAR(top, 2 * R, 1e-4 * R);
  Window high = w;
  high.lo[2] = 1.5 * R;
  EXPECT_EQ(CastRays(s, high, R / 10, 0.0).hits, 0);
  // The centre line: 500 rays, the profile is R + sqrt(R^2 - x^2) over |x| < R.
  const LineProfile line = CastLine(s, w, 500, 0.0);
  for (std::size_t i = 0; i < line.x.size(); ++i)
    EXPECT_NEAR(line.z[i], std::fabs(line.x[i]) < R ? R + std::sqrt(R * R - line.x[i] * line.x[i]) : 0.0, 1e-15);
}

TEST(AnalysisMetrics, TwoSizeSegregation) {
  // Small spheres (5 um) fill the left half of a layer, large ones (10 um) the right half.
  Spheres s;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 8; ++j) s.Add(5e-6 + 1e-5 * i, 5e-6 + 1e-5 * j, 5e-6, 5e-6);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 4; ++j) s.Add(2e-4 + 1e-5 + 2e-5 * i, 1e-5 + 2e-5 * j, 1e-5, 1e-5);
  Window w;
  w.hi[0] = 4e-4, w.hi[1] = 8e-5, w.hi[2] = 2e-5;
  const double ref = s.MeanRadius();
  EXPECT_NEAR(ref, (160 * 5e-6 + 40 * 1e-5) / 200, 1e-18);
  const int  cells[3] = {2, 1, 1};
  const auto si       = Segregation(s, w, cells, ref);
  ASSERT_EQ(si.size(), 2u);
  EXPECT_EQ(si[0].centres, 160);
  EXPECT_EQ(si[1].centres, 40);
  EXPECT_NEAR(si[0].index, 5e-6 / ref, 1e-12);
  EXPECT_NEAR(si[1].index, 1e-5 / ref, 1e-12);
  // Four cells: the same halves split again, and the values do not change.
  const int  four[3] = {4, 1, 1};
  const auto s4      = Segregation(s, w, four, ref);
  EXPECT_NEAR(s4[1].index, 5e-6 / ref, 1e-12);
  EXPECT_NEAR(s4[2].index, 1e-5 / ref, 1e-12);
}

TEST(AnalysisMetrics, ConePileAngle) {
  // Spheres on a cubic lattice filling a cone of angle alpha on the substrate z = 0.
  for (double alpha : {30.0, 40.0}) {
    const double H = 1e-3, r = 1e-5, a = 2 * r, B = H / std::tan(alpha * kPi / 180);
    Spheres      s;
    const int    n = (int)(B / a) + 1;
    for (int k = 0; (k + 0.5) * a < H; ++k)
      for (int j = -n; j <= n; ++j)
        for (int i = -n; i <= n; ++i) {
          const double x = i * a, y = j * a, z = (k + 0.5) * a;
          if (z <= H - std::hypot(x, y) * std::tan(alpha * kPi / 180)) s.Add(x, y, z, r);
        }
    Window w;
    w.lo[0] = w.lo[1] = -1.2 * B, w.hi[0] = w.hi[1] = 1.2 * B, w.lo[2] = 0, w.hi[2] = 2 * H;
    const Surface   surf = CastRays(s, w, 5e-6, 0.0);
    const ReposeFit fit  = FitRepose(surf, 0.0, nullptr, 0.2, 0.8);
    EXPECT_NEAR(fit.angleDeg, alpha, 0.5) << "alpha " << alpha;
    EXPECT_NEAR(fit.axis[0], 0, 2 * r);
    EXPECT_NEAR(fit.axis[1], 0, 2 * r);
    EXPECT_GT(fit.points, 1000);
    // Seed 001's measure from the height and the base's diameter 2B: the same angle for a whole cone (H: the
    // top sphere's top, within a lattice spacing of the cone's apex).
    EXPECT_NEAR(fit.height, H, a);
    EXPECT_NEAR(HeightReposeAngleDeg(fit.height, 2 * B), alpha, 0.5) << "alpha " << alpha;
  }
  EXPECT_NEAR(HeightReposeAngleDeg(1.0, 2.0), 45.0, 1e-12);
  EXPECT_EQ(HeightReposeAngleDeg(1.0, 0.0), 0.0);
}

TEST(AnalysisPores, DelaunayTetrahedra) {
  // One regular tetrahedron: sphericity 0.671 (seed 001), equivalent radius (3V/4pi)^(1/3).
  Spheres      s;
  const double e = 1e-5;
  s.Add(0, 0, 0, 1e-6), s.Add(e, 0, 0, 1e-6), s.Add(0.5 * e, std::sqrt(3.0) / 2 * e, 0, 1e-6);
  s.Add(0.5 * e, std::sqrt(3.0) / 6 * e, std::sqrt(2.0 / 3.0) * e, 1e-6);
  Window w;
  for (int d = 0; d < 3; ++d) w.lo[d] = -e, w.hi[d] = 2 * e;
  PoreStats p = DelaunayPores(s, w);
  ASSERT_EQ(p.volume.size(), 1u);
  const double V = e * e * e / (6 * std::sqrt(2.0));
  EXPECT_NEAR(p.volume[0], V, 1e-12 * V);
  EXPECT_NEAR(p.sphericity[0], 0.671, 5e-4);
  EXPECT_NEAR(p.equivalentRadius[0], std::cbrt(3 * V / (4 * kPi)), 1e-12 * e);
  // A cubic lattice (co-spherical points): the tetrahedra tile the hull, (n-1)^3 a^3, none flat.
  Spheres lat = CubicLattice(5, 1e-6, 1e-5, false);
  for (int d = 0; d < 3; ++d) w.lo[d] = 0, w.hi[d] = 5e-5;
  p = DelaunayPores(lat, w);
  EXPECT_NEAR(p.hullVolume, 64e-15, 1e-9 * 64e-15);
  for (double v : p.volume) EXPECT_GT(v, 1e-6 * 1e-15);
  EXPECT_GE(p.volume.size(), 5u * 64);  // each cube in 5 or 6 tetrahedra
  EXPECT_LE(p.volume.size(), 6u * 64);
}
