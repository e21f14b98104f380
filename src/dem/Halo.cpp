#include "vofdem/dem/Halo.hpp"

#include <algorithm>
#include <cstring>

namespace vofdem {

namespace {

// Squared distance from point x to the box b = {lo, hi}.
inline PetscReal Distance2(const PetscReal x[3], const std::array<PetscReal, 6> &b) {
  PetscReal s = 0;
  for (int d = 0; d < 3; ++d) {
    const PetscReal e = x[d] < b[d] ? b[d] - x[d] : (x[d] > b[3 + d] ? x[d] - b[3 + d] : 0);
    s += e * e;
  }
  return s;
}

// Squared distance between two boxes.
inline PetscReal BoxDistance2(const std::array<PetscReal, 6> &a, const std::array<PetscReal, 6> &b) {
  PetscReal s = 0;
  for (int d = 0; d < 3; ++d) {
    const PetscReal e = std::max({a[d] - b[3 + d], b[d] - a[3 + d], (PetscReal)0});
    s += e * e;
  }
  return s;
}

constexpr int kTagCount = 200, kTagData = 300, kTagValues = 400;  // + the sender's image code (0..26)
constexpr int kFull = 14;    // x3 v3 omega3 radius mass id(bits) type clump(bits)
constexpr int kMoving = 9;   // x3 v3 omega3

}  // namespace

PetscErrorCode Halo::SetUp(const Grid &grid) {
  PetscInt        m[3];
  const PetscInt *l[3];
  PetscMPIInt     size;

  PetscFunctionBeginUser;
  comm_ = grid.Comm();
  periodic_.SetUp(grid);
  PetscCallMPI(MPI_Comm_rank(comm_, &rank_));
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  PetscCall(DMDAGetInfo(grid.CellDM(), nullptr, nullptr, nullptr, nullptr, &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(grid.CellDM(), &l[0], &l[1], &l[2]));
  boxes_.assign(size, {});
  // DMDA numbers ranks x fastest: rank = i + m0 (j + m1 k).
  for (PetscInt k = 0, zs = 0; k < m[2]; zs += l[2][k], ++k)
    for (PetscInt j = 0, ys = 0; j < m[1]; ys += l[1][j], ++j)
      for (PetscInt i = 0, xs = 0; i < m[0]; xs += l[0][i], ++i) {
        const PetscInt start[3] = {xs, ys, zs}, count[3] = {l[0][i], l[1][j], l[2][k]};
        auto          &b        = boxes_[i + m[0] * (j + m[1] * k)];
        for (int d = 0; d < 3; ++d) {
          b[d]     = grid.Lower()[d] + start[d] * grid.Spacing()[d];
          b[3 + d] = start[d] + count[d] == grid.Cells()[d] ? grid.Upper()[d] : grid.Lower()[d] + (start[d] + count[d]) * grid.Spacing()[d];
        }
      }
  PetscFunctionReturn(0);
}

PetscErrorCode Halo::Build(const ParticleArrays &a, const PetscReal *om, PetscReal cutoff) {
  PetscFunctionBeginUser;
  const PetscReal c2   = cutoff * cutoff;
  const auto     &mine = boxes_[rank_];
  ranks_.clear();
  images_.clear();
  // Entry (q, k): rank q is within the cut-off of this rank's box shifted by image k; with k the
  // unshifted image, q must be another rank. Images in rank order, then image code.
  for (PetscMPIInt q = 0; q < (PetscMPIInt)boxes_.size(); ++q)
    for (int k = 0; k < PeriodicImages::kCount; ++k) {
      if (!periodic_.Valid(k) || (k == PeriodicImages::kNone && q == rank_)) continue;
      std::array<PetscReal, 6> shifted = mine;
      for (int d = 0; d < 3; ++d) shifted[d] += periodic_.Shift(k)[d], shifted[3 + d] += periodic_.Shift(k)[d];
      if (BoxDistance2(shifted, boxes_[q]) < c2) ranks_.push_back(q), images_.push_back(k);
    }
  send_.assign(ranks_.size(), {});
  for (PetscInt p = 0; p < a.n; ++p) {
    const PetscReal *x = &a.x[3 * p];
    // Particles deeper inside than the cut-off go nowhere (nor do their images: the other boxes and
    // this box's own images lie outside it).
    PetscReal inner = PETSC_MAX_REAL;
    for (int d = 0; d < 3; ++d) inner = std::min({inner, x[d] - mine[d], mine[3 + d] - x[d]});
    if (inner > cutoff) continue;
    for (size_t q = 0; q < ranks_.size(); ++q) {
      const PetscReal *s     = periodic_.Shift(images_[q]);
      const PetscReal  xs[3] = {x[0] + s[0], x[1] + s[1], x[2] + s[2]};
      if (Distance2(xs, boxes_[ranks_[q]]) < c2) send_[q].push_back(p);
    }
  }
  PetscCall(Exchange(a, om, true));
  PetscFunctionReturn(0);
}

PetscErrorCode Halo::Refresh(const ParticleArrays &a, const PetscReal *om) {
  PetscFunctionBeginUser;
  PetscCall(Exchange(a, om, false));
  PetscFunctionReturn(0);
}

PetscErrorCode Halo::Restore(const ParticleArrays &a, const PetscReal *om, const std::vector<PetscMPIInt> &ranks, const std::vector<int> &images,
                             const std::vector<std::vector<PetscInt>> &send) {
  PetscFunctionBeginUser;
  ranks_  = ranks;
  images_ = images;
  send_  = send;
  PetscCall(Exchange(a, om, true));
  PetscFunctionReturn(0);
}

PetscErrorCode Halo::Exchange(const ParticleArrays &a, const PetscReal *om, bool full) {
  const int                base = full ? kFull : kMoving, width = base + (carryViscosity_ ? 1 : 0);
  const int                nq = (int)ranks_.size();
  std::vector<MPI_Request> req(2 * nq);

  PetscFunctionBeginUser;
  if (full) {  // counts first: the receiver sizes its ghost arrays
    std::vector<PetscInt> sendCount(nq);
    recvCount_.assign(nq, 0);
    for (int q = 0; q < nq; ++q) {
      sendCount[q] = (PetscInt)send_[q].size();
      PetscCallMPI(MPI_Irecv(&recvCount_[q], 1, MPIU_INT, ranks_[q], kTagCount + PeriodicImages::Opposite(images_[q]), comm_, &req[q]));
      PetscCallMPI(MPI_Isend(&sendCount[q], 1, MPIU_INT, ranks_[q], kTagCount + images_[q], comm_, &req[nq + q]));
    }
    PetscCallMPI(MPI_Waitall(2 * nq, req.data(), MPI_STATUSES_IGNORE));
    PetscInt total = 0;
    for (int q = 0; q < nq; ++q) total += recvCount_[q];
    x.resize(3 * total), xOwner.resize(3 * total), image.resize(total), v.resize(3 * total), omega.resize(3 * total), radius.resize(total), mass.resize(total), id.resize(total);
    type.resize(total), clump.resize(total);
    if (carryViscosity_) viscosity.resize(total);
  }
  size_t sendTotal = 0, recvTotal = 0;
  for (int q = 0; q < nq; ++q) sendTotal += send_[q].size(), recvTotal += recvCount_[q];
  sendBuf_.resize(width * sendTotal);
  recvBuf_.resize(width * recvTotal);
  PetscReal *s = sendBuf_.data();
  for (int q = 0; q < nq; ++q)
    for (PetscInt p : send_[q]) {
      for (int d = 0; d < 3; ++d) s[d] = a.x[3 * p + d], s[3 + d] = a.v[3 * p + d], s[6 + d] = om[3 * p + d];
      if (full) {
        s[9]  = a.radius[p];
        s[10] = a.mass[p];
        std::memcpy(&s[11], &a.id[p], sizeof(PetscInt64));  // the id's bits, not its value
        s[12] = (PetscReal)a.type[p];  // exact: a small integer
        std::memcpy(&s[13], &a.clump[p], sizeof(PetscInt64));
      }
      if (carryViscosity_) s[base] = a.fluidViscosity[p];
      s += width;
    }
  for (int q = 0, so = 0, ro = 0; q < nq; ++q) {
    PetscCallMPI(MPI_Irecv(recvBuf_.data() + (size_t)width * ro, width * (int)recvCount_[q], MPIU_REAL, ranks_[q], kTagData + PeriodicImages::Opposite(images_[q]),
                           comm_, &req[q]));
    PetscCallMPI(MPI_Isend(sendBuf_.data() + (size_t)width * so, width * (int)send_[q].size(), MPIU_REAL, ranks_[q], kTagData + images_[q], comm_, &req[nq + q]));
    so += (int)send_[q].size(), ro += (int)recvCount_[q];
  }
  PetscCallMPI(MPI_Waitall(2 * nq, req.data(), MPI_STATUSES_IGNORE));
  const PetscReal *r = recvBuf_.data();
  for (int q = 0, g = 0; q < nq; ++q) {
    // What q sends with this entry is its particles shifted by the opposite image.
    const int        k = PeriodicImages::Opposite(images_[q]);
    const PetscReal *sh = periodic_.Shift(k);
    for (PetscInt i = 0; i < recvCount_[q]; ++i, ++g, r += width) {
      for (int d = 0; d < 3; ++d) xOwner[3 * g + d] = r[d], x[3 * g + d] = r[d] + sh[d], v[3 * g + d] = r[3 + d], omega[3 * g + d] = r[6 + d];
      if (carryViscosity_) viscosity[g] = r[base];
      if (!full) continue;
      image[g]  = (unsigned char)k;
      radius[g] = r[9];
      mass[g]   = r[10];
      std::memcpy(&id[g], &r[11], sizeof(PetscInt64));
      type[g] = (PetscInt)r[12];
      std::memcpy(&clump[g], &r[13], sizeof(PetscInt64));
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Halo::SendValues(int width, const PetscReal *values, std::vector<PetscReal> *ghost) const {
  const int                nq = (int)ranks_.size();
  std::vector<MPI_Request> req(2 * nq);
  size_t                   sendTotal = 0, recvTotal = 0;

  PetscFunctionBeginUser;
  for (int q = 0; q < nq; ++q) sendTotal += send_[q].size(), recvTotal += recvCount_[q];
  std::vector<PetscReal> out(width * sendTotal);
  ghost->resize(width * recvTotal);
  PetscReal *s = out.data();
  for (int q = 0; q < nq; ++q)
    for (PetscInt p : send_[q]) s = std::copy(values + (size_t)width * p, values + (size_t)width * (p + 1), s);
  for (int q = 0, so = 0, ro = 0; q < nq; ++q) {
    PetscCallMPI(MPI_Irecv(ghost->data() + (size_t)width * ro, width * (int)recvCount_[q], MPIU_REAL, ranks_[q], kTagValues + PeriodicImages::Opposite(images_[q]), comm_, &req[q]));
    PetscCallMPI(MPI_Isend(out.data() + (size_t)width * so, width * (int)send_[q].size(), MPIU_REAL, ranks_[q], kTagValues + images_[q], comm_, &req[nq + q]));
    so += (int)send_[q].size(), ro += (int)recvCount_[q];
  }
  PetscCallMPI(MPI_Waitall(2 * nq, req.data(), MPI_STATUSES_IGNORE));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
