#include "vofdem/io/RankArchive.hpp"

#include "vofdem/io/ReadAll.hpp"

#include "vofdem/base/Runtime.hpp"

#include <petscvec.h>
#include <petscviewerhdf5.h>

namespace vofdem {

namespace {

}  // namespace

PetscErrorCode RankArchive::Begin(PetscViewer viewer, MPI_Comm comm, bool loading, const char *what, bool gatherAll) {
  PetscMPIInt size, rank;

  PetscFunctionBeginUser;
  viewer_  = viewer;
  comm_    = comm;
  loading_ = loading;
  gatherAll_ = gatherAll;
  what_    = what;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  ranks_ = savedRanks_ = size;
  rank_  = rank;
  next_  = 1;
  row_.assign(1, 0);  // the row's length, set by Finish()
  if (!loading) PetscFunctionReturn(0);
  PetscBool has = PETSC_FALSE;
  PetscCall(PetscViewerHDF5HasDataset(viewer, "layout", &has));
  if (!has) VofdemInputError(comm, "%s: the file holds no saved state here (no dataset 'layout')", what);
  PetscCall(ReadAll(viewer, comm, "layout", -1, 1, &row_));
  rowLength_ = row_.empty() ? 0 : (size_t)row_[0];
  if (rowLength_ < 1 || row_.size() % rowLength_) VofdemInputError(comm, "%s: the dataset 'layout' is malformed", what);
  savedRanks_ = (int)(row_.size() / rowLength_);
  PetscFunctionReturn(0);
}

PetscErrorCode RankArchive::NextEntry(PetscReal *v) {
  PetscFunctionBeginUser;
  if (next_ >= rowLength_) VofdemInputError(comm_, "%s: the saved state has fewer entries than this program reads (saved by another version?)", what_.c_str());
  *v = row_[(SameRanks() ? rank_ : 0) * rowLength_ + next_];
  PetscFunctionReturn(0);
}

PetscErrorCode RankArchive::ScalarReal(PetscReal *v) {
  PetscFunctionBeginUser;
  if (loading_) PetscCall(NextEntry(v));
  else row_.push_back(*v);
  ++next_;
  PetscFunctionReturn(0);
}

PetscErrorCode RankArchive::ArrayReal(const char *name, PetscInt bs) {
  PetscInt n = (PetscInt)buf_.size(), total = 0;

  PetscFunctionBeginUser;
  if (!loading_) {
    row_.push_back(n);
    PetscCallMPI(MPI_Allreduce(&n, &total, 1, MPIU_INT, MPI_SUM, comm_));
    if (total > 0) {  // an empty dataset is not written (HDF5 chunks must not be empty)
      Vec v;
      PetscCall(VecCreateMPIWithArray(comm_, bs, n, PETSC_DECIDE, buf_.data(), &v));
      PetscCall(PetscObjectSetName((PetscObject)v, name));
      PetscCall(VecView(v, viewer_));
      PetscCall(VecDestroy(&v));
    }
    ++next_;
    PetscFunctionReturn(0);
  }
  PetscReal mine = 0;
  PetscCall(NextEntry(&mine));
  for (int q = 0; q < savedRanks_; ++q) total += (PetscInt)row_[q * rowLength_ + next_];
  ++next_;
  buf_.clear();
  if (total == 0) PetscFunctionReturn(0);
  if (!SameRanks()) {
    PetscCall(ReadAll(viewer_, comm_, name, total, bs, &buf_));
    PetscFunctionReturn(0);
  }
  Vec                v;
  const PetscScalar *a;
  PetscCall(VecCreate(comm_, &v));
  PetscCall(VecSetSizes(v, (PetscInt)mine, total));
  PetscCall(VecSetBlockSize(v, bs));
  PetscCall(VecSetType(v, VECSTANDARD));
  PetscCall(PetscObjectSetName((PetscObject)v, name));
  PetscCall(VecLoad(v, viewer_));
  PetscCall(VecGetArrayRead(v, &a));
  buf_.assign(a, a + (PetscInt)mine);
  PetscCall(VecRestoreArrayRead(v, &a));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

PetscErrorCode RankArchive::Finish() {
  Vec v;

  PetscFunctionBeginUser;
  if (loading_) PetscFunctionReturn(0);
  row_[0] = (PetscReal)row_.size();
  PetscCall(VecCreateMPIWithArray(comm_, 1, (PetscInt)row_.size(), PETSC_DECIDE, row_.data(), &v));
  PetscCall(PetscObjectSetName((PetscObject)v, "layout"));
  PetscCall(VecView(v, viewer_));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
