// Dem::Save / Dem::Load: all DEM state in an HDF5 viewer, under the group "dem" of the viewer's
// current group, through RankArchive (one dataset per array, rank segments in rank order).
//
// On the rank count that saved, Load puts back each rank's particles in memory order, the neighbour
// pairs in their order with springs and touching flags, the wall candidates, the halo's neighbour
// ranks and send lists (so ghosts return in the same order), the per-rank contact statistics and the
// counters: the continued run is bitwise the uninterrupted one (docs/petsc-notes.md, "Determinism
// and restart"). On another rank count each rank keeps the saved particles it owns, the springs of
// touching contacts are carried by id pair, and one rebuild makes the lists and ghosts anew;
// trajectories then agree to round-off over short horizons.
#include "vofdem/dem/Dem.hpp"

#include "vofdem/base/Runtime.hpp"
#include "vofdem/io/RankArchive.hpp"

#include <petscviewerhdf5.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

namespace vofdem {

namespace {

// Every swarm field, saved in memory order. A new swarm field is one more name here.
constexpr const char *const kSwarmFields[] = {field::position, field::velocity, field::force,  field::radius,   field::mass,
                                    field::id,       field::reference, field::omega, field::torque, field::type, field::clump, field::rigid,
                                    field::fluidDrag, field::fluidVelocity, field::fluidForce, field::fluidImpulse, field::fluidAddedMass, field::fluidExplicitImpulse, field::fluidCapillaryImpulse, field::fluidSurfacePlane,
                                    field::fluidRotationalDrag, field::fluidRotation, field::fluidViscosity,
                                    DMSwarmField_pid, DMSwarmField_rank, DMSwarmPICField_cellid};
constexpr int kNumSwarmFields = sizeof(kSwarmFields) / sizeof(kSwarmFields[0]);
// The fluid_* fields (kSwarmFields[kFirstFluid ...], as ParticleSwarm.hpp's kFluidFields) exist only in a coupled scene;
// a DEM-only run saves them empty, keeping the archive's order, and reads an older file's (which holds them) with
// their widths from kFluidFields.
constexpr int kFirstFluid = 12;
constexpr bool FluidFieldsInPlace() {
  for (int k = 0; k < kNumFluidFields; ++k)
    if (kSwarmFields[kFirstFluid + k] != kFluidFields[k].name) return false;
  return true;
}
static_assert(FluidFieldsInPlace(), "kSwarmFields holds ParticleSwarm.hpp's kFluidFields in their order from kFirstFluid");
bool IsFluidField(int f) { return f >= kFirstFluid && f < kFirstFluid + kNumFluidFields; }
constexpr int kClumpField = 10, kRigidField = 11;  // the clump id, then the clumps' rigid state (clump scenes only)
static_assert(kSwarmFields[kClumpField] == field::clump && kSwarmFields[kRigidField] == field::rigid, "kSwarmFields: clump, rigid");
constexpr int kStatsWidth     = 4 + 18;  // pair and wall contacts, max overlap, elastic energy, wall forces

// A field this scene's swarm does not hold (ParticleSwarm: the fluid_* ones without a coupling, `rigid` without
// clumps) is saved empty with its width, keeping the archive's layout, and an older file's values are dropped on load.
bool Absent(const ParticleSwarm &swarm, int f) { return (IsFluidField(f) && !swarm.HasFluidFields()) || (f == kRigidField && !swarm.HasRigidFields()); }
PetscInt AbsentWidth(int f) { return f == kRigidField ? kRigidWidth : kFluidFields[f - kFirstFluid].width; }

// Copies swarm field `name` of local particles into `out` (toSwarm false) or back (true), as doubles.
PetscErrorCode CopyField(DM swarm, const char *name, std::vector<PetscReal> *out, PetscInt *bs, bool toSwarm) {
  PetscDataType type;
  void         *data;
  PetscInt      n;

  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetLocalSize(swarm, &n));
  PetscCall(DMSwarmGetField(swarm, name, bs, &type, &data));
  const size_t len = (size_t)n * *bs;
  if (!toSwarm) out->resize(len);
  PetscCheck(out->size() >= len, PETSC_COMM_SELF, PETSC_ERR_PLIB, "field %s: %zu saved values for %zu", name, out->size(), len);
  auto copy = [&](auto *p) {
    for (size_t k = 0; k < len; ++k) {
      if (toSwarm) p[k] = (std::remove_pointer_t<decltype(p)>)(*out)[k];
      else (*out)[k] = (PetscReal)p[k];
    }
  };
  switch (type) {
  case PETSC_REAL: copy((PetscReal *)data); break;
  case PETSC_INT64: copy((PetscInt64 *)data); break;
  case PETSC_INT: copy((PetscInt *)data); break;
  default: SETERRQ(PETSC_COMM_SELF, PETSC_ERR_SUP, "swarm field %s: unsupported type for Save/Load", name);
  }
  PetscCall(DMSwarmRestoreField(swarm, name, bs, &type, &data));
  PetscFunctionReturn(0);
}

}  // namespace

struct Dem::SavedState {
  std::vector<std::vector<PetscReal>> fields;  // swarm fields, kSwarmFields order
  std::vector<PetscInt>               fieldBs;
  std::vector<PetscReal> pairIds, wallIds, wallSetIds, haloRanks, haloImages, sendCounts, send, stats;
  std::vector<PetscReal> particleOutputs, contactOutputs;  // the XDMF index entries, on rank 0
  std::vector<PetscReal> bondCounts;  // bonds made and broken on this rank (halves, Bonds.hpp), and whether they were made
  std::vector<PetscReal> heat[kNumHeatFields];  // the heat fields (ParticleSwarm.hpp kHeatFields; empty without them)
};

// The archived state, in order; Save and Load both run this, so a new piece of state is one line.
// Arrays that are not members are staged in `st` (filled before saving, used after loading).
PetscErrorCode Dem::ArchiveState(RankArchive &ar, SavedState &st) {
  PetscFunctionBeginUser;
  PetscCall(ar.Scalar(&rebuilds_));
  PetscCall(ar.Scalar(&inserted_));
  PetscCall(ar.Scalar(&steps_));
  PetscCall(ar.Scalar(&rMin_));
  PetscCall(ar.Scalar(&rMax_));
  PetscCall(ar.Scalar(&rayleighTime_));
  PetscCall(ar.Scalar(&adhesionRange_));
  PetscCall(ar.Scalar(&time_));
  PetscCall(sources_.ArchiveState(ar));   // insertion counters (ParticleSources.hpp)
  PetscCall(wallSet_.ArchiveState(ar));   // -dem_walls: clock, candidates, springs (Walls.hpp)
  for (int f = 0; f < kNumSwarmFields; ++f) PetscCall(ar.Array((std::string("swarm_") + kSwarmFields[f]).c_str(), &st.fields[f], st.fieldBs[f]));
  PetscCall(ar.Array("pair_first", &list_.first));
  PetscCall(ar.Array("pair_second", &list_.second));
  PetscCall(ar.Array("pair_ids", &st.pairIds, 2));
  PetscCall(ar.Array("pair_spring", &list_.spring, kSpringWidth));
  PetscCall(ar.Array("pair_touching", &list_.touching));
  PetscCall(ar.Array("pair_rstar", &list_.rstar));
  PetscCall(ar.Array("pair_sqrt_mstar", &list_.sqrtMstar));
  PetscCall(ar.Array("pair_material", &list_.material));
  PetscCall(ar.Array("wall_particle", &walls_.particle));
  PetscCall(ar.Array("wall_ids", &st.wallIds));
  PetscCall(ar.Array("wall_face", &walls_.wall));
  PetscCall(ar.Array("wall_touching", &walls_.touching));
  PetscCall(ar.Array("wall_spring", &walls_.spring, kSpringWidth));
  PetscCall(ar.Array("halo_ranks", &st.haloRanks));
  PetscCall(ar.Array("halo_images", &st.haloImages));
  PetscCall(ar.Array("halo_send_counts", &st.sendCounts));
  PetscCall(ar.Array("halo_send", &st.send));
  PetscCall(ar.Array("stats", &st.stats, kStatsWidth));
  PetscCall(ar.Array("output_particles", &st.particleOutputs, 3));  // step, time, count of each output so far (rank 0)
  PetscCall(ar.Array("output_contacts", &st.contactOutputs, 3));
  // Appended 2026-11-27 (files written before it load without it: a restart of theirs on another rank
  // count starts the -dem_walls contacts without their springs).
  if (ar.HasMore()) PetscCall(ar.Array("wallset_ids", &st.wallSetIds));
  // Appended 2026-11-29: the step the contacts allowed, measured every -dem_contact_step_every steps, so that
  // a restart steps as the run did (files written before it keep the value SetUp measured from their state).
  if (ar.HasMore()) PetscCall(ar.Scalar(&contactStepLimit_));
  // Appended 2026-12-04: the bonds (P13), one history per pair of the list (empty without -dem_cohesion bond), and
  // the counts (files written before them load without bonds).
  if (ar.HasMore()) {
    PetscCall(ar.Array("pair_bond", &bonds_.state, bond::kWidth));
    PetscCall(ar.Array("bond_counts", &st.bondCounts, 3));
  }
  // Appended 2026-12-04: the particles' enthalpy and temperature (P11; empty without a heat coupling; files
  // written before them load without them, which a run with particle heat refuses in Load).
  // Appended 2026-12-07: each particle's energy account (heat_absorbed, heat_exchanged; heat_conducted
  // from 2026-12-08); older files load what they lack as 0.
  for (int f = 0; f < kNumHeatFields && ar.HasMore(); ++f) PetscCall(ar.Array((std::string("swarm_") + kHeatFields[f].name).c_str(), &st.heat[f], kHeatFields[f].width));
  PetscFunctionReturn(0);
}

// What ArchiveState writes, every value a double: the swarm fields per particle, the pair and wall
// lists per entry, the halo's send lists, and a constant for the rest.
PetscErrorCode Dem::SavedBytes(PetscInt64 *bytes) const {
  PetscInt      bs, n;
  PetscDataType type;
  void         *data;
  PetscInt64    values = 0, perParticle = 0, all;

  PetscFunctionBeginUser;
  for (int f = 0; f < kNumSwarmFields; ++f) {
    if (Absent(swarm_, f)) continue;
    PetscCall(DMSwarmGetField(swarm_.Dm(), kSwarmFields[f], &bs, &type, &data));
    PetscCall(DMSwarmRestoreField(swarm_.Dm(), kSwarmFields[f], &bs, &type, &data));
    perParticle += bs;
  }
  if (swarm_.HasHeatFields()) perParticle += kNumHeatFields;
  PetscCall(DMSwarmGetLocalSize(swarm_.Dm(), &n));
  values = perParticle * n + (PetscInt64)list_.Size() * (2 + 2 + kSpringWidth + 4) + (PetscInt64)bonds_.state.size() + (PetscInt64)walls_.Size() * (4 + kSpringWidth) +
           (PetscInt64)wallSet_.Candidates() * (5 + kSpringWidth);
  for (const auto &s : halo_.SendLists()) values += 1 + (PetscInt64)s.size();
  if (out_.particleEntries.size() + out_.contactEntries.size()) values += 3 * (PetscInt64)(out_.particleEntries.size() + out_.contactEntries.size());
  PetscCallMPI(MPI_Allreduce(&values, &all, 1, MPIU_INT64, MPI_SUM, comm_));
  *bytes = 8 * all + 64 * 1024;
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::Save(PetscViewer viewer) {
  RankArchive ar;
  SavedState  st;
  PetscBool   hdf5;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERHDF5, &hdf5));
  PetscCheck(hdf5, comm_, PETSC_ERR_SUP, "Dem::Save needs an HDF5 viewer");
  st.fields.resize(kNumSwarmFields);
  st.fieldBs.resize(kNumSwarmFields);
  for (int f = 0; f < kNumSwarmFields; ++f) {
    if (Absent(swarm_, f)) st.fieldBs[f] = AbsentWidth(f);  // saved empty
    else PetscCall(CopyField(swarm_.Dm(), kSwarmFields[f], &st.fields[f], &st.fieldBs[f], false));
  }
  for (int f = 0; f < kNumHeatFields && swarm_.HasHeatFields(); ++f) {
    PetscInt bs;
    PetscCall(CopyField(swarm_.Dm(), kHeatFields[f].name, &st.heat[f], &bs, false));
  }
  {  // ids of the pairs (lower first) and of the wall candidates: the keys of a rank-count change
    ParticleArrays a;
    PetscCall(swarm_.GetArrays(&a));
    auto idOf = [&](PetscInt j) { return j < a.n ? a.id[j] : halo_.id[j - a.n]; };
    for (size_t k = 0; k < list_.Size(); ++k) st.pairIds.push_back((PetscReal)idOf(list_.first[k])), st.pairIds.push_back((PetscReal)idOf(list_.second[k]));
    for (size_t k = 0; k < walls_.Size(); ++k) st.wallIds.push_back((PetscReal)a.id[walls_.particle[k]]);
    wallSet_.CandidateIds(a, &st.wallSetIds);
    PetscCall(swarm_.RestoreArrays(&a));
  }
  st.haloRanks.assign(halo_.Ranks().begin(), halo_.Ranks().end());
  st.haloImages.assign(halo_.ImageCodes().begin(), halo_.ImageCodes().end());
  for (const auto &s : halo_.SendLists()) st.sendCounts.push_back((PetscReal)s.size()), st.send.insert(st.send.end(), s.begin(), s.end());
  st.stats = {(PetscReal)stats_.pairContacts, (PetscReal)stats_.wallContacts, stats_.maxOverlap, stats_.elastic};
  st.bondCounts = {bonds_.madeHalves, bonds_.brokenHalves, bonds_.Made() ? 1.0 : 0.0};
  for (int f = 0; f < 6; ++f) st.stats.insert(st.stats.end(), stats_.wallForce[f], stats_.wallForce[f] + 3);
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  for (const XdmfEntry &e : rank == 0 ? out_.particleEntries : std::vector<XdmfEntry>{})
    st.particleOutputs.insert(st.particleOutputs.end(), {(PetscReal)e.step, e.time, (PetscReal)e.nodes});
  for (const XdmfEntry &e : rank == 0 ? out_.contactEntries : std::vector<XdmfEntry>{})
    st.contactOutputs.insert(st.contactOutputs.end(), {(PetscReal)e.step, e.time, (PetscReal)e.segments});
  PetscCall(PetscViewerHDF5PushGroup(viewer, "dem"));
  PetscCall(ar.Begin(viewer, comm_, false, "Dem::Save"));
  PetscCall(ArchiveState(ar, st));
  PetscCall(ar.Finish());
  PetscCall(PetscViewerHDF5PopGroup(viewer));
  {  // Each rank's box: a load on as many ranks but another decomposition must not reuse the halo.
    RankArchive            dec;
    std::vector<PetscReal> box(6);
    grid_->LocalBox(&box[0], &box[3]);
    PetscCall(PetscViewerHDF5PushGroup(viewer, "dem/decomposition"));
    PetscCall(dec.Begin(viewer, comm_, false, "Dem::Save"));
    PetscCall(dec.Array("box", &box, 6));
    PetscCall(dec.Finish());
    PetscCall(PetscViewerHDF5PopGroup(viewer));
  }
  PetscFunctionReturn(0);
}

// Call after SetUp() with the options of the run that saved: the loaded state replaces the inserted one.
// The ownership ranges a -dem_balance run had when it saved: each rank's saved box gives its cells per
// direction (rank = i + m0 (j + m1 k), as DMDA numbers them); when they differ from the grid's, the grid
// is repartitioned to them as Balance() does. Collective; same rank count only.
PetscErrorCode Dem::RestoreOwnership(const std::vector<PetscReal> &savedBox) {
  PetscMPIInt     rank, size;
  PetscInt        m[3];
  const PetscInt *l[3];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  PetscCall(DMDAGetInfo(grid_->CellDM(), nullptr, nullptr, nullptr, nullptr, &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(grid_->CellDM(), &l[0], &l[1], &l[2]));
  const PetscReal *lo = grid_->Lower(), *h = grid_->Spacing();
  std::vector<PetscInt> mine(3 * size, 0), cells(3 * size);
  for (int d = 0; d < 3; ++d) {
    const PetscInt first = (PetscInt)std::llround((savedBox[d] - lo[d]) / h[d]), last = (PetscInt)std::llround((savedBox[3 + d] - lo[d]) / h[d]);
    mine[3 * rank + d] = last - first;
  }
  PetscCallMPI(MPI_Allreduce(mine.data(), cells.data(), 3 * size, MPIU_INT, MPI_SUM, comm_));
  std::vector<PetscInt> slabs[3];
  bool                  differs = false;
  for (int d = 0; d < 3; ++d) {
    slabs[d].assign(m[d], 0);
    for (PetscInt q = 0; q < m[d]; ++q) {  // the rank at index q along d, 0 along the others
      const PetscInt r = d == 0 ? q : d == 1 ? m[0] * q : m[0] * m[1] * q;
      slabs[d][q]      = cells[3 * r + d];
      differs          = differs || slabs[d][q] != l[d][q];
    }
    PetscInt total = 0;
    for (PetscInt c : slabs[d]) total += c;
    PetscCheck(total == grid_->Cells()[d], comm_, PETSC_ERR_FILE_UNEXPECTED, "checkpoint: the saved ranks' boxes hold %" PetscInt_FMT " cells along %c, the grid %" PetscInt_FMT, total, "xyz"[d], grid_->Cells()[d]);
  }
  if (!differs) PetscFunctionReturn(0);
  PetscCall(grid_->Repartition(slabs));
  PetscCall(DMSwarmSetCellDM(swarm_.Dm(), grid_->VertexDM()));
  PetscCall(halo_.SetUp(*grid_));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::Load(PetscViewer viewer) {
  RankArchive ar;
  SavedState  st;
  PetscBool   hdf5;
  DM          dm = swarm_.Dm();

  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERHDF5, &hdf5));
  PetscCheck(hdf5, comm_, PETSC_ERR_SUP, "Dem::Load needs an HDF5 viewer");
  st.fields.resize(kNumSwarmFields);
  st.fieldBs.resize(kNumSwarmFields);
  for (int f = 0; f < kNumSwarmFields; ++f) {  // block sizes from the swarm itself
    PetscDataType type;
    void         *data;
    if (Absent(swarm_, f)) {
      st.fieldBs[f] = AbsentWidth(f);
      continue;
    }
    PetscCall(DMSwarmGetField(dm, kSwarmFields[f], &st.fieldBs[f], &type, &data));
    PetscCall(DMSwarmRestoreField(dm, kSwarmFields[f], &st.fieldBs[f], &type, &data));
  }
  bool sameDecomposition;
  {  // As many ranks, each with the box it had: then the bitwise path (halo and lists as saved).
    RankArchive            dec;
    std::vector<PetscReal> saved, box(6);
    PetscCall(PetscViewerHDF5PushGroup(viewer, "dem/decomposition"));
    PetscCall(dec.Begin(viewer, comm_, true, "Dem::Load"));
    PetscCall(dec.Array("box", &saved, 6));
    PetscCall(PetscViewerHDF5PopGroup(viewer));
    // -dem_balance moved the ownership ranges: the run goes on with the saved ones (bitwise), not with the
    // grid's initial even split (which would repartition at the first rebuild, on another path).
    if (balance_ && dec.SameRanks()) PetscCall(RestoreOwnership(saved));
    grid_->LocalBox(&box[0], &box[3]);
    int same = dec.SameRanks() && saved == box, all;
    PetscCallMPI(MPI_Allreduce(&same, &all, 1, MPI_INT, MPI_MIN, comm_));
    sameDecomposition = all;
  }
  PetscCall(PetscViewerHDF5PushGroup(viewer, "dem"));
  PetscCall(ar.Begin(viewer, comm_, true, "Dem::Load", !sameDecomposition));
  PetscCall(ArchiveState(ar, st));
  PetscCall(PetscViewerHDF5PopGroup(viewer));
  PetscCheck(bonds_.On() || bonds_.state.empty(), comm_, PETSC_ERR_FILE_UNEXPECTED, "checkpoint: it holds bonds (P13), but this run has no -dem_cohesion bond");
  if (bonds_.On() && !st.bondCounts.empty()) {  // as saved on this rank; on another rank count the totals go to rank 0
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(comm_, &rank));
    PetscReal made = 0, broken = 0;
    for (size_t k = 0; k + 2 < st.bondCounts.size(); k += 3) made += st.bondCounts[k], broken += st.bondCounts[k + 1];
    const bool keepHere = ar.SameRanks() || rank == 0;
    bonds_.madeHalves = keepHere ? made : 0, bonds_.brokenHalves = keepHere ? broken : 0;
    bonds_.SetMade(st.bondCounts[2] != 0);
  }
  // A file written before the bonds: none (on another rank count Rebuild() sizes the histories).
  if (ar.SameRanks() && bonds_.state.size() != bond::kWidth * list_.Size()) bonds_.state.assign(bonds_.On() ? bond::kWidth * list_.Size() : 0, 0);
  const int    iPos = 0, iId = 5;
  const size_t saved = st.fields[iId].size();
  std::vector<size_t> keep;  // saved particles this rank holds, in saved order
  if (ar.SameRanks()) {
    for (size_t k = 0; k < saved; ++k) keep.push_back(k);
  } else {
    // A clump's members stay together (P10): all go to the owner of its lowest-id member.
    std::unordered_map<PetscInt64, size_t>   lead;
    for (size_t k = 0; k < saved; ++k) {
      const PetscInt64 c = (PetscInt64)st.fields[kClumpField][k];
      if (c < 0) continue;
      auto it = lead.find(c);
      if (it == lead.end()) lead.emplace(c, k);
      else if (st.fields[iId][k] < st.fields[iId][it->second]) it->second = k;
    }
    for (size_t k = 0; k < saved; ++k) {
      const PetscInt64 c = (PetscInt64)st.fields[kClumpField][k];
      // OwnsParticle: a centre past a periodic face since the last rebuild belongs to the face's other side
      // (OwnsPoint would give it to no rank: the D7 run restarted with 3 of 32,000 spheres missing).
      if (grid_->OwnsParticle(&st.fields[iPos][3 * (c < 0 ? k : lead[c])])) keep.push_back(k);
    }
  }
  PetscCall(DMSwarmSetLocalSizes(dm, (PetscInt)keep.size(), 64));
  PetscCall(swarm_.FieldsMoved());
  for (int f = 0; f < kNumSwarmFields; ++f) {
    if (IsFluidField(f) && !swarm_.HasFluidFields()) {
      // A DEM-only run's file written before these fields became optional holds them, all zero; a coupled
      // run's would not restart as DEM-only (Checkpoint.cpp compares the physics), so a value here is corruption.
      PetscCheck(std::all_of(st.fields[f].begin(), st.fields[f].end(), [](PetscReal v) { return v == 0; }), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
                 "checkpoint: the particles' field %s holds fluid coupling state, but this run has no coupling", kSwarmFields[f]);
      continue;
    }
    if (f == kRigidField && !swarm_.HasRigidFields()) {
      // A file written before `rigid` became optional holds it for every particle; only clump members use it, and
      // a scene without clumps cannot take a file with some (the clump ids were compacted to this rank's above).
      PetscCheck(std::all_of(st.fields[kClumpField].begin(), st.fields[kClumpField].begin() + keep.size(), [](PetscReal c) { return c < 0; }), PETSC_COMM_SELF,
                 PETSC_ERR_FILE_UNEXPECTED, "checkpoint: its particles include rigid clumps (P10), but this run's scene has none (no clump insertion, no clump column in -dem_particles_file)");
      continue;
    }
    const PetscInt bs = st.fieldBs[f];
    for (size_t j = 0; j < keep.size(); ++j)  // in place: j <= keep[j]
      std::copy_n(&st.fields[f][bs * keep[j]], bs, &st.fields[f][bs * j]);
    PetscInt bsOut;
    PetscCall(CopyField(dm, kSwarmFields[f], &st.fields[f], &bsOut, true));
  }
  for (int f = 0; f < kNumHeatFields; ++f) {  // the heat fields (P11), one value per saved particle or none
    const bool held = st.heat[f].size() == saved && saved > 0;
    if (!swarm_.HasHeatFields()) {
      PetscCheck(st.heat[f].empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "checkpoint: the particles' field %s holds their heat, but this run's particles exchange none", kHeatFields[f].name);
      continue;
    }
    if (!held && f >= kNumHeatState) st.heat[f].assign(saved, 0);  // a file from before the account: it starts here
    else PetscCheck(held || saved == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "checkpoint: it holds no particle %s (written without particle heat); this run's particles exchange heat (-physics with dem and energy)",
               kHeatFields[f].name);
    for (size_t j = 0; j < keep.size(); ++j) st.heat[f][j] = st.heat[f][keep[j]];
    PetscInt bsOut;
    PetscCall(CopyField(dm, kHeatFields[f].name, &st.heat[f], &bsOut, true));
  }
  ParticleArrays a;
  if (ar.SameRanks()) {
    std::vector<PetscMPIInt>           ranks(st.haloRanks.begin(), st.haloRanks.end());
    std::vector<std::vector<PetscInt>> send(ranks.size());
    for (size_t q = 0, o = 0; q < ranks.size(); o += (size_t)st.sendCounts[q], ++q)
      send[q].assign(st.send.begin() + o, st.send.begin() + o + (size_t)st.sendCounts[q]);
    const std::vector<int> images(st.haloImages.begin(), st.haloImages.end());
    PetscCall(swarm_.GetArrays(&a));
    PetscCall(halo_.Restore(a, a.omega, ranks, images, send));
    PeriodicImages::PairImages(list_, a.n, halo_.image.data(), &pairImage_);  // the seam shifts of the pairs
    JkrPairConstants();
    PetscCall(sources_.FindDeletionCandidates(a, 0.5 * skin_));  // from the saved reference positions, as Rebuild() would
    PetscCall(swarm_.RestoreArrays(&a));
  } else {
    // Springs of touching contacts by id pair, for the contacts of particles this rank now holds;
    // Rebuild() passes them on to the ranks that hold the partner as a ghost.
    std::vector<PetscInt64> ids(st.fields[iId].size());
    for (size_t k = 0; k < ids.size(); ++k) ids[k] = (PetscInt64)st.fields[iId][k];
    std::sort(ids.begin(), ids.end());
    auto local = [&](PetscReal id) { return std::binary_search(ids.begin(), ids.end(), (PetscInt64)id); };
    auto zero  = [](const PetscReal *s) { return std::all_of(s, s + kSpringWidth, [](PetscReal v) { return v == 0; }); };
    springs_.clear();
    for (size_t k = 0; k < list_.touching.size(); ++k) {
      const PetscReal *s = &list_.spring[kSpringWidth * k], lo = st.pairIds[2 * k], hi = st.pairIds[2 * k + 1];
      if (!list_.touching[k] || zero(s) || !(local(lo) || local(hi))) continue;
      std::copy(s, s + kSpringWidth, springs_[{(PetscInt64)lo, (PetscInt64)hi}].begin());
    }
    for (size_t k = 0; k < walls_.touching.size(); ++k)
      if (walls_.touching[k] && local(st.wallIds[k]))
        std::copy(&walls_.spring[kSpringWidth * k], &walls_.spring[kSpringWidth * (k + 1)], springs_[PairKey::Wall((PetscInt64)st.wallIds[k], walls_.wall[k])].begin());
    // Intact bonds (P13) alike, touching or not.
    bonds_.carried.clear();
    for (size_t k = 0; k < bonds_.state.size() / bond::kWidth; ++k) {
      const PetscReal *h = &bonds_.state[bond::kWidth * k], lo = st.pairIds[2 * k], hi = st.pairIds[2 * k + 1];
      if (h[bond::kState] == 0 || !(local(lo) || local(hi))) continue;
      std::copy(h, h + bond::kWidth, bonds_.carried[{(PetscInt64)lo, (PetscInt64)hi}].begin());
    }
    bonds_.state.clear();
    // The loaded lists are all ranks' concatenated: Rebuild() makes this rank's from the particles.
    list_.first.clear(), list_.second.clear(), list_.spring.clear(), list_.touching.clear(), list_.rstar.clear(), list_.sqrtMstar.clear();
    walls_.Clear();
    list_.material.clear();
    if (!wallSet_.CarrySprings(st.wallSetIds, local, &springs_))
      PetscCall(PetscPrintf(comm_, "Dem::Load: the checkpoint predates the -dem_walls candidates' ids: on another rank count their contacts restart without tangential springs\n"));
    wallSet_.ClearCandidates();  // their indices are the saving ranks'
    const PetscInt rebuilds = rebuilds_;
    PetscCall(Rebuild());
    rebuilds_ = rebuilds;
    // The statistics of the last evaluation, as totals on rank 0 (Summarize sums over ranks).
    std::vector<PetscReal> sum(kStatsWidth, 0);
    for (size_t r = 0; r < st.stats.size() / kStatsWidth; ++r)
      for (int j = 0; j < kStatsWidth; ++j) sum[j] = j == 2 ? std::max(sum[j], st.stats[kStatsWidth * r + j]) : sum[j] + st.stats[kStatsWidth * r + j];
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(comm_, &rank));
    if (rank == 0) st.stats = sum;
    else std::fill(st.stats.begin(), st.stats.end(), 0.0);
  }
  // The output indices so far (only rank 0 writes them).
  out_.particleEntries.clear(), out_.contactEntries.clear();
  for (size_t k = 0; k + 2 < st.particleOutputs.size(); k += 3) {
    out_.particleEntries.push_back(DemOutputSettings::ParticleEntry((PetscInt)st.particleOutputs[k], st.particleOutputs[k + 1], (PetscInt)st.particleOutputs[k + 2]));
    if (swarm_.HasHeatFields()) out_.particleEntries.back().attributes.push_back({"temperature", "/temperature"});  // DemOutput.cpp
  }
  for (size_t k = 0; k + 2 < st.contactOutputs.size(); k += 3)
    out_.contactEntries.push_back(DemOutputSettings::ContactEntry((PetscInt)st.contactOutputs[k], st.contactOutputs[k + 1], (PetscInt)st.contactOutputs[k + 2]));
  stats_.pairContacts = (PetscInt)st.stats[0];
  stats_.wallContacts = (PetscInt)st.stats[1];
  stats_.maxOverlap   = st.stats[2];
  stats_.elastic      = st.stats[3];
  for (int f = 0; f < 6; ++f) std::copy_n(&st.stats[4 + 3 * f], 3, stats_.wallForce[f]);
  clumps_.Invalidate();  // the loaded particles' local order
  PetscFunctionReturn(0);
}

}  // namespace vofdem
