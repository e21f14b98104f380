#include "vofdem/dem/RandomFill.hpp"

#include "vofdem/core/Random.hpp"
#include "vofdem/dem/SphereHash.hpp"

#include <cmath>

namespace vofdem {

void RandomFill(const SizeDistribution &sizes, const RandomFillRequest &req, RandomFillResult *out) {
  PetscReal volume = 1;
  for (int d = 0; d < 3; ++d) volume *= req.upper[d] - req.lower[d];
  const PetscReal target = req.fraction * volume;  // solid volume to reach when count == 0
  // Expected number of particles: sizes the hash (about one particle per cell) and the arrays.
  const double expected = req.count > 0 ? req.count : target / (4.0 / 3.0 * PETSC_PI * sizes.MeanCube()) + 1;
  SphereHash   hash;
  hash.Reset(req.lower, req.upper, 2 * sizes.MaxRadius(), expected);
  hash.Reserve((size_t)(1.1 * expected) + 16);
  out->x.clear(), out->radius.clear();
  out->x.reserve(3 * ((size_t)(1.1 * expected) + 16)), out->radius.reserve((size_t)(1.1 * expected) + 16);
  out->candidates = 0;
  out->complete   = false;
  PetscReal solid = 0;
  for (PetscInt64 k = 0;; ++k) {
    if (req.count > 0 ? k >= req.count : solid >= target) {
      out->complete = true;
      break;
    }
    // The same stream as the lattice fill for the radius; candidate centres on streams 16, 17, ...
    const PetscReal r = sizes.Radius(random::Uniform(req.seed, (std::uint64_t)k, 6));
    PetscReal       x[3];
    bool            placed = false;
    bool            fits   = true;
    for (int d = 0; d < 3; ++d) fits = fits && req.upper[d] - req.lower[d] >= 2 * r;
    for (PetscInt t = 0; fits && t < req.attempts && !placed; ++t) {
      ++out->candidates;
      for (int d = 0; d < 3; ++d)
        x[d] = req.lower[d] + r + (req.upper[d] - req.lower[d] - 2 * r) * random::Uniform(req.seed, (std::uint64_t)k, 16 + 3 * (std::uint64_t)t + d);
      placed = !hash.Overlaps(x, r);
    }
    if (!placed) break;
    hash.Add(x, r);
    out->x.insert(out->x.end(), x, x + 3);
    out->radius.push_back(r);
    solid += 4.0 / 3.0 * PETSC_PI * r * r * r;
  }
  out->fraction = solid / volume;
}

}  // namespace vofdem
