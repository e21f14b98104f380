// The contact loop of the walls beyond the box faces (Walls.hpp): one instance per contact model,
// bound outside the loop by Dem::ComputeForces like the box faces' loop. Per group of candidates
// (one particle, one wall) the wall kind is switched on once; per candidate there is no dispatch.
#pragma once

#include "vofdem/dem/ContactLaw.hpp"
#include "vofdem/dem/Walls.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace walldetail {
inline bool Has(const std::vector<PetscInt> &v, PetscInt x) { return std::find(v.begin(), v.end(), x) != v.end(); }
}  // namespace walldetail

template <hertz::Rolling RM, int COH, bool NEAR, bool LIN, bool MULTI>
void WallSet::Evaluate(const ParticleArrays &a, const WallContactLaw &law, PetscReal dt, PetscInt *contacts, PetscReal *elastic, PetscReal *maxOverlap) {
  constexpr bool JKR = COH == kJkr;
  std::fill(load_.begin(), load_.end(), 0);
  std::fill(loadContacts_.begin(), loadContacts_.end(), 0);
  for (size_t g = 0; g + 1 < group_.size(); ++g) {
    const PetscInt b = group_[g], m = group_[g + 1] - b, p = part_[b];
    const int      wi = wallOf_[b];
    const Wall    &w  = walls_[wi];
    const PetscReal r = a.radius[p], *x = &a.x[3 * p], *v = &a.v[3 * p], *om = &a.omega[3 * p];
    const hertz::PairMaterial  &mat     = MULTI ? law.table->Wall(a.type[p]) : *law.material;
    const hertz::RollingParams &rolling = MULTI ? law.table->WallRolling(a.type[p]) : *law.rolling;
    // JKR's constants depend on the material and R* = r only: once per particle and wall, not per contact and step.
    const hertz::JkrPair jkr      = JKR ? hertz::JkrConstants(mat, r) : hertz::JkrPair{};
    const PetscReal      breakGap = JKR ? r - jkr.breakOverlap : r;  // beyond this centre-surface distance no contact force
    const PetscReal presentGap = NEAR ? r + law.range : breakGap;
    PetscReal       x0[3];
    wall::ToReference(w.pose, w.motion, x, x0);
    // 1. Geometry of every candidate in the wall's reference frame: the distance from the centre
    // to the surface, the normal towards the centre, the region.
    for (PetscInt k = 0; k < m; ++k) {
      Scratch &s = scratch_[k];
      s.present = 0, s.keep = 0, s.region = (int)wall::Region::Face, s.which = 0;
      switch (w.kind) {
      case WallKind::Plane:
        s.gap = wall::PlaneDistance(w.point, w.dir, x0);
        std::copy(w.dir, w.dir + 3, s.n0);
        s.present = 1;
        break;
      case WallKind::Cylinder:
        s.present = wall::CylinderGap(w.point, w.dir, w.radius, w.inside, w.lo, w.hi, x0, &s.gap, s.n0);
        break;
      case WallKind::Mesh: {
        const PetscInt   t = elem_[b + k];
        const PetscReal *c = &w.mesh.corner[9 * t];
        PetscReal        q[3], d[3];
        s.region = (int)wall::ClosestOnTriangle(c, c + 3, c + 6, x0, q, &s.which);
        for (int e = 0; e < 3; ++e) d[e] = x0[e] - q[e];
        s.gap = std::sqrt(wall::Dot(d, d));
        if (s.gap > 0) {
          for (int e = 0; e < 3; ++e) s.n0[e] = d[e] / s.gap;
        } else {  // the centre on the triangle: its face normal (either side would do)
          const PetscReal e0[3] = {c[3] - c[0], c[4] - c[1], c[5] - c[2]}, e1[3] = {c[6] - c[0], c[7] - c[1], c[8] - c[2]};
          wall::CrossProduct(e0, e1, s.n0);
          const PetscReal l = std::sqrt(wall::Dot(s.n0, s.n0));
          for (int e = 0; e < 3; ++e) s.n0[e] /= l;
        }
        s.present = 1;
      } break;
      }
      // Present: within reach of a force (contact, a JKR bond that has not broken, van der Waals).
      const bool bonded = JKR && spring_[kSpringWidth * (b + k) + kJkrBonded] != 0;
      s.present = s.present && (s.gap < r || (bonded && s.gap < breakGap) || (NEAR && s.gap < presentGap));
    }
    // 2. Counted once: faces win over edges over vertices; a feature shared by triangles once.
    if (w.kind != WallKind::Mesh) {
      scratch_[0].keep = scratch_[0].present;
    } else {
      const PetscInt *tv = w.mesh.triVertex.data(), *te = w.mesh.triEdge.data();
      covered_.clear();  // edge ids e >= 0, vertex ids as -1 - v
      for (PetscInt k = 0; k < m; ++k) {
        Scratch &s = scratch_[k];
        if (!s.present || s.region != (int)wall::Region::Face) continue;
        const PetscInt t = elem_[b + k];
        s.keep           = 1;
        for (int e = 0; e < 3; ++e) covered_.push_back(te[3 * t + e]), covered_.push_back(-1 - tv[3 * t + e]);
      }
      for (PetscInt k = 0; k < m; ++k) {
        Scratch &s = scratch_[k];
        if (!s.present || s.region != (int)wall::Region::Edge) continue;
        const PetscInt t = elem_[b + k], edge = te[3 * t + s.which];
        if (walldetail::Has(covered_, edge)) continue;
        s.keep = 1;
        covered_.push_back(edge), covered_.push_back(-1 - tv[3 * t + s.which]), covered_.push_back(-1 - tv[3 * t + (s.which + 1) % 3]);
      }
      for (PetscInt k = 0; k < m; ++k) {
        Scratch &s = scratch_[k];
        if (!s.present || s.region != (int)wall::Region::Vertex) continue;
        const PetscInt vertex = -1 - tv[3 * elem_[b + k] + s.which];
        if (walldetail::Has(covered_, vertex)) continue;
        s.keep = 1;
        covered_.push_back(vertex);
      }
      // A contact that moved to a neighbouring triangle takes over the spring of the one that ended.
      released_.clear();
      for (PetscInt k = 0; k < m; ++k)
        if (touching_[b + k] && !scratch_[k].keep) released_.push_back(k);
      size_t next = 0;
      for (PetscInt k = 0; k < m && next < released_.size(); ++k)
        if (scratch_[k].keep && !touching_[b + k] && scratch_[k].gap < r) {
          const PetscReal *from = &spring_[kSpringWidth * (b + released_[next++])];
          std::copy(from, from + kSpringWidth, &spring_[kSpringWidth * (b + k)]);
        }
      for (PetscInt k : released_) std::fill(&spring_[kSpringWidth * (b + k)], &spring_[kSpringWidth * (b + k + 1)], 0), touching_[b + k] = 0;
    }
    // 3. Forces of the kept contacts.
    PetscReal *load = &load_[6 * wi];
    for (PetscInt k = 0; k < m; ++k) {
      const Scratch &s  = scratch_[k];
      PetscReal     *xi = &spring_[kSpringWidth * (b + k)];
      if (!s.keep) {
        if (touching_[b + k]) std::fill(xi, xi + kSpringWidth, 0), touching_[b + k] = 0;
        continue;
      }
      const PetscReal delta = r - s.gap;
      PetscReal       n[3], rn[3], pc[3], arm[3], F[3], Ft[3], tq[3], M[3], u[3], wxr[3], vrel[3], wrel[3], Tw[3];
      wall::DirectionToWorld(w.pose, s.n0, n);
      for (int e = 0; e < 3; ++e) rn[e] = -r * n[e], pc[e] = x[e] + rn[e], arm[e] = pc[e] - w.pose.center[e];
      if constexpr (NEAR) {  // across the gap -delta: van der Waals attraction (P7) and lubrication (P8), R* = R
        PetscReal uw[3];
        wall::SurfaceVelocity(w.motion, w.pose, pc, uw);
        const PetscReal vn = (v[0] - uw[0]) * n[0] + (v[1] - uw[1]) * n[1] + (v[2] - uw[2]) * n[2];  // > 0 leaving the wall
        const PetscReal mu = !law.fluidLubrication ? 1 : law.lubricationUniform > 0 ? law.lubricationUniform : a.fluidViscosity[p];
        const PetscReal fv = hertz::VdwAttraction(*law.vdw, -delta, r) + mu * hertz::LubricationCoefficient(*law.lubrication, -delta, r) * vn;
        for (int e = 0; e < 3; ++e) a.f[3 * p + e] -= fv * n[e], F[e] = fv * n[e];
        wall::CrossProduct(arm, F, Tw);
        for (int e = 0; e < 3; ++e) load[e] += F[e], load[3 + e] += Tw[e];
      }
      // In contact from touching on; a JKR bond holds until its break overlap (P6).
      const bool inContact = delta > 0 || (JKR && xi[kJkrBonded] != 0 && delta > jkr.breakOverlap);
      if (!inContact) {
        if (touching_[b + k]) std::fill(xi, xi + kSpringWidth, 0), touching_[b + k] = 0;
        continue;
      }
      touching_[b + k] = 1;
      // Relative velocity of the particle's surface against the wall's at the contact (P3).
      wall::SurfaceVelocity(w.motion, w.pose, pc, u);
      wall::CrossProduct(om, rn, wxr);
      for (int e = 0; e < 3; ++e) vrel[e] = v[e] + wxr[e] - u[e], wrel[e] = om[e] - w.pose.moving * w.motion.omega * w.motion.axis[e];
      hertz::NormalLaw nl = NormalLawAt<COH, LIN>(mat, law.linearKn, delta, r, xi, JKR ? &jkr : nullptr);
      if constexpr (COH == kSjkr) nl.Fel -= law.sjkrDensity * hertz::SjkrWallArea(r, delta);
      const PetscReal        Sn = nl.Sn, Fn = hertz::Contact(mat, nl, n, std::sqrt(a.mass[p]), vrel, dt, xi, F, Ft);
      wall::CrossProduct(rn, Ft, tq);
      // Rolling against the wall: I_r = 1.4 m R^2 about the contact, secant stiffness (2/3) S_n (P5).
      hertz::RollingTorque<RM>(rolling, Fn, nl.frictionOffset, 2.0 / 3.0 * Sn, r, 1.4 * a.mass[p] * r * r, n, wrel, dt, xi + 3, M);
      for (int e = 0; e < 3; ++e) a.f[3 * p + e] += F[e], a.torque[3 * p + e] += tq[e] + M[e], F[e] = -F[e];
      // The wall gets -F at the contact point and -M: its torque about its rotation point.
      wall::CrossProduct(arm, F, Tw);
      for (int e = 0; e < 3; ++e) load[e] += F[e], load[3 + e] += Tw[e] - M[e];
      ++loadContacts_[wi];
      ++*contacts;
      if (LIN) *elastic += 0.5 * law.linearKn * delta * delta;
      else if (!JKR) *elastic += hertz::ElasticEnergy(Sn, delta);
      *maxOverlap = std::max(*maxOverlap, delta / (2 * r));
    }
  }
}

}  // namespace vofdem
