#include "vofdem/dem/PeriodicImages.hpp"

#include "vofdem/base/Runtime.hpp"

namespace vofdem {

void PeriodicImages::SetUp(const Grid &grid) {
  any_ = false;
  for (int d = 0; d < 3; ++d) {
    periodic_[d] = grid.Periodic(d);
    lower_[d]    = grid.Lower()[d];
    upper_[d]    = grid.Upper()[d];
    length_[d]   = upper_[d] - lower_[d];
    any_         = any_ || periodic_[d];
  }
  for (int k = 0; k < kCount; ++k) {
    const int s[3] = {k % 3 - 1, (k / 3) % 3 - 1, k / 9 - 1};
    valid_[k]      = true;
    for (int d = 0; d < 3; ++d) {
      if (s[d] && !periodic_[d]) valid_[k] = false;
      // Exactly +L, -L or 0, so that the shift of the opposite image is the exact negative.
      shift_[k][d] = s[d] == 0 ? 0 : (s[d] > 0 ? length_[d] : -length_[d]);
    }
  }
}

PetscInt PeriodicImages::Wrap(PetscInt n, PetscReal *x) const {
  PetscInt moved = 0;
  if (!any_) return 0;
  for (PetscInt p = 0; p < n; ++p)
    for (int d = 0; d < 3; ++d) {
      if (!periodic_[d]) continue;
      PetscReal &c = x[3 * p + d];
      // The upper face belongs to the box (Grid::OwnsPoint), the lower one too: only strictly
      // outside points move, by one length (a particle moves at most half the skin between wraps).
      if (c < lower_[d]) c += length_[d], ++moved;
      else if (c > upper_[d]) c -= length_[d], ++moved;
    }
  return moved;
}

PetscErrorCode PeriodicImages::Check(MPI_Comm comm, PetscReal cutoff, const char *cutoffText) const {
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d)
    if (periodic_[d] && length_[d] < 2 * cutoff)
      VofdemInputError(comm, "option -grid_periodic: the box is %g m long in %c, less than twice the contact cut-off %s = %g m (a pair would meet twice)",
                       (double)length_[d], "xyz"[d], cutoffText, (double)cutoff);
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicImages::CheckRanks(const Grid &grid) const {
  PetscInt m[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetInfo(grid.CellDM(), nullptr, nullptr, nullptr, nullptr, &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  for (int d = 0; d < 3; ++d)
    if (periodic_[d] && m[d] > 2)
      VofdemInputError(grid.Comm(), "option -grid_periodic: %c is split over %" PetscInt_FMT " ranks, at most 2 are supported along a periodic direction (set -grid_ranks)",
                       "xyz"[d], m[d]);
  PetscFunctionReturn(0);
}

void PeriodicImages::PairImages(const NeighbourList &list, PetscInt nLocal, const unsigned char *ghostImage, std::vector<unsigned char> *pairImage) {
  pairImage->resize(list.Size());
  for (size_t k = 0; k < list.Size(); ++k) {
    // Seen from here x_a - x_b = (x_a,owner + S_a) - (x_b,owner + S_b): the pair's shift is S_a - S_b,
    // S_a for a ghost a, -S_b = S_opposite for a ghost b (at most one of them is a ghost).
    const PetscInt a = list.first[k], b = list.second[k];
    (*pairImage)[k] = (unsigned char)(b >= nLocal ? Opposite(ghostImage[b - nLocal]) : a >= nLocal ? ghostImage[a - nLocal] : kNone);
  }
}

}  // namespace vofdem
