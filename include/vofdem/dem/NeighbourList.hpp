// Verlet list of the particle pairs closer than r_i + r_j + skin, built with linked cells of at
// least 2 R_max + skin and reused until a particle has moved half the skin. The per-pair cut-off
// keeps small-small pairs of a polydisperse powder from being listed at the large spheres' range. Indices below nLocal are local particles, the
// others ghost (index - nLocal); at least one of each pair is local. Each pair is stored with the
// lower global id first, the orientation its springs are seen from, so that a pair two ranks both
// evaluate gives the same arithmetic there. Each pair carries its springs (P3, P5), so the contact
// loop reads history from an array, not a hash; across rebuilds the springs of touching pairs are
// carried by the particles' global ids (ContactHistory).
#pragma once

#include "vofdem/base/Random.hpp"

#include <petscsys.h>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace vofdem {

// History values per contact: the tangential spring (m) and the rolling spring (N m), x,y,z each;
// then the JKR contact radius (m) and whether the JKR bond holds (1) (P6).
inline constexpr int kSpringWidth = 8;
inline constexpr int kJkrRadius = 6, kJkrBonded = 7;

// Springs of touching pairs keyed by the pair of global ids (lower id first), stored as seen from
// the lower id; a wall contact is keyed by (particle id, -1 - wall). Lives only while lists are
// rebuilt and particles migrate.
struct PairKey {
  PetscInt64 lo, hi;
  bool operator==(const PairKey &o) const { return lo == o.lo && hi == o.hi; }
  bool IsWall() const { return hi < 0; }
  static PairKey Wall(PetscInt64 id, int wall) { return {id, -1 - (PetscInt64)wall}; }
};
struct PairKeyHash {
  size_t operator()(const PairKey &k) const { return (size_t)random::Mix(random::Mix((std::uint64_t)k.lo) ^ (std::uint64_t)k.hi); }
};
using ContactHistory = std::unordered_map<PairKey, std::array<PetscReal, kSpringWidth>, PairKeyHash>;

// What a pair needs besides geometry: the particles' types (for the pair's material) and clump ids
// (spheres of one rigid clump never touch each other, P10). Local then ghost arrays.
struct PairTags {
  const PetscInt   *typeLocal = nullptr, *typeGhost = nullptr;
  const PetscInt64 *clumpLocal = nullptr, *clumpGhost = nullptr;
  PetscInt          typeCount = 1;
};

class NeighbourList {
public:
  // Builds the pairs among nLocal local and nGhost ghost particles with r_i + r_j + skin, binning
  // in the box [lo - cutoff, hi + cutoff] with cutoff = 2 R_max + skin; radius and mass (local then
  // ghost) also give each pair its R*, m*.
  PetscErrorCode Build(PetscInt nLocal, const PetscReal *xLocal, const PetscReal *rLocal, const PetscReal *mLocal, const PetscInt64 *idLocal,
                       PetscInt nGhost, const PetscReal *xGhost, const PetscReal *rGhost, const PetscReal *mGhost, const PetscInt64 *idGhost,
                       PetscReal cutoff, PetscReal skin, const PetscReal lo[3], const PetscReal hi[3], const PairTags &tags = {});

  size_t Size() const { return first.size(); }
  std::vector<PetscInt>  first, second;  // the pairs
  std::vector<PetscReal> spring;         // kSpringWidth per pair, as seen from the lower id
  std::vector<char>      touching;       // the pair touched at the last evaluation (its springs may be non-zero)
  std::vector<PetscReal> rstar, sqrtMstar;  // R* and sqrt(m*) of the pair: fixed while the list lives
  std::vector<PetscInt>  material;          // index of the pair of types into the MaterialTable

private:
  std::vector<PetscInt> cellStart_, cellOf_, order_;
  std::vector<std::array<PetscReal, 4>> packed_;  // x, y, z, r in order_'s order
};

// Candidate wall contacts, built with the neighbour list: every local particle within its radius
// plus the skin of a wall, so the contact loop visits those only. Each entry carries its springs.
struct WallList {
  std::vector<PetscInt>  particle;
  std::vector<int>       wall;
  std::vector<char>      touching;
  std::vector<PetscReal> spring;  // kSpringWidth per entry
  size_t                 Size() const { return particle.size(); }
  void                   Clear() { particle.clear(), wall.clear(), touching.clear(), spring.clear(); }
  void                   Add(PetscInt p, int w) {
    particle.push_back(p), wall.push_back(w), touching.push_back(0);
    spring.insert(spring.end(), kSpringWidth, 0);
  }
};

}  // namespace vofdem

