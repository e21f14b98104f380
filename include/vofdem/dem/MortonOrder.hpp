// Morton (Z-order) reordering of a rank's local particles (-dem_sort_every), for locality: the
// neighbour list is built in local-index order, so after a sort the particles of one pair, and of
// consecutive pairs, sit close together in memory and the pair loop's reads of positions and
// velocities and writes of forces hit cache lines already loaded. Without it the order is the
// insertion order, scrambled further by every migration (DMSwarmMigrate appends arrivals and fills
// holes from the end).
//
// The sort runs inside a neighbour-list rebuild, after migration and before the ghosts and the new
// list are built, so no local index is held anywhere at that moment; springs are carried by id
// pairs across the rebuild and survive. Every swarm field moves (ours and DMSwarm's own: pid, rank,
// cellid) because points are moved with DMSwarmCopyPoint. The key is taken over the whole box, not
// the rank's, so the order depends only on positions and ids (ties by id): any rank's particles are
// in the order they have on one rank, and a pair's contributions to a particle's force are summed
// in the same order on every decomposition, as without sorting (the list is built in local order).
// A bitwise restart on the same rank count stays bitwise (the rebuild counter is archived).
// Sorting changes the summation order against an unsorted run: results agree to round-off.
#pragma once

#include "vofdem/base/Options.hpp"
#include "vofdem/grid/Grid.hpp"

#include <petscdmswarm.h>

#include <cstdint>
#include <vector>

namespace vofdem {

// 63-bit Morton key of a point quantised on a 2^21 grid per direction over [lo, lo + 1/inv):
// bit 3k of the key is bit k of the x cell, 3k+1 of y, 3k+2 of z. Points outside are clamped.
std::uint64_t MortonKey(const PetscReal x[3], const PetscReal lo[3], const PetscReal inv[3]);

class MortonOrder {
public:
  // -dem_sort_every (inside the caller's PetscOptionsBegin block for the "dem_" prefix).
  PetscErrorCode SetFromOptions(OptionReader &opt);
  PetscInt       Every() const { return every_; }
  // Whether the rebuild numbered `rebuild` (0 = the first) sorts.
  bool Due(PetscInt rebuild) const { return every_ > 0 && rebuild % every_ == 0; }
  // Sorts the swarm's local particles by the Morton key of their position in the box [lo, hi]
  // (ties by the "id" field). Not collective.
  PetscErrorCode Sort(DM swarm, const PetscReal lo[3], const PetscReal hi[3]);
  // At the rebuild numbered `rebuild`: sorts over the whole box of `grid` when Due(rebuild).
  PetscErrorCode Apply(PetscInt rebuild, DM swarm, const Grid &grid);

private:
  // Default 10, from measurements on the dem-vs-liggghts bed (1 rank, perf cycles): one sort took
  // 16-20 ms for 23k particles (about two steps). From a shuffled file order it cut the run's cycles
  // by 15 % (cache misses -75 %; 31 % on a 13.5k bed); from the file's id order, which is the fill
  // lattice's and already local, the change was within the machine's noise (+-5 %). Every 10th
  // rebuild keeps the cost below 2 % where rebuilds come every 10 steps, and the order decays slowly
  // (between sorts particles move at most 5 skins, and migration only appends arrivals).
  PetscInt      every_ = 10;
  PetscLogEvent event_ = 0;  // -log_view: DEMMortonSort
  struct Entry {
    std::uint64_t key;
    PetscInt64    id;
    PetscInt      index;
  };
  std::vector<Entry>    entries_;  // kept between sorts: no allocation once sized
  std::vector<PetscInt> from_;
  std::vector<char>     done_;
};

}  // namespace vofdem
