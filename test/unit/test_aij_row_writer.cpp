// AijRowWriter: values written in place equal, entry for entry, a fresh MatSetValuesStencil assembly of the
// same rows, with stencils that wrap (periodic x) and that leave the box (dropped, as MatSetValuesStencil
// drops them); a row whose shape changed is refused, and nothing is written past it.
#include "vofdem/grid/AijRowWriter.hpp"

#include "PetscTestEnvironment.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace vofdem;

namespace {

const PetscInt kN[3] = {5, 4, 3};

// Row (i, j, k) of a 7-point stencil on a grid periodic in x: every neighbour, also those outside the y and z walls (index -1 or N,
// which MatSetValuesStencil drops below the box and which this test keeps inside it above), values from `seed`.
PetscInt Row(PetscInt i, PetscInt j, PetscInt k, double seed, bool narrow, MatStencil col[7], PetscScalar val[7]) {
  PetscInt n = 0;
  col[n]     = {k, j, i, 0};
  val[n++]   = 10 + seed + 0.1 * i + 0.01 * j + 0.001 * k;
  const PetscInt d[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  for (int s = 0; s < (narrow ? 2 : 6); ++s) {
    const PetscInt q[3] = {i + d[s][0], j + d[s][1], k + d[s][2]};
    if (q[1] >= kN[1] || q[2] >= kN[2]) continue;  // above the box: not passed (MatSetValuesStencil would misplace them)
    col[n]   = {q[2], q[1], q[0], 0};
    val[n++] = -(1 + seed * (s + 1) + 0.5 * i - 0.25 * j + 0.125 * k);
  }
  return n;
}

// A fresh assembly of every row with `seed`; with a writer: recorded by it.
PetscErrorCode Assemble(DM da, Mat A, double seed, AijRowWriter *w) {
  PetscInt    xs, ys, zs, xm, ym, zm;
  MatStencil  col[7];
  PetscScalar val[7];
  PetscFunctionBeginUser;
  PetscCall(MatZeroEntries(A));
  PetscCall(DMDAGetCorners(da, &xs, &ys, &zs, &xm, &ym, &zm));
  if (w) w->Reset();
  for (PetscInt k = zs; k < zs + zm; ++k)
    for (PetscInt j = ys; j < ys + ym; ++j)
      for (PetscInt i = xs; i < xs + xm; ++i) {
        const PetscInt n = Row(i, j, k, seed, false, col, val);
        PetscCall(MatSetValuesStencil(A, 1, col, n, col, val, INSERT_VALUES));
        if (w) PetscCall(w->Note(A, da, col[0], n, col));
      }
  PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  if (w) PetscCall(w->Finish(A));
  PetscFunctionReturn(0);
}

// max |A - B| over all entries.
double Difference(Mat A, Mat B) {
  Mat       D;
  PetscReal norm;
  EXPECT_EQ(MatDuplicate(A, MAT_COPY_VALUES, &D), 0);
  EXPECT_EQ(MatAXPY(D, -1, B, SAME_NONZERO_PATTERN), 0);
  EXPECT_EQ(MatNorm(D, NORM_MAX, &norm), 0);
  EXPECT_EQ(MatDestroy(&D), 0);
  return norm;
}

}  // namespace

TEST(AijRowWriter, InPlaceValuesEqualAFreshAssembly) {
  DM  da;
  Mat A, B;
  ASSERT_EQ(DMDACreate3d(PETSC_COMM_SELF, DM_BOUNDARY_PERIODIC, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_STAR, kN[0], kN[1], kN[2], 1, 1, 1, 1, 1, nullptr, nullptr, nullptr, &da), 0);
  ASSERT_EQ(DMSetUp(da), 0);
  ASSERT_EQ(DMCreateMatrix(da, &A), 0);
  ASSERT_EQ(DMCreateMatrix(da, &B), 0);
  AijRowWriter w;
  ASSERT_FALSE(w.Ready());
  ASSERT_EQ(Assemble(da, A, 0.5, &w), 0);
  ASSERT_TRUE(w.Ready());

  // New values in place against a fresh assembly with them.
  PetscInt    xs, ys, zs, xm, ym, zm;
  MatStencil  col[7];
  PetscScalar val[7];
  ASSERT_EQ(DMDAGetCorners(da, &xs, &ys, &zs, &xm, &ym, &zm), 0);
  bool complete = false, fits = true;
  ASSERT_EQ(w.Begin(A), 0);
  for (PetscInt k = zs; k < zs + zm; ++k)
    for (PetscInt j = ys; j < ys + ym; ++j)
      for (PetscInt i = xs; i < xs + xm; ++i) {
        const PetscInt n = Row(i, j, k, 2.25, false, col, val);
        fits             = fits && w.Put(n, col, val);
      }
  ASSERT_EQ(w.End(A, &complete), 0);
  EXPECT_TRUE(fits);
  EXPECT_TRUE(complete);
  ASSERT_EQ(Assemble(da, B, 2.25, nullptr), 0);
  EXPECT_EQ(Difference(A, B), 0.0) << "the in-place values are those of a fresh assembly";
  ASSERT_EQ(Assemble(da, B, 0.5, nullptr), 0);
  EXPECT_GT(Difference(A, B), 0.1) << "and not the recorded ones";

  // A row of another shape (fewer entries) is refused; the rest is not written, and End says so.
  PetscScalar before;
  PetscInt    last = 0;
  ASSERT_EQ(MatGetValues(A, 1, &last, 1, &last, &before), 0);
  ASSERT_EQ(w.Begin(A), 0);
  PetscInt n = Row(xs, ys, zs, 7.0, true, col, val);
  EXPECT_FALSE(w.Put(n, col, val));
  ASSERT_EQ(w.End(A, &complete), 0);
  EXPECT_FALSE(complete);
  PetscScalar after;
  ASSERT_EQ(MatGetValues(A, 1, &last, 1, &last, &after), 0);
  EXPECT_EQ(before, after);

  ASSERT_EQ(MatDestroy(&A), 0);
  ASSERT_EQ(MatDestroy(&B), 0);
  ASSERT_EQ(DMDestroy(&da), 0);
}

TEST(AijRowWriter, NotReadyForOtherMatrixTypes) {
  DM  da;
  Mat A;
  ASSERT_EQ(DMDACreate3d(PETSC_COMM_SELF, DM_BOUNDARY_PERIODIC, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_STAR, kN[0], kN[1], kN[2], 1, 1, 1, 1, 1, nullptr, nullptr, nullptr, &da), 0);
  ASSERT_EQ(DMSetUp(da), 0);
  ASSERT_EQ(DMSetMatType(da, MATBAIJ), 0);
  ASSERT_EQ(DMCreateMatrix(da, &A), 0);
  AijRowWriter w;
  ASSERT_EQ(Assemble(da, A, 1.0, &w), 0);
  EXPECT_FALSE(w.Ready()) << "BAIJ: the caller keeps MatSetValuesStencil";
  ASSERT_EQ(MatDestroy(&A), 0);
  ASSERT_EQ(DMDestroy(&da), 0);
}
