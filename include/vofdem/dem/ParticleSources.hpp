// Particles entering and leaving during a run: insertion sources (-dem_inserts a,b: each a box or
// slot of centres fed at a rate in particles/s or kg/s with a velocity and spread, between a start
// and an end time) and deletion boxes (-dem_delete_boxes: a particle whose centre is inside one is
// removed, with its contact histories). Both act only when the neighbour lists are rebuilt, which
// they request (NeedsChange), since they change the particles' local indices.
//
// Insertion is decided identically on every rank: particle k of a source draws its radius,
// velocity and candidate centres from the counter-based generator keyed by k, and is tested for
// overlap against ALL particles near the source (gathered on every rank), so the decision does not
// depend on the rank count; only the rank that owns the accepted centre stores the particle. New
// global ids continue after the largest id so far.
//
// A source with -dem_insert_<name>_clumps inserts rigid clumps (P10; ClumpInsertion.cpp) instead of
// spheres: its rate counts clumps, its size distribution gives each clump's volume-equivalent radius.
#pragma once

#include "vofdem/base/Options.hpp"
#include "vofdem/dem/ClumpLibrary.hpp"
#include "vofdem/dem/NeighbourList.hpp"
#include "vofdem/dem/ParticleSwarm.hpp"
#include "vofdem/dem/SizeDistribution.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace vofdem {

class SphereHash;

struct InsertionSource {
  std::string      name;
  PetscReal        lower[3] = {0, 0, 0}, upper[3] = {0, 0, 0};  // region of the centres, m
  PetscReal        rate = 0, massRate = 0;                      // particles/s or kg/s (one of them)
  PetscReal        velocity[3] = {0, 0, 0}, spread = 0;         // m/s
  PetscReal        regionVelocity[3] = {0, 0, 0};               // m/s: the region moves (a feed slot on a spreader) from `start`
  PetscReal        now[6] = {0, 0, 0, 0, 0, 0};                 // the region at the current insertion (lower, upper)
  PetscReal        start = 0, end = PETSC_MAX_REAL;             // s
  PetscReal        every = 0;                                   // s: batches (NeedsChange); 0: each particle when due
  PetscInt         attempts = 100;                              // candidate centres per particle and round
  PetscInt         type = 0;                                    // particle type (index into -dem_types)
  PetscReal        density = 0;                                 // kg/m^3, the type's
  SizeDistribution sizes;                                       // clumps: of the volume-equivalent radius
  std::vector<int>       clumps;                                 // ClumpLibrary templates (empty: spheres)
  std::vector<PetscReal> clumpCdf;                               // cumulative number fractions of `clumps`
  std::uint64_t    seed = 0;
  // State (the same on every rank).
  PetscInt64 count = 0;        // particles inserted
  PetscReal  mass  = 0;        // kg inserted
  PetscInt64 tries = 0;        // candidate centres already tried for particle `count`
  PetscReal  retryAt = 0;      // after a round found no room: the next try, one particle period later
  PetscInt64 blocked = 0;      // rounds that found no room
};

class ParticleSources {
public:
  // Row of a new particle in Insert(): x3 v3 r id mass clump lead-x3 rigid(kRigidWidth).
  static constexpr int kRow = 13 + kRigidWidth;
  // Inside the Dem's PetscOptionsBegin block; `radius` is -dem_radius (the default size).
  // types/densities: the names of -dem_types and their densities.
  PetscErrorCode SetFromOptions(OptionReader &opt, MPI_Comm comm, PetscReal radius, const std::vector<std::string> &types, const std::vector<PetscReal> &densities);
  // After the initial particles exist: checks the regions, ids continue after the largest one.
  PetscErrorCode SetUp(const Grid &grid, const ParticleSwarm &swarm, std::uint64_t seed);
  bool Active() const { return !sources_.empty() || !boxes_.empty(); }
  bool InsertsClumps() const {
    for (const auto &s : sources_)
      if (!s.clumps.empty()) return true;
    return false;
  }
  const ClumpLibrary &Library() const { return library_; }
  // Widens [rmin, rmax] by the sizes the sources can insert (time step and neighbour cut-off).
  void RadiusRange(PetscReal *rmin, PetscReal *rmax) const;
  // Collective: whether Apply() at time t would insert or delete a particle.
  PetscErrorCode NeedsChange(PetscReal t, const ParticleSwarm &swarm, PetscBool *change) const;
  // Collective, at the end of each rebuild (local indices final) and after a same-ranks Load: the local
  // particles that can reach a deletion box before the next rebuild, when none moves farther than `reach`
  // from its reference position (the half skin of the rebuild rule). NeedsChange then looks at those only,
  // and skips its reduction when no rank has any: the same steps delete the same particles as a scan of all.
  PetscErrorCode FindDeletionCandidates(const ParticleArrays &a, PetscReal reach);
  // Collective: deletes the particles in deletion boxes (and their springs), then inserts what the
  // sources owe at time t. rMax bounds the radius of every particle present.
  PetscErrorCode Apply(PetscReal t, ParticleSwarm &swarm, ContactHistory *springs, PetscReal rMax);
  PetscErrorCode View(PetscViewer viewer) const;

  // Particles removed by something else (Dem::RemoveParticles: melted into the fluid), all ranks' count and mass.
  void       CountRemoved(PetscInt64 count, PetscReal mass) { deleted_ += count, massDeleted_ += mass; }
  PetscInt64 Inserted() const { return inserted_; }
  PetscInt64 Deleted() const { return deleted_; }
  PetscReal  MassInserted() const { return massInserted_; }
  PetscReal  MassDeleted() const { return massDeleted_; }
  const std::vector<InsertionSource> &Sources() const { return sources_; }
  // The counters and per-source state (the same on every rank); Dem::Save/Load.
  template <class Archive>
  PetscErrorCode ArchiveState(Archive &ar) {
    PetscFunctionBeginUser;
    PetscCall(ar.Scalar(&nextId_));
    PetscCall(ar.Scalar(&inserted_));
    PetscCall(ar.Scalar(&deleted_));
    PetscCall(ar.Scalar(&massInserted_));
    PetscCall(ar.Scalar(&massDeleted_));
    for (InsertionSource &s : sources_) {
      PetscCall(ar.Scalar(&s.count));
      PetscCall(ar.Scalar(&s.mass));
      PetscCall(ar.Scalar(&s.tries));
      PetscCall(ar.Scalar(&s.retryAt));
      PetscCall(ar.Scalar(&s.blocked));
    }
    PetscFunctionReturn(0);
  }

private:
  bool           Due(const InsertionSource &s, PetscReal t) const;
  static PetscReal MassOf(const InsertionSource &s, PetscReal r) { return s.density * 4.0 / 3.0 * PETSC_PI * r * r * r; }
  bool           InDeletionBox(const PetscReal x[3], PetscReal margin = 0) const;  // margin: each box grown by it
  // ClumpInsertion.cpp: the clump options of a source; the largest distance of a member's surface
  // from the inserted centre (the bounding radius), and the members' radius range.
  PetscErrorCode ClumpsFromOptions(OptionReader &opt, InsertionSource &s);
  PetscReal      Reach(const InsertionSource &s) const;
  void           MemberRadii(const InsertionSource &s, PetscReal *rmin, PetscReal *rmax) const;
  // One candidate round for particle `count` of the source (all its attempts); on success appends
  // the particle's rows (kRow reals each) to newParticles_ and adds it to the hash.
  bool           TrySphere(InsertionSource &s, std::uint64_t key, PetscReal r, SphereHash &hash);
  bool           TryClump(InsertionSource &s, std::uint64_t key, PetscReal rEq, SphereHash &hash);
  void           AppendRow(const PetscReal x[3], const PetscReal v[3], PetscReal r, PetscReal mass, PetscInt64 clump, const PetscReal lead[3],
                           const PetscReal *rigidState);
  PetscErrorCode Delete(ParticleSwarm &swarm, ContactHistory *springs);
  PetscErrorCode Insert(PetscReal t, InsertionSource &s, ParticleSwarm &swarm, PetscReal rMax);

  MPI_Comm                     comm_ = MPI_COMM_NULL;
  const Grid                  *grid_ = nullptr;
  std::vector<InsertionSource> sources_;
  std::vector<PetscReal>       boxes_;  // deletion boxes: xlo,ylo,zlo,xhi,yhi,zhi each
  std::vector<PetscInt>        deletionCandidates_;           // local indices (FindDeletionCandidates)
  bool                         candidatesKnown_    = false;   // else NeedsChange scans every particle
  bool                         candidatesAnywhere_ = true;    // some rank has candidates
  PetscInt64                   nextId_ = 0, inserted_ = 0, deleted_ = 0;
  PetscReal                    massInserted_ = 0, massDeleted_ = 0;
  std::vector<PetscReal>       near_, newParticles_;  // work arrays, reused
  ClumpLibrary                 library_;              // -dem_clump_templates and the built-in shapes
  PlacedClump                  placed_;               // work: the clump being tried
  PetscInt64                   clumpBase_ = 0;        // inserted clump ids: clumpBase_ + the id of the clump's first member
};

}  // namespace vofdem
