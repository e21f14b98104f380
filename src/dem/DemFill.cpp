#include "vofdem/dem/Dem.hpp"

#include "vofdem/base/MemoryBudget.hpp"
#include "vofdem/base/Random.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/dem/RandomFill.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/io/InputPath.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace vofdem {

// A particle of a fill at local index p: centre x, radius r, the fill's type, velocity and spread
// (the random part keyed by id and seed), at rest in rotation, in no clump.
void Dem::StoreFilled(const ParticleArrays &a, PetscInt p, PetscInt64 id, const PetscReal x[3], PetscReal r, std::uint64_t seed) const {
  for (int d = 0; d < 3; ++d) {
    a.x[3 * p + d] = x[d];
    a.v[3 * p + d] = fillVelocity_[d] + fillSpread_ * (2 * random::Uniform(seed, (std::uint64_t)id, 3 + d) - 1);
    a.f[3 * p + d] = a.omega[3 * p + d] = a.torque[3 * p + d] = 0;
  }
  a.radius[p] = r;
  a.mass[p]   = types_[fillType_].density * 4.0 / 3.0 * PETSC_PI * r * r * r;
  a.id[p]     = id;
  a.type[p]   = fillType_;
  a.clump[p]  = -1;
}

// Lattice fill: centres at lower + R + j + i*s, R the largest fill radius and j the jitter
// amplitude, so that jittered particles neither overlap each other nor leave the region. Every rank
// walks the same lattice and keeps the points it owns; ids, jitter and each particle's radius
// (drawn from -dem_fill_size_distribution, SizeDistribution.hpp; R is then its upper cut-off) depend
// only on the lattice index and the seed, so the same particles result on any rank count.
PetscErrorCode Dem::Fill(std::uint64_t seed) {
  PetscReal lo[3], hi[3];
  PetscInt  n[3];

  PetscFunctionBeginUser;
  if (fillRandom_) {
    PetscCall(FillRandom(seed));
    PetscFunctionReturn(0);
  }
  if (fillCount_ == 0) PetscFunctionReturn(0);
  for (int d = 0; d < 3; ++d) {
    lo[d] = fillLowerSet_ ? fillLower_[d] : grid_->Lower()[d];
    hi[d] = fillUpperSet_ ? fillUpper_[d] : grid_->Upper()[d];
    if (lo[d] < grid_->Lower()[d] || hi[d] > grid_->Upper()[d] || !(hi[d] > lo[d]))
      VofdemInputError(comm_, "options -dem_fill_lower/-dem_fill_upper: the region [%g, %g] in %c must be non-empty and inside the box [%g, %g]",
                       (double)lo[d], (double)hi[d], "xyz"[d], (double)grid_->Lower()[d], (double)grid_->Upper()[d]);
  }
  const PetscReal rFill  = fillSizes_.MaxRadius();
  const PetscReal jitter = fillJitter_ * (fillSpacing_ - 2 * rFill) / 2;
  auto radiusOf = [&](PetscInt64 id) { return fillSizes_.Radius(random::Uniform(seed, (std::uint64_t)id, 6)); };
  PetscInt64      total  = 1;
  for (int d = 0; d < 3; ++d) {
    const PetscReal room = hi[d] - lo[d] - 2 * (rFill + jitter);
    n[d]                 = room < 0 ? 0 : (PetscInt)std::floor(room / fillSpacing_ * (1 + 1e-12)) + 1;
    total *= n[d];
  }
  if (fillCount_ < 0 && total > PETSC_MAX_INT)
    VofdemInputError(comm_, "option -dem_fill_count -1: the fill region holds %" PetscInt64_FMT " particles, more than this build's 32-bit indices allow; give a count or a smaller region",
                     total);
  if (fillCount_ > total)
    VofdemInputError(comm_, "option -dem_fill_count: cannot fit %" PetscInt_FMT " particles, the fill region holds %" PetscInt64_FMT " at spacing %g m",
                     fillCount_, total, (double)fillSpacing_);
  const PetscInt64 want = fillCount_ < 0 ? total : fillCount_;
  if (want == 0) VofdemInputError(comm_, "options -dem_fill_*: the fill region is too small for a single particle of radius %g m", (double)rFill);
  {  // the ranks share the lattice: the busiest holds at least its share
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(comm_, &size));
    PetscCall(CheckMemoryRequest(comm_, "-dem_fill_count", want, swarm_.BytesPerParticle() / size, "particles (their swarm fields, shared among the ranks)"));
  }

  auto centre = [&](PetscInt64 id, PetscReal x[3]) {
    const PetscInt64 idx[3] = {id % n[0], (id / n[0]) % n[1], id / ((PetscInt64)n[0] * n[1])};
    for (int d = 0; d < 3; ++d) x[d] = lo[d] + rFill + jitter + idx[d] * fillSpacing_ + jitter * (2 * random::Uniform(seed, (std::uint64_t)id, d) - 1);
  };
  PetscInt local = 0;
  for (PetscInt64 id = 0; id < want; ++id) {
    PetscReal x[3];
    centre(id, x);
    if (grid_->OwnsPoint(x)) ++local;
  }
  PetscInt       first;
  ParticleArrays a;
  PetscCall(swarm_.AddLocal(local, &first));
  PetscCall(swarm_.GetArrays(&a));
  PetscInt p = first;
  for (PetscInt64 id = 0; id < want; ++id) {
    PetscReal x[3];
    centre(id, x);
    if (!grid_->OwnsPoint(x)) continue;
    StoreFilled(a, p++, id, x, radiusOf(id), seed);
  }
  PetscCall(swarm_.RestoreArrays(&a));
  PetscCall(swarm_.GlobalCount(&inserted_));
  PetscCheck(inserted_ == want, comm_, PETSC_ERR_PLIB, "lattice fill placed %" PetscInt_FMT " particles instead of %" PetscInt64_FMT, inserted_, want);
  PetscCall(swarm_.Migrate());  // agree with the swarm's own point location; set the reference positions
  PetscFunctionReturn(0);
}

// Random non-overlapping fill of the region (RandomFill.hpp): every rank computes the same
// particles from -seed and keeps those it owns; velocities as in the lattice fill. A target that
// cannot be met (too dense for random sequential addition) is an input error saying what was reached.
PetscErrorCode Dem::FillRandom(std::uint64_t seed) {
  RandomFillRequest req;
  RandomFillResult  res;

  PetscFunctionBeginUser;
  if (fillCount_ < 0) VofdemInputError(comm_, "option -dem_fill_count -1 (as many as fit) is for -dem_fill_mode lattice; give a count or -dem_fill_volume_fraction");
  if (fillCount_ > 0 && fillFraction_ > 0) VofdemInputError(comm_, "options -dem_fill_count and -dem_fill_volume_fraction: give one target for the random fill");
  if (fillCount_ == 0 && fillFraction_ == 0) VofdemInputError(comm_, "option -dem_fill_mode random needs -dem_fill_count or -dem_fill_volume_fraction");
  for (int d = 0; d < 3; ++d) {
    req.lower[d] = fillLowerSet_ ? fillLower_[d] : grid_->Lower()[d];
    req.upper[d] = fillUpperSet_ ? fillUpper_[d] : grid_->Upper()[d];
    if (req.lower[d] < grid_->Lower()[d] || req.upper[d] > grid_->Upper()[d] || !(req.upper[d] > req.lower[d]))
      VofdemInputError(comm_, "options -dem_fill_lower/-dem_fill_upper: the region [%g, %g] in %c must be non-empty and inside the box [%g, %g]",
                       (double)req.lower[d], (double)req.upper[d], "xyz"[d], (double)grid_->Lower()[d], (double)grid_->Upper()[d]);
    // Across a whole periodic direction the fill has no faces: no radius-wide gap at the seam.
    req.periodic[d] = grid_->Periodic(d) && req.lower[d] == grid_->Lower()[d] && req.upper[d] == grid_->Upper()[d];
  }
  {  // up front: what cannot fit the region or the memory is refused before anything is allocated
    PetscReal region = 1;
    for (int d = 0; d < 3; ++d) region *= req.upper[d] - req.lower[d];
    const PetscReal mean = 4.0 / 3.0 * PETSC_PI * fillSizes_.MeanCube();
    const double    count = fillCount_ > 0 ? (double)fillCount_ : fillFraction_ * region / mean;
    // Random sequential addition of equal spheres cannot pass its jamming limit (0.3841); no packing passes 1.
    const PetscReal limit = fillSizes_.MaxRadius() == fillSizes_.MinRadius() ? 0.3841 : 1.0;
    if (fillCount_ > 0 && fillCount_ * mean > limit * region)
      VofdemInputError(comm_, "option -dem_fill_count: %" PetscInt_FMT " particles fill %.3g of the fill region's volume; a random fill %s (-dem_fill_mode lattice packs denser)",
                       fillCount_, (double)(fillCount_ * mean / region), limit < 1 ? "of equal spheres stops at its jamming limit 0.3841" : "cannot pass 1");
    if (count > (double)PETSC_MAX_INT)
      VofdemInputError(comm_, "option -dem_fill_volume_fraction: %.3g of the region is about %.3g particles, more than this build's 32-bit indices allow (%d)", (double)fillFraction_, count, (int)PETSC_MAX_INT);
    // every rank places all of them (RandomFill.cpp: radii, order, centres and the hash's copy, 84 bytes each), then keeps its own
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(comm_, &size));
    PetscCall(CheckMemoryRequest(comm_, fillCount_ > 0 ? "-dem_fill_count" : "-dem_fill_volume_fraction", (PetscInt64)count, 84.0 + swarm_.BytesPerParticle() / size,
                                 "particles of a random fill (every rank places all of them)"));
  }
  req.count    = fillCount_;
  req.fraction = fillFraction_;
  req.attempts = fillAttempts_;
  req.seed     = seed;
  RandomFill(fillSizes_, req, &res);
  const PetscInt64 placed = (PetscInt64)res.radius.size();
  if (!res.complete) {
    if (fillCount_ > 0)
      VofdemInputError(comm_, "option -dem_fill_count: placed only %" PetscInt64_FMT " of %" PetscInt_FMT " particles (volume fraction %.4f) before one found no room in %" PetscInt_FMT " attempts (-dem_fill_attempts); random sequential addition of equal spheres stalls near 0.3 (jamming limit 0.38)",
                       placed, fillCount_, (double)res.fraction, fillAttempts_);
    VofdemInputError(comm_, "option -dem_fill_volume_fraction: reached only %.4f of %g (%" PetscInt64_FMT " particles) before one found no room in %" PetscInt_FMT " attempts (-dem_fill_attempts); random sequential addition of equal spheres stalls near 0.3 (jamming limit 0.38)",
                     (double)res.fraction, (double)fillFraction_, placed, fillAttempts_);
  }
  if (placed > PETSC_MAX_INT) VofdemInputError(comm_, "option -dem_fill_volume_fraction: %" PetscInt64_FMT " particles exceed this build's 32-bit indices", placed);
  PetscInt local = 0, first;
  for (PetscInt64 id = 0; id < placed; ++id) local += grid_->OwnsPoint(&res.x[3 * id]);
  ParticleArrays a;
  PetscCall(swarm_.AddLocal(local, &first));
  PetscCall(swarm_.GetArrays(&a));
  for (PetscInt64 id = 0, p = first; id < placed; ++id) {
    if (!grid_->OwnsPoint(&res.x[3 * id])) continue;
    StoreFilled(a, (PetscInt)p++, id, &res.x[3 * id], res.radius[id], seed);
  }
  PetscCall(swarm_.RestoreArrays(&a));
  PetscCall(swarm_.GlobalCount(&inserted_));
  PetscCheck(inserted_ == placed, comm_, PETSC_ERR_PLIB, "random fill placed %" PetscInt_FMT " particles instead of %" PetscInt64_FMT, inserted_, placed);
  PetscCall(swarm_.Migrate());
  fillReached_ = res.fraction;
  PetscFunctionReturn(0);
}

// Particles from a CSV file, after the lattice fill (ids continue from it). The header names the
// columns: x,y,z (m) are required; vx,vy,vz (m/s), wx,wy,wz (rad/s) and radius (m, default
// -dem_radius) are optional, in any order. Every rank reads the file and keeps the particles it
// owns, so the result does not depend on the rank count. A bad file is an input error naming file
// and line; so is a particle outside the box or cut deeply by a face.
// Whether the particles file's header names a clump column: then the swarm holds the clumps' rigid state
// (ParticleSwarm::SetRigidFields, before the swarm exists). A file that cannot be read says no here;
// ReadParticles reports it.
bool Dem::ParticlesFileNamesClumps() const {
  if (particlesFile_.empty()) return false;
  std::ifstream in(particlesFile_);
  std::string   header, c;
  if (!in || !std::getline(in, header)) return false;
  std::stringstream ss(header);
  while (std::getline(ss, c, ',')) {
    c.erase(0, c.find_first_not_of(" \t\r"));
    c.erase(c.find_last_not_of(" \t\r") + 1);
    if (c == "clump") return true;
  }
  return false;
}

PetscErrorCode Dem::ReadParticles() {
  static const char *const names[] = {"x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz", "radius", "type", "clump"};
  constexpr int            kCols   = 12;

  PetscFunctionBeginUser;
  if (particlesFile_.empty()) PetscFunctionReturn(0);
  std::ifstream in(particlesFile_);
  if (!in) VofdemInputError(comm_, "option -dem_particles_file: cannot open '%s'%s", particlesFile_.c_str(), RelativePathNote(particlesFile_).c_str());
  auto cells = [](const std::string &line) {
    std::vector<std::string> out;
    std::stringstream        ss(line);
    std::string              c;
    while (std::getline(ss, c, ',')) out.push_back(c);
    return out;
  };
  std::string      line;
  std::vector<int> column;  // column k holds quantity column[k] (index into names)
  std::getline(in, line);
  for (auto c : cells(line)) {
    c.erase(0, c.find_first_not_of(" \t\r"));
    c.erase(c.find_last_not_of(" \t\r") + 1);
    int q = -1;
    for (int i = 0; i < kCols; ++i)
      if (c == names[i]) q = i;
    if (q < 0) VofdemInputError(comm_, "%s:1: unknown column '%s' (known: x,y,z,vx,vy,vz,wx,wy,wz,radius,type,clump)", particlesFile_.c_str(), c.c_str());
    column.push_back(q);
  }
  for (int q = 0; q < 3; ++q)
    if (std::find(column.begin(), column.end(), q) == column.end())
      VofdemInputError(comm_, "%s:1: the header must name the columns x, y and z", particlesFile_.c_str());
  std::vector<std::array<PetscReal, kCols>> rows;
  std::vector<int>                          lines;  // the file's line of each row
  for (int lineNo = 2; std::getline(in, line); ++lineNo) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::array<PetscReal, kCols> r{};
    r[11] = -1;  // no clump
    r[9]            = radius_;
    const auto vals = cells(line);
    bool       ok   = vals.size() == column.size();
    for (size_t k = 0; ok && k < vals.size(); ++k) {
      char *end = nullptr;
      r[column[k]] = std::strtod(vals[k].c_str(), &end);
      ok = end != vals[k].c_str() && std::string(end).find_first_not_of(" \t\r") == std::string::npos;
    }
    if (!ok) VofdemInputError(comm_, "%s:%d: expected %d comma-separated numbers, as the header names", particlesFile_.c_str(), lineNo, (int)column.size());
    if (!(r[9] > 0)) VofdemInputError(comm_, "%s:%d: the radius must be positive", particlesFile_.c_str(), lineNo);
    if (!(r[11] >= -1 && r[11] == std::floor(r[11]))) VofdemInputError(comm_, "%s:%d: the clump must be an integer id >= 0 (or -1: none)", particlesFile_.c_str(), lineNo);
    if (!(r[10] >= 0 && r[10] < (PetscReal)types_.size() && r[10] == std::floor(r[10])))
      VofdemInputError(comm_, "%s:%d: the type must be an index into -dem_types, 0 to %d", particlesFile_.c_str(), lineNo, (int)types_.size() - 1);
    rows.push_back(r);
    lines.push_back(lineNo);
  }
  // The spheres of a clump (P10) start on one rank: the owner of its first sphere (lowest id).
  std::map<PetscReal, size_t> firstOfClump;
  for (size_t k = 0; k < rows.size(); ++k)
    if (rows[k][11] >= 0) firstOfClump.emplace(rows[k][11], k);
  // A settled particle rests with a small overlap on a wall: accept up to 5 % of the radius. Along a periodic
  // direction there is no wall: a centre up to a radius outside the box (a particle that crossed the face since
  // the run that wrote the file last wrapped it) is wrapped in; a clump's other spheres are placed at their
  // image nearest its first sphere, so that the clump is one body (they may stick out of the box, as in a run).
  for (size_t k = 0; k < rows.size(); ++k) {
    auto          &r    = rows[k];
    const bool     lead = r[11] < 0 || firstOfClump[r[11]] == k;
    for (int d = 0; d < 3; ++d) {
      const PetscReal lo = grid_->Lower()[d], hi = grid_->Upper()[d], L = hi - lo;
      bool            ok = true;
      if (!grid_->Periodic(d)) ok = r[d] - 0.95 * r[9] >= lo && r[d] + 0.95 * r[9] <= hi;
      else if (lead) {
        ok = r[d] >= lo - r[9] && r[d] <= hi + r[9];
        if (r[d] < lo) r[d] += L;
        else if (r[d] > hi) r[d] -= L;
      }
      if (!ok && grid_->Periodic(d))
        VofdemInputError(comm_, "%s:%d: the particle at (%g, %g, %g) m with radius %g m lies more than its radius outside the periodic box along %c",
                         particlesFile_.c_str(), lines[k], (double)r[0], (double)r[1], (double)r[2], (double)r[9], "xyz"[d]);
      if (!ok)
        VofdemInputError(comm_, "%s:%d: the particle at (%g, %g, %g) m with radius %g m is not inside the box (or overlaps a wall by more than 5 %% of its radius)",
                         particlesFile_.c_str(), lines[k], (double)r[0], (double)r[1], (double)r[2], (double)r[9]);
    }
  }
  for (size_t k = 0; k < rows.size(); ++k) {
    if (rows[k][11] < 0 || firstOfClump[rows[k][11]] == k) continue;
    const auto &lead = rows[firstOfClump[rows[k][11]]];
    for (int d = 0; d < 3; ++d)
      if (grid_->Periodic(d)) {
        const PetscReal L = grid_->Upper()[d] - grid_->Lower()[d];
        rows[k][d] -= L * std::round((rows[k][d] - lead[d]) / L);
      }
  }
  PetscInt first, local = 0, start;
  auto owned = [&](const std::array<PetscReal, kCols> &r) { return grid_->OwnsPoint(r[11] >= 0 ? rows[firstOfClump[r[11]]].data() : r.data()); };
  for (const auto &r : rows) local += owned(r);
  PetscCall(swarm_.GlobalCount(&start));
  PetscCall(swarm_.AddLocal(local, &first));
  ParticleArrays a;
  PetscCall(swarm_.GetArrays(&a));
  for (size_t k = 0, p = first; k < rows.size(); ++k) {
    const auto &r = rows[k];
    if (!owned(r)) continue;
    for (int d = 0; d < 3; ++d) {
      a.x[3 * p + d]     = r[d];
      a.v[3 * p + d]     = r[3 + d];
      a.omega[3 * p + d] = r[6 + d];
      a.f[3 * p + d] = a.torque[3 * p + d] = 0;
    }
    a.radius[p] = r[9];
    a.type[p]   = (PetscInt)r[10];
    a.mass[p]   = types_[a.type[p]].density * 4.0 / 3.0 * PETSC_PI * r[9] * r[9] * r[9];
    a.id[p]     = start + (PetscInt64)k;
    a.clump[p]  = (PetscInt64)r[11];
    ++p;
  }
  PetscCall(swarm_.RestoreArrays(&a));
  if (!historyFile_.empty()) {
    std::vector<char> ownedRow(rows.size());
    for (size_t k = 0; k < rows.size(); ++k) ownedRow[k] = owned(rows[k]);
    PetscCall(ReadContactHistory(rows.size(), start, ownedRow));
  }
  PetscCall(swarm_.Migrate());
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::SaveParticles(const std::string &path) const {
  ParticleArrays            a;
  PetscMPIInt               rank, size;
  std::vector<PetscReal>    mine;
  std::vector<PetscReal>    all;
  std::vector<PetscMPIInt>  counts, displs;
  constexpr int             W = 13;  // id (as a real: exact below 2^53) + 9 values + radius + type + clump

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  PetscCall(swarm_.GetArrays(&a));
  mine.resize((size_t)W * a.n);
  for (PetscInt p = 0; p < a.n; ++p) {
    mine[W * p] = (PetscReal)a.id[p];
    for (int d = 0; d < 3; ++d) mine[W * p + 1 + d] = a.x[3 * p + d], mine[W * p + 4 + d] = a.v[3 * p + d], mine[W * p + 7 + d] = a.omega[3 * p + d];
    // Along a periodic direction a particle may have crossed the face since the last wrap (Dem::Rebuild): the
    // file holds its image in the box, as the run would after the next wrap (ReadParticles joins clumps again).
    for (int d = 0; d < 3; ++d)
      if (grid_->Periodic(d)) {
        const PetscReal lo = grid_->Lower()[d], hi = grid_->Upper()[d];
        PetscReal      &c  = mine[W * p + 1 + d];
        if (c < lo) c += hi - lo;
        else if (c > hi) c -= hi - lo;
      }
    mine[W * p + 10] = a.radius[p];
    mine[W * p + 11] = (PetscReal)a.type[p];
    mine[W * p + 12] = (PetscReal)a.clump[p];
  }
  PetscCall(swarm_.RestoreArrays(&a));
  PetscMPIInt n = (PetscMPIInt)mine.size();
  counts.resize(size), displs.resize(size);
  PetscCallMPI(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm_));
  PetscMPIInt total = 0;
  if (rank == 0)
    for (int q = 0; q < size; ++q) displs[q] = total, total += counts[q];
  all.resize(total);
  PetscCallMPI(MPI_Gatherv(mine.data(), n, MPIU_REAL, all.data(), counts.data(), displs.data(), MPIU_REAL, 0, comm_));
  std::string text;
  if (rank == 0) {
    std::vector<std::array<PetscReal, W>> rows(total / W);
    for (size_t r = 0; r < rows.size(); ++r) std::copy(&all[W * r], &all[W * r] + W, rows[r].begin());
    std::sort(rows.begin(), rows.end(), [](const auto &x, const auto &y) { return x[0] < y[0]; });
    text = "x,y,z,vx,vy,vz,wx,wy,wz,radius,type,clump\n";
    char line[512];
    for (const auto &r : rows) {
      std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%lld\n", r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8], r[9], r[10], (int)r[11], (long long)r[12]);
      text += line;
    }
  }
  PetscCall(WriteTextFile(comm_, path, text, "option -dem_save_particles"));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
