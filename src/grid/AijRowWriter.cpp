#include "vofdem/grid/AijRowWriter.hpp"

#include <algorithm>

namespace vofdem {

void AijRowWriter::Reset() {
  ready_ = false;
  start_.assign(1, 0);
  shape_.clear();
  rows_.clear();
  cols_.clear();
  pos_.clear();
}

// MatSetValuesStencil's own index arithmetic (3-D, one component): the local index in the ghosted box,
// -1 if below it in any direction (dropped).
PetscErrorCode AijRowWriter::Local(DM da, const MatStencil &s, PetscInt *local) const {
  PetscInt gs[3], gm[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetGhostCorners(da, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  const PetscInt k = s.k - gs[2], j = s.j - gs[1], i = s.i - gs[0];
  *local = (k < 0 || j < 0 || i < 0) ? -1 : (k * gm[1] + j) * gm[0] + i;
  PetscFunctionReturn(0);
}

PetscErrorCode AijRowWriter::Note(Mat A, DM da, const MatStencil &row, PetscInt nc, const MatStencil col[]) {
  ISLocalToGlobalMapping map;
  PetscInt               l, g;

  PetscFunctionBeginUser;
  if (unsupported_) PetscFunctionReturn(0);  // the matrix type cannot be written in place: nothing to record
  if (start_.empty()) start_.assign(1, 0);
  PetscCall(MatGetLocalToGlobalMapping(A, &map, nullptr));
  PetscCall(Local(da, row, &l));
  PetscCall(ISLocalToGlobalMappingApply(map, 1, &l, &g));
  rows_.push_back(g);
  for (PetscInt c = 0; c < nc; ++c) {
    PetscCall(Local(da, col[c], &l));
    g = -1;
    if (l >= 0) PetscCall(ISLocalToGlobalMappingApply(map, 1, &l, &g));
    cols_.push_back(g);
  }
  start_.push_back(cols_.size());
  shape_.push_back(Shape(nc, col));
  PetscFunctionReturn(0);
}

PetscErrorCode AijRowWriter::Finish(Mat A) {
  PetscBool       seq, mpi, done;
  Mat             blocks[2] = {nullptr, nullptr};
  const PetscInt *garray = nullptr, *ia[2] = {nullptr, nullptr}, *ja[2] = {nullptr, nullptr};
  PetscInt        n, rstart, cstart, cend, found = 1, all;

  PetscFunctionBeginUser;
  ready_ = false;
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)A, MATSEQAIJ, &seq));
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)A, MATMPIAIJ, &mpi));
  if (!seq && !mpi) found = 0, unsupported_ = true;
  else if (seq) blocks[0] = A;
  else PetscCall(MatMPIAIJGetSeqAIJ(A, &blocks[0], &blocks[1], &garray));
  PetscCall(MatGetOwnershipRange(A, &rstart, nullptr));
  PetscCall(MatGetOwnershipRangeColumn(A, &cstart, &cend));
  for (int b = 0; b < 2 && found; ++b)
    if (blocks[b]) {
      PetscCall(MatGetRowIJ(blocks[b], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia[b], &ja[b], &done));
      if (!done) found = 0;
    }
  if (found) {
    pos_.assign(cols_.size(), kIgnored);
    for (size_t r = 0; r + 1 < start_.size() && found; ++r) {
      const PetscInt lr = rows_[r] - rstart;
      for (size_t e = start_[r]; e < start_[r + 1] && found; ++e) {
        const PetscInt c = cols_[e];
        if (c < 0) continue;  // dropped by MatSetValuesStencil as well
        bool hit = false;
        if (!mpi || (c >= cstart && c < cend)) {  // the diagonal block: columns local to the rank
          const PetscInt lc = mpi ? c - cstart : c;
          for (PetscInt p = ia[0][lr]; p < ia[0][lr + 1] && !hit; ++p)
            if (ja[0][p] == lc) pos_[e] = p, hit = true;
        } else
          for (PetscInt p = ia[1][lr]; p < ia[1][lr + 1] && !hit; ++p)
            if (garray[ja[1][p]] == c) pos_[e] = -(int64_t)p - 2, hit = true;
        if (!hit) found = 0;
      }
    }
  }
  for (int b = 0; b < 2; ++b)
    if (ia[b]) PetscCall(MatRestoreRowIJ(blocks[b], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia[b], &ja[b], &done));
  // Every rank writes in place or none does (End() is collective through the state of the parallel matrix).
  PetscCallMPI(MPI_Allreduce(&found, &all, 1, MPIU_INT, MPI_MIN, PetscObjectComm((PetscObject)A)));
  ready_ = all == 1;
  rows_.clear(), rows_.shrink_to_fit();
  cols_.clear(), cols_.shrink_to_fit();
  if (!ready_) Reset();
  PetscFunctionReturn(0);
}

PetscErrorCode AijRowWriter::Begin(Mat A) {
  PetscBool mpi;
  PetscFunctionBeginUser;
  row_ = 0;
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)A, MATMPIAIJ, &mpi));
  Ad_ = A, Ao_ = nullptr;
  if (mpi) PetscCall(MatMPIAIJGetSeqAIJ(A, &Ad_, &Ao_, nullptr));
  PetscCall(MatSeqAIJGetArray(Ad_, &diag_));
  if (Ao_) PetscCall(MatSeqAIJGetArray(Ao_, &off_));
  PetscFunctionReturn(0);
}

PetscErrorCode AijRowWriter::End(Mat A, bool *complete) {
  PetscInt mine, all;
  PetscFunctionBeginUser;
  PetscCall(MatSeqAIJRestoreArray(Ad_, &diag_));
  if (Ao_) PetscCall(MatSeqAIJRestoreArray(Ao_, &off_));
  // An assembly of nothing new: marks the matrix changed (its state), so that the preconditioner is set up again.
  PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  mine = row_ + 1 == start_.size();
  PetscCallMPI(MPI_Allreduce(&mine, &all, 1, MPIU_INT, MPI_MIN, PetscObjectComm((PetscObject)A)));
  *complete = all == 1;
  PetscFunctionReturn(0);
}

}  // namespace vofdem
