// Clump insertion shapes (ClumpLibrary, P10): an inserted clump's member spheres, mass and principal
// moments (the template computed once at unit size and scaled: volume s^3, inertia s^5) against the
// union of the placed spheres computed anew by ClumpTemplate::Compute, for the four built-in regolith
// shapes and a user template, at a size and orientation that are not the template's.
#include "vofdem/dem/ClumpLibrary.hpp"
#include "vofdem/dem/Clumps.hpp"

#include "PetscTestEnvironment.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {


// The placed clump's union, computed from its world spheres, has the placed mass, centroid and moments.
void CheckPlaced(vofdem::ClumpLibrary &lib, int t, double rEq) {
  const double rho = 2770, X[3] = {1e-3, -2e-3, 5e-4};
  double       q[4] = {0.3, -0.5, 0.7, 0.2};
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double &c : q) c /= n;
  vofdem::PlacedClump p;
  lib.Place(t, rEq, q, X, rho, &p);
  const size_t m = lib.Template(t).spheres.size();
  ASSERT_EQ(p.r.size(), m);
  EXPECT_NEAR(p.mass, rho * 4.0 / 3.0 * PETSC_PI * rEq * rEq * rEq, 1e-12 * p.mass) << lib.Name(t) << ": mass is that of the volume-equivalent sphere";
  vofdem::ClumpTemplate direct;
  for (size_t k = 0; k < m; ++k) {
    vofdem::ClumpSphere s;
    for (int d = 0; d < 3; ++d) s.x[d] = p.x[3 * k + d];
    s.r = p.r[k];
    direct.spheres.push_back(s);
    // Member radii and distances from the base are the template's scaled by s.
    const double scale = p.r[0];  // the base sphere's radius
    EXPECT_NEAR(p.r[k], scale * lib.Template(t).spheres[k].r, 1e-14 * scale);
  }
  direct.Compute();
  EXPECT_NEAR(rho * direct.volume, p.mass, 1e-10 * p.mass) << lib.Name(t);
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(direct.centroid[d], X[d], 1e-10 * rEq) << lib.Name(t) << ": the centroid is where it was placed";
    EXPECT_NEAR(rho * direct.principal[d], p.inertia[d], 1e-9 * p.inertia[2]) << lib.Name(t) << ": principal moment " << d;
  }
  // The body-frame centres map onto the world centres by q (Clumps' convention x_k = X + R(q) b_k),
  // and the body frame is principal: the direct inertia tensor rotated into it is diagonal.
  double I[9] = {0};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double ea[3] = {0, 0, 0}, eb[3] = {0, 0, 0}, ra[3], rb[3];
      ea[a] = 1, eb[b] = 1;
      vofdem::rigid::QuatRotate(q, ea, ra);
      vofdem::rigid::QuatRotate(q, eb, rb);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) I[3 * a + b] += ra[i] * direct.inertia[3 * i + j] * rb[j];
    }
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      EXPECT_NEAR(rho * I[3 * a + b], a == b ? p.inertia[a] : 0.0, 1e-9 * p.inertia[2]) << lib.Name(t) << ": body-frame inertia (" << a << "," << b << ")";
}

}  // namespace

TEST(ClumpInsertion, RegolithShapesScaleAndRotate) {
  vofdem::ClumpLibrary lib;
  for (const char *name : {"regolith1", "regolith2", "regolith3", "regolith4"}) {
    int t;
    ASSERT_EQ(lib.Find(name, &t), 0);
    ASSERT_GE(t, 0);
    EXPECT_EQ(lib.Template(t).spheres.size(), (size_t)(name[8] - '0' + 1)) << name << ": the base and its satellites";
    CheckPlaced(lib, t, 4.7e-5);
    CheckPlaced(lib, t, 3.1e-5);
  }
  int t;
  ASSERT_EQ(lib.Find("sphere", &t), 0);
  EXPECT_EQ(t, -1);
}

TEST(ClumpInsertion, UserTemplate) {
  vofdem::ClumpLibrary lib;
  ASSERT_EQ(lib.Add(PETSC_COMM_SELF, "peanut", {0, 0, 0, 1, 0, 0, 1.1, 0.9}, "test"), 0);
  int t;
  ASSERT_EQ(lib.Find("peanut", &t), 0);
  ASSERT_EQ(t, 0);
  CheckPlaced(lib, t, 1e-4);
}
