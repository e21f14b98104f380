#include "vofdem/dem/MortonOrder.hpp"

#include "vofdem/dem/ParticleSwarm.hpp"

#include <algorithm>

namespace vofdem {

namespace {

// The low 21 bits of v spread to every third bit (bit k -> bit 3k).
std::uint64_t Spread3(std::uint64_t v) {
  v &= 0x1fffffULL;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

}  // namespace

std::uint64_t MortonKey(const PetscReal x[3], const PetscReal lo[3], const PetscReal inv[3]) {
  constexpr PetscReal cells = 1 << 21;
  std::uint64_t       c[3];
  for (int d = 0; d < 3; ++d) {
    const PetscReal s = (x[d] - lo[d]) * inv[d] * cells;
    c[d]              = s <= 0 ? 0 : s >= cells - 1 ? (std::uint64_t)(cells - 1) : (std::uint64_t)s;
  }
  return Spread3(c[0]) | Spread3(c[1]) << 1 | Spread3(c[2]) << 2;
}

PetscErrorCode MortonOrder::SetFromOptions(OptionReader &opt) {
  PetscFunctionBeginUser;
  PetscCall(opt.Int("-sort_every", "Reorder the local particles along a Morton (Z-order) curve every this many neighbour-list rebuilds, for memory locality (0: never)",
                    &every_, 0));
  if (!event_) PetscCall(PetscLogEventRegister("DEMMortonSort", DM_CLASSID, &event_));
  PetscFunctionReturn(0);
}

PetscErrorCode MortonOrder::Apply(PetscInt rebuild, DM swarm, const Grid &grid) {
  PetscFunctionBeginUser;
  if (!Due(rebuild)) PetscFunctionReturn(0);
  PetscCall(PetscLogEventBegin(event_, 0, 0, 0, 0));
  PetscCall(Sort(swarm, grid.Lower(), grid.Upper()));
  PetscCall(PetscLogEventEnd(event_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode MortonOrder::Sort(DM swarm, const PetscReal lo[3], const PetscReal hi[3]) {
  PetscInt         n;
  PetscReal       *x;
  PetscInt64      *id;
  PetscReal        inv[3];

  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetLocalSize(swarm, &n));
  if (n < 2) PetscFunctionReturn(0);
  for (int d = 0; d < 3; ++d) inv[d] = hi[d] > lo[d] ? 1 / (hi[d] - lo[d]) : 0;
  entries_.resize(n);
  PetscCall(DMSwarmGetField(swarm, field::position, nullptr, nullptr, (void **)&x));
  PetscCall(DMSwarmGetField(swarm, field::id, nullptr, nullptr, (void **)&id));
  for (PetscInt p = 0; p < n; ++p) entries_[p] = {MortonKey(&x[3 * p], lo, inv), id[p], p};
  PetscCall(DMSwarmRestoreField(swarm, field::id, nullptr, nullptr, (void **)&id));
  PetscCall(DMSwarmRestoreField(swarm, field::position, nullptr, nullptr, (void **)&x));
  // Ids are unique, so (key, id) is a total order: the result does not depend on the incoming order.
  std::sort(entries_.begin(), entries_.end(), [](const Entry &a, const Entry &b) { return a.key != b.key ? a.key < b.key : a.id < b.id; });
  from_.resize(n);
  bool moved = false;
  for (PetscInt p = 0; p < n; ++p) from_[p] = entries_[p].index, moved = moved || from_[p] != p;
  if (!moved) PetscFunctionReturn(0);
  // Slot p takes the point now at from_[p]. Each cycle of the permutation is walked once with one
  // spare point (appended at index n, removed afterwards) holding the cycle's first point:
  // n + cycles copies of whole points, every registered field at once.
  PetscCall(DMSwarmAddNPoints(swarm, 1));
  const PetscInt spare = n;
  done_.assign(n, 0);
  for (PetscInt s = 0; s < n; ++s) {
    if (done_[s]) continue;
    done_[s] = 1;
    if (from_[s] == s) continue;
    PetscCall(DMSwarmCopyPoint(swarm, s, spare));
    PetscInt j = s;
    while (from_[j] != s) {
      PetscCall(DMSwarmCopyPoint(swarm, from_[j], j));
      j        = from_[j];
      done_[j] = 1;
    }
    PetscCall(DMSwarmCopyPoint(swarm, spare, j));
  }
  PetscCall(DMSwarmRemovePoint(swarm));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
