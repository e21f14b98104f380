// Contacts of the particle module: the rebuild sequence (springs by id -> migrate -> ghosts ->
// exchange springs -> new list -> springs back onto pairs) and the force evaluation.
#include "vofdem/dem/Dem.hpp"
#include "vofdem/dem/ContactLaw.hpp"
#include "vofdem/dem/ContactLawTable.hpp"
#include "vofdem/dem/HistoryExchange.hpp"
#include "vofdem/dem/WallContacts.hpp"

#include <algorithm>
#include <type_traits>

namespace vofdem {

namespace {

// The normal law of the scene's contact model at overlap delta (P3, P4, P6); a JKR contact keeps
// its contact radius and bond flag in the history.
inline void Cross(const PetscReal a[3], const PetscReal b[3], PetscReal c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

}  // namespace

PetscErrorCode Dem::RemoveParticles(const std::vector<PetscInt> &local) {
  ParticleArrays a;
  PetscReal      mine[2] = {0, 0}, all[2];

  PetscFunctionBeginUser;
  PetscCall(swarm_.GetArrays(&a));
  for (PetscInt p : local) removeIds_.push_back(a.id[p]), mine[0] += 1, mine[1] += a.mass[p];
  PetscCall(swarm_.RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(mine, all, 2, MPIU_REAL, MPIU_SUM, comm_));
  if (all[0] == 0) PetscFunctionReturn(0);
  sources_.CountRemoved((PetscInt64)all[0], all[1]);
  PetscCall(PetscLogEventBegin(evRebuild_, 0, 0, 0, 0));
  PetscCall(Rebuild());
  PetscCall(PetscLogEventEnd(evRebuild_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::Rebuild() {
  ParticleArrays          a;
  std::vector<PetscInt64> localIds;

  PetscFunctionBeginUser;
  // 1. Springs of touching pairs, by the pair's global ids (local indices change below). springs_
  // is empty here, except after Load() on another rank count, which puts the saved springs in.
  PetscCall(swarm_.GetArrays(&a));
  // Either index of a pair may be a ghost (pairs are stored lower id first).
  auto idOf = [&](PetscInt j) { return j < a.n ? a.id[j] : halo_.id[j - a.n]; };
  for (size_t k = 0; k < list_.Size(); ++k) {
    const PetscReal *s = &list_.spring[kSpringWidth * k];
    if (!list_.touching[k] || std::all_of(s, s + kSpringWidth, [](PetscReal v) { return v == 0; })) continue;
    auto &h = springs_[{idOf(list_.first[k]), idOf(list_.second[k])}];  // lower id first
    std::copy(s, s + kSpringWidth, h.begin());
  }
  bonds_.Collect(list_, idOf);  // intact bonds (P13), touching or not
  for (size_t k = 0; k < walls_.Size(); ++k) {
    if (!walls_.touching[k]) continue;
    const PetscReal *s = &walls_.spring[kSpringWidth * k];
    auto            &h = springs_[PairKey::Wall(a.id[walls_.particle[k]], walls_.wall[k])];
    std::copy(s, s + kSpringWidth, h.begin());
  }
  if (balance_) BalanceContactLoads(a);  // -dem_balance: each particle's contacts weigh in (DemBalance.cpp)
  // Periodic directions: positions back into the box before migration (PeriodicImages.hpp).
  if (halo_.Images().Any()) halo_.Images().Wrap(a.n, a.x);
  wallSet_.SaveSprings(a, &springs_);
  PetscCall(swarm_.RestoreArrays(&a));
  // 1b. Deletion boxes and insertion sources (their springs go with deleted particles).
  if (sources_.Active()) {
    PetscCall(sources_.Apply(time_, swarm_, &springs_, rMax_));
    // A clump inserted across a periodic face has members past it: into the box too, or the
    // migration below would drop them.
    if (halo_.Images().Any()) {
      PetscCall(swarm_.GetArrays(&a));
      halo_.Images().Wrap(a.n, a.x);
      PetscCall(swarm_.RestoreArrays(&a));
    }
  }
  // 1c. Particles a coupling took (RemoveParticles, which counted them), with their springs.
  if (!removeIds_.empty()) {
    std::sort(removeIds_.begin(), removeIds_.end());
    auto gone = [&](PetscInt64 id) { return std::binary_search(removeIds_.begin(), removeIds_.end(), id); };
    PetscCall(swarm_.GetArrays(&a));
    std::vector<PetscInt> remove;
    for (PetscInt p = a.n - 1; p >= 0; --p)
      if (gone(a.id[p])) remove.push_back(p);
    PetscCall(swarm_.RestoreArrays(&a));
    for (PetscInt p : remove) PetscCall(DMSwarmRemovePointAtIndex(swarm_.Dm(), p));
    PetscCall(swarm_.FieldsMoved());
    for (auto it = springs_.begin(); it != springs_.end();) it = gone(it->first.lo) || (!it->first.IsWall() && gone(it->first.hi)) ? springs_.erase(it) : std::next(it);
    removeIds_.clear();
  }
  PetscBool repartitioned;
  PetscCall(Balance(&repartitioned));  // -dem_balance: new ownership ranges when the counts are uneven
  // 2. Particles to their owners; 3. ghosts within the cut-off.
  PetscCall(swarm_.Migrate());
  PetscCall(sort_.Apply(rebuilds_, swarm_.Dm(), *grid_));  // -dem_sort_every: before any local index is taken (MortonOrder.hpp)
  PetscCall(swarm_.FieldsMoved());                          // the sort's spare point may have resized the swarm
  // A JKR bond may hold adhesionRange_ beyond touching: the cut-offs include it.
  const PetscReal cutoff = 2 * rMax_ + skin_ + adhesionRange_;
  if (halo_.Images().Any()) PetscCall(halo_.Images().Check(comm_, cutoff, "2 R_max + skin + adhesion range"));
  PetscCall(swarm_.GetArrays(&a));
  PetscCall(halo_.Build(a, a.omega, cutoff));
  localIds.assign(a.id, a.id + a.n);
  PetscCall(swarm_.RestoreArrays(&a));
  // 4. Springs to the ranks that now hold one of the pair.
  PetscCall(ExchangeSprings(localIds));
  if (repartitioned) PetscCall(GatherSprings());  // a particle may have moved beyond the halo's ranks
  // 5. The new list, its springs from the carried ones.
  PetscReal lo[3], hi[3];
  grid_->LocalBox(lo, hi);
  PetscCall(swarm_.GetArrays(&a));
  PetscCall(list_.Build(a.n, a.x, a.radius, a.mass, a.id, halo_.Count(), halo_.x.data(), halo_.radius.data(), halo_.mass.data(), halo_.id.data(),
                        cutoff, skin_ + adhesionRange_, lo, hi, PairTags{a.type, halo_.type.data(), a.clump, halo_.clump.data(), table_.Count()}));
  PeriodicImages::PairImages(list_, a.n, halo_.image.data(), &pairImage_);
  JkrPairConstants();
  for (size_t k = 0; k < list_.Size() && !springs_.empty(); ++k) {
    const auto it = springs_.find({idOf(list_.first[k]), idOf(list_.second[k])});  // lower id first
    if (it != springs_.end()) {
      std::copy(it->second.begin(), it->second.end(), &list_.spring[kSpringWidth * k]);
      list_.touching[k] = 1;
    }
  }
  bonds_.Attach(list_, idOf);
  // 6. Wall candidates: particles that can reach a face before the next rebuild (they move at most
  // half the skin); their springs from the carried ones.
  walls_.Clear();
  const PetscReal *glo = grid_->Lower(), *ghi = grid_->Upper();
  for (PetscInt p = 0; p < a.n; ++p)
    for (int face = 0; face < 6; ++face) {
      const int       d    = face / 2;
      if (halo_.Images().Periodic(d)) continue;  // no walls across a periodic direction
      const PetscReal dist = face % 2 ? ghi[d] - a.x[3 * p + d] : a.x[3 * p + d] - glo[d];
      if (dist >= a.radius[p] + skin_ + adhesionRange_) continue;
      walls_.Add(p, face);
      const auto it = springs_.empty() ? springs_.end() : springs_.find(PairKey::Wall(a.id[p], face));
      if (it != springs_.end()) {
        std::copy(it->second.begin(), it->second.end(), &walls_.spring[kSpringWidth * (walls_.Size() - 1)]);
        walls_.touching.back() = 1;
      }
    }
  wallSet_.BuildCandidates(a, skin_ + adhesionRange_, springs_);  // -dem_walls, same reach
  PetscCall(sources_.FindDeletionCandidates(a, 0.5 * skin_));     // Step(): no particle moves farther before a rebuild
  PetscCall(swarm_.RestoreArrays(&a));
  springs_.clear();
  ++rebuilds_;
  clumps_.Invalidate();  // local indices changed (migration, sorting, insertion, deletion)
  PetscFunctionReturn(0);
}

// The springs, then the intact bonds, to the ranks that need them (HistoryExchange.hpp); receivers keep what they
// lack, and histories of contacts that are not in the new lists are dropped at steps 5 and 6 of Rebuild().
PetscErrorCode Dem::ExchangeSprings(const std::vector<PetscInt64> &localIds) {
  PetscFunctionBeginUser;
  PetscCall(ExchangeHistory<kSpringWidth>(halo_, localIds, 73, &springs_));
  if (bonds_.On()) PetscCall(ExchangeHistory<bond::kWidth>(halo_, localIds, 75, &bonds_.carried));
  PetscFunctionReturn(0);
}

// The JKR constants of the list's pairs (HertzMindlin.hpp JkrPair), whenever the list is made or loaded.
void Dem::JkrPairConstants() {
  jkrPairs_.resize(jkr_ ? list_.Size() : 0);
  for (size_t k = 0; k < jkrPairs_.size(); ++k) jkrPairs_[k] = hertz::JkrConstants(table_.Count() > 1 ? table_.Pair(list_.material[k]) : pair_, list_.rstar[k]);
}

PetscErrorCode Dem::ComputeForces(PetscReal dt) {
  PetscFunctionBeginUser;
  // The scene's laws (ContactLawTable.hpp: one row each) are bound here, once, as template arguments of the
  // loops; so are whether a near-field force acts (van der Waals or lubrication) and whether the pair
  // constants vary by type (several types: each pair's from the table; one type keeps them fixed).
  const bool near = vdw_.hamaker > 0 || lubrication_.viscosity > 0, multi = table_.Count() > 1;
  PetscCall(contact::AtRow<std::size(contact::kRollingLaws)>(rollingRow_, [&](auto rolling) {
    constexpr hertz::Rolling RM = contact::kRollingLaws[decltype(rolling)::value].model;
    return contact::AtRow<std::size(contact::kCohesionLaws)>(cohesionRow_, [&](auto cohesion) {
      constexpr auto cohesionRow = contact::kCohesionLaws[decltype(cohesion)::value];
      return contact::AtRow<std::size(contact::kNormalLaws)>(normalRow_, [&](auto normal) -> PetscErrorCode {
        constexpr int  COH = cohesionRow.model;
        constexpr bool LIN = contact::kNormalLaws[decltype(normal)::value].linear;
        if constexpr (LIN && cohesionRow.hertzOnly) {
          return PETSC_ERR_PLIB;  // refused in SetFromOptions
        } else {
          if (near) return multi ? ComputeForcesWith<RM, COH, true, LIN, true>(dt) : ComputeForcesWith<RM, COH, true, LIN, false>(dt);
          return multi ? ComputeForcesWith<RM, COH, false, LIN, true>(dt) : ComputeForcesWith<RM, COH, false, LIN, false>(dt);
        }
      });
    });
  }));
  if (bonds_.Due(time_)) MakeBonds();  // -dem_bond_at_time (P13): they act from the next evaluation on
  PetscFunctionReturn(0);
}

// Forces and torques on the local particles: gravity, the box faces, and the pairs of the list
// (P3, P5). A pair is always evaluated from its lower id ("a") to its higher id ("b"), so a pair
// that two ranks both evaluate (one particle a ghost) gives bit-identical results and springs there.
// MULTI: several particle types, whose pair constants come from the MaterialTable; a single type
// keeps them in registers for the whole loop.
template <hertz::Rolling RM, int COH, bool NEAR, bool LIN, bool MULTI>
PetscErrorCode Dem::ComputeForcesWith(PetscReal dt) {
  constexpr bool JKR = COH == kJkr, SJKR = COH == kSjkr, BOND = COH == kBond;
  ParticleArrays a;

  PetscFunctionBeginUser;
  PetscCheck(!JKR || jkrPairs_.size() == list_.Size(), PETSC_COMM_SELF, PETSC_ERR_PLIB, "JKR constants for %zu pairs, the list has %zu", jkrPairs_.size(), list_.Size());
  stats_ = LocalStats{};
  PetscCall(swarm_.GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p)
    for (int d = 0; d < 3; ++d) a.f[3 * p + d] = a.mass[p] * gravity_[d], a.torque[3 * p + d] = 0;
  // Box faces: spheres of infinite radius and mass (P3), R* = R, m* = m; only the candidates.
  const PetscReal *lo = grid_->Lower(), *hi = grid_->Upper();
  if (record_.on) record_.Reset(list_.Size(), walls_.Size());
  for (size_t k = 0; k < walls_.Size(); ++k) {
    const PetscInt  p = walls_.particle[k];
    const int       face = walls_.wall[k], d = face / 2;
    const PetscReal r = a.radius[p], *x = &a.x[3 * p], *v = &a.v[3 * p], *w = &a.omega[3 * p];
    const PetscReal delta = r - (face % 2 ? hi[d] - x[d] : x[d] - lo[d]);
    PetscReal      *xi    = &walls_.spring[kSpringWidth * k];
    // In contact from touching on; a JKR bond holds until its break overlap (P6).
    const hertz::PairMaterial &wm = MULTI ? table_.Wall(a.type[p]) : wall_;
    const bool inContact = delta > 0 || (JKR && xi[kJkrBonded] != 0 && delta > hertz::JkrBreakOverlap(wm, r));
    if constexpr (NEAR) {  // across the gap -delta: van der Waals attraction (P7) and lubrication (P8), R* = R
      const PetscReal sgn = face % 2 ? -1 : 1;  // the inward normal is sgn e_d
      const PetscReal mu = fluidLubrication_ ? (lubricationUniform_ > 0 ? lubricationUniform_ : a.fluidViscosity[p]) : 1;  // -coupling_lubrication
      const PetscReal fv = hertz::VdwAttraction(vdwWalls_ ? vdw_ : noVdw_, -delta, r) + mu * hertz::LubricationCoefficient(lubrication_, -delta, r) * sgn * v[d];
      a.f[3 * p + d] -= sgn * fv;
      stats_.wallForce[face][d] += sgn * fv;
    }
    if (!inContact) {
      if (walls_.touching[k]) std::fill(xi, xi + kSpringWidth, 0), walls_.touching[k] = 0;
      continue;
    }
    walls_.touching[k] = 1;
    PetscReal n[3] = {0, 0, 0}, rn[3], wxr[3], vrel[3], F[3], Ft[3], tq[3], M[3];
    n[d] = face % 2 ? -1 : 1;  // inward normal: +e_d on the lower face, -e_d on the upper
    for (int e = 0; e < 3; ++e) rn[e] = -r * n[e];  // centre to contact point
    Cross(w, rn, wxr);
    for (int e = 0; e < 3; ++e) vrel[e] = v[e] + wxr[e];
    hertz::NormalLaw law = NormalLawAt<COH, LIN>(wm, linearKn_, delta, r, xi);
    if constexpr (SJKR) law.Fel -= sjkrDensity_ * hertz::SjkrWallArea(r, delta);
    const PetscReal        Sn = law.Sn, Fn = hertz::Contact(wm, law, n, std::sqrt(a.mass[p]), vrel, dt, xi, F, Ft);
    Cross(rn, Ft, tq);
    // Rolling against the face: w_rel = w, I_r = I + m R^2 = 1.4 m R^2 about the contact; the
    // secant normal stiffness F_n,elastic / delta is (2/3) S_n.
    hertz::RollingTorque<RM>(MULTI ? table_.WallRolling(a.type[p]) : rollingParams_, Fn, law.frictionOffset, 2.0 / 3.0 * Sn, r, 1.4 * a.mass[p] * r * r, n, w, dt, xi + 3, M);
    for (int e = 0; e < 3; ++e) a.f[3 * p + e] += F[e], a.torque[3 * p + e] += tq[e] + M[e], stats_.wallForce[face][e] -= F[e];
    if (record_.on) ContactRecord::Store(&record_.wall[ContactRecord::kWidth * k], F, Ft);
    ++stats_.wallContacts;
    if (LIN) stats_.elastic += 0.5 * linearKn_ * delta * delta;
    else if (!JKR) stats_.elastic += hertz::ElasticEnergy(Sn, delta);
    stats_.maxOverlap = std::max(stats_.maxOverlap, delta / (2 * r));
  }
  wallSet_.Evaluate<RM, COH, NEAR, LIN, MULTI>(a, {&wall_, linearKn_, &rollingParams_, vdwWalls_ ? &vdw_ : &noVdw_, &table_, sjkrDensity_, &lubrication_, adhesionRange_, fluidLubrication_, lubricationUniform_}, dt,
                                               &stats_.wallContacts, &stats_.elastic, &stats_.maxOverlap);
  const PetscInt n = a.n, ng = halo_.Count();
  hot_.resize(n + ng);
  for (PetscInt p = 0; p < n; ++p) {
    HotParticle &h = hot_[p];
    for (int e = 0; e < 3; ++e) h.x[e] = a.x[3 * p + e], h.v[e] = a.v[3 * p + e], h.w[e] = a.omega[3 * p + e];
    h.r = a.radius[p], h.m = a.mass[p];
    h.mu = !fluidLubrication_ ? 1 : lubricationUniform_ > 0 ? lubricationUniform_ : a.fluidViscosity[p];
  }
  for (PetscInt g = 0; g < ng; ++g) {
    HotParticle &h = hot_[n + g];
    // The owner's position: periodic pairs add their image shift to the difference (PeriodicImages.hpp).
    for (int e = 0; e < 3; ++e) h.x[e] = halo_.xOwner[3 * g + e], h.v[e] = halo_.v[3 * g + e], h.w[e] = halo_.omega[3 * g + e];
    h.r = halo_.radius[g], h.m = halo_.mass[g];
    h.mu = !fluidLubrication_ ? 1 : lubricationUniform_ > 0 ? lubricationUniform_ : halo_.viscosity[g];
  }
  PetscReal *__restrict__ force = a.f, *__restrict__ torque = a.torque;
  const PeriodicImages &images = halo_.Images();
  // Bonds (P13): the law and reach in registers, the histories beside the list's springs.
  const bond::Params bondLaw = bonds_.Law();
  const PetscReal    bondReach = bonds_.Reach();
  PetscReal         *bondState = BOND ? bonds_.state.data() : nullptr, bondsBroken = 0;
  PetscCheck(!BOND || bonds_.state.size() == bond::kWidth * list_.Size(), PETSC_COMM_SELF, PETSC_ERR_PLIB, "bond histories for %zu pairs, the list has %zu", bonds_.state.size() / bond::kWidth, list_.Size());
  // Prefetches a few pairs ahead: the springs' line (loaded for touching pairs only, so the hardware
  // does not see a stream) and the second particle's x and r (two lines of HotParticle).
  constexpr size_t kSpringsAhead = 8, kParticleAhead = 16;
  const size_t     pairs         = list_.Size();
  for (size_t k = 0; k < pairs; ++k) {
    if (k + kParticleAhead < pairs) {
      const HotParticle &f = hot_[list_.second[k + kParticleAhead]];
      __builtin_prefetch(f.x), __builtin_prefetch(&f.r);
    }
    if (k + kSpringsAhead < pairs) __builtin_prefetch(&list_.spring[kSpringWidth * (k + kSpringsAhead)]);
    const PetscInt ia = list_.first[k], ib = list_.second[k];  // lower id first
    const PetscReal *xa = hot_[ia].x, *xb = hot_[ib].x, *sh = images.Shift(pairImage_[k]);
    const PetscReal  dx[3] = {(xa[0] - xb[0]) + sh[0], (xa[1] - xb[1]) + sh[1], (xa[2] - xb[2]) + sh[2]};
    const PetscReal  dist2 = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2], rsum = hot_[ia].r + hot_[ib].r;
    PetscReal       *stored = &list_.spring[kSpringWidth * k];
    const hertz::PairMaterial &pm = MULTI ? table_.Pair(list_.material[k]) : pair_;
    // In contact from touching on; a JKR bond holds until its break overlap (P6). A bonded pair touched
    // at the last evaluation: the byte is read first, so the springs' line is loaded only for those.
    const bool inContact =
      dist2 < rsum * rsum ||
      (JKR && list_.touching[k] && stored[kJkrBonded] != 0 && rsum - std::sqrt(dist2) > jkrPairs_[k].breakOverlap);
    if constexpr (NEAR) {  // along the line of centres across the gap: van der Waals (P7) and lubrication (P8)
      const PetscReal rangeSum = rsum + adhesionRange_;
      if (dist2 < rangeSum * rangeSum) {
        const PetscReal dist = std::sqrt(dist2), gap = dist - rsum, *va = hot_[ia].v, *vb = hot_[ib].v;
        // f = -(c v_n) n on a, with v_n = (v_a - v_b) . dx / dist > 0 separating: divided by dist once more below.
        const PetscReal vnDist = (va[0] - vb[0]) * dx[0] + (va[1] - vb[1]) * dx[1] + (va[2] - vb[2]) * dx[2];
        // The lubrication's viscosity: the pair's mean of the fluid's with -coupling_lubrication, else 1 (lubrication_ holds it).
        const PetscReal mu = 0.5 * (hot_[ia].mu + hot_[ib].mu);
        const PetscReal fv = (hertz::VdwAttraction(vdw_, gap, list_.rstar[k]) + mu * hertz::LubricationCoefficient(lubrication_, gap, list_.rstar[k]) * vnDist / dist) / dist;
        if (ia < n)
          for (int e = 0; e < 3; ++e) force[3 * ia + e] -= fv * dx[e];
        if (ib < n)
          for (int e = 0; e < 3; ++e) force[3 * ib + e] += fv * dx[e];
      }
    }
    if constexpr (BOND) {  // beside the contact law, touching or not (P13)
      PetscReal *h = &bondState[bond::kWidth * k];
      if (h[bond::kState] != 0) {
        const HotParticle &A = hot_[ia], &B = hot_[ib];
        // Lever arms from the centres to the bond's plane, in the ratio of the radii: a pair turning as one
        // rigid body moves its two contact points alike (no spurious shear across a gap or an overlap).
        const PetscReal dist = std::sqrt(dist2), inv = 1 / dist, la = A.r * dist / rsum, lb = B.r * dist / rsum;
        const PetscReal nb[3] = {dx[0] * inv, dx[1] * inv, dx[2] * inv};
        PetscReal       rw[3], wxn[3], du[3], dth[3], Fb[3], nxFs[3];
        for (int e = 0; e < 3; ++e) rw[e] = la * A.w[e] + lb * B.w[e];
        Cross(rw, nb, wxn);
        for (int e = 0; e < 3; ++e) du[e] = (A.v[e] - B.v[e] - wxn[e]) * dt, dth[e] = (A.w[e] - B.w[e]) * dt;
        const PetscReal     spin = 0.5 * dt * ((A.w[0] + B.w[0]) * nb[0] + (A.w[1] + B.w[1]) * nb[1] + (A.w[2] + B.w[2]) * nb[2]);
        const bond::Section sec  = bond::SectionOf(bondLaw, A.r, B.r);
        bond::Load          load;
        if (dist - rsum > bondReach || bond::Update(bondLaw, sec, nb, du, dth, spin, h, &load)) {
          std::fill(h, h + bond::kWidth, 0);  // broken, for good
          bondsBroken += ia < n && ib < n ? 2 : 1;
        } else {
          const PetscReal *Fs = &h[bond::kFs], *Ms = &h[bond::kMs];
          for (int e = 0; e < 3; ++e) Fb[e] = h[bond::kFn] * nb[e] + Fs[e];
          Cross(nb, Fs, nxFs);
          if (ia < n)
            for (int e = 0; e < 3; ++e) force[3 * ia + e] += Fb[e], torque[3 * ia + e] += h[bond::kMn] * nb[e] + Ms[e] - la * nxFs[e];
          if (ib < n)
            for (int e = 0; e < 3; ++e) force[3 * ib + e] -= Fb[e], torque[3 * ib + e] -= h[bond::kMn] * nb[e] + Ms[e] + lb * nxFs[e];
          stats_.bondSigma = std::max(stats_.bondSigma, load.sigma / bondLaw.tensile);
          stats_.bondTau   = std::max(stats_.bondTau, load.tau / bondLaw.shear);
        }
      }
    }
    if (!inContact) {
      if (list_.touching[k]) std::fill(stored, stored + kSpringWidth, 0), list_.touching[k] = 0;
      continue;
    }
    list_.touching[k] = 1;
    // The springs are worked on in a local copy and stored once: through the pointer, every store
    // would make the compiler reload what it might alias.
    PetscReal xi[kSpringWidth];
    std::copy(stored, stored + kSpringWidth, xi);
    // Copies, not references: stores into the force arrays below cannot alias them.
    const HotParticle A = hot_[ia], B = hot_[ib];
    const PetscReal   dist = std::sqrt(dist2), inv = 1 / dist, delta = rsum - dist, Rstar = list_.rstar[k];
    PetscReal         nrm[3], rw[3], wxn[3], vrel[3], F[3], Ft[3], nxF[3], wrel[3], M[3];
    for (int e = 0; e < 3; ++e) nrm[e] = dx[e] * inv, rw[e] = A.r * A.w[e] + B.r * B.w[e], wrel[e] = A.w[e] - B.w[e];
    Cross(rw, nrm, wxn);
    for (int e = 0; e < 3; ++e) vrel[e] = A.v[e] - B.v[e] - wxn[e];  // surface of A against surface of B
    hertz::NormalLaw law = NormalLawAt<COH, LIN>(pm, linearKn_, delta, Rstar, xi, JKR ? &jkrPairs_[k] : nullptr);
    if constexpr (SJKR) law.Fel -= sjkrDensity_ * hertz::SjkrPairArea(A.r, B.r, dist);
    const PetscReal        Sn = law.Sn, Fn = hertz::Contact(pm, law, nrm, list_.sqrtMstar[k], vrel, dt, xi, F, Ft);
    Cross(nrm, Ft, nxF);
    if constexpr (RM != hertz::Rolling::None) {
      const PetscReal Ia = 1.4 * A.m * A.r * A.r, Ib = 1.4 * B.m * B.r * B.r;  // about the contact point
      // How far n turned over the step: the centres drifted by dt v (Step), so dn = dt (v_a - v_b)_t / dist
      // and the turn is n x dn (EPSD's spring turns with it; HertzMindlin.hpp RollingTorque).
      PetscReal turn[3];
      if constexpr (RM == hertz::Rolling::Epsd) {
        const PetscReal vc[3] = {(A.v[0] - B.v[0]) * dt * inv, (A.v[1] - B.v[1]) * dt * inv, (A.v[2] - B.v[2]) * dt * inv};
        Cross(nrm, vc, turn);
      }
      hertz::RollingTorque<RM>(MULTI ? table_.Rolling(list_.material[k]) : rollingParams_, Fn, law.frictionOffset, 2.0 / 3.0 * Sn, Rstar, Ia * Ib / (Ia + Ib), nrm, wrel, dt, xi + 3, M,
                               RM == hertz::Rolling::Epsd ? turn : nullptr);
    } else {
      M[0] = M[1] = M[2] = 0;
    }
    std::copy(xi, xi + kSpringWidth, stored);
    if (record_.on) ContactRecord::Store(&record_.pair[ContactRecord::kWidth * k], F, Ft);
    // Torques: -R n x F_t on both, +M on A and -M on B; forces +F on A, -F on B; only local
    // particles are written.
    if (ia < n)
      for (int e = 0; e < 3; ++e) force[3 * ia + e] += F[e], torque[3 * ia + e] += M[e] - A.r * nxF[e];
    if (ib < n)
      for (int e = 0; e < 3; ++e) force[3 * ib + e] -= F[e], torque[3 * ib + e] -= M[e] + B.r * nxF[e];
    // A pair with a ghost is counted by both ranks: count it half on each.
    const bool both = ia < n && ib < n;
    stats_.pairContacts += both ? 2 : 1;
    if (LIN) stats_.elastic += (both ? 1.0 : 0.5) * 0.5 * linearKn_ * delta * delta;
    else if (!JKR) stats_.elastic += (both ? 1.0 : 0.5) * hertz::ElasticEnergy(Sn, delta);
    const PetscReal twoRmin = 2 * std::min(A.r, B.r);
    if (delta > stats_.maxOverlap * twoRmin) stats_.maxOverlap = delta / twoRmin;  // rarely: no division per contact
  }
  bonds_.brokenHalves += bondsBroken;
  PetscCall(swarm_.RestoreArrays(&a));
  PetscFunctionReturn(0);
}

}  // namespace vofdem

namespace vofdem {

// The step the contacts allow as they are (HertzMindlin.hpp SpinContact, SpinStep): per local sphere the
// sums of its contacts' spin stiffness and damping, from the particle pairs that touched at the last force
// evaluation and the box faces (the -dem_walls contacts are left out: at most a few per sphere). Hertz
// contacts at their overlap now, JKR at their contact radius, linear ones at k_n. Members of clumps move
// with their clump's inertia and are left out. The smallest step over all ranks, times kContactStepSafety.
// Called after ComputeForces, whose hot_ holds the positions, radii and masses (ghosts included).
PetscErrorCode Dem::UpdateContactStepLimit() {
  ParticleArrays a;
  PetscReal      local = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  PetscCall(swarm_.GetArrays(&a));
  const PetscInt n = a.n;
  spinW2_.assign(n, 0), spinRate_.assign(n, 0);
  const bool       multi = table_.Count() > 1;
  const PetscReal *lo = grid_->Lower(), *hi = grid_->Upper();
  auto stiffness = [&](const hertz::PairMaterial &c, PetscReal delta, PetscReal Rstar, const PetscReal *xi) {
    if (linear_) return linearKn_;
    if (jkr_) return 2 * c.Estar * xi[kJkrRadius];
    return 2 * c.Estar * std::sqrt(Rstar * std::max(delta, (PetscReal)0));
  };
  for (size_t k = 0; k < walls_.Size(); ++k) {
    if (!walls_.touching[k]) continue;
    const PetscInt p = walls_.particle[k];
    if (a.clump[p] >= 0) continue;
    const int       face = walls_.wall[k], d = face / 2;
    const PetscReal r = a.radius[p], delta = r - (face % 2 ? hi[d] - a.x[3 * p + d] : a.x[3 * p + d] - lo[d]);
    const hertz::PairMaterial &c = multi ? table_.Wall(a.type[p]) : wall_;
    hertz::SpinContact(c, stiffness(c, delta, r, &walls_.spring[kSpringWidth * k]), a.mass[p], a.mass[p], 0, &spinW2_[p], &spinRate_[p]);
  }
  const PeriodicImages &images = halo_.Images();
  for (size_t k = 0; k < list_.Size(); ++k) {
    if (!list_.touching[k]) continue;
    const PetscInt   ia = list_.first[k], ib = list_.second[k];
    const PetscReal *xa = hot_[ia].x, *xb = hot_[ib].x, *sh = images.Shift(pairImage_[k]);
    const PetscReal  dx[3] = {(xa[0] - xb[0]) + sh[0], (xa[1] - xb[1]) + sh[1], (xa[2] - xb[2]) + sh[2]};
    const PetscReal  delta = hot_[ia].r + hot_[ib].r - std::sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
    const hertz::PairMaterial &c = multi ? table_.Pair(list_.material[k]) : pair_;
    const PetscReal Sn = stiffness(c, delta, list_.rstar[k], &list_.spring[kSpringWidth * k]), mstar = list_.sqrtMstar[k] * list_.sqrtMstar[k];
    if (ia < n && a.clump[ia] < 0) hertz::SpinContact(c, Sn, mstar, hot_[ia].m, hot_[ib].r / hot_[ia].r, &spinW2_[ia], &spinRate_[ia]);
    if (ib < n && a.clump[ib] < 0) hertz::SpinContact(c, Sn, mstar, hot_[ib].m, hot_[ia].r / hot_[ib].r, &spinW2_[ib], &spinRate_[ib]);
  }
  for (PetscInt p = 0; p < n; ++p)
    if (spinW2_[p] > 0) local = std::min(local, hertz::SpinStep(spinW2_[p], spinRate_[p]));
  PetscCall(swarm_.RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(&local, &contactStepLimit_, 1, MPIU_REAL, MPI_MIN, comm_));
  if (contactStepLimit_ < PETSC_MAX_REAL) contactStepLimit_ *= kContactStepSafety;
  if (!contactStepNoted_ && contactStepLimit_ < std::min(dtFactor_ * rayleighTime_, jkrStepLimit_)) {  // once a run: the banner named another basis
    contactStepNoted_ = true;
    PetscCall(PetscPrintf(comm_, "vofdem: dem: from t = %g s the contacts as they are allow steps of at most %g s, %.3g of the Rayleigh time, less than -dem_dt_factor gives (loaded, damped contacts; HertzMindlin.hpp SpinStep)\n",
                          (double)time_, (double)contactStepLimit_, (double)(contactStepLimit_ / rayleighTime_)));
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
