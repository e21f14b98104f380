#include "vofdem/dem/RandomFill.hpp"

#include "vofdem/base/Random.hpp"
#include "vofdem/dem/SphereHash.hpp"

#include <algorithm>
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
  for (int d = 0; d < 3; ++d)
    if (req.periodic[d]) hash.SetPeriodic(d, req.lower[d], req.upper[d]);
  out->x.clear(), out->radius.clear();
  out->candidates = 0;
  out->complete   = false;
  // All radii first (particle k's from key k), until the count or the solid volume is reached;
  // then the largest are placed first (ties by id): a large sphere late in a random sequence
  // rarely finds a hole, which would stall a polydisperse fill early.
  std::vector<PetscReal>  radii;
  std::vector<PetscInt64> order;
  PetscReal               solid = 0;
  for (PetscInt64 k = 0; req.count > 0 ? k < req.count : solid < target; ++k) {
    const PetscReal r = sizes.Radius(random::Uniform(req.seed, (std::uint64_t)k, 6));  // the lattice fill's stream
    radii.push_back(r);
    order.push_back(k);
    solid += 4.0 / 3.0 * PETSC_PI * r * r * r;
  }
  std::stable_sort(order.begin(), order.end(), [&](PetscInt64 i, PetscInt64 j) { return radii[i] > radii[j]; });
  out->x.assign(3 * radii.size(), 0);
  out->radius = radii;
  solid       = 0;
  size_t placedCount = 0;
  for (PetscInt64 k : order) {
    const PetscReal r = radii[k];
    PetscReal       x[3];
    bool            placed = false, fits = true;
    for (int d = 0; d < 3; ++d) fits = fits && req.upper[d] - req.lower[d] >= 2 * r;
    for (PetscInt t = 0; fits && t < req.attempts && !placed; ++t) {  // candidate centres on streams 16, 17, ...
      ++out->candidates;
      for (int d = 0; d < 3; ++d) {
        const PetscReal u = random::Uniform(req.seed, (std::uint64_t)k, 16 + 3 * (std::uint64_t)t + d);
        x[d]              = req.periodic[d] ? req.lower[d] + (req.upper[d] - req.lower[d]) * u : req.lower[d] + r + (req.upper[d] - req.lower[d] - 2 * r) * u;
      }
      placed = !hash.Overlaps(x, r);
    }
    if (!placed) break;
    hash.Add(x, r);
    std::copy(x, x + 3, &out->x[3 * k]);
    solid += 4.0 / 3.0 * PETSC_PI * r * r * r;
    ++placedCount;
  }
  out->complete = placedCount == radii.size();
  if (!out->complete) {  // report what was reached; the particles are incomplete and not to be used
    out->x.clear(), out->radius.resize(placedCount);
  }
  out->fraction = solid / volume;
}

}  // namespace vofdem
