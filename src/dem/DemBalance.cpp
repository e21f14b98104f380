// Load balancing of DEM-only scenes (-dem_balance histogram): at a neighbour-list rebuild, when the
// largest load of a rank exceeds -dem_balance_threshold times the mean, the grid's ownership ranges
// are recomputed from histograms of the load per cell layer, one per direction that is split over
// several ranks (a DMDA's ranges are a tensor product: each direction's cuts equalise the loads of
// its slabs). A particle's load is 1 plus -dem_balance_contact_weight times its contacts at the last
// force evaluation: a settling pile's touching particles cost several times a falling one's (D7's
// tungsten pile on 2 ranks, by counts alone: 6.0 s of forces on the pile's rank, 0.5 s on the other). The grid then rebuilds its DMDAs, the swarm takes the new
// vertex DMDA, the halo the new rank boxes, and every particle goes straight to its new owner.
// Coupled scenes must not do this: there the fluid cells decide the decomposition (docs/architecture.md).
#include "vofdem/dem/Dem.hpp"
#include "vofdem/dem/HistoryExchange.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"

// DMSwarmSetMigrateType is not public in PETSc 3.18: the swarm's migration type is switched to
// "basic" (send each point to the rank in its DMSwarm_rank field) through the private header.
#include <petsc/private/dmswarmimpl.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

namespace vofdem {

PetscErrorCode Dem::SetBalanceFromOptions(PetscOptionItems *PetscOptionsObject) {
  OptionReader opt(PetscOptionsObject);

  PetscFunctionBeginUser;
  static const std::vector<std::string> kinds  = {"none", "histogram"};
  std::vector<std::string>              chosen = {"none"};
  PetscCall(opt.NameList("-balance", "Load balancing of DEM-only scenes: none, histogram (ownership ranges from particle counts per cell layer)", kinds, &chosen));
  if (chosen.size() != 1) VofdemInputError(comm_, "option -dem_balance: give one method (none or histogram)");
  balance_ = (PetscBool)(chosen[0] == "histogram");
  PetscCall(opt.Real("-balance_threshold", "Repartition when the largest particle count of a rank exceeds this times the mean (checked at rebuilds)", "-",
                     &balanceThreshold_, RealRange::Closed(1, PETSC_MAX_REAL)));
  PetscCall(opt.Real("-balance_contact_weight", "Load of a contact in particles' (a particle's load is 1 + this x its contacts)", "-", &balanceContactWeight_, RealRange::NonNegative()));
  PetscCall(opt.Bool("-balance_monitor", "Print the particles per rank before and after each repartition", &balanceMonitor_));
  PetscFunctionReturn(0);
}

namespace {

// Cuts n cell layers with loads h into m slabs of at least one layer whose loads are as even as the
// layers allow: slab r ends at the layer boundary closest to (r+1)/m of the total.
std::vector<PetscInt> SplitHistogram(const std::vector<PetscReal> &h, PetscInt m) {
  const PetscInt         n = (PetscInt)h.size();
  std::vector<PetscReal> cum(n + 1, 0);
  for (PetscInt i = 0; i < n; ++i) cum[i + 1] = cum[i] + h[i];
  std::vector<PetscInt> slabs(m);
  PetscInt              start = 0;
  for (PetscInt r = 0; r + 1 < m; ++r) {
    const double target = (double)cum[n] * (r + 1) / m;
    PetscInt     best = start + 1;
    for (PetscInt e = start + 1; e <= n - (m - 1 - r); ++e)
      if (std::abs((double)cum[e] - target) < std::abs((double)cum[best] - target)) best = e;
    slabs[r] = best - start;
    start    = best;
  }
  slabs[m - 1] = n - start;
  return slabs;
}

// Largest / mean load per rank, and the particle counts of all ranks.
PetscErrorCode Imbalance(MPI_Comm comm, PetscInt n, PetscReal load, PetscReal *ratio, std::vector<PetscInt> *counts) {
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  counts->resize(size);
  PetscCallMPI(MPI_Allgather(&n, 1, MPIU_INT, counts->data(), 1, MPIU_INT, comm));
  PetscReal most, total;
  PetscCallMPI(MPI_Allreduce(&load, &most, 1, MPIU_REAL, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(&load, &total, 1, MPIU_REAL, MPI_SUM, comm));
  *ratio = total > 0 ? most * size / total : 1;
  PetscFunctionReturn(0);
}

// The cell layer along d of coordinate x, clamped to the box (a centre may be just outside it).
PetscInt Layer(const Grid &g, PetscReal x, int d) {
  return std::min(g.Cells()[d] - 1, std::max<PetscInt>(0, (PetscInt)((x - g.Lower()[d]) / g.Spacing()[d])));
}

std::string Describe(const std::vector<PetscInt> &counts) {
  if (counts.size() > 16) return "";
  std::string s = " (";
  for (size_t q = 0; q < counts.size(); ++q) s += (q ? ", " : "") + std::to_string(counts[q]);
  return s + ")";
}

}  // namespace

// Contacts of each of the n local particles at the last force evaluation: touching pairs (JKR bonds
// included) and box faces.
void Dem::CountContacts(PetscInt n, std::vector<PetscInt> *c) const {
  c->assign(n, 0);
  for (size_t k = 0; k < list_.Size(); ++k)
    if (list_.touching[k]) {
      if (list_.first[k] < n) ++(*c)[list_.first[k]];
      if (list_.second[k] < n) ++(*c)[list_.second[k]];
    }
  for (size_t k = 0; k < walls_.Size(); ++k)
    if (walls_.touching[k] && walls_.particle[k] < n) ++(*c)[walls_.particle[k]];
}

PetscErrorCode Dem::BalanceLoad(PetscReal *load) const {
  PetscInt              n;
  std::vector<PetscInt> c;

  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetLocalSize(swarm_.Dm(), &n));
  CountContacts(n, &c);
  *load = n;
  for (PetscInt k : c) *load += balanceContactWeight_ * k;
  PetscFunctionReturn(0);
}

// At the start of Rebuild, while the list's indices are still this rank's particles': each local
// particle's contacts at the last force evaluation (pairs and box faces) as loads per cell layer of
// every direction, and their sum on this rank. Balance() adds them to the particle counts.
void Dem::BalanceContactLoads(const ParticleArrays &a) {
  const PetscInt *nc = grid_->Cells();
  balanceLoads_.assign(nc[0] + nc[1] + nc[2], 0);
  balanceLocalContacts_ = 0;
  if (!balance_ || balanceContactWeight_ == 0) return;
  CountContacts(a.n, &balanceContacts_);
  for (PetscInt p = 0; p < a.n; ++p) {
    if (!balanceContacts_[p]) continue;
    const PetscReal w = balanceContactWeight_ * balanceContacts_[p];
    balanceLocalContacts_ += w;
    for (int d = 0, off = 0; d < 3; off += nc[d], ++d) balanceLoads_[off + Layer(*grid_, a.x[3 * p + d], d)] += w;
  }
}

PetscErrorCode Dem::Balance(PetscBool *repartitioned) {
  PetscMPIInt           size;
  ParticleArrays        a;
  PetscReal             before, after;
  std::vector<PetscInt> countsBefore, countsAfter;

  PetscFunctionBeginUser;
  *repartitioned = PETSC_FALSE;
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  if (!balance_ || size == 1) PetscFunctionReturn(0);
  PetscInt n;
  PetscCall(DMSwarmGetLocalSize(swarm_.Dm(), &n));
  PetscCall(Imbalance(comm_, n, n + balanceLocalContacts_, &before, &countsBefore));
  if (before <= balanceThreshold_) PetscFunctionReturn(0);

  // Histograms of the cell layers along every split direction, summed over ranks.
  PetscInt        m[3];
  const PetscInt *l[3];
  PetscCall(DMDAGetInfo(grid_->CellDM(), nullptr, nullptr, nullptr, nullptr, &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(grid_->CellDM(), &l[0], &l[1], &l[2]));
  const PetscInt *nc = grid_->Cells();
  auto layer = [&](PetscReal x, int d) { return Layer(*grid_, x, d); };
  std::vector<PetscReal> hist(balanceLoads_);
  hist.resize(nc[0] + nc[1] + nc[2], 0);
  std::vector<PetscReal> global(hist.size());
  PetscCall(swarm_.GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p)
    for (int d = 0, off = 0; d < 3; off += nc[d], ++d)
      if (m[d] > 1) hist[off + layer(a.x[3 * p + d], d)] += 1;
  PetscCall(swarm_.RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(hist.data(), global.data(), (int)hist.size(), MPIU_REAL, MPI_SUM, comm_));
  // A direction is cut anew only if that evens its slabs' loads (layers are whole cells, so a bed a
  // few cells high may allow no better cut than the present one) by at least 2 %, so that a lattice
  // plane crossing a layer boundary does not make the cut flip back and forth.
  auto unevenness = [&](const PetscInt *counts, PetscInt ranks, PetscInt off) {
    PetscReal most = 0, total = 0;
    for (PetscInt r = 0, c = 0; r < ranks; c += counts[r], ++r) {
      PetscReal sum = 0;
      for (PetscInt i = c; i < c + counts[r]; ++i) sum += global[off + i];
      most = std::max(most, sum), total += sum;
    }
    return total ? (PetscReal)most * ranks / total : 1;
  };
  std::vector<PetscInt> slabs[3];
  bool                  changed = false;
  for (int d = 0, off = 0; d < 3; off += nc[d], ++d) {
    slabs[d].assign(l[d], l[d] + m[d]);
    if (m[d] == 1) continue;
    const auto cut = SplitHistogram(std::vector<PetscReal>(global.begin() + off, global.begin() + off + nc[d]), m[d]);
    if (unevenness(cut.data(), m[d], off) < unevenness(l[d], m[d], off) * (1 - 0.02)) slabs[d] = cut, changed = true;
  }
  if (!changed) PetscFunctionReturn(0);  // the layers allow no better cut
  PetscReal predicted = 1;  // the new slabs' largest / mean load, the worst split direction
  for (int d = 0, off = 0; d < 3; off += nc[d], ++d)
    if (m[d] > 1) predicted = std::max(predicted, unevenness(slabs[d].data(), m[d], off));

  PetscCall(grid_->Repartition(slabs));
  PetscCall(DMSwarmSetCellDM(swarm_.Dm(), grid_->VertexDM()));
  PetscCall(halo_.SetUp(*grid_));
  // Every particle straight to its new owner (rank = i + m0 (j + m1 k), as DMDA numbers them):
  // DMSwarmMigrate of the PIC type reaches only neighbouring ranks.
  {
    PetscInt *rank;
    PetscCall(swarm_.GetArrays(&a));
    PetscCall(DMSwarmGetField(swarm_.Dm(), DMSwarmField_rank, nullptr, nullptr, (void **)&rank));
    for (PetscInt p = 0; p < a.n; ++p) {
      PetscInt r[3];
      for (int d = 0; d < 3; ++d) {
        const PetscInt c = layer(a.x[3 * p + d], d);
        PetscInt       q = 0, end = slabs[d][0];
        while (c >= end) end += slabs[d][++q];
        r[d] = q;
      }
      rank[p] = r[0] + m[0] * (r[1] + m[1] * r[2]);
    }
    {  // a rigid clump goes whole, to the owner of its lowest-id member (P10; see ParticleSwarm::Migrate)
      std::unordered_map<PetscInt64, PetscInt> lead;
      for (PetscInt p = 0; p < a.n; ++p) {
        if (a.clump[p] < 0) continue;
        auto it = lead.find(a.clump[p]);
        if (it == lead.end()) lead.emplace(a.clump[p], p);
        else if (a.id[p] < a.id[it->second]) it->second = p;
      }
      for (PetscInt p = 0; p < a.n && !lead.empty(); ++p)
        if (a.clump[p] >= 0) rank[p] = rank[lead[a.clump[p]]];
    }
    PetscCall(DMSwarmRestoreField(swarm_.Dm(), DMSwarmField_rank, nullptr, nullptr, (void **)&rank));
    PetscCall(swarm_.RestoreArrays(&a));
    DM_Swarm                *impl = (DM_Swarm *)swarm_.Dm()->data;
    const DMSwarmMigrateType type = impl->migrate_type;
    impl->migrate_type            = DMSWARM_MIGRATE_BASIC;
    PetscInt total0, total1;
    PetscCall(DMSwarmGetSize(swarm_.Dm(), &total0));
    PetscCall(DMSwarmMigrate(swarm_.Dm(), PETSC_TRUE));
    PetscCall(swarm_.FieldsMoved());
    impl->migrate_type = type;
    PetscCall(DMSwarmGetSize(swarm_.Dm(), &total1));
    PetscCheck(total0 == total1, comm_, PETSC_ERR_PLIB, "repartition lost %" PetscInt_FMT " of %" PetscInt_FMT " particles", total0 - total1, total0);
  }
  PetscCall(DMSwarmGetLocalSize(swarm_.Dm(), &n));
  PetscCall(Imbalance(comm_, n, n, &after, &countsAfter));
  ++repartitions_;
  if (balanceMonitor_)
    PetscCall(PetscPrintf(comm_,
                          "dem: repartition %" PetscInt_FMT " at rebuild %" PetscInt_FMT ": load (particles + %g x contacts) largest / mean %.3f -> %.3f (by layers); particles per rank%s -> %s\n",
                          repartitions_, rebuilds_, (double)balanceContactWeight_, (double)before, (double)predicted, Describe(countsBefore).c_str(), Describe(countsAfter).c_str()));
  *repartitioned = PETSC_TRUE;
  PetscFunctionReturn(0);
}

// After a repartition a particle may have moved to a rank that is not among its old rank's halo
// ranks, so ExchangeSprings may miss its springs: every rank gets all of them, and all intact bonds
// (rare, and the maps are small: touching pairs and bonds only; HistoryExchange.hpp).
PetscErrorCode Dem::GatherSprings() {
  PetscFunctionBeginUser;
  PetscCall(GatherHistory<kSpringWidth>(comm_, &springs_));
  if (bonds_.On()) PetscCall(GatherHistory<bond::kWidth>(comm_, &bonds_.carried));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
