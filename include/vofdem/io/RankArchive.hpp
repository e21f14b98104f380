// Rank-local arrays in an HDF5 viewer, for Save/Load of state that lives per rank (particles in
// memory order, neighbour pairs, halo send lists). Every Array() call writes this rank's values as
// its segment of one dataset (segments in rank order, via VecView of an MPI Vec); the length of
// each segment and every Scalar() go into one row per rank of the dataset "layout", written by
// Finish(). Load replays the same calls in the same order: on the saving rank count each rank gets
// its own segment back, bit for bit; on another rank count every rank gets all ranks' segments
// concatenated (rank order) and the caller redistributes. Adding a piece of state is one call in
// Save and the same call in Load. Values travel as doubles: integers up to 2^53 are exact.
#pragma once

#include <petscviewer.h>

#include <string>
#include <type_traits>
#include <vector>

namespace vofdem {

class RankArchive {
public:
  // Collective. Saving: opens nothing, writes under the viewer's current group. Loading: reads
  // "layout" first (an input error naming `what` if it is missing); `gatherAll` asks for every
  // rank's segments even on the saving rank count (e.g. when the decomposition differs).
  PetscErrorCode Begin(PetscViewer viewer, MPI_Comm comm, bool loading, const char *what, bool gatherAll = false);
  PetscErrorCode Finish();  // saving: writes "layout"

  bool Loading() const { return loading_; }
  // True when loading on the rank count that saved: segments come back per rank.
  bool SameRanks() const { return savedRanks_ == ranks_ && !gatherAll_; }
  int  SavedRanks() const { return savedRanks_; }
  // Loading: whether the saved rows hold another entry. State appended to the end of a layout reads it
  // only then, so files written before the addition still load (saving: always true).
  bool HasMore() const { return !loading_ || next_ < rowLength_; }

  // One value per rank (loading on another rank count: the value of saved rank 0).
  template <class T>
  PetscErrorCode Scalar(T *value) {
    PetscReal v = (PetscReal)*value;
    PetscFunctionBeginUser;
    PetscCall(ScalarReal(&v));
    *value = (T)v;
    PetscFunctionReturn(0);
  }
  // An array of `bs` values per item; loading resizes `values`.
  template <class T>
  PetscErrorCode Array(const char *name, std::vector<T> *values, PetscInt bs = 1) {
    static_assert(std::is_arithmetic<T>::value, "arrays of numbers");
    PetscFunctionBeginUser;
    if (!loading_) buf_.assign(values->begin(), values->end());
    PetscCall(ArrayReal(name, bs));
    if (loading_) {
      values->resize(buf_.size());
      for (size_t k = 0; k < buf_.size(); ++k) (*values)[k] = (T)buf_[k];
    }
    PetscFunctionReturn(0);
  }

private:
  PetscErrorCode ScalarReal(PetscReal *v);
  PetscErrorCode ArrayReal(const char *name, PetscInt bs);
  PetscErrorCode NextEntry(PetscReal *v);

  PetscViewer            viewer_ = nullptr;
  MPI_Comm               comm_   = MPI_COMM_NULL;
  bool                   loading_ = false, gatherAll_ = false;
  int                    ranks_ = 1, rank_ = 0, savedRanks_ = 1;
  std::string            what_;
  // Saving: this rank's layout row; loading: all saved rows. A row starts with its own length.
  std::vector<PetscReal> row_;
  size_t                 next_ = 1;  // next entry of a row
  size_t                 rowLength_ = 0;
  std::vector<PetscReal> buf_;
};

}  // namespace vofdem
