#include "vofdem/coupling/GaussianFilter.hpp"

#include "vofdem/base/Runtime.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace {

PetscLogEvent evApply = 0;  // "CouplingFilter": every Apply, so -log_view shows the filter's share

// out[i] = sum_t w[t] rows[t][i], i in [0, n), t in [0, taps): the taps in blocks of 8, then 4, then the
// remaining 1-3 in one block, so that the running sum stays in a register and out is stored once per block
// (15 taps: 3 passes over out instead of 6), the first block without reading out (no clearing); each point's
// sum in the order t = 0, 1, ... (bitwise the result of one tap per sweep). Contiguous in i, so it vectorises;
// built for AVX2 as well where the compiler can, picked at run time (the plain build is SSE2 only: AVX2 made the
// filter 22 % faster in the bubbling bed at cell/d 0.5; the blocks of 8, another ~20 % per pass).
template <int M, bool First>
inline void SumBlock(PetscScalar *__restrict out, const PetscScalar *const *rows, const PetscReal *w, PetscInt n) {
  const PetscScalar *s[M];
  PetscReal          c[M];
  for (int q = 0; q < M; ++q) s[q] = rows[q], c[q] = w[q];
  for (PetscInt i = 0; i < n; ++i) {
    PetscScalar v = First ? 0 : out[i];
#pragma GCC unroll 8
    for (int q = 0; q < M; ++q) v += c[q] * s[q][i];
    out[i] = v;
  }
}

template <bool First>
inline void SumBlockOf(PetscInt m, PetscScalar *out, const PetscScalar *const *rows, const PetscReal *w, PetscInt n) {
  switch (m) {
  case 8: SumBlock<8, First>(out, rows, w, n); break;
  case 4: SumBlock<4, First>(out, rows, w, n); break;
  case 3: SumBlock<3, First>(out, rows, w, n); break;
  case 2: SumBlock<2, First>(out, rows, w, n); break;
  default: SumBlock<1, First>(out, rows, w, n); break;
  }
}

#if defined(__GNUC__) && defined(__x86_64__)
__attribute__((target_clones("avx2", "default")))
#endif
void SumShiftedRows(PetscScalar *out, const PetscScalar *const *rows, const PetscReal *w, PetscInt taps, PetscInt n) {
  for (PetscInt t = 0; t < taps;) {
    const PetscInt m = taps - t >= 8 ? 8 : taps - t >= 4 ? 4 : taps - t;
    if (t == 0) SumBlockOf<true>(m, out, rows, w, n);
    else SumBlockOf<false>(m, out, rows + t, w + t, n);
    t += m;
  }
}

}  // namespace

std::vector<PetscReal> GaussianFilter::Taps(PetscReal h, PetscReal spread) {
  if (!(spread > 0)) return {1.0};
  // Taps to 3 b: with the tent's h the deposit reaches about as far as the smooth kernel itself, whose weight ends at
  // its cut-off rc = sqrt(13) sigma = 3.6 sigma (docs/physics.md K1); 4 b (as before 2026-11-26) kept tails beyond that,
  // at a third more taps. The variance is matched exactly either way.
  const PetscInt         R = std::max((PetscInt)1, (PetscInt)std::ceil(3 * std::sqrt(spread) / h));
  std::vector<PetscReal> g(2 * R + 1);
  auto make = [&](PetscReal b) {
    PetscReal sum = 0;
    for (PetscInt t = -R; t <= R; ++t) sum += (g[t + R] = std::exp(-(t * h) * (t * h) / (2 * b * b)));
    for (PetscReal &w : g) w /= sum;
  };
  auto variance = [&]() {
    PetscReal v = 0;
    for (PetscInt t = -R; t <= R; ++t) v += (t * h) * (t * h) * g[t + R];
    return v;
  };
  // The discrete variance grows monotonically with b, from 0 (b -> 0) to above `spread` at b = 4 sqrt(spread)
  // (taps truncated at about 0.75 b, nearly flat: variance ~R^2 h^2/3 >= 3 spread): bisection to round-off.
  PetscReal a = 1e-6 * std::sqrt(spread), c = 4 * std::sqrt(spread);
  for (int it = 0; it < 200 && c - a > 1e-15 * c; ++it) {
    const PetscReal b = 0.5 * (a + c);
    make(b);
    (variance() < spread ? a : c) = b;
  }
  make(0.5 * (a + c));
  return g;
}

bool GaussianFilter::Fits(DM location, const PetscReal h[3], const PetscReal spread[3], const bool periodic[3]) {
  PetscInt        m[3], width = 1;
  const PetscInt *l[3];
  if (DMDAGetInfo(location, nullptr, nullptr, nullptr, nullptr, &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr)) return false;
  if (DMDAGetOwnershipRanges(location, &l[0], &l[1], &l[2])) return false;
  for (int e = 0; e < 3; ++e) width = std::max(width, (PetscInt)(Taps(h[e], spread[e]).size() - 1) / 2);
  for (int e = 0; e < 3; ++e)
    if ((m[e] > 1 || periodic[e]) && *std::min_element(l[e], l[e] + m[e]) < width) return false;
  return true;
}

PetscErrorCode GaussianFilter::SetUp(DM location, const PetscReal h[3], const PetscReal spread[3], const PetscInt lo[3], const PetscInt hi[3], const bool periodic[3]) {
  PetscInt        N[3], m[3], width = 1;
  const PetscInt *l[3];
  DMBoundaryType  bt[3];
  MPI_Comm        comm;

  PetscFunctionBeginUser;
  if (!evApply) PetscCall(PetscLogEventRegister("CouplingFilter", DM_CLASSID, &evApply));
  PetscCall(PetscObjectGetComm((PetscObject)location, &comm));
  PetscCall(DMDAGetInfo(location, nullptr, &N[0], &N[1], &N[2], &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(location, &l[0], &l[1], &l[2]));
  for (int e = 0; e < 3; ++e) {
    taps_[e]     = Taps(h[e], spread[e]);
    R_[e]        = (PetscInt)(taps_[e].size() - 1) / 2;
    lo_[e]       = lo[e];
    hi_[e]       = hi[e];
    periodic_[e] = periodic[e];
    bt[e]        = periodic[e] ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_NONE;
    width        = std::max(width, R_[e]);
  }
  for (int e = 0; e < 3; ++e) {
    if (m[e] == 1 && !periodic[e]) continue;
    const PetscInt fewest = *std::min_element(l[e], l[e] + m[e]);
    if (fewest < width)
      VofdemInputError(comm,
                       "option -coupling_smoothing gaussian: its taps reach %" PetscInt_FMT " points, more than the %" PetscInt_FMT
                       " a rank holds along %c (use fewer ranks along %c, or -coupling_smoothing diffusion or kernel)",
                       width, fewest, "xyz"[e], "xyz"[e]);
  }
  PetscCall(DMDACreate3d(comm, bt[0], bt[1], bt[2], DMDA_STENCIL_STAR, N[0], N[1], N[2], m[0], m[1], m[2], 1, width, l[0], l[1], l[2], &dm_));
  PetscCall(DMSetUp(dm_));
  PetscCall(DMCreateLocalVector(dm_, &local_));
  PetscCall(DMCreateGlobalVector(dm_, &copy_));
  for (int e = 0; e < 3; ++e) needGhosts_[e] = m[e] > 1 || periodic[e];
  PetscInt cs[3], cn[3];
  PetscCall(DMDAGetCorners(dm_, &cs[0], &cs[1], &cs[2], &cn[0], &cn[1], &cn[2]));
  rows_.assign((size_t)(2 * width + 1), nullptr);
  ext_.assign((size_t)(std::max(cn[0], (PetscInt)1) + 2 * width), 0.0);
  if (needGhosts_[0] && R_[0]) {
    const PetscMPIInt *nb;
    PetscCall(DMDAGetNeighbors(dm_, &nb));  // 3-D: [9 (dz + 1) + 3 (dy + 1) + dx + 1]
    for (int side = 0; side < 2; ++side) {
      const PetscMPIInt r = nb[side ? 14 : 12];
      xNeighbour_[side]   = r < 0 ? MPI_PROC_NULL : r;
      haloSend_[side].assign((size_t)(R_[0] * cn[1] * cn[2]), 0.0);
      haloRecv_[side].assign((size_t)(R_[0] * cn[1] * cn[2]), 0.0);
    }
  }
  PetscFunctionReturn(0);
}

// The first and last R_x values of every owned row to the left and right neighbours, their last and first
// into haloRecv_[0] and [1] (no neighbour: MPI_PROC_NULL, nothing received; the pass folds there).
PetscErrorCode GaussianFilter::ExchangeXHalo(Vec v, const PetscInt s[3], const PetscInt n[3]) {
  const PetscScalar ***a;
  MPI_Comm            comm;
  MPI_Request         req[4];
  const PetscInt      R = R_[0];

  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)dm_, &comm));
  PetscCall(DMDAVecGetArrayRead(dm_, v, &a));
  for (PetscInt k = 0; k < n[2]; ++k)
    for (PetscInt j = 0; j < n[1]; ++j) {
      const PetscScalar *row = &a[s[2] + k][s[1] + j][s[0]];
      const size_t       at  = (size_t)((k * n[1] + j) * R);
      std::copy(row, row + R, haloSend_[0].data() + at);
      std::copy(row + n[0] - R, row + n[0], haloSend_[1].data() + at);
    }
  PetscCall(DMDAVecRestoreArrayRead(dm_, v, &a));
  const PetscMPIInt count = (PetscMPIInt)haloSend_[0].size(), toLeft = 71, toRight = 72;
  PetscCallMPI(MPI_Irecv(haloRecv_[0].data(), count, MPIU_SCALAR, xNeighbour_[0], toRight, comm, &req[0]));
  PetscCallMPI(MPI_Irecv(haloRecv_[1].data(), count, MPIU_SCALAR, xNeighbour_[1], toLeft, comm, &req[1]));
  PetscCallMPI(MPI_Isend(haloSend_[0].data(), count, MPIU_SCALAR, xNeighbour_[0], toLeft, comm, &req[2]));
  PetscCallMPI(MPI_Isend(haloSend_[1].data(), count, MPIU_SCALAR, xNeighbour_[1], toRight, comm, &req[3]));
  PetscCallMPI(MPI_Waitall(4, req, MPI_STATUSES_IGNORE));
  PetscFunctionReturn(0);
}

PetscErrorCode GaussianFilter::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&local_));
  PetscCall(VecDestroy(&copy_));
  PetscCall(DMDestroy(&dm_));
  PetscFunctionReturn(0);
}

// Row by row (x fastest), each output row a sum of shifted source rows (SumShiftedRows). The x pass works in
// place (each row is laid out in ext_ before it is overwritten); a y or z pass that needs no ghosts reads the
// current values and writes the other buffer (v or copy_), so that no pass copies the vector; one that needs
// ghosts reads a ghost update and writes in place. The result ends in v (one copy if the last pass wrote copy_).
PetscErrorCode GaussianFilter::Apply(Vec v) {
  PetscFunctionBeginUser;
  PetscCall(Apply(v, nullptr, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode GaussianFilter::Apply(Vec v, const PetscInt inPlanes[2], const PetscInt outPlanes[2]) {
  PetscInt s[3], n[3];
  Vec      cur = v;  // where the values are now

  PetscFunctionBeginUser;
  if (inPlanes && inPlanes[0] > inPlanes[1]) PetscFunctionReturn(0);  // v is zero
  PetscCall(PetscLogEventBegin(evApply, 0, 0, 0, 0));
  PetscCall(DMDAGetCorners(dm_, &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  // Restricted (z whole on every rank): the z pass computes the planes O = outPlanes (active ones) and reads the
  // active planes within R_z of them (folding stays inside: the mirror images of planes beyond a wall end lie
  // between the wall and O's far end + R_z); the x and y passes compute X = those planes where v may be
  // non-zero; the planes the z pass reads beyond X are zeroed in copy_ (the y pass's output). The passes'
  // copies of the points they do not take are made only where needed: v keeps those values itself (the x pass works in
  // place, the z pass writes v back) but on the planes computed: the z pass sums whole x rows.
  const bool restrict_ = inPlanes && outPlanes && Restricts();
  PetscInt   O[2] = {s[2], s[2] + n[2]}, X[2] = {s[2], s[2] + n[2]};  // [begin, end)
  if (restrict_) {
    O[0] = std::max({outPlanes[0], lo_[2], s[2]}), O[1] = std::min({outPlanes[1], hi_[2], s[2] + n[2] - 1}) + 1;
    const PetscInt need0 = std::max(lo_[2], O[0] - R_[2]), need1 = std::min(hi_[2], O[1] - 1 + R_[2]) + 1;
    X[0] = std::max(need0, inPlanes[0]), X[1] = std::min(need1, inPlanes[1] + 1);
    if (O[0] >= O[1]) {
      PetscCall(PetscLogEventEnd(evApply, 0, 0, 0, 0));
      PetscFunctionReturn(0);
    }
    if (X[1] < X[0]) X[1] = X[0];
    // copy_'s planes in [need0, need1) outside X read as zero
    PetscScalar ***c;
    PetscCall(DMDAVecGetArray(dm_, copy_, &c));
    for (PetscInt k = need0; k < need1; ++k)
      if (k < X[0] || k >= X[1])
        for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) std::fill(&c[k][j][s[0]], &c[k][j][s[0]] + n[0], 0.0);
    PetscCall(DMDAVecRestoreArray(dm_, copy_, &c));
  }
  for (int e = 0; e < 3; ++e) {
    if (!R_[e]) continue;
    const PetscScalar ***in;
    PetscScalar       ***out;
    const bool          ghosts = needGhosts_[e];
    const bool          inPlace = e == 0, swap = e > 0 && !ghosts;
    const Vec           dst = swap ? (cur == v ? copy_ : v) : cur;
    if (e == 0 && ghosts) PetscCall(ExchangeXHalo(cur, s, n));
    PetscCall(DMDAVecGetArray(dm_, dst, &out));
    if (inPlace) in = const_cast<const PetscScalar ***>(out);
    else if (ghosts) {
      PetscCall(DMGlobalToLocal(dm_, cur, INSERT_VALUES, local_));
      PetscCall(DMDAVecGetArrayRead(dm_, local_, &in));
    } else PetscCall(DMDAVecGetArrayRead(dm_, cur, &in));
    const PetscInt   R = R_[e];
    const PetscReal *g = taps_[e].data() + R;  // g[t], t in [-R, R]
    // The points written: the active range (wall faces keep their value).
    PetscInt a[3], b[3];
    for (int d = 0; d < 3; ++d) {
      a[d] = periodic_[d] ? s[d] : std::max(s[d], lo_[d]);
      b[d] = periodic_[d] ? s[d] + n[d] : std::min(s[d] + n[d], hi_[d] + 1);
    }
    if (restrict_) {  // the planes this pass computes
      const PetscInt *P = e == 2 ? O : X;
      a[2] = std::max(a[2], P[0]), b[2] = std::max(a[2], std::min(b[2], P[1]));
    }
    const bool foldAll = !periodic_[e];
    // Every output row is a sum of 2R + 1 shifted source rows: along x the row itself, laid out once with its
    // folded images (or periodic ghosts) each side, so that no folding happens inside the tap loop; along y
    // and z whole rows of the neighbouring lines, folded at walls.
    const PetscInt nx = b[0] - a[0];
    if (nx <= 0 || b[1] <= a[1] || b[2] <= a[2]) {  // nothing active on this rank
    } else if (e == 0) {
      // ext[i], i in [a[0] - R, b[0] + R): the row, its images beyond the active range (walls), else the
      // row itself or its ghosts; only the ends are folded. Points of the row beyond this rank's share come
      // from the exchanged ends (ghosts only).
      PetscScalar   *ext = ext_.data() + R - a[0];
      const PetscInt m0 = foldAll ? std::max(a[0] - R, lo_[0]) : a[0] - R, m1 = foldAll ? std::min(b[0] + R, hi_[0] + 1) : b[0] + R;
      const PetscInt o0 = std::max(m0, s[0]), o1 = std::min(m1, s[0] + n[0]);  // the owned part of [m0, m1)
      for (PetscInt t = -R; t <= R; ++t) rows_[t + R] = ext + a[0] + t;
      for (PetscInt k = a[2]; k < b[2]; ++k)
        for (PetscInt j = a[1]; j < b[1]; ++j) {
          const PetscScalar *src = &in[k][j][0];
          const size_t       row = (size_t)(((k - s[2]) * n[1] + (j - s[1])) * R);
          auto               at  = [&](PetscInt i) {  // ends: i in [s0 - R, s0) and [s0 + n0, s0 + n0 + R)
            return i < s[0] ? haloRecv_[0][row + (size_t)(i - (s[0] - R))] : i >= s[0] + n[0] ? haloRecv_[1][row + (size_t)(i - s[0] - n[0])] : src[i];
          };
          for (PetscInt i = a[0] - R; i < m0; ++i) ext[i] = at(Fold(0, i));
          for (PetscInt i = m0; i < o0; ++i) ext[i] = at(i);
          std::copy(src + o0, src + o1, ext + o0);
          for (PetscInt i = std::max(o1, m0); i < m1; ++i) ext[i] = at(i);
          for (PetscInt i = m1; i < b[0] + R; ++i) ext[i] = at(Fold(0, i));
          SumShiftedRows(&out[k][j][a[0]], rows_.data(), g - R, 2 * R + 1, nx);
        }
    } else if (swap) {
      // The source is laid out as v: consecutive rows are contiguous, so lines that need no folding are summed
      // as one long row, whole x rows (the x wall faces among them are put right below).
      const PetscInt     sy = n[0], sz = n[0] * n[1];
      PetscScalar       *o = &out[s[2]][s[1]][s[0]];
      const PetscScalar *c = &in[s[2]][s[1]][s[0]];
      auto line = [&](PetscInt j, PetscInt k) { return (j - s[1]) * sy + (k - s[2]) * sz; };
      for (PetscInt k = a[2]; k < b[2]; ++k) {
        if (e == 2) {  // the whole plane of lines j in [a1, b1) at once
          for (PetscInt t = -R; t <= R; ++t) rows_[t + R] = c + line(a[1], foldAll ? Fold(2, k + t) : k + t);
          SumShiftedRows(o + line(a[1], k), rows_.data(), g - R, 2 * R + 1, (b[1] - a[1]) * sy);
          continue;
        }
        // y: the lines whose taps all stay in the active range at once, the others one by one
        PetscInt j0 = a[1], j1 = b[1];
        if (foldAll) j0 = std::max(a[1], lo_[1] + R), j1 = std::min(b[1], hi_[1] - R + 1);
        if (j1 > j0) {
          for (PetscInt t = -R; t <= R; ++t) rows_[t + R] = c + line(j0 + t, k);
          SumShiftedRows(o + line(j0, k), rows_.data(), g - R, 2 * R + 1, (j1 - j0) * sy);
        } else j0 = j1 = b[1];
        for (PetscInt j = a[1]; j < b[1]; ++j) {
          if (j >= j0 && j < j1) continue;
          for (PetscInt t = -R; t <= R; ++t) rows_[t + R] = &in[k][foldAll ? Fold(1, j + t) : j + t][a[0]];
          SumShiftedRows(&out[k][j][a[0]], rows_.data(), g - R, 2 * R + 1, nx);
        }
      }
    } else {
      for (PetscInt k = a[2]; k < b[2]; ++k)
        for (PetscInt j = a[1]; j < b[1]; ++j) {
          const PetscInt q = e == 1 ? j : k;
          for (PetscInt t = -R; t <= R; ++t) {
            const PetscInt r = foldAll ? Fold(e, q + t) : q + t;
            rows_[t + R]     = (e == 1 ? &in[k][r][0] : &in[r][j][0]) + a[0];
          }
          SumShiftedRows(&out[k][j][a[0]], rows_.data(), g - R, 2 * R + 1, nx);
        }
    }
    if (swap) {
      // The points the pass does not take (wall faces: whole planes, lines, the x ends of rows) keep their value.
      // Restricted: only on the planes computed (the z pass sums whole x rows, so the x ends must be right in
      // copy_ on the planes it reads and put back in v on the planes it writes).
      for (PetscInt k = restrict_ ? a[2] : s[2]; k < (restrict_ ? b[2] : s[2] + n[2]); ++k)
        for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
          const PetscScalar *src = &in[k][j][0];
          PetscScalar       *dst = &out[k][j][0];
          if (k < a[2] || k >= b[2] || j < a[1] || j >= b[1] || nx <= 0) std::copy(src + s[0], src + s[0] + n[0], dst + s[0]);
          else {
            std::copy(src + s[0], src + a[0], dst + s[0]);
            std::copy(src + b[0], src + s[0] + n[0], dst + b[0]);
          }
        }
    }
    if (!inPlace) PetscCall(DMDAVecRestoreArrayRead(dm_, ghosts ? local_ : cur, &in));
    PetscCall(DMDAVecRestoreArray(dm_, dst, &out));
    cur = dst;
  }
  if (cur != v) PetscCall(VecCopy(cur, v));
  PetscCall(PetscLogEventEnd(evApply, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
