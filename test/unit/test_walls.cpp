// Walls beyond the box faces: triangle regions, STL reading, and the "counted once" rule for a
// sphere touching a mesh where triangles meet (its total force must equal a single plane's).
#include "vofdem/dem/TriangleBins.hpp"
#include "vofdem/dem/WallContacts.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace vofdem;

namespace {

// One particle of radius R at x, resting, with the arrays the contact loop reads.
struct OneParticle {
  PetscReal  x[3], v[3] = {0, 0, 0}, f[3] = {0, 0, 0}, r, m, ref[3] = {0, 0, 0}, w[3] = {0, 0, 0}, t[3] = {0, 0, 0};
  PetscInt64 id = 7;
  OneParticle(PetscReal px, PetscReal py, PetscReal pz, PetscReal R) : x{px, py, pz}, r(R), m(2500 * 4.0 / 3.0 * PETSC_PI * R * R * R) {}
  ParticleArrays Arrays() {
    ParticleArrays a;
    a.n = 1, a.x = x, a.v = v, a.f = f, a.radius = &r, a.mass = &m, a.reference = ref, a.omega = w, a.torque = t, a.id = &id;
    return a;
  }
};

// Force on the particle from the walls of `set` (one evaluation) and the number of contacts;
// `rebuild` false: with the candidates the set already has (e.g. from a restart).
void Evaluate(WallSet &set, OneParticle &p, PetscReal force[3], PetscInt *contacts, bool rebuild = true) {
  const PetscReal            lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
  const hertz::PairMaterial  mat   = hertz::MakePairMaterial(1e8, 0.28, 1e8, 0.28, 0.5, 0.5);
  const hertz::RollingParams rolling{};
  const hertz::VanDerWaals   vdw{};
  PetscReal                  elastic = 0, overlap = 0;
  set.Prepare(lo, hi);
  ParticleArrays a = p.Arrays();
  if (rebuild) set.BuildCandidates(a, 1e-4, {});
  p.f[0] = p.f[1] = p.f[2] = 0;
  *contacts = 0;
  const hertz::Lubrication   lub{};
  set.Evaluate<hertz::Rolling::None, kNoCohesion, false, false, false>(a, {&mat, 0, &rolling, &vdw, nullptr, 0, &lub, 0}, 1e-6, contacts, &elastic, &overlap);
  for (int d = 0; d < 3; ++d) force[d] = p.f[d];
}

// Mesh from corners (9 per triangle).
StlMesh Mesh(const std::vector<PetscReal> &corners) {
  StlMesh m;
  m.Build(corners);
  return m;
}

// Force of a single plane z = 0 on the same sphere.
PetscReal PlaneForce(PetscReal x, PetscReal y, PetscReal z, PetscReal R) {
  WallSet         set;
  const PetscReal point[3] = {0, 0, 0}, normal[3] = {0, 0, 1};
  set.AddPlane("floor", point, normal);
  OneParticle p(x, y, z, R);
  PetscReal   F[3];
  PetscInt    n;
  Evaluate(set, p, F, &n);
  EXPECT_EQ(n, 1);
  return F[2];
}

// The calls of RankArchive (io/RankArchive.hpp) kept in memory: what WallSet::ArchiveState saves
// comes back in the same order on load.
struct MemoryArchive {
  bool                                loading = false;
  size_t                              next    = 0;
  std::vector<std::vector<PetscReal>> entries;
  bool                                Loading() const { return loading; }
  bool                                SameRanks() const { return true; }
  template <class T>
  PetscErrorCode Scalar(T *value) {
    if (!loading) entries.push_back({(PetscReal)*value});
    else *value = (T)entries[next++][0];
    return 0;
  }
  template <class T>
  PetscErrorCode Array(const char *, std::vector<T> *values, PetscInt = 1) {
    if (!loading) entries.emplace_back(values->begin(), values->end());
    else {
      const std::vector<PetscReal> &e = entries[next++];
      values->assign(e.begin(), e.end());
    }
    return 0;
  }
};

}  // namespace

TEST(Walls, ClosestPointRegions) {
  const PetscReal a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0};
  PetscReal       q[3];
  int             which;
  const PetscReal face[3] = {0.2, 0.2, 1}, edge[3] = {0.5, -0.3, 0.1}, vtx[3] = {1.5, -0.2, 0}, hyp[3] = {0.8, 0.8, -1};
  EXPECT_EQ(wall::ClosestOnTriangle(a, b, c, face, q, &which), wall::Region::Face);
  EXPECT_DOUBLE_EQ(q[2], 0);
  EXPECT_EQ(wall::ClosestOnTriangle(a, b, c, edge, q, &which), wall::Region::Edge);
  EXPECT_EQ(which, 0);
  EXPECT_DOUBLE_EQ(q[0], 0.5);
  EXPECT_DOUBLE_EQ(q[1], 0);
  EXPECT_EQ(wall::ClosestOnTriangle(a, b, c, vtx, q, &which), wall::Region::Vertex);
  EXPECT_EQ(which, 1);
  EXPECT_EQ(wall::ClosestOnTriangle(a, b, c, hyp, q, &which), wall::Region::Edge);
  EXPECT_EQ(which, 1);
  EXPECT_NEAR(q[0], 0.5, 1e-15);
}

TEST(Walls, CylinderGapInsideAndOutside) {
  const PetscReal point[3] = {0, 0, 0}, axis[3] = {0, 0, 1}, p[3] = {0.3, 0.4, 5};
  PetscReal       gap, n[3];
  ASSERT_TRUE(wall::CylinderGap(point, axis, 1.0, true, PETSC_MIN_REAL, PETSC_MAX_REAL, p, &gap, n));
  EXPECT_NEAR(gap, 0.5, 1e-15);
  EXPECT_NEAR(n[0], -0.6, 1e-15);  // towards the axis, from the surface to the particle
  ASSERT_TRUE(wall::CylinderGap(point, axis, 0.2, false, PETSC_MIN_REAL, PETSC_MAX_REAL, p, &gap, n));
  EXPECT_NEAR(gap, 0.3, 1e-15);
  EXPECT_NEAR(n[1], 0.8, 1e-15);
  EXPECT_FALSE(wall::CylinderGap(point, axis, 1.0, true, 0, 1, p, &gap, n));  // beyond the open end
}

TEST(Walls, MotionRoundTripAndSurfaceVelocity) {
  wall::Motion m;
  m.velocity[0] = 0.1, m.omega = 2, m.center[0] = 1;  // about z through (1, 0, 0), moving in x
  const wall::Pose P = wall::PoseAt(m, 0.25);
  const PetscReal  x[3] = {2, 0.5, 0.3};
  PetscReal        x0[3], n[3], u[3];
  wall::ToReference(P, m, x, x0);
  // Back to the world: c(t) + Rot (x0 - c).
  const PetscReal s[3] = {x0[0] - m.center[0], x0[1] - m.center[1], x0[2] - m.center[2]};
  wall::DirectionToWorld(P, s, n);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(P.center[d] + n[d], x[d], 1e-14);
  wall::SurfaceVelocity(m, P, x, u);  // V + w e_z x (x - c(t)), c(t) = (1.025, 0, 0)
  EXPECT_NEAR(u[0], 0.1 - 2 * 0.5, 1e-14);
  EXPECT_NEAR(u[1], 2 * (2 - 1.025), 1e-14);
  EXPECT_NEAR(u[2], 0, 1e-14);
}

TEST(Walls, StlAsciiBinaryAndWelding) {
  const std::string ascii = "solid square\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 1 1 0\n  endloop\n endfacet\n"
                            " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 1 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid square\n";
  const PetscReal        offset[3] = {0, 0, 0.5};
  std::vector<PetscReal> corners;
  std::string            error;
  ASSERT_TRUE(ParseStl(ascii, 2.0, offset, &corners, &error)) << error;
  ASSERT_EQ(corners.size(), 18u);
  EXPECT_DOUBLE_EQ(corners[5], 0.5);  // z of the second vertex, shifted
  EXPECT_DOUBLE_EQ(corners[6], 2.0);  // x of the third, scaled
  StlMesh m = Mesh(corners);
  EXPECT_EQ(m.Triangles(), 2);
  EXPECT_EQ(m.vertex.size(), 12u);  // 4 welded vertices
  EXPECT_EQ(m.edges, 5);            // the diagonal shared
  // Binary round trip (floats) and a truncated copy.
  const std::string      bin  = BinaryStl(corners);
  const PetscReal        zero[3] = {0, 0, 0};
  std::vector<PetscReal> back;
  ASSERT_TRUE(ParseStl(bin, 1.0, zero, &back, &error)) << error;
  EXPECT_EQ(back, corners);
  EXPECT_FALSE(ParseStl(bin.substr(0, bin.size() - 7), 1.0, zero, &back, &error));
  EXPECT_NE(error.find("the header announces 2 triangles (184 bytes), the file has 177 bytes"), std::string::npos) << error;
  // Malformed ASCII names its line.
  std::string bad = ascii;
  bad.replace(bad.find("vertex 1 0 0"), 12, "vertex 1 0");
  EXPECT_FALSE(ParseStl(bad, 1.0, zero, &back, &error));
  EXPECT_NE(error.find("ASCII STL line 5: expected 'vertex x y z'"), std::string::npos) << error;
}

// A sphere on the shared edge (diagonal) of two coplanar triangles: one contact, the plane's force.
TEST(Walls, SphereOnSharedEdgeCountedOnce) {
  const PetscReal R = 1e-3, z = R - 1e-5;
  const StlMesh   square = Mesh({-0.01, -0.01, 0, 0.01, -0.01, 0, 0.01, 0.01, 0, -0.01, -0.01, 0, 0.01, 0.01, 0, -0.01, 0.01, 0});
  const PetscReal plane = PlaneForce(0, 0, z, R);
  ASSERT_GT(plane, 0);
  for (PetscReal shift : {0.0, 1e-15, -1e-15, 1e-12}) {  // on the diagonal, and rounding either side
    WallSet set;
    set.AddMesh("square", square);
    OneParticle p(0.002 + shift, 0.002, z, R);
    PetscReal   F[3];
    PetscInt    n;
    Evaluate(set, p, F, &n);
    EXPECT_EQ(n, 1) << "shift " << shift;
    EXPECT_NEAR(F[2], plane, 1e-12 * plane) << "shift " << shift;
    // Within the region tolerance the contact is on the edge and its normal tilts by the shift / gap.
    EXPECT_NEAR(F[0], 0, 1e-9 * plane);
  }
}

// A sphere on a vertex shared by 6 triangles (a hexagonal fan): one contact, the plane's force.
TEST(Walls, SphereOnVertexOfSixTrianglesCountedOnce) {
  const PetscReal        R = 1e-3, z = R - 2e-5, L = 0.01;
  std::vector<PetscReal> corners;
  for (int k = 0; k < 6; ++k) {
    const PetscReal a0 = k * PETSC_PI / 3, a1 = ((k + 1) % 6) * PETSC_PI / 3;  // the last spoke is the first, bit for bit
    corners.insert(corners.end(), {0, 0, 0, L * std::cos(a0), L * std::sin(a0), 0, L * std::cos(a1), L * std::sin(a1), 0});
  }
  const StlMesh fan = Mesh(corners);
  ASSERT_EQ(fan.Triangles(), 6);
  ASSERT_EQ(fan.vertex.size(), 3u * 7);  // centre + 6 spokes
  const PetscReal plane = PlaneForce(0, 0, z, R);
  for (PetscReal shift : {0.0, 1e-16, 3e-14}) {
    WallSet set;
    set.AddMesh("fan", fan);
    OneParticle p(shift, -shift, z, R);
    PetscReal   F[3];
    PetscInt    n;
    Evaluate(set, p, F, &n);
    EXPECT_EQ(n, 1) << "shift " << shift;
    EXPECT_NEAR(F[2], plane, 1e-12 * plane) << "shift " << shift;
  }
  // Without the rule all six triangles would push: the test can fail.
  EXPECT_GT(6 * plane, 1.5 * plane);
}

// A restart evaluates with the saved candidates before its first rebuild: the contact loop's scratch
// must fit the largest saved group (six triangles here; a fresh set had room for none, and the
// tungsten funnel's restart overran the heap).
TEST(Walls, RestoredCandidatesEvaluateAsSaved) {
  const PetscReal        R = 1e-3, z = R - 2e-5, L = 0.01;
  std::vector<PetscReal> corners;
  for (int k = 0; k < 6; ++k) {
    const PetscReal a0 = k * PETSC_PI / 3, a1 = ((k + 1) % 6) * PETSC_PI / 3;
    corners.insert(corners.end(), {0, 0, 0, L * std::cos(a0), L * std::sin(a0), 0, L * std::cos(a1), L * std::sin(a1), 0});
  }
  const StlMesh fan = Mesh(corners);
  WallSet       saved, restored;
  saved.AddMesh("fan", fan), restored.AddMesh("fan", fan);
  OneParticle p(1e-4, 5e-5, z, R);
  PetscReal   F[3], G[3];
  PetscInt    n, m;
  Evaluate(saved, p, F, &n);
  ASSERT_EQ(saved.Candidates(), 6u);
  MemoryArchive ar;
  ASSERT_EQ(saved.ArchiveState(ar), 0);
  ar.loading = true;
  const PetscReal lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
  restored.Prepare(lo, hi);
  ASSERT_EQ(restored.ArchiveState(ar), 0);
  ASSERT_EQ(restored.Candidates(), 6u);
  Evaluate(restored, p, G, &m, false);
  EXPECT_EQ(m, n);
  for (int d = 0; d < 3; ++d) EXPECT_EQ(G[d], F[d]) << "component " << d;
  EXPECT_GT(F[2], 0);
}

// A sphere in a concave corner of two perpendicular faces touches both: two contacts.
TEST(Walls, ConcaveCornerKeepsBothFaces) {
  const PetscReal R = 1e-3, d = R - 1e-5;
  const StlMesh   corner = Mesh({0, -1, 0, 1, -1, 0, 1, 1, 0, 0, -1, 0, 1, 1, 0, 0, 1, 0,     // floor z = 0, x in [0, 1]
                                 0, -1, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, 1, 1, 0, -1, 1});  // wall x = 0
  WallSet         set;
  set.AddMesh("corner", corner);
  OneParticle p(d, 0.3, d, R);
  PetscReal   F[3];
  PetscInt    n;
  Evaluate(set, p, F, &n);
  EXPECT_EQ(n, 2);
  EXPECT_NEAR(F[0], F[2], 1e-12 * F[2]);
  EXPECT_NEAR(F[2], PlaneForce(0, 0, d, R), 1e-12 * F[2]);
}

// A moving wall: the surface velocity enters the contact (P3): a plane sliding under a resting
// sphere drags it along (friction in the direction of the wall's motion).
TEST(Walls, MovingPlaneDragsRestingSphere) {
  const PetscReal R = 1e-3, point[3] = {0, 0, 0}, normal[3] = {0, 0, 1};
  wall::Motion    m;
  m.velocity[0] = 0.1;
  WallSet set;
  set.AddPlane("belt", point, normal, m);
  OneParticle p(0, 0, R - 1e-5, R);
  PetscReal   F[3];
  PetscInt    n;
  Evaluate(set, p, F, &n);
  EXPECT_EQ(n, 1);
  EXPECT_GT(F[0], 0);
  EXPECT_NEAR(set.LocalLoad(0)[0], -F[0], 1e-15);  // the belt feels the opposite force
}

// A roller: a rod (cylinder, particles outside) turning about its own axis drags a sphere resting on
// it along its surface velocity, and feels the opposite torque about its axis.
TEST(Walls, RotatingRollerDragsSphereAndFeelsTorque) {
  const PetscReal R = 1e-3, Rc = 5e-3, point[3] = {0, 0, 0}, axis[3] = {0, 1, 0};
  wall::Motion    m;
  m.axis[0] = 0, m.axis[1] = 1, m.axis[2] = 0, m.omega = 10;  // about y: the top moves at w e_y x Rc e_z = +w Rc e_x
  WallSet set;
  set.AddCylinder("roller", point, axis, Rc, false, m);
  OneParticle p(0, 0, Rc + R - 1e-5, R);
  PetscReal   F[3];
  PetscInt    n;
  Evaluate(set, p, F, &n);
  EXPECT_EQ(n, 1);
  EXPECT_GT(F[2], 0);
  EXPECT_GT(F[0], 0);
  // The roller gets -F at the contact point z = Rc - 1e-5: a torque about y against its rotation.
  EXPECT_NEAR(set.LocalLoad(0)[4], -(Rc - 1e-5) * F[0], 1e-12 * std::abs(F[0]) * Rc);
  EXPECT_LT(set.LocalLoad(0)[4], 0);
}

// The rebuild rule: a wall moving at 0.1 m/s asks for a rebuild once it may have moved half the skin.
TEST(Walls, MovingWallTriggersRebuild) {
  const PetscReal point[3] = {0, 0, 0}, normal[3] = {0, 0, 1}, lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
  wall::Motion    m;
  m.velocity[2] = 0.1;
  WallSet set;
  set.AddPlane("lift", point, normal, m);
  set.Prepare(lo, hi);
  OneParticle p(0, 0, 0.5, 1e-3);
  set.BuildCandidates(p.Arrays(), 1e-4, {});
  set.Advance(4e-4);  // 40 um < 50 um
  EXPECT_FALSE(set.MovedBeyond(5e-5));
  set.Advance(2e-4);  // 60 um
  EXPECT_TRUE(set.MovedBeyond(5e-5));
  set.BuildCandidates(p.Arrays(), 1e-4, {});
  EXPECT_FALSE(set.MovedBeyond(5e-5));
}

// The mesh walls' binning (TriangleBins) must offer every triangle within reach of a point, in
// increasing order, as a search through all triangles finds them: random slivers and points, some
// outside the mesh's box (up to the reach), and a reach smaller than the bins were built for.
TEST(Walls, TriangleBinsOfferEveryTriangleWithinReach) {
  std::uint64_t state = 12345;
  auto          uniform = [&]() {  // xorshift, reproducible on any platform
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return (state >> 11) * (1.0 / 9007199254740992.0);
  };
  const PetscInt         triangles = 300;
  std::vector<PetscReal> corner(9 * triangles);
  PetscReal              lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  for (PetscInt t = 0; t < triangles; ++t) {
    // Long slivers (a cone's facets) and small triangles, in a 2 x 1 x 1 box.
    const PetscReal a[3] = {2 * uniform(), uniform(), uniform()}, len = t % 3 ? 0.05 : 1.0;
    for (int v = 0; v < 3; ++v)
      for (int d = 0; d < 3; ++d) {
        const PetscReal c = a[d] + (v ? len * (uniform() - 0.5) : 0);
        corner[9 * t + 3 * v + d] = c, lo[d] = std::min(lo[d], c), hi[d] = std::max(hi[d], c);
      }
  }
  const PetscReal reach = 0.03;
  TriangleBins    bins;
  bins.Build(corner.data(), triangles, lo, hi, reach);
  long found = 0;
  for (int k = 0; k < 20000; ++k) {
    PetscReal x[3];
    for (int d = 0; d < 3; ++d) x[d] = lo[d] - reach + (hi[d] - lo[d] + 2 * reach) * uniform();
    const PetscReal        limit = (k % 2 ? 1.0 : 0.5) * reach;
    std::vector<PetscInt> all, offered;
    for (PetscInt t = 0; t < triangles; ++t) {
      PetscReal q[3];
      int       which;
      wall::ClosestOnTriangle(&corner[9 * t], &corner[9 * t + 3], &corner[9 * t + 6], x, q, &which);
      const PetscReal s[3] = {x[0] - q[0], x[1] - q[1], x[2] - q[2]};
      if (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] < limit * limit) all.push_back(t);
    }
    const PetscInt *b, *e;
    bins.Near(x, &b, &e);
    ASSERT_TRUE(std::is_sorted(b, e));
    for (const PetscInt *it = b; it != e; ++it) {
      PetscReal q[3];
      int       which;
      wall::ClosestOnTriangle(&corner[9 * *it], &corner[9 * *it + 3], &corner[9 * *it + 6], x, q, &which);
      const PetscReal s[3] = {x[0] - q[0], x[1] - q[1], x[2] - q[2]};
      if (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] < limit * limit) offered.push_back(*it);
    }
    ASSERT_EQ(offered, all) << "point " << k;
    found += (long)all.size();
    // And the bins are much shorter than the mesh (they are the point of it).
    ASSERT_LT(e - b, triangles / 2);
  }
  EXPECT_GT(found, 1000);  // the points did meet triangles
}
