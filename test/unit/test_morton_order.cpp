// Morton keys and the Z-order sort of a swarm's points (MortonOrder.hpp): the key interleaves the
// cell bits, and the sort moves every field of a point together and puts the points in key order.
#include "vofdem/dem/MortonOrder.hpp"
#include "vofdem/dem/ParticleSwarm.hpp"

#include "PetscTestEnvironment.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

using namespace vofdem;

TEST(MortonOrder, KeyInterleavesCellBits) {
  const PetscReal lo[3] = {0, 0, 0}, inv[3] = {1, 1, 1}, cell = 1.0 / (1 << 21);
  auto key = [&](PetscReal i, PetscReal j, PetscReal k) {
    const PetscReal x[3] = {(i + 0.5) * cell, (j + 0.5) * cell, (k + 0.5) * cell};
    return MortonKey(x, lo, inv);
  };
  EXPECT_EQ(key(1, 0, 0), 1u);
  EXPECT_EQ(key(0, 1, 0), 2u);
  EXPECT_EQ(key(0, 0, 1), 4u);
  EXPECT_EQ(key(2, 0, 0), 8u);
  EXPECT_EQ(key(3, 3, 3), 63u);
  // Outside the box: clamped to the first and last cells.
  const PetscReal below[3] = {-1, -1, -1}, above[3] = {2, 2, 2};
  EXPECT_EQ(MortonKey(below, lo, inv), 0u);
  EXPECT_EQ(MortonKey(above, lo, inv), (std::uint64_t(1) << 63) - 1);
}

TEST(MortonOrder, SortMovesWholePointsIntoKeyOrder) {
  DM             swarm;
  const PetscInt n = 200;
  ASSERT_EQ(DMCreate(PETSC_COMM_SELF, &swarm), 0);
  ASSERT_EQ(DMSetType(swarm, DMSWARM), 0);
  ASSERT_EQ(DMSetDimension(swarm, 3), 0);
  ASSERT_EQ(DMSwarmSetType(swarm, DMSWARM_BASIC), 0);
  ASSERT_EQ(DMSwarmInitializeFieldRegister(swarm), 0);
  ASSERT_EQ(DMSwarmRegisterPetscDatatypeField(swarm, field::position, 3, PETSC_REAL), 0);
  ASSERT_EQ(DMSwarmRegisterPetscDatatypeField(swarm, field::id, 1, PETSC_INT64), 0);
  ASSERT_EQ(DMSwarmRegisterPetscDatatypeField(swarm, field::mass, 1, PETSC_REAL), 0);
  ASSERT_EQ(DMSwarmFinalizeFieldRegister(swarm), 0);
  ASSERT_EQ(DMSwarmSetLocalSizes(swarm, n, 4), 0);
  PetscReal  *x, *m;
  PetscInt64 *id;
  // Points scattered over the unit box by a fixed pseudo-random walk; two share a position.
  ASSERT_EQ(DMSwarmGetField(swarm, field::position, nullptr, nullptr, (void **)&x), 0);
  ASSERT_EQ(DMSwarmGetField(swarm, field::id, nullptr, nullptr, (void **)&id), 0);
  ASSERT_EQ(DMSwarmGetField(swarm, field::mass, nullptr, nullptr, (void **)&m), 0);
  std::uint64_t s = 12345;
  for (PetscInt p = 0; p < n; ++p) {
    for (int d = 0; d < 3; ++d) s = s * 6364136223846793005ULL + 1442695040888963407ULL, x[3 * p + d] = (PetscReal)(s >> 11) / (PetscReal)(1ULL << 53);
    id[p] = 1000 - p, m[p] = 3.0 * id[p] + x[3 * p];  // mass ties each point's fields together
  }
  for (int d = 0; d < 3; ++d) x[3 * 7 + d] = x[3 * 3 + d];
  m[7] = 3.0 * id[7] + x[3 * 7];
  ASSERT_EQ(DMSwarmRestoreField(swarm, field::mass, nullptr, nullptr, (void **)&m), 0);
  ASSERT_EQ(DMSwarmRestoreField(swarm, field::id, nullptr, nullptr, (void **)&id), 0);
  ASSERT_EQ(DMSwarmRestoreField(swarm, field::position, nullptr, nullptr, (void **)&x), 0);

  MortonOrder     order;
  const PetscReal lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}, inv[3] = {1, 1, 1};
  ASSERT_EQ(order.Sort(swarm, lo, hi), 0);

  PetscInt after;
  ASSERT_EQ(DMSwarmGetLocalSize(swarm, &after), 0);
  EXPECT_EQ(after, n);  // the spare point is gone
  ASSERT_EQ(DMSwarmGetField(swarm, field::position, nullptr, nullptr, (void **)&x), 0);
  ASSERT_EQ(DMSwarmGetField(swarm, field::id, nullptr, nullptr, (void **)&id), 0);
  ASSERT_EQ(DMSwarmGetField(swarm, field::mass, nullptr, nullptr, (void **)&m), 0);
  std::vector<int> seen(n, 0);
  for (PetscInt p = 0; p < n; ++p) {
    ASSERT_GT(id[p], 1000 - n);
    ASSERT_LE(id[p], 1000);
    ++seen[1000 - id[p]];
    EXPECT_EQ(m[p], 3.0 * id[p] + x[3 * p]) << "fields of point " << p << " were not moved together";
    if (p > 0) {
      const std::uint64_t kp = MortonKey(&x[3 * (p - 1)], lo, inv), k = MortonKey(&x[3 * p], lo, inv);
      EXPECT_TRUE(kp < k || (kp == k && id[p - 1] < id[p])) << "points " << p - 1 << " and " << p << " out of order";
    }
  }
  for (PetscInt q = 0; q < n; ++q) EXPECT_EQ(seen[q], 1) << "id " << 1000 - q;
  ASSERT_EQ(DMSwarmRestoreField(swarm, field::mass, nullptr, nullptr, (void **)&m), 0);
  ASSERT_EQ(DMSwarmRestoreField(swarm, field::id, nullptr, nullptr, (void **)&id), 0);
  ASSERT_EQ(DMSwarmRestoreField(swarm, field::position, nullptr, nullptr, (void **)&x), 0);
  ASSERT_EQ(DMDestroy(&swarm), 0);
}
