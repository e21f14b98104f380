// Rigid multi-sphere clumps (docs/physics.md P10): the member spheres of a clump (same clump id, all on
// one rank: ParticleSwarm::Migrate moves a clump whole) move as one rigid body.
//
// Each member carries the body's state in the swarm field "rigid" (kRigidWidth reals): the
// orientation quaternion q (body -> world, w x y z), its centre in the body frame b (principal axes,
// origin at the union's centroid), the clump's mass M and principal moments I1..I3 (the union of the
// spheres, overlaps once: ClumpTemplate). Members keep v_k = V + w x R b_k and w_k = w, so the clump's
// velocity V and angular velocity w are read back from any member; the member's "mass" is its share
// M/n (totals stay right; the contact laws damp with that share).
//
// Integration (velocity Verlet, as for spheres): half kick V += dt/2 F/M, L += dt/2 T with F, T the
// sums over the members (T about the centroid: sum tau_k + R b_k x (f_k - m_k g): gravity acts at the
// centroid); drift X += dt V and the
// orientation by the implicit-midpoint quaternion update with L fixed:
//   q_mid = q exp(dt/2 w_b(q)),  q' = q exp(dt w_b(q_mid)),  w_b(q) = I^-1 R(q)^T L,
// which keeps |L| exactly and the energy of a torque-free body to O(dt^2) without drift.
// Each member moves by the body's increment (x_k += dX + R' b_k - R b_k), so a member wrapped across
// a periodic face stays wrapped.
#pragma once

#include "vofdem/dem/ClumpTemplate.hpp"
#include "vofdem/dem/ParticleSwarm.hpp"

#include <unordered_map>
#include <vector>

namespace vofdem {

namespace rigid {
constexpr int kQ = 0, kBody = 4, kMass = 7, kInertia = 8;  // offsets in a member's "rigid" entry
void QuatRotate(const PetscReal q[4], const PetscReal v[3], PetscReal out[3]);         // R(q) v
void QuatRotateInverse(const PetscReal q[4], const PetscReal v[3], PetscReal out[3]);  // R(q)^T v
void QuatFromMatrix(const PetscReal R[9], PetscReal q[4]);                             // R row-major, proper rotation
void QuatMultiply(const PetscReal a[4], const PetscReal b[4], PetscReal r[4]);          // a b: b first, then a
// The rotation that best takes the n points P onto the n points Q after centring both (Horn 1987).
void BestRotation(int n, const PetscReal *P, const PetscReal *Q, PetscReal q[4]);
}  // namespace rigid

class Clumps {
public:
  // After the particles of a file are placed (all members of a clump local): computes each clump's
  // template from its members as placed, sets the
  // members' rigid state and mass shares, and makes their velocities rigid (V, w: the means of the
  // members' given v and w). `density` of each member's type. Returns the number of local clumps.
  // A shape is computed once: a clump whose radii and member distances (in member order) repeat
  // an earlier one's is that one rotated; the rotation (BestRotation) is checked to map every
  // member onto its place within 1e-6 of the first radius, else the clump is computed anew (a mirror
  // image, say).
  // `gravity`: the acceleration the force loop gives every sphere (m g), which acts on a clump at its
  // centroid (M g, no torque), not at its members.
  PetscErrorCode SetUp(const ParticleArrays &a, const std::vector<PetscReal> &typeDensity, const PetscReal gravity[3], PetscInt *count);
  bool     Any() const { return any_; }
  PetscInt ShapesComputed() const { return shapes_; }  // union quadratures SetUp ran (the rest were rotations)
  void SetAny(bool any) { any_ = any; }
  // The local particles were reordered, added or removed (Dem::Rebuild, Dem::Load): the members of
  // each clump are regrouped at the next use (not at every kick: grouping is most of a clump step).
  void Invalidate() { stale_ = true; }
  // Half kick of every local clump with its members' forces and torques (then, with drift, the move).
  void Kick(const ParticleArrays &a, PetscReal dt, bool drift) const;
  // Kinetic energy of the local clumps: translational and rotational.
  void Energy(const ParticleArrays &a, PetscReal *translational, PetscReal *rotational) const;

private:
  void Group(const ParticleArrays &a) const;    // members_ of each local clump (a cache, hence mutable)
  void Flatten() const;                         // order_ and start_ from members_, in its iteration order
  bool     any_    = false;
  PetscInt shapes_ = 0;
  PetscReal gravity_[3] = {0, 0, 0};
  mutable std::unordered_map<PetscInt64, std::vector<PetscInt>> members_;
  // The same grouping flat, for the kicks: clump c's members are order_[start_[c] .. start_[c + 1]), its
  // first member (whose entry the kick reads the body's state from) first; scratch_ holds R b_k per member.
  mutable std::vector<PetscInt>  order_, start_;
  mutable std::vector<PetscReal> scratch_;
  mutable bool     stale_    = true;
  mutable PetscInt groupedN_ = -1;  // a.n when grouped: a changed count regroups even without Invalidate()
};

}  // namespace vofdem
