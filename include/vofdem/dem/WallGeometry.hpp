// Geometry of the walls beyond the six box faces: distances from a sphere centre to an infinite
// plane, a cylinder, and a triangle (closest point and the region it lies in: face, edge or vertex),
// and the rigid motion of a wall (translation plus rotation about an axis). Pure inline functions:
// they run inside the wall-contact loop and are unit-tested on their own (test/unit/test_walls.cpp).
#pragma once

#include <petscsys.h>

#include <cmath>

namespace vofdem::wall {

inline PetscReal Dot(const PetscReal a[3], const PetscReal b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline void      CrossProduct(const PetscReal a[3], const PetscReal b[3], PetscReal c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

// Where on a triangle the closest point lies. A sphere touching a mesh where triangles meet sees
// the same edge or vertex from each of them; the region tells the contact loop which contacts are
// one and the same (WallSet's "counted once" rule).
enum class Region : int { Face = 0, Edge = 1, Vertex = 2 };

// Closest point of triangle (a, b, c) to p. Returns the region; `which` is the edge (0: ab, 1: bc,
// 2: ca) or the vertex (0: a, 1: b, 2: c). A point whose projection lies within a relative
// tolerance of the boundary (barycentric coordinate below kEps) is classified on the boundary, so
// that a sphere centred over a shared edge or vertex gets the same answer from every triangle that
// shares it, whatever the rounding.
inline constexpr PetscReal kRegionEps = 1e-9;
inline Region ClosestOnTriangle(const PetscReal a[3], const PetscReal b[3], const PetscReal c[3], const PetscReal p[3], PetscReal q[3], int *which) {
  PetscReal e0[3], e1[3], ap[3];
  for (int d = 0; d < 3; ++d) e0[d] = b[d] - a[d], e1[d] = c[d] - a[d], ap[d] = p[d] - a[d];
  const PetscReal d00 = Dot(e0, e0), d01 = Dot(e0, e1), d11 = Dot(e1, e1), d20 = Dot(ap, e0), d21 = Dot(ap, e1);
  const PetscReal den = d00 * d11 - d01 * d01;
  if (den > 0) {  // barycentric coordinates (u, v, w) of the projection onto the plane
    const PetscReal v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den, u = 1 - v - w;
    if (u > kRegionEps && v > kRegionEps && w > kRegionEps) {
      for (int d = 0; d < 3; ++d) q[d] = a[d] + v * e0[d] + w * e1[d];
      *which = 0;
      return Region::Face;
    }
  }
  // On the boundary or outside: the nearest of the three edges (segments).
  const PetscReal *from[3] = {a, b, c}, *to[3] = {b, c, a};
  PetscReal        best = PETSC_MAX_REAL, bestT = 0;
  int              bestEdge = 0;
  for (int k = 0; k < 3; ++k) {
    PetscReal e[3], s[3];
    for (int d = 0; d < 3; ++d) e[d] = to[k][d] - from[k][d], s[d] = p[d] - from[k][d];
    const PetscReal ee = Dot(e, e);
    PetscReal       t  = ee > 0 ? Dot(s, e) / ee : 0;
    t                  = t < 0 ? 0 : (t > 1 ? 1 : t);
    PetscReal dist2    = 0;
    for (int d = 0; d < 3; ++d) {
      const PetscReal r = s[d] - t * e[d];
      dist2 += r * r;
    }
    if (dist2 < best) best = dist2, bestT = t, bestEdge = k;
  }
  for (int d = 0; d < 3; ++d) q[d] = from[bestEdge][d] + bestT * (to[bestEdge][d] - from[bestEdge][d]);
  if (bestT <= kRegionEps) {
    *which = bestEdge;
    return Region::Vertex;
  }
  if (bestT >= 1 - kRegionEps) {
    *which = (bestEdge + 1) % 3;
    return Region::Vertex;
  }
  *which = bestEdge;
  return Region::Edge;
}

// Signed distance of p from the plane through `point` with unit normal n (positive on the side n
// points to: where the particles are).
inline PetscReal PlaneDistance(const PetscReal point[3], const PetscReal n[3], const PetscReal p[3]) {
  const PetscReal s[3] = {p[0] - point[0], p[1] - point[1], p[2] - point[2]};
  return Dot(s, n);
}

// Gap between a sphere centre p and a cylinder surface (axis through `point`, unit direction `axis`,
// radius R), with the unit normal n pointing from the surface towards p. inside: the particles
// are inside the cylinder. Returns false where the cylinder has no surface for p: beyond its axial
// extent [lo, hi] (open ends), or on the axis itself.
inline bool CylinderGap(const PetscReal point[3], const PetscReal axis[3], PetscReal R, bool inside, PetscReal lo, PetscReal hi, const PetscReal p[3],
                        PetscReal *gap, PetscReal n[3]) {
  PetscReal s[3] = {p[0] - point[0], p[1] - point[1], p[2] - point[2]};
  const PetscReal along = Dot(s, axis);
  if (along < lo || along > hi) return false;
  for (int d = 0; d < 3; ++d) s[d] -= along * axis[d];
  const PetscReal rho = std::sqrt(Dot(s, s));
  if (rho == 0) return false;
  const PetscReal sign = inside ? -1 : 1;
  for (int d = 0; d < 3; ++d) n[d] = sign * s[d] / rho;
  *gap = inside ? R - rho : rho - R;
  return true;
}

// Rigid motion of a wall: x(t) = c + V t + Rot(w t) (x0 - c), a rotation by angle w t about the
// unit axis a through the rotation point c (which itself moves with V), then the translation.
struct Motion {
  PetscReal velocity[3] = {0, 0, 0};  // m/s
  PetscReal center[3]   = {0, 0, 0};  // m, rotation point at t = 0
  PetscReal axis[3]     = {0, 0, 1};  // unit
  PetscReal omega       = 0;          // rad/s
  PetscReal start       = 0;          // s: the wall rests at its t = 0 pose until then (a blade that waits for the powder to settle)
  bool Moves() const { return omega != 0 || velocity[0] != 0 || velocity[1] != 0 || velocity[2] != 0; }
  // Time the wall has been moving at time t.
  PetscReal Elapsed(PetscReal t) const { return t > start ? t - start : 0; }
};

// The pose of a wall at one time: rotation matrix and the current rotation point.
struct Pose {
  PetscReal rot[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  PetscReal center[3] = {0, 0, 0};  // c + V t
  PetscReal moving    = 1;          // 0 before the motion's start time: the surface is at rest
};

// Rodrigues' formula for the rotation by angle `theta` about the unit axis a.
inline Pose PoseAt(const Motion &m, PetscReal time) {
  Pose            P;
  const PetscReal t = m.Elapsed(time);
  P.moving          = time >= m.start ? 1 : 0;
  const PetscReal th = m.omega * t, c = std::cos(th), s = std::sin(th), C = 1 - c, *a = m.axis;
  if (th != 0) {
    P.rot[0][0] = c + a[0] * a[0] * C, P.rot[0][1] = a[0] * a[1] * C - a[2] * s, P.rot[0][2] = a[0] * a[2] * C + a[1] * s;
    P.rot[1][0] = a[1] * a[0] * C + a[2] * s, P.rot[1][1] = c + a[1] * a[1] * C, P.rot[1][2] = a[1] * a[2] * C - a[0] * s;
    P.rot[2][0] = a[2] * a[0] * C - a[1] * s, P.rot[2][1] = a[2] * a[1] * C + a[0] * s, P.rot[2][2] = c + a[2] * a[2] * C;
  }
  for (int d = 0; d < 3; ++d) P.center[d] = m.center[d] + m.velocity[d] * t;
  return P;
}

// World point -> the wall's reference frame (its geometry as given at t = 0): c + Rot^T (x - c(t)).
inline void ToReference(const Pose &P, const Motion &m, const PetscReal x[3], PetscReal x0[3]) {
  const PetscReal s[3] = {x[0] - P.center[0], x[1] - P.center[1], x[2] - P.center[2]};
  for (int d = 0; d < 3; ++d) x0[d] = m.center[d] + P.rot[0][d] * s[0] + P.rot[1][d] * s[1] + P.rot[2][d] * s[2];
}

// A direction from the reference frame to the world: Rot n0.
inline void DirectionToWorld(const Pose &P, const PetscReal n0[3], PetscReal n[3]) {
  for (int d = 0; d < 3; ++d) n[d] = P.rot[d][0] * n0[0] + P.rot[d][1] * n0[1] + P.rot[d][2] * n0[2];
}

// Velocity of the wall's material point now at world position x: V + w a x (x - c(t)) (P3: the
// surface velocity enters the contact's relative velocity).
inline void SurfaceVelocity(const Motion &m, const Pose &P, const PetscReal x[3], PetscReal u[3]) {
  const PetscReal s[3] = {x[0] - P.center[0], x[1] - P.center[1], x[2] - P.center[2]};
  PetscReal       axs[3];
  CrossProduct(m.axis, s, axs);
  for (int d = 0; d < 3; ++d) u[d] = P.moving * (m.velocity[d] + m.omega * axs[d]);
}

}  // namespace vofdem::wall
