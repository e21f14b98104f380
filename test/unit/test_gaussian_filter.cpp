// GaussianFilter::Apply restricted to planes (the coupling's deposits and reads near the particles only) gives
// bitwise the values of the whole filter where it promises them: a deposit zero outside some z planes, filtered
// everywhere; a field filtered on a band of planes; next to the walls (folding) and in the middle, on the three
// kinds of location (all points active; a face location whose own walled direction is x, whose wall faces keep
// their values; the same along z). Also: the whole filter keeps a constant and conserves the total (K3).
#include "vofdem/coupling/GaussianFilter.hpp"

#include "PetscTestEnvironment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace vofdem;

namespace {

const PetscInt  kN[3]      = {11, 6, 30};
const PetscReal kH[3]      = {1.0, 1.0, 1.0};
const PetscReal kSpread[3] = {2.2, 1.3, 2.9};  // R = 5, 4, 6 taps per side

struct Location {
  const char *name;
  PetscInt    lo[3], hi[3];
};

const Location kLocations[] = {{"cells", {0, 0, 0}, {10, 5, 29}}, {"x faces", {1, 0, 0}, {9, 5, 29}}, {"z faces", {0, 0, 1}, {10, 5, 28}}};

// A value at (i, j, k) that no symmetry of the filter reproduces.
PetscScalar Value(PetscInt i, PetscInt j, PetscInt k) { return std::sin(1.3 * i + 0.7 * j * j + 0.37 * k) + 0.01 * (i + 2 * j + 3 * k); }

// v = Value on the planes [k0, k1] (all points), zero elsewhere.
PetscErrorCode Fill(DM da, Vec v, PetscInt k0, PetscInt k1) {
  PetscScalar ***a;
  PetscFunctionBeginUser;
  PetscCall(DMDAVecGetArray(da, v, &a));
  for (PetscInt k = 0; k < kN[2]; ++k)
    for (PetscInt j = 0; j < kN[1]; ++j)
      for (PetscInt i = 0; i < kN[0]; ++i) a[k][j][i] = k >= k0 && k <= k1 ? Value(i, j, k) : 0;
  PetscCall(DMDAVecRestoreArray(da, v, &a));
  PetscFunctionReturn(0);
}

// Points of the planes [k0, k1] where a and b differ (bitwise).
PetscInt Differences(DM da, Vec a, Vec b, PetscInt k0, PetscInt k1) {
  const PetscScalar ***x, ***y;
  PetscInt             count = 0;
  if (DMDAVecGetArrayRead(da, a, &x) || DMDAVecGetArrayRead(da, b, &y)) return -1;
  for (PetscInt k = std::max((PetscInt)0, k0); k <= std::min(kN[2] - 1, k1); ++k)
    for (PetscInt j = 0; j < kN[1]; ++j)
      for (PetscInt i = 0; i < kN[0]; ++i) count += x[k][j][i] != y[k][j][i];
  if (DMDAVecRestoreArrayRead(da, a, &x) || DMDAVecRestoreArrayRead(da, b, &y)) return -1;
  return count;
}

class GaussianFilterTest : public ::testing::TestWithParam<int> {
protected:
  void SetUp() override {
    ASSERT_EQ(DMDACreate3d(PETSC_COMM_SELF, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_STAR, kN[0], kN[1], kN[2], 1, 1, 1, 1, 1, nullptr, nullptr, nullptr, &da_), 0);
    ASSERT_EQ(DMSetUp(da_), 0);
    const Location &l        = kLocations[GetParam()];
    const bool      periodic[3] = {false, false, false};
    ASSERT_EQ(filter_.SetUp(da_, kH, kSpread, l.lo, l.hi, periodic), 0);
    ASSERT_EQ(DMCreateGlobalVector(da_, &whole_), 0);
    ASSERT_EQ(VecDuplicate(whole_, &part_), 0);
  }
  void TearDown() override {
    EXPECT_EQ(VecDestroy(&whole_), 0);
    EXPECT_EQ(VecDestroy(&part_), 0);
    EXPECT_EQ(filter_.Destroy(), 0);
    EXPECT_EQ(DMDestroy(&da_), 0);
  }
  DM             da_ = nullptr;
  Vec            whole_ = nullptr, part_ = nullptr;
  GaussianFilter filter_;
};

TEST_P(GaussianFilterTest, RestrictsOnOneRank) {
  EXPECT_TRUE(filter_.Restricts());
  EXPECT_EQ(filter_.Radius(0), 5);
  EXPECT_EQ(filter_.Radius(1), 4);
  EXPECT_EQ(filter_.Radius(2), 6);
}

// A deposit on planes [k0, k1], filtered: equal everywhere (zero beyond the planes widened by R_z).
TEST_P(GaussianFilterTest, DepositOnSomePlanesEqualsTheWholeFilterEverywhere) {
  const PetscInt bands[][2] = {{12, 15}, {0, 3}, {1, 2}, {25, 29}, {14, 14}, {0, 29}};
  const PetscInt R          = filter_.Radius(2);
  for (const auto &b : bands) {
    ASSERT_EQ(Fill(da_, whole_, b[0], b[1]), 0);
    ASSERT_EQ(Fill(da_, part_, b[0], b[1]), 0);
    const PetscInt out[2] = {b[0] - R, b[1] + R};
    ASSERT_EQ(filter_.Apply(whole_), 0);
    ASSERT_EQ(filter_.Apply(part_, b, out), 0);
    EXPECT_EQ(Differences(da_, whole_, part_, 0, kN[2] - 1), 0) << kLocations[GetParam()].name << ", planes " << b[0] << "-" << b[1];
  }
}

// A field everywhere, wanted on planes [k0, k1]: equal there.
TEST_P(GaussianFilterTest, FieldWantedOnSomePlanesEqualsTheWholeFilterThere) {
  const PetscInt bands[][2] = {{20, 24}, {0, 2}, {26, 29}, {9, 9}, {0, 29}};
  const PetscInt all[2]     = {0, kN[2] - 1};
  for (const auto &b : bands) {
    ASSERT_EQ(Fill(da_, whole_, 0, kN[2] - 1), 0);
    ASSERT_EQ(Fill(da_, part_, 0, kN[2] - 1), 0);
    ASSERT_EQ(filter_.Apply(whole_), 0);
    ASSERT_EQ(filter_.Apply(part_, all, b), 0);
    EXPECT_EQ(Differences(da_, whole_, part_, b[0], b[1]), 0) << kLocations[GetParam()].name << ", planes " << b[0] << "-" << b[1];
  }
}

// The same filter run twice in a row with other bands in between: nothing stale in its buffers leaks in.
TEST_P(GaussianFilterTest, NoStateCarriesOverBetweenCalls) {
  const PetscInt R = filter_.Radius(2), all[2] = {0, kN[2] - 1}, wide[2] = {0, kN[2] - 1};
  ASSERT_EQ(Fill(da_, part_, 0, kN[2] - 1), 0);
  ASSERT_EQ(filter_.Apply(part_, all, wide), 0);  // fills the buffers with a whole field
  const PetscInt b[2] = {10, 12}, out[2] = {b[0] - R, b[1] + R};
  ASSERT_EQ(Fill(da_, whole_, b[0], b[1]), 0);
  ASSERT_EQ(Fill(da_, part_, b[0], b[1]), 0);
  ASSERT_EQ(filter_.Apply(whole_), 0);
  ASSERT_EQ(filter_.Apply(part_, b, out), 0);
  EXPECT_EQ(Differences(da_, whole_, part_, 0, kN[2] - 1), 0);
}

// K3: the active points' total is kept, the wall faces keep their values, a constant stays constant.
TEST_P(GaussianFilterTest, ConservesAndKeepsWallFaces) {
  const Location &l = kLocations[GetParam()];
  ASSERT_EQ(Fill(da_, whole_, 0, kN[2] - 1), 0);
  PetscScalar before, after;
  ASSERT_EQ(VecSum(whole_, &before), 0);
  ASSERT_EQ(filter_.Apply(whole_), 0);
  ASSERT_EQ(VecSum(whole_, &after), 0);
  EXPECT_NEAR(PetscRealPart(after), PetscRealPart(before), 1e-12 * std::fabs(PetscRealPart(before)));
  const PetscScalar ***a;
  ASSERT_EQ(DMDAVecGetArrayRead(da_, whole_, &a), 0);
  for (PetscInt k = 0; k < kN[2]; ++k)
    for (PetscInt j = 0; j < kN[1]; ++j)
      for (PetscInt i = 0; i < kN[0]; ++i) {
        const PetscInt q[3] = {i, j, k};
        bool           wall = false;
        for (int e = 0; e < 3; ++e) wall = wall || q[e] < l.lo[e] || q[e] > l.hi[e];
        if (wall) {
          EXPECT_EQ(a[k][j][i], Value(i, j, k)) << l.name << " wall face " << i << "," << j << "," << k;
        }
      }
  ASSERT_EQ(DMDAVecRestoreArrayRead(da_, whole_, &a), 0);
  ASSERT_EQ(VecSet(whole_, 2.5), 0);
  ASSERT_EQ(filter_.Apply(whole_), 0);
  PetscReal lo, hi;
  ASSERT_EQ(VecMin(whole_, nullptr, &lo), 0);
  ASSERT_EQ(VecMax(whole_, nullptr, &hi), 0);
  EXPECT_NEAR(lo, 2.5, 1e-14);
  EXPECT_NEAR(hi, 2.5, 1e-14);
}

INSTANTIATE_TEST_SUITE_P(Locations, GaussianFilterTest, ::testing::Values(0, 1, 2));

}  // namespace
