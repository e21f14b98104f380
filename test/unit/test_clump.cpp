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

#include "vofdem/dem/Clumps.hpp"

namespace {
// Local particle arrays for Clumps::SetUp: n spheres at rest.
struct Arrays {
  std::vector<PetscReal>  x, v, f, r, m, w, t, rigid;
  std::vector<PetscInt64> id, clump;
  std::vector<PetscInt>   type;
  void Add(const PetscReal p[3], PetscReal radius, PetscInt64 c) {
    for (int d = 0; d < 3; ++d) x.push_back(p[d]), v.push_back(0), f.push_back(0), w.push_back(0), t.push_back(0);
    r.push_back(radius), m.push_back(0), id.push_back((PetscInt64)id.size()), clump.push_back(c), type.push_back(0);
    for (int k = 0; k < vofdem::kRigidWidth; ++k) rigid.push_back(0);
  }
  vofdem::ParticleArrays View() {
    vofdem::ParticleArrays a;
    a.n = (PetscInt)r.size(), a.x = x.data(), a.v = v.data(), a.f = f.data(), a.radius = r.data(), a.mass = m.data(), a.omega = w.data();
    a.torque = t.data(), a.id = id.data(), a.clump = clump.data(), a.type = type.data(), a.rigid = rigid.data();
    return a;
  }
};
}  // namespace

TEST(Clumps, RepeatedShapeByRotation) {
  // Clump 0: four spheres, not in a plane; clump 1: the same rotated (axis (1,2,2)/3, 1 rad) and moved;
  // clump 2: its mirror image in x (no rotation maps it: computed anew, same moments).
  const PetscReal s[4][4] = {{0, 0, 0, 4e-5}, {4.5e-5, 1e-5, 0, 3e-5}, {-1e-5, 3.5e-5, 2e-5, 2.5e-5}, {1e-5, -1e-5, 3.5e-5, 2.2e-5}};
  const PetscReal qr[4]   = {std::cos(0.5), std::sin(0.5) / 3, 2 * std::sin(0.5) / 3, 2 * std::sin(0.5) / 3};
  Arrays          A;
  for (const auto &e : s) {
    PetscReal p[3] = {1e-3 + e[0], 1e-3 + e[1], 1e-3 + e[2]}, y[3];
    A.Add(p, e[3], 0);
    vofdem::rigid::QuatRotate(qr, e, y);
    const PetscReal py[3] = {2e-3 + y[0], 1e-3 + y[1], 1e-3 + y[2]}, pm[3] = {3e-3 - e[0], 1e-3 + e[1], 1e-3 + e[2]};
    A.Add(py, e[3], 1);
    A.Add(pm, e[3], 2);
  }
  vofdem::Clumps         clumps;
  vofdem::ParticleArrays a = A.View();
  PetscInt               count;
  const PetscReal        g[3] = {0, 0, -9.81};
  ASSERT_EQ(clumps.SetUp(a, {2500}, g, &count), 0);
  EXPECT_EQ(count, 3);
  EXPECT_EQ(clumps.ShapesComputed(), 2);  // clump 1 is clump 0 rotated
  const PetscReal *g0 = &A.rigid[0], *g1 = &A.rigid[vofdem::kRigidWidth], *g2 = &A.rigid[2 * vofdem::kRigidWidth];
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(g1[vofdem::rigid::kInertia + k % 3], g0[vofdem::rigid::kInertia + k % 3], 1e-9 * g0[vofdem::rigid::kInertia + 2]);
  EXPECT_NEAR(g1[vofdem::rigid::kMass], g0[vofdem::rigid::kMass], 1e-12 * g0[vofdem::rigid::kMass]);
  EXPECT_NEAR(g2[vofdem::rigid::kMass], g0[vofdem::rigid::kMass], 1e-9 * g0[vofdem::rigid::kMass]);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(g2[vofdem::rigid::kInertia + k], g0[vofdem::rigid::kInertia + k], 1e-9 * g0[vofdem::rigid::kInertia + 2]);
  // Every clump: member k - member 0 = R(q) (b_k - b_0), and the centroid x_k - R(q) b_k is that of the
  // union computed directly from the clump's own positions.
  for (int c = 0; c < 3; ++c) {
    ClumpTemplate direct;
    for (int k = 0; k < 4; ++k) {
      vofdem::ClumpSphere m;
      for (int d = 0; d < 3; ++d) m.x[d] = A.x[3 * (3 * k + c) + d];
      m.r = A.r[3 * k + c];
      direct.spheres.push_back(m);
    }
    direct.Compute();
    for (int k = 0; k < 4; ++k) {
      const PetscReal *g = &A.rigid[vofdem::kRigidWidth * (3 * k + c)];
      PetscReal        rb[3];
      vofdem::rigid::QuatRotate(g + vofdem::rigid::kQ, g + vofdem::rigid::kBody, rb);
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(A.x[3 * (3 * k + c) + d] - rb[d], direct.centroid[d], 1e-12) << "clump " << c << " member " << k;
    }
  }
  // Clump 1's orientation is the rotation times clump 0's.
  PetscReal expect[4];
  vofdem::rigid::QuatMultiply(qr, g0 + vofdem::rigid::kQ, expect);
  const PetscReal sign = expect[0] * g1[0] + expect[1] * g1[1] + expect[2] * g1[2] + expect[3] * g1[3] > 0 ? 1 : -1;
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(g1[vofdem::rigid::kQ + k], sign * expect[k], 1e-9);
}
