// Contact histories carried by the pair's global ids (the springs, ContactHistory; the bonds, BondHistory) on their
// way between ranks while the lists are rebuilt: ExchangeHistory with the halo's neighbour ranks, GatherHistory
// to every rank after a repartition. A record is the two ids' bits, then the W values.
#pragma once

#include "vofdem/dem/Halo.hpp"
#include "vofdem/dem/NeighbourList.hpp"

#include <petscsys.h>

#include <array>
#include <cstring>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace vofdem {

template <int W>
using HistoryMap = std::unordered_map<PairKey, std::array<PetscReal, W>, PairKeyHash>;

namespace history {

template <int W>
inline void Append(const PairKey &key, const std::array<PetscReal, W> &s, std::vector<PetscReal> *out) {
  PetscReal rec[2 + W];
  std::memcpy(&rec[0], &key.lo, sizeof(PetscInt64));
  std::memcpy(&rec[1], &key.hi, sizeof(PetscInt64));
  std::copy(s.begin(), s.end(), &rec[2]);
  out->insert(out->end(), rec, rec + 2 + W);
}

template <int W>
inline void Keep(const PetscReal *rec, HistoryMap<W> *map) {
  PairKey key;
  std::memcpy(&key.lo, &rec[0], sizeof(PetscInt64));
  std::memcpy(&key.hi, &rec[1], sizeof(PetscInt64));
  std::array<PetscReal, W> h;
  std::copy(rec + 2, rec + 2 + W, h.begin());
  map->emplace(key, h);  // receivers keep what they lack
}

}  // namespace history

// Each rank sends a history to a neighbour when the neighbour now holds one of the pair as a ghost, or when one
// of the pair has left this rank (it is somewhere among the neighbours); a wall's goes only when its particle
// has left. `tag` and tag + 1 are the messages' tags.
template <int W>
PetscErrorCode ExchangeHistory(const Halo &halo, const std::vector<PetscInt64> &localIds, int tag, HistoryMap<W> *map) {
  const auto   &ranks = halo.Ranks();
  const auto   &send  = halo.SendLists();
  const int     nq    = (int)ranks.size();
  constexpr int width = 2 + W;

  PetscFunctionBeginUser;
  if (nq == 0) PetscFunctionReturn(0);
  std::unordered_set<PetscInt64>      local(localIds.begin(), localIds.end());
  std::vector<std::vector<PetscReal>> out(nq);
  std::vector<PetscInt>               outCount(nq), inCount(nq);
  for (int q = 0; q < nq; ++q) {
    std::unordered_set<PetscInt64> sent;
    for (PetscInt p : send[q]) sent.insert(localIds[p]);
    for (const auto &[key, s] : *map) {
      // A wall contact travels only with its particle; a pair also to where its partner is a ghost.
      const bool left = !local.count(key.lo) || (!key.IsWall() && !local.count(key.hi));
      if (!left && (key.IsWall() || (!sent.count(key.lo) && !sent.count(key.hi)))) continue;
      history::Append<W>(key, s, &out[q]);
    }
    outCount[q] = (PetscInt)(out[q].size() / width);
  }
  std::vector<MPI_Request> req(2 * nq);
  MPI_Comm                 comm = halo.Comm();
  for (int q = 0; q < nq; ++q) {
    PetscCallMPI(MPI_Irecv(&inCount[q], 1, MPIU_INT, ranks[q], tag, comm, &req[q]));
    PetscCallMPI(MPI_Isend(&outCount[q], 1, MPIU_INT, ranks[q], tag, comm, &req[nq + q]));
  }
  PetscCallMPI(MPI_Waitall(2 * nq, req.data(), MPI_STATUSES_IGNORE));
  std::vector<std::vector<PetscReal>> in(nq);
  for (int q = 0; q < nq; ++q) {
    in[q].resize((size_t)width * inCount[q]);
    PetscCallMPI(MPI_Irecv(in[q].data(), width * (int)inCount[q], MPIU_REAL, ranks[q], tag + 1, comm, &req[q]));
    PetscCallMPI(MPI_Isend(out[q].data(), width * (int)outCount[q], MPIU_REAL, ranks[q], tag + 1, comm, &req[nq + q]));
  }
  PetscCallMPI(MPI_Waitall(2 * nq, req.data(), MPI_STATUSES_IGNORE));
  for (int q = 0; q < nq; ++q)
    for (PetscInt r = 0; r < inCount[q]; ++r) history::Keep<W>(&in[q][(size_t)width * r], map);
  PetscFunctionReturn(0);
}

// Every rank gets all histories (after a repartition a particle may have moved beyond its old rank's halo ranks).
template <int W>
PetscErrorCode GatherHistory(MPI_Comm comm, HistoryMap<W> *map) {
  constexpr int width = 2 + W;
  PetscMPIInt   size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscReal> out;
  out.reserve(map->size() * width);
  for (const auto &[key, s] : *map) history::Append<W>(key, s, &out);
  int              count = (int)out.size();
  std::vector<int> counts(size), offsets(size + 1, 0);
  PetscCallMPI(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (int q = 0; q < size; ++q) offsets[q + 1] = offsets[q] + counts[q];
  std::vector<PetscReal> in(offsets[size]);
  PetscCallMPI(MPI_Allgatherv(out.data(), count, MPIU_REAL, in.data(), counts.data(), offsets.data(), MPIU_REAL, comm));
  for (size_t r = 0; r + width <= in.size(); r += width) history::Keep<W>(&in[r], map);
  PetscFunctionReturn(0);
}

}  // namespace vofdem
