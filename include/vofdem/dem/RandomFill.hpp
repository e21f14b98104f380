// Random non-overlapping fill of a box (random sequential addition): particle k draws its radius
// from the size distribution (until the count or volume fraction is reached); then, largest
// first, each draws candidate centres until one overlaps no placed particle, at most `attempts`
// times. Every draw is keyed by (seed, k, attempt) with the counter-based
// generator and the whole sequence is computed on every rank, so the particles are the same on
// any rank count (each rank then keeps those it owns). A cell hash makes each test O(1), so the
// fill costs O(N) expected time below the jamming fraction (0.38 for equal spheres; with a bounded number of attempts it stalls near 0.3).
#pragma once

#include "vofdem/dem/SizeDistribution.hpp"

#include <petscsys.h>

#include <cstdint>
#include <vector>

namespace vofdem {

struct RandomFillRequest {
  PetscReal     lower[3] = {0, 0, 0}, upper[3] = {0, 0, 0};  // particles lie entirely inside (but see `periodic`)
  // periodic[d]: the region spans a periodic direction of the domain (lower and upper are its faces):
  // centres anywhere in [lower, upper), spheres kept apart across the faces too (no gap at the seam)
  bool          periodic[3] = {false, false, false};
  PetscInt      count    = 0;  // target number of particles; 0: fill to `fraction`
  PetscReal     fraction = 0;  // target solid volume fraction of the box
  PetscInt      attempts = 1000;  // candidate centres per particle before giving up
  std::uint64_t seed     = 0;
};

struct RandomFillResult {
  std::vector<PetscReal> x, radius;  // 3 and 1 per particle, in id order (id = index); when incomplete only radius.size() = placed count
  PetscReal              fraction   = 0;     // solid volume fraction reached
  PetscInt64             candidates = 0;     // candidate centres tried
  bool                   complete   = false; // the target was met
};

// Pure computation (no communication), identical on every rank.
void RandomFill(const SizeDistribution &sizes, const RandomFillRequest &req, RandomFillResult *out);

}  // namespace vofdem
