// Clump templates (P10): mass and inertia of the union of overlapping spheres against analytic
// two-sphere values (slices z = const of the union are discs of the larger sphere's radius there),
// and the principal frame.
#include "vofdem/dem/ClumpTemplate.hpp"

#include <gtest/gtest.h>

#include <cmath>

using vofdem::ClumpTemplate;

namespace {

// Exact V, I_axis and I_perp (about the centroid) of two spheres of radii a (at z = 0) and b (at
// z = d) along z: slices are discs of radius^2 max(a^2 - z^2, b^2 - (z-d)^2), piecewise polynomial
// in z, integrated by 12-point Gauss-Legendre per piece (exact to degree 23).
void TwoSphereExact(double a, double b, double d, double *V, double *zc, double *Iaxis, double *Iperp) {
  const double zs = (d * d + a * a - b * b) / (2 * d);  // the plane where both slices are equal
  const double lo = std::min(-a, d - b), hi = std::max(a, d + b);
  const double gx[6] = {0.1252334085114689, 0.3678314989981802, 0.5873179542866175, 0.7699026741943047, 0.9041172563704749, 0.9815606342467192};
  const double gw[6] = {0.2491470458134028, 0.2334925365383548, 0.2031674267230659, 0.1600783285433462, 0.1069393259953184, 0.0471753363865118};
  double       m[4] = {0, 0, 0, 0};  // int rho^2, z rho^2, z^2 rho^2, rho^4 (times pi)
  for (const auto &piece : {std::make_pair(lo, zs), std::make_pair(zs, hi)}) {
    const double p = piece.first, q = piece.second, h = 0.5 * (q - p), c = 0.5 * (q + p);
    for (int i = 0; i < 12; ++i) {
      const double z = c + h * (i < 6 ? gx[i] : -gx[i - 6]), w = h * gw[i % 6];
      const double r2 = std::max(0.0, std::max(a * a - z * z, b * b - (z - d) * (z - d)));
      m[0] += w * r2, m[1] += w * z * r2, m[2] += w * z * z * r2, m[3] += w * r2 * r2;
    }
  }
  *V = PETSC_PI * m[0], *zc = m[1] / m[0];
  *Iaxis = 0.5 * PETSC_PI * m[3];                                            // discs: (pi/2) rho^4
  *Iperp = 0.25 * PETSC_PI * m[3] + PETSC_PI * (m[2] - 2 * *zc * m[1] + *zc * *zc * m[0]);  // (pi/4) rho^4 + pi rho^2 (z - zc)^2
}

ClumpTemplate Two(double a, double b, double d, const double axis[3]) {
  ClumpTemplate t;
  t.spheres.resize(2);
  t.spheres[0].r = a, t.spheres[1].r = b;
  for (int k = 0; k < 3; ++k) t.spheres[0].x[k] = 1e-4, t.spheres[1].x[k] = 1e-4 + d * axis[k];  // off the origin
  t.Compute();
  return t;
}

}  // namespace

TEST(ClumpTemplate, TwoEqualSpheres) {
  const double R = 5e-5, d = 0.8 * R, z[3] = {0, 0, 1};
  double       V, zc, Ia, Ip;
  TwoSphereExact(R, R, d, &V, &zc, &Ia, &Ip);
  // The textbook value of the volume: two spheres minus the lens pi (4R + d)(2R - d)^2 / 12.
  EXPECT_NEAR(V, 2 * 4.0 / 3.0 * PETSC_PI * R * R * R - PETSC_PI * (4 * R + d) * (2 * R - d) * (2 * R - d) / 12, 1e-12 * V);
  const ClumpTemplate t = Two(R, R, d, z);
  EXPECT_NEAR(t.volume, V, 1e-10 * V);
  EXPECT_NEAR(t.centroid[2], 1e-4 + d / 2, 1e-12 * R);
  // Principal moments ascending: the axis of symmetry has the smallest.
  EXPECT_NEAR(t.principal[0], Ia, 1e-10 * Ia);
  EXPECT_NEAR(t.principal[1], Ip, 1e-10 * Ip);
  EXPECT_NEAR(t.principal[2], Ip, 1e-10 * Ip);
  EXPECT_NEAR(std::fabs(t.axes[2 * 3 + 0]), 1, 1e-9);  // first principal axis along z
  // Members in the body frame: +-d/2 along the first axis.
  EXPECT_NEAR(std::fabs(t.body[0]), d / 2, 1e-12 * R);
  EXPECT_NEAR(t.body[0], -t.body[3], 1e-12 * R);
  EXPECT_NEAR(t.boundingRadius, d / 2 + R, 1e-12 * R);
}

TEST(ClumpTemplate, TwoUnequalSpheresOnASlantedAxis) {
  // The frame must not matter: the same pair along a slanted axis gives the same principal values.
  const double a = 6e-5, b = 3.5e-5, d = 5e-5, n = std::sqrt(14.0), axis[3] = {1 / n, -2 / n, 3 / n};
  double       V, zc, Ia, Ip;
  TwoSphereExact(a, b, d, &V, &zc, &Ia, &Ip);
  const ClumpTemplate t = Two(a, b, d, axis);
  EXPECT_NEAR(t.volume, V, 1e-10 * V);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(t.centroid[k], 1e-4 + zc * axis[k], 1e-12 * a);
  EXPECT_NEAR(t.principal[0], Ia, 1e-10 * Ia);
  EXPECT_NEAR(t.principal[1], Ip, 1e-10 * Ip);
  EXPECT_NEAR(t.principal[2], Ip, 1e-10 * Ip);
  // A sphere inside the other adds nothing.
  ClumpTemplate inner;
  inner.spheres.resize(2);
  inner.spheres[0].r = 2e-5, inner.spheres[1].r = 5e-6, inner.spheres[1].x[0] = 1e-5;
  inner.Compute();
  const double Vs = 4.0 / 3.0 * PETSC_PI * 8e-15;
  EXPECT_NEAR(inner.volume, Vs, 1e-10 * Vs);
  EXPECT_NEAR(inner.principal[0], 0.4 * Vs * 4e-10, 1e-10 * 0.4 * Vs * 4e-10);
}

TEST(ClumpTemplate, FourSpheresConverged) {
  // A base sphere with three satellites (seed 002's shapes are of this kind): 32 and 64 nodes agree.
  ClumpTemplate t;
  const double  c[4][4] = {{0, 0, 0, 4e-5}, {3.5e-5, 0, 0, 2.5e-5}, {-1e-5, 3e-5, 1e-5, 2e-5}, {0, -1e-5, -3.2e-5, 2.2e-5}};
  for (const auto &s : c) {
    vofdem::ClumpSphere m;
    m.x[0] = s[0], m.x[1] = s[1], m.x[2] = s[2], m.r = s[3];
    t.spheres.push_back(m);
  }
  ClumpTemplate fine = t;
  t.Compute(32), fine.Compute(64);
  EXPECT_NEAR(t.volume, fine.volume, 1e-10 * fine.volume);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(t.principal[k], fine.principal[k], 1e-10 * fine.principal[2]);
  // Less than the sum of the spheres (overlaps counted once), more than the base sphere.
  double sum = 0;
  for (const auto &s : c) sum += 4.0 / 3.0 * PETSC_PI * s[3] * s[3] * s[3];
  EXPECT_LT(t.volume, sum);
  EXPECT_GT(t.volume, 4.0 / 3.0 * PETSC_PI * 6.4e-14);
  // The body frame diagonalises the inertia: axes^T I axes = diag(principal).
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double v = 0;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) v += t.axes[3 * k + i] * t.inertia[3 * k + l] * t.axes[3 * l + j];
      EXPECT_NEAR(v, i == j ? t.principal[i] : 0.0, 1e-12 * t.principal[2]);
    }
}
