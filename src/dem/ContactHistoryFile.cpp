// The contact history of a particles file (-dem_save_contact_history, -dem_contact_history_file): the springs of the
// touching pairs, so that a scene started from the particles another run saved keeps what a checkpoint
// keeps of its contacts. Without it the tangential and rolling springs start from zero and a JKR pair
// stretched beyond touching (held by its bond, P6) is read as apart: a cohesive pile loses the bonds that
// hold it in tension and slumps at the first step. Written: the pairs of particles, and the contacts with
// the box faces (j = -1 - face, faces 0-5 as x-lo, x-hi, y-lo, ..., z-hi: a bed handed on in the same box
// keeps its floor's friction and bonds); contacts with -dem_walls belong to the scene that had them. The
// file names the particles by their rows (0-based, header not counted) in the particles file written with
// it: the ids of the reading run are others (ReadParticles numbers the rows from the swarm's count).
#include "vofdem/dem/Dem.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/io/InputPath.hpp"
#include "vofdem/io/TextFile.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace vofdem {

namespace {

constexpr const char *kHeader = "i,j,tx,ty,tz,rx,ry,rz,jkr_radius,jkr_bonded";
constexpr int         kColumns = 2 + kSpringWidth;

}  // namespace

PetscErrorCode Dem::SaveContactHistory(const std::string &path) const {
  ParticleArrays           a;
  PetscMPIInt              rank, size;
  std::vector<PetscReal>   ids, pairs;  // ids as reals: exact below 2^53

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  PetscCall(swarm_.GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p) ids.push_back((PetscReal)a.id[p]);
  auto idOf = [&](PetscInt j) { return j < a.n ? a.id[j] : halo_.id[j - a.n]; };
  for (size_t k = 0; k < list_.Size(); ++k) {
    const PetscReal *s = &list_.spring[kSpringWidth * k];
    if (!list_.touching[k] || std::all_of(s, s + kSpringWidth, [](PetscReal v) { return v == 0; })) continue;
    pairs.push_back((PetscReal)idOf(list_.first[k]));  // lower id first, as the springs are seen
    pairs.push_back((PetscReal)idOf(list_.second[k]));
    pairs.insert(pairs.end(), s, s + kSpringWidth);
  }
  for (size_t k = 0; k < walls_.Size(); ++k) {  // the box faces
    const PetscReal *s = &walls_.spring[kSpringWidth * k];
    if (!walls_.touching[k] || std::all_of(s, s + kSpringWidth, [](PetscReal v) { return v == 0; })) continue;
    pairs.push_back((PetscReal)a.id[walls_.particle[k]]);
    pairs.push_back((PetscReal)(-1 - walls_.wall[k]));
    pairs.insert(pairs.end(), s, s + kSpringWidth);
  }
  PetscCall(swarm_.RestoreArrays(&a));
  // Both to rank 0 (a pair with a ghost is held by two ranks, with bit-identical springs: kept once).
  auto gather = [&](const std::vector<PetscReal> &mine, std::vector<PetscReal> *all) -> PetscErrorCode {
    std::vector<PetscMPIInt> counts(size), displs(size);
    PetscMPIInt              n = (PetscMPIInt)mine.size(), total = 0;
    PetscFunctionBeginUser;
    PetscCallMPI(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm_));
    if (rank == 0)
      for (int q = 0; q < size; ++q) displs[q] = total, total += counts[q];
    all->resize(total);
    PetscCallMPI(MPI_Gatherv(mine.data(), n, MPIU_REAL, all->data(), counts.data(), displs.data(), MPIU_REAL, 0, comm_));
    PetscFunctionReturn(0);
  };
  std::vector<PetscReal> allIds, allPairs;
  PetscCall(gather(ids, &allIds));
  PetscCall(gather(pairs, &allPairs));
  std::string text;
  if (rank == 0) {
    std::sort(allIds.begin(), allIds.end());  // SaveParticles writes the particles in this order
    std::vector<std::array<PetscReal, kColumns>> rows(allPairs.size() / kColumns);
    for (size_t r = 0; r < rows.size(); ++r) std::copy(&allPairs[kColumns * r], &allPairs[kColumns * r] + kColumns, rows[r].begin());
    std::sort(rows.begin(), rows.end(), [](const auto &x, const auto &y) { return x[0] < y[0] || (x[0] == y[0] && x[1] < y[1]); });
    rows.erase(std::unique(rows.begin(), rows.end(), [](const auto &x, const auto &y) { return x[0] == y[0] && x[1] == y[1]; }), rows.end());
    text = std::string(kHeader) + "\n";
    char line[512];
    for (const auto &r : rows) {
      const auto i = std::lower_bound(allIds.begin(), allIds.end(), r[0]) - allIds.begin();
      const auto j = r[1] < 0 ? (std::ptrdiff_t)r[1] : std::lower_bound(allIds.begin(), allIds.end(), r[1]) - allIds.begin();  // a face: as it is
      int        n = std::snprintf(line, sizeof line, "%lld,%lld", (long long)i, (long long)j);
      for (int c = 2; c < kColumns; ++c) n += std::snprintf(line + n, sizeof line - n, ",%.17g", (double)r[c]);
      text += line;
      text += '\n';
    }
  }
  PetscCall(WriteTextFile(comm_, path, text, "option -dem_save_contact_history"));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::ReadContactHistory(size_t rows, PetscInt64 start, const std::vector<char> &ownedRow) {
  PetscFunctionBeginUser;
  std::ifstream in(historyFile_);
  if (!in) VofdemInputError(comm_, "option -dem_contact_history_file: cannot open '%s'%s", historyFile_.c_str(), RelativePathNote(historyFile_).c_str());
  std::string line;
  std::getline(in, line);
  line.erase(line.find_last_not_of(" \t\r") + 1);
  if (line != kHeader) VofdemInputError(comm_, "%s:1: the header must be '%s' (as -dem_save_contact_history writes it)", historyFile_.c_str(), kHeader);
  for (int lineNo = 2; std::getline(in, line); ++lineNo) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::array<PetscReal, kColumns> v{};
    std::stringstream               ss(line);
    std::string                     cell;
    int                             n  = 0;
    bool                            ok = true;
    while (ok && std::getline(ss, cell, ',')) {
      char *end = nullptr;
      if (n < kColumns) v[n] = std::strtod(cell.c_str(), &end);
      ok = n < kColumns && end != cell.c_str() && std::string(end).find_first_not_of(" \t\r") == std::string::npos && std::isfinite(v[n]);
      ++n;
    }
    if (!ok || n != kColumns) VofdemInputError(comm_, "%s:%d: expected %d comma-separated finite numbers (%s)", historyFile_.c_str(), lineNo, kColumns, kHeader);
    const PetscReal i = v[0], j = v[1];
    if (!(i == std::floor(i) && j == std::floor(j) && i >= 0 && i < (PetscReal)rows && (j < 0 ? j >= -6 : i < j && j < (PetscReal)rows)))
      VofdemInputError(comm_, "%s:%d: give two rows i < j of the particles file (0 to %zu), or a row i and a box face j = -1 - face (-1 to -6)", historyFile_.c_str(), lineNo,
                       rows - 1);
    if (!(v[kColumns - 1] == 0 || v[kColumns - 1] == 1)) VofdemInputError(comm_, "%s:%d: jkr_bonded must be 0 or 1", historyFile_.c_str(), lineNo);
    if (!ownedRow[(size_t)i] && (j < 0 || !ownedRow[(size_t)j])) continue;  // neither particle starts on this rank
    const PairKey key = j < 0 ? PairKey::Wall(start + (PetscInt64)i, (int)(-1 - j)) : PairKey{start + (PetscInt64)i, start + (PetscInt64)j};
    std::copy(v.begin() + 2, v.end(), springs_[key].begin());
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
