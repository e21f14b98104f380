#include "vofdem/dem/ParticleSources.hpp"

#include "vofdem/base/Random.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/dem/SphereHash.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <unordered_set>

namespace vofdem {

PetscErrorCode ParticleSources::SetFromOptions(OptionReader &opt, MPI_Comm comm, PetscReal radius, const std::vector<std::string> &types,
                                               const std::vector<PetscReal> &densities) {
  std::string names;
  PetscBool   help = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  comm_    = comm;
  PetscCall(opt.String("-inserts", "Names of insertion sources, comma-separated; each is set by -dem_insert_<name>_* options", &names));
  sources_.clear();
  PetscCall(library_.SetFromOptions(opt, comm));  // before the sources that name its templates
  std::vector<std::string> list = SplitList(names);
  // -help lists every source's options: for the sources named, without the checks that would stop the listing, or
  // once for a source called NAME.
  const bool dummy = help && list.empty();
  if (dummy) list = {"NAME"};
  for (const auto &n : list) {
    if (n.empty() || !std::all_of(n.begin(), n.end(), [](char c) { return std::isalnum((unsigned char)c); }))
      VofdemInputError(comm, "option -dem_inserts: '%s' is not a name (letters and digits only)", n.c_str());
    for (const auto &s : sources_)
      if (s.name == n) VofdemInputError(comm, "option -dem_inserts: the name '%s' is given twice", n.c_str());
    InsertionSource s;
    s.name              = n;
    const std::string p = "-insert_" + n + "_";
    auto              o = [&](const char *suffix) { return p + suffix; };
    PetscBool         lowerSet = PETSC_FALSE, upperSet = PETSC_FALSE;
    PetscCall(opt.RealVector(o("lower").c_str(), "Lower corner of the region the new centres are drawn in (a slot may be flat)", "m", s.lower, 3, RealRange::Any(), &lowerSet));
    PetscCall(opt.RealVector(o("upper").c_str(), "Upper corner of the region the new centres are drawn in", "m", s.upper, 3, RealRange::Any(), &upperSet));
    if (!help && (!lowerSet || !upperSet)) VofdemInputError(comm, "options -dem_insert_%s_lower and -dem_insert_%s_upper: both are needed", n.c_str(), n.c_str());
    PetscCall(opt.Real(o("rate").c_str(), "Insertion rate by number", "particles/s", &s.rate, RealRange::NonNegative()));
    PetscCall(opt.Real(o("mass_rate").c_str(), "Insertion rate by mass (instead of -dem_insert_<name>_rate)", "kg/s", &s.massRate, RealRange::NonNegative()));
    if (!help && (s.rate > 0) == (s.massRate > 0))
      VofdemInputError(comm, "options -dem_insert_%s_rate and -dem_insert_%s_mass_rate: give exactly one positive rate", n.c_str(), n.c_str());
    PetscCall(opt.RealVector(o("velocity").c_str(), "Initial velocity of the inserted particles", "m/s", s.velocity, 3));
    PetscCall(opt.RealVector(o("region_velocity").c_str(), "Velocity of the region from the start time on (a feed slot moving with a spreader); insertion ends before the region leaves the box",
                             "m/s", s.regionVelocity, 3));
    PetscCall(opt.Real(o("velocity_spread").c_str(), "Random part of the initial velocity: each component uniform in [-spread, spread]", "m/s", &s.spread,
                       RealRange::NonNegative()));
    PetscCall(opt.Real(o("start").c_str(), "Time insertion starts", "s", &s.start, RealRange::NonNegative()));
    PetscCall(opt.Real(o("end").c_str(), "Time insertion ends; what a full region held back by then is not inserted later (default: never)", "s", &s.end, RealRange::NonNegative()));
    PetscCall(opt.Real(o("every").c_str(), "Insert in batches: the source asks for a neighbour-list rebuild at most once per this interval, and what "
                       "falls due in between goes in at the next rebuild (0: each particle as soon as it is due, one rebuild each)", "s", &s.every, RealRange::NonNegative()));
    if (!help && !(s.end > s.start)) VofdemInputError(comm, "option -dem_insert_%s_end: %g s is not after the start %g s", n.c_str(), (double)s.end, (double)s.start);
    PetscCall(opt.Int(o("attempts").c_str(), "Candidate centres per particle before a round gives up (the slot is full; retried one particle period later)",
                      &s.attempts, 1));
    PetscCall(s.sizes.SetFromOptions(opt, comm, "insert_" + n + "_", radius));
    PetscCall(ClumpsFromOptions(opt, s));  // ClumpInsertion.cpp
    std::string type = types[0];
    PetscCall(opt.String(o("type").c_str(), "Particle type of the inserted particles (default: the first of -dem_types)", &type));
    const auto it = std::find(types.begin(), types.end(), type);
    if (it == types.end()) VofdemInputError(comm, "option -dem_insert_%s_type: no type '%s' in -dem_types", n.c_str(), type.c_str());
    s.type    = (PetscInt)(it - types.begin());
    s.density = densities[s.type];
    if (!dummy) sources_.push_back(s);
  }
  PetscBool boxesSet = PETSC_FALSE;
  boxes_.clear();
  PetscCall(opt.RealList("-delete_boxes", "Deletion boxes, 6 numbers each (xlo,ylo,zlo,xhi,yhi,zhi): a particle whose centre enters one is removed", "m", &boxes_,
                         6 * 32, RealRange::Any(), &boxesSet));
  if (boxes_.size() % 6)
    VofdemInputError(comm, "option -dem_delete_boxes: %d numbers are not whole boxes of 6 (xlo,ylo,zlo,xhi,yhi,zhi)", (int)boxes_.size());
  for (size_t b = 0; b < boxes_.size(); b += 6)
    for (int d = 0; d < 3; ++d)
      if (!(boxes_[b + 3 + d] > boxes_[b + d]))
        VofdemInputError(comm, "option -dem_delete_boxes: box %d is empty in %c (upper %g <= lower %g)", (int)(b / 6 + 1), "xyz"[d], (double)boxes_[b + 3 + d],
                         (double)boxes_[b + d]);
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSources::SetUp(const Grid &grid, const ParticleSwarm &swarm, std::uint64_t seed) {
  ParticleArrays a;

  PetscFunctionBeginUser;
  grid_ = &grid;
  for (size_t k = 0; k < sources_.size(); ++k) {
    InsertionSource &s = sources_[k];
    // A stream of keys of its own per source: the sources draw independent numbers.
    s.seed             = random::Mix(seed ^ random::Mix(0x5eed0000ULL + k));
    const PetscReal r  = Reach(s);
    for (int d = 0; d < 3; ++d) {
      // Along a periodic direction the region may reach the faces (a feed slot across the whole width):
      // new particles are kept apart from the old ones across the faces (SphereHash::SetPeriodic).
      if (grid.Periodic(d) && !(s.upper[d] >= s.lower[d] && s.lower[d] >= grid.Lower()[d] && s.upper[d] <= grid.Upper()[d]))
        VofdemInputError(comm_, "options -dem_insert_%s_lower/-dem_insert_%s_upper: the region [%g, %g] in %c must be ordered and inside the periodic box [%g, %g]",
                         s.name.c_str(), s.name.c_str(), (double)s.lower[d], (double)s.upper[d], "xyz"[d], (double)grid.Lower()[d], (double)grid.Upper()[d]);
      if (!grid.Periodic(d) && (!(s.upper[d] >= s.lower[d]) || s.lower[d] - r < grid.Lower()[d] || s.upper[d] + r > grid.Upper()[d]))
        VofdemInputError(comm_, "options -dem_insert_%s_lower/-dem_insert_%s_upper: the region [%g, %g] in %c must be ordered and at least the largest radius %g m inside the box [%g, %g]",
                         s.name.c_str(), s.name.c_str(), (double)s.lower[d], (double)s.upper[d], "xyz"[d], (double)r, (double)grid.Lower()[d], (double)grid.Upper()[d]);
    }
    // A moving region stops inserting before it would leave the box.
    for (int d = 0; d < 3; ++d) {
      const PetscReal v = s.regionVelocity[d];
      if (v > 0) s.end = std::min(s.end, s.start + (grid.Upper()[d] - r - s.upper[d]) / v);
      if (v < 0) s.end = std::min(s.end, s.start + (grid.Lower()[d] + r - s.lower[d]) / v);
    }
  }
  PetscInt64 tops[2] = {-1, -1}, globalTops[2];  // largest particle id, largest clump id
  PetscCall(swarm.GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p) tops[0] = std::max(tops[0], (PetscInt64)a.id[p]), tops[1] = std::max(tops[1], (PetscInt64)a.clump[p]);
  PetscCall(swarm.RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(tops, globalTops, 2, MPIU_INT64, MPI_MAX, comm_));
  nextId_ = globalTops[0] + 1;
  // Inserted clumps take ids above those of the initial particles' clumps; with the id of their first
  // member added they are unique, and the same after a restart (the initial particles are the same).
  clumpBase_ = globalTops[1] + 1;
  PetscFunctionReturn(0);
}

void ParticleSources::RadiusRange(PetscReal *rmin, PetscReal *rmax) const {
  for (const auto &s : sources_) {
    PetscReal lo, hi;
    MemberRadii(s, &lo, &hi);
    *rmin = std::min(*rmin, lo), *rmax = std::max(*rmax, hi);
  }
}

// Particle `count` of a source is due once the clock has passed its turn: by number, when
// floor(rate (t - start)) exceeds the count; by mass, when the mass inserted with it would not
// exceed mass_rate (t - start). Insertion stops at the end time (Apply closes the source).
bool ParticleSources::Due(const InsertionSource &s, PetscReal t) const {
  if (t < s.start || t < s.retryAt) return false;
  const PetscReal span = std::min(t, s.end) - s.start;
  if (s.rate > 0) return (PetscReal)s.count < std::floor(s.rate * span);
  const PetscReal r = s.sizes.Radius(random::Uniform(s.seed, (std::uint64_t)s.count, 6));
  return s.mass + MassOf(s, r) <= s.massRate * span;
}

bool ParticleSources::InDeletionBox(const PetscReal x[3], PetscReal margin) const {
  for (size_t b = 0; b < boxes_.size(); b += 6)
    if (x[0] >= boxes_[b] - margin && x[0] <= boxes_[b + 3] + margin && x[1] >= boxes_[b + 1] - margin && x[1] <= boxes_[b + 4] + margin &&
        x[2] >= boxes_[b + 2] - margin && x[2] <= boxes_[b + 5] + margin)
      return true;
  return false;
}

PetscErrorCode ParticleSources::NeedsChange(PetscReal t, const ParticleSwarm &swarm, PetscBool *change) const {
  PetscFunctionBeginUser;
  *change = PETSC_FALSE;
  // A batched source asks for a rebuild only for what fell due by the last batch time; rebuilds the
  // particles' motion makes in between insert what is due then (Apply). Stateless, so restarts agree.
  for (const auto &s : sources_) {
    const PetscReal tb = s.every > 0 && t > s.start ? s.start + s.every * std::floor((t - s.start) / s.every) : t;
    if (Due(s, tb)) *change = PETSC_TRUE;  // the same on every rank: no communication
  }
  if (*change || boxes_.empty()) PetscFunctionReturn(0);
  if (candidatesKnown_ && !candidatesAnywhere_) PetscFunctionReturn(0);  // no rank has a particle that can reach a box
  ParticleArrays a;
  int            local = 0, any;
  PetscCall(swarm.GetArrays(&a));
  if (candidatesKnown_)
    for (size_t k = 0; k < deletionCandidates_.size() && !local; ++k) local = InDeletionBox(&a.x[3 * deletionCandidates_[k]]);
  else
    for (PetscInt p = 0; p < a.n && !local; ++p) local = InDeletionBox(&a.x[3 * p]);
  PetscCall(swarm.RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(&local, &any, 1, MPI_INT, MPI_LOR, comm_));
  *change = (PetscBool)any;
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSources::FindDeletionCandidates(const ParticleArrays &a, PetscReal reach) {
  int local, any;

  PetscFunctionBeginUser;
  deletionCandidates_.clear();
  candidatesKnown_ = false;
  if (boxes_.empty()) PetscFunctionReturn(0);
  // Each box grown by the reach along every axis holds the reach's ball around it (a margin for round-off).
  // Around the reference positions, from which the rebuild rule measures the motion (after a rebuild they
  // are the positions; a checkpoint loaded on the same ranks restores them from between two rebuilds).
  const PetscReal m = reach * (1 + 1e-9) + 1e-15;
  for (PetscInt p = 0; p < a.n; ++p)
    if (InDeletionBox(&a.reference[3 * p], m)) deletionCandidates_.push_back(p);
  local = !deletionCandidates_.empty();
  PetscCallMPI(MPI_Allreduce(&local, &any, 1, MPI_INT, MPI_LOR, comm_));
  candidatesAnywhere_ = any;
  candidatesKnown_    = true;
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSources::Apply(PetscReal t, ParticleSwarm &swarm, ContactHistory *springs, PetscReal rMax) {
  PetscFunctionBeginUser;
  if (!boxes_.empty()) PetscCall(Delete(swarm, springs));
  for (auto &s : sources_) {
    if (Due(s, t)) PetscCall(Insert(t, s, swarm, rMax));
    // The first rebuild after the end time inserts what was due by then and closes the source
    // (retryAt, saved with the counters): what a full region held back is not inserted later,
    // and the shortfall is said once.
    if (t > s.end && s.retryAt < PETSC_MAX_REAL) {
      s.retryAt = PETSC_MAX_REAL;
      if (s.blocked && s.rate > 0 && (PetscReal)s.count < std::floor(s.rate * (s.end - s.start)))
        PetscCall(PetscPrintf(comm_, "dem: insertion '%s' ended at t = %g s with %" PetscInt64_FMT " of %.0f particles: its region was full %" PetscInt64_FMT " times (a larger region or a lower rate)\n",
                              s.name.c_str(), (double)s.end, s.count, (double)std::floor(s.rate * (s.end - s.start)), s.blocked));
      if (s.blocked && s.rate == 0 && s.mass < s.massRate * (s.end - s.start) - MassOf(s, s.sizes.Mean()))
        PetscCall(PetscPrintf(comm_, "dem: insertion '%s' ended at t = %g s with %g of %g kg: its region was full %" PetscInt64_FMT " times (a larger region or a lower rate)\n", s.name.c_str(),
                              (double)s.end, (double)s.mass, (double)(s.massRate * (s.end - s.start)), s.blocked));
    }
  }
  PetscFunctionReturn(0);
}

// Removes from the end so that the particle DMSwarm swaps into a freed slot was already looked at.
PetscErrorCode ParticleSources::Delete(ParticleSwarm &swarm, ContactHistory *springs) {
  ParticleArrays                 a;
  std::unordered_set<PetscInt64> gone;
  PetscReal                      local[2] = {0, 0}, global[2];  // count, mass

  PetscFunctionBeginUser;
  PetscCall(swarm.GetArrays(&a));
  // A rigid clump (P10) goes whole once any member's centre is in a box (its members are all on this
  // rank); its members' mass shares add up to its mass.
  std::unordered_set<PetscInt64> clumps;
  for (PetscInt p = 0; p < a.n; ++p)
    if (a.clump[p] >= 0 && InDeletionBox(&a.x[3 * p])) clumps.insert(a.clump[p]);
  std::vector<PetscInt> remove;
  for (PetscInt p = a.n - 1; p >= 0; --p)
    if (InDeletionBox(&a.x[3 * p]) || (a.clump[p] >= 0 && clumps.count(a.clump[p])))
      remove.push_back(p), gone.insert(a.id[p]), local[0] += 1, local[1] += a.mass[p];
  PetscCall(swarm.RestoreArrays(&a));
  for (PetscInt p : remove) PetscCall(DMSwarmRemovePointAtIndex(swarm.Dm(), p));
  PetscCall(swarm.FieldsMoved());  // a removal may shrink the fields' storage
  // Their contact histories go too (pairs with a ghost partner would be dropped at the next list
  // anyway, as they are in no list).
  if (!gone.empty() && springs)
    for (auto it = springs->begin(); it != springs->end();) {
      if (gone.count(it->first.lo) || (!it->first.IsWall() && gone.count(it->first.hi))) it = springs->erase(it);
      else ++it;
    }
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPIU_REAL, MPIU_SUM, comm_));
  deleted_ += (PetscInt64)global[0];
  massDeleted_ += global[1];
  PetscFunctionReturn(0);
}

void ParticleSources::AppendRow(const PetscReal x[3], const PetscReal v[3], PetscReal r, PetscReal mass, PetscInt64 clump, const PetscReal lead[3],
                                const PetscReal *rigidState) {
  newParticles_.insert(newParticles_.end(), {x[0], x[1], x[2], v[0], v[1], v[2], r, (PetscReal)nextId_, mass, (PetscReal)clump, lead[0], lead[1], lead[2]});  // ids exact below 2^53
  if (rigidState) newParticles_.insert(newParticles_.end(), rigidState, rigidState + kRigidWidth);
  else newParticles_.insert(newParticles_.end(), kRigidWidth, 0.0);
  ++nextId_, ++inserted_;
}

bool ParticleSources::TrySphere(InsertionSource &s, std::uint64_t key, PetscReal r, SphereHash &hash) {
  PetscReal x[3], v[3];
  bool      placed = false;
  for (PetscInt k = 0; k < s.attempts && !placed; ++k, ++s.tries) {
    for (int d = 0; d < 3; ++d) x[d] = s.now[d] + (s.now[3 + d] - s.now[d]) * random::Uniform(s.seed, key, 16 + 3 * (std::uint64_t)s.tries + d);
    placed = !hash.Overlaps(x, r);
  }
  if (!placed) return false;
  hash.Add(x, r);
  for (int d = 0; d < 3; ++d) v[d] = s.velocity[d] + s.spread * (2 * random::Uniform(s.seed, key, 3 + d) - 1);
  AppendRow(x, v, r, MassOf(s, r), -1, x, nullptr);
  return true;
}

// Every rank gathers the particles whose centres lie within r_source + rMax of the source region
// and runs the same sequential placement; each keeps the new particles whose centres it owns.
PetscErrorCode ParticleSources::Insert(PetscReal t, InsertionSource &s, ParticleSwarm &swarm, PetscReal rMax) {
  ParticleArrays a;
  PetscMPIInt    size;
  // Every sphere that a new particle's members could touch: centres within its reach (bounding
  // radius) plus rMax of the region; hash cells at least a largest member's plus rMax wide.
  const PetscReal reach = Reach(s) + rMax;
  PetscReal       lo[3], hi[3], rLo, rHi;
  MemberRadii(s, &rLo, &rHi);

  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) {  // the region now (it may move: -dem_insert_<name>_region_velocity)
    const PetscReal shift = s.regionVelocity[d] * std::max((PetscReal)0, std::min(t, s.end) - s.start);
    s.now[d] = s.lower[d] + shift, s.now[3 + d] = s.upper[d] + shift;
    lo[d] = s.now[d] - reach, hi[d] = s.now[3 + d] + reach;
    // Reaching past a periodic face: the particles near the opposite face count too (all along d).
    if (grid_->Periodic(d) && (lo[d] < grid_->Lower()[d] || hi[d] > grid_->Upper()[d])) lo[d] = grid_->Lower()[d] - reach, hi[d] = grid_->Upper()[d] + reach;
  }
  near_.clear();
  PetscCall(swarm.GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p) {
    const PetscReal *x = &a.x[3 * p];
    if (x[0] < lo[0] || x[0] > hi[0] || x[1] < lo[1] || x[1] > hi[1] || x[2] < lo[2] || x[2] > hi[2]) continue;
    near_.insert(near_.end(), {x[0], x[1], x[2], a.radius[p]});
  }
  PetscCall(swarm.RestoreArrays(&a));
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  std::vector<PetscMPIInt> counts(size), displs(size);
  PetscMPIInt              n = (PetscMPIInt)near_.size(), total = 0;
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_));
  for (int q = 0; q < size; ++q) displs[q] = total, total += counts[q];
  std::vector<PetscReal> all(total);
  PetscCallMPI(MPI_Allgatherv(near_.data(), n, MPIU_REAL, all.data(), counts.data(), displs.data(), MPIU_REAL, comm_));
  // Whether a candidate overlaps is a yes/no over the same set on every rank: the order does not matter.
  SphereHash hash;
  hash.Reset(lo, hi, rHi + rMax, total / 4 + 64);
  for (int d = 0; d < 3; ++d)
    if (grid_->Periodic(d)) hash.SetPeriodic(d, grid_->Lower()[d], grid_->Upper()[d]);
  for (PetscMPIInt k = 0; k < total; k += 4) hash.Add(&all[k], all[k + 3]);
  newParticles_.clear();  // kRow reals per new sphere or clump member
  while (Due(s, t)) {
    const std::uint64_t key = (std::uint64_t)s.count;
    const PetscReal     r   = s.sizes.Radius(random::Uniform(s.seed, key, 6));  // clumps: volume-equivalent
    const bool          placed = s.clumps.empty() ? TrySphere(s, key, r, hash) : TryClump(s, key, r, hash);
    if (!placed) {  // the slot is full: try again one particle period later, from fresh candidates
      ++s.blocked;
      s.retryAt = t + (s.rate > 0 ? 1 / s.rate : MassOf(s, s.sizes.Mean()) / s.massRate);
      break;
    }
    ++s.count;
    s.tries = 0;
    s.mass += MassOf(s, r);  // a clump's volume is that of its volume-equivalent sphere
    massInserted_ += MassOf(s, r);
  }
  // Each rank keeps the new particles it owns; a clump's members all go to the owner of its first.
  PetscInt local = 0, first;
  // OwnsParticle: a clump across a periodic face may have its first member (the lead) past the face.
  for (size_t k = 0; k < newParticles_.size(); k += kRow) local += grid_->OwnsParticle(&newParticles_[k + 10]);
  PetscCall(swarm.AddLocal(local, &first));
  PetscCall(swarm.GetArrays(&a));
  for (size_t k = 0, p = first; k < newParticles_.size(); k += kRow) {
    const PetscReal *q = &newParticles_[k];
    if (!grid_->OwnsParticle(q + 10)) continue;
    for (int d = 0; d < 3; ++d) a.x[3 * p + d] = a.reference[3 * p + d] = q[d], a.v[3 * p + d] = q[3 + d], a.f[3 * p + d] = a.omega[3 * p + d] = a.torque[3 * p + d] = 0;
    a.radius[p] = q[6];
    a.id[p]     = (PetscInt64)q[7];
    a.mass[p]   = q[8];
    a.clump[p]  = (PetscInt64)q[9];
    a.type[p]   = s.type;
    if (a.clump[p] >= 0) std::copy(q + 13, q + 13 + kRigidWidth, &a.rigid[kRigidWidth * p]);
    ++p;
  }
  PetscCall(swarm.RestoreArrays(&a));
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSources::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  for (const auto &s : sources_) {
    char rate[64];
    if (s.rate > 0) std::snprintf(rate, sizeof rate, "%g particles/s", (double)s.rate);
    else std::snprintf(rate, sizeof rate, "%g kg/s", (double)s.massRate);
    std::string what = "";
    for (size_t k = 0; k < s.clumps.size(); ++k)
      what += (k ? ", " : "; clumps ") + library_.Name(s.clumps[k]) + " " + std::to_string((double)(s.clumpCdf[k] - (k ? s.clumpCdf[k - 1] : 0)));
    if (!s.clumps.empty()) what += " by number, sizes of the volume-equivalent radius";
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: insertion '%s'%s: %s into [%g, %g] x [%g, %g] x [%g, %g] m from t = %g s%s, velocity (%g, %g, %g) +- %g m/s; sizes: %s\n",
                                     s.name.c_str(), what.c_str(), rate, (double)s.lower[0], (double)s.upper[0], (double)s.lower[1], (double)s.upper[1], (double)s.lower[2],
                                     (double)s.upper[2], (double)s.start, s.end < PETSC_MAX_REAL ? (" to " + std::to_string((double)s.end) + " s").c_str() : "",
                                     (double)s.velocity[0], (double)s.velocity[1], (double)s.velocity[2], (double)s.spread, s.sizes.Describe().c_str()));
  }
  if (!boxes_.empty()) PetscCall(PetscViewerASCIIPrintf(viewer, "dem: %d deletion box(es)\n", (int)(boxes_.size() / 6)));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
