#include "vofdem/coupling/KernelAverager.hpp"

#include "vofdem/base/Runtime.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace {

// fn(offset, w) for each point of a tent (KernelAverager::TentSpan) with nonzero weight w = g_x g_y g_z, the
// factors gw (all points, or with the wall faces left out).
template <class Tent, class F>
inline void ForEachTentPoint(const Tent &t, const PetscReal (*gw)[2], F &&fn) {
  for (PetscInt c = 0; c < t.n[2]; ++c)
    for (PetscInt b = 0; b < t.n[1]; ++b) {
      const PetscReal wyz = gw[1][b] * gw[2][c];
      const PetscInt  o   = t.base + b * t.stride[1] + c * t.stride[2];
      for (PetscInt a = 0; a < t.n[0]; ++a) {
        const PetscReal w = gw[0][a] * wyz;
        if (w != 0) fn(o + a, w);
      }
    }
}

}  // namespace

PetscErrorCode KernelAverager::Layout(int loc, DM *dm) const {
  const Grid     &grid = sg_->Base();
  const PetscInt *l[3];
  PetscInt        m[3], N[3];
  DMBoundaryType  bt[3];

  PetscFunctionBeginUser;
  DM base = sg_->Location(loc);
  PetscCall(DMDAGetInfo(base, nullptr, &N[0], &N[1], &N[2], &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(base, &l[0], &l[1], &l[2]));
  for (int d = 0; d < 3; ++d) {
    bt[d] = grid.Periodic(d) ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_NONE;
    // PETSc needs every rank to own at least the ghost width wherever there is a neighbour.
    for (PetscInt r = 0; r < m[d] && m[d] > 1; ++r)
      if (l[d][r] < width_)
        VofdemInputError(grid.Comm(),
                         "%s: the kernel reaches %" PetscInt_FMT " cells, more than the %" PetscInt_FMT " cells a rank owns in %c; use fewer ranks in %c (-grid_ranks), more cells, or a narrower kernel (-%s_kernel_width)",
                         settings_.owner, width_, l[d][r], "xyz"[d], "xyz"[d], settings_.owner);
    if (m[d] == 1 && grid.Periodic(d) && N[d] < width_)
      VofdemInputError(grid.Comm(), "%s: the kernel reaches %" PetscInt_FMT " cells, more than the %" PetscInt_FMT " periodic cells in %c; use a narrower kernel (-%s_kernel_width)",
                       settings_.owner, width_, N[d], "xyz"[d], settings_.owner);
  }
  PetscCall(DMDACreate3d(grid.Comm(), bt[0], bt[1], bt[2], DMDA_STENCIL_BOX, N[0], N[1], N[2], m[0], m[1], m[2], 1, width_, l[0], l[1], l[2], dm));
  PetscCall(DMSetUp(*dm));
  PetscFunctionReturn(0);
}

PetscErrorCode KernelAverager::SetUp(const StaggeredGrid &sg, const Settings &s, PetscReal maxCutoff, PetscReal margin) {
  PetscFunctionBeginUser;
  sg_       = &sg;
  settings_ = s;
  const PetscReal *h    = sg.Base().Spacing();
  const PetscReal  hmin = std::min(h[0], std::min(h[1], h[2]));
  // Unresolved: the containing cell and its faces (one point beyond the cell's index either way);
  // linear: the two points either side; divided: the cells of points up to a radius (maxCutoff) away, and their faces.
  const PetscReal reach = s.shape == kernel::Shape::Unresolved || s.shape == kernel::Shape::Linear ? hmin : s.shape == kernel::Shape::Divided ? hmin + maxCutoff : maxCutoff;
  width_ = (PetscInt)std::ceil((reach + margin) / hmin) + 1;
  tentKey_.clear(), tentState_.clear(), tentAxes_.clear();  // the tents remembered were for another grid
  for (auto &e : excluded_) e.clear();                       // and so were the excluded points
  excluding_ = false;
  for (int loc = 0; loc < 4; ++loc) {
    PetscCall(Layout(loc, &dm_[loc]));
    PetscCall(DMCreateLocalVector(dm_[loc], &local_[loc]));
    PetscCall(DMDAGetGhostCorners(dm_[loc], &gs_[loc][0], &gs_[loc][1], &gs_[loc][2], &gm_[loc][0], &gm_[loc][1], &gm_[loc][2]));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode KernelAverager::Destroy() {
  PetscFunctionBeginUser;
  for (int loc = 0; loc < 4; ++loc) {
    PetscCall(VecDestroy(&local_[loc]));
    for (Vec &v : pool_[loc]) PetscCall(VecDestroy(&v));
    pool_[loc].clear();
    PetscCall(DMDestroy(&dm_[loc]));
  }
  PetscFunctionReturn(0);
}

// The tent's points of location loc around x: for each direction the two points either side (clamped to
// the box), weights the products of the directions' factors max(1 - |t - s|, 0), zero weights dropped.
bool KernelAverager::GatherTent(int loc, const PetscReal x[3], PetscInt *off, PetscReal *raw, char *wall, size_t &m, PetscReal &sumAll, PetscReal &sumInner) const {
  const Grid      &grid = sg_->Base();
  const PetscReal *h = grid.Spacing();
  PetscInt         q0[3], q1[3];
  PetscReal        s[3], f[3][2] = {{0, 0}, {0, 0}, {0, 0}};
  PetscInt         wallAt[2] = {PETSC_MIN_INT, PETSC_MIN_INT};  // the wall-face indices along loc (faces only, not periodic; no index is PETSC_MIN_INT, a periodic one may be -1)
  for (int e = 0; e < 3; ++e) {
    const PetscInt N = sg_->Points(loc, e);
    // Continuous index of x in the location's numbering (faces normal to e sit at integer indices).
    s[e]        = (x[e] - grid.Lower()[e]) / h[e] - (loc == e ? 0 : 0.5);
    PetscInt lo = 0, hi = N - 1;
    if (grid.Periodic(e)) {
      // A particle held by this rank may have been wrapped to the far side of the box since it last
      // migrated: use its image nearest this rank's points.
      const PetscReal mid = gs_[loc][e] + 0.5 * gm_[loc][e];
      if (s[e] - mid > 0.5 * N) s[e] -= N;
      else if (s[e] - mid < -0.5 * N) s[e] += N;
      lo = PETSC_MIN_INT, hi = PETSC_MAX_INT;
    } else if (loc == e) wallAt[0] = 0, wallAt[1] = N - 1;
    const PetscInt below = (PetscInt)std::floor(s[e]);
    q0[e] = std::max(below, lo);
    q1[e] = std::min(below + 1, hi);
    if (q0[e] < gs_[loc][e] || q1[e] >= gs_[loc][e] + gm_[loc][e]) return false;
    for (PetscInt t = q0[e]; t <= q1[e]; ++t) f[e][t - q0[e]] = std::max(1 - std::fabs(t - s[e]), 0.0);
  }
  const PetscInt sy = gm_[loc][0], sz = gm_[loc][0] * gm_[loc][1];
  PetscReal      all = 0, inner = 0;
  size_t         count = 0;
  for (PetscInt k = q0[2]; k <= q1[2]; ++k)
    for (PetscInt j = q0[1]; j <= q1[1]; ++j) {
      const bool     rowWall = (loc == 1 && (j == wallAt[0] || j == wallAt[1])) || (loc == 2 && (k == wallAt[0] || k == wallAt[1]));
      const PetscInt base    = (j - gs_[loc][1]) * sy + (k - gs_[loc][2]) * sz - gs_[loc][0];
      for (PetscInt i = q0[0]; i <= q1[0]; ++i) {
        const PetscReal w = f[0][i - q0[0]] * f[1][j - q0[1]] * f[2][k - q0[2]];
        if (w <= 0) continue;
        Append(base + i, w, rowWall || (loc == 0 && (i == wallAt[0] || i == wallAt[1])), off, raw, wall, count, all, inner);
      }
    }
  m = count, sumAll = all, sumInner = inner;
  return true;
}

// The points of location loc around x with their raw kernel weights. The wall faces of the location's
// own component are included and flagged in pts.wall (deposits and pressure-gradient averages leave
// them out), so one gather serves both kinds of use. False if the support leaves this rank's
// ghosted region.
bool KernelAverager::Gather(int loc, const PetscReal x[3], PetscReal H, Points &pts) const {
  pts.n      = 0;
  pts.sumAll = pts.sumInner = 0;
  if (settings_.shape == kernel::Shape::Divided) return GatherDivided(loc, x, H, pts);
  if (settings_.shape == kernel::Shape::Linear) {
    if (pts.raw.size() < 8) {
      pts.offsets.resize(8);
      pts.raw.resize(8);
      pts.wall.resize(8);
    }
    return GatherTent(loc, x, pts.offsets.data(), pts.raw.data(), pts.wall.data(), pts.n, pts.sumAll, pts.sumInner);
  }
  const Grid      &grid = sg_->Base();
  const PetscReal *h = grid.Spacing();
  PetscInt         q0[3], q1[3], N[3];
  PetscReal        s[3];
  const bool      unresolved = settings_.shape == kernel::Shape::Unresolved;  // no kernel of radius rc
  const PetscReal rc         = unresolved ? 0 : Cutoff(H);
  PetscInt        wallAt[2] = {PETSC_MIN_INT, PETSC_MIN_INT};  // the wall-face indices along loc (faces only, not periodic; no index is PETSC_MIN_INT, a periodic one may be -1)
  for (int e = 0; e < 3; ++e) {
    N[e] = sg_->Points(loc, e);
    // Continuous index of x in the location's numbering (faces normal to e sit at integer indices).
    s[e] = (x[e] - grid.Lower()[e]) / h[e] - (loc == e ? 0 : 0.5);
    PetscReal c = (x[e] - grid.Lower()[e]) / h[e];  // in cells
    PetscInt  lo = 0, hi = N[e] - 1;
    if (grid.Periodic(e)) {
      // A particle held by this rank may have been wrapped to the far side of the box since it last
      // migrated: use its image nearest this rank's points.
      const PetscReal mid = gs_[loc][e] + 0.5 * gm_[loc][e];
      if (s[e] - mid > 0.5 * N[e]) s[e] -= N[e], c -= N[e];
      else if (s[e] - mid < -0.5 * N[e]) s[e] += N[e], c += N[e];
      lo = PETSC_MIN_INT, hi = PETSC_MAX_INT;
    } else if (loc == e) wallAt[0] = 0, wallAt[1] = N[e] - 1;
    if (unresolved) {
      const PetscInt cell = (PetscInt)std::floor(c);  // the containing cell
      const PetscInt cc = grid.Periodic(e) ? cell : std::min(std::max(cell, (PetscInt)0), grid.Cells()[e] - 1);
      q0[e] = cc, q1[e] = loc == e ? cc + 1 : cc;
    } else {
      q0[e] = (PetscInt)std::ceil(s[e] - rc / h[e]);
      q1[e] = (PetscInt)std::floor(s[e] + rc / h[e]);
    }
    q0[e] = std::max(q0[e], lo);
    q1[e] = std::min(q1[e], hi);
    if (q0[e] < gs_[loc][e] || q1[e] >= gs_[loc][e] + gm_[loc][e]) return false;
  }
  // Room for every point of the index box (grown once, reused: no allocation per particle).
  size_t box = 1;
  for (int e = 0; e < 3; ++e) box *= (size_t)std::max(q1[e] - q0[e] + 1, (PetscInt)0);
  if (pts.raw.size() < box) {
    pts.offsets.resize(box);
    pts.raw.resize(box);
    pts.wall.resize(box);
  }
  const PetscInt  sy = gm_[loc][0], sz = gm_[loc][0] * gm_[loc][1];
  const PetscReal rc2 = rc * rc, irc2 = unresolved ? 0 : 1 / rc2, i2H2 = 1 / (2 * H * H);
  const bool      smooth = settings_.shape == kernel::Shape::Smooth && !unresolved;
  // dx^2 of every x index of the box, computed once per particle (the same numbers as in the loop).
  if (pts.dx2.size() < (size_t)std::max(q1[0] - q0[0] + 1, (PetscInt)0)) pts.dx2.resize(q1[0] - q0[0] + 1);
  for (PetscInt i = q0[0]; i <= q1[0]; ++i) {
    const PetscReal dx = (i - s[0]) * h[0];
    pts.dx2[i - q0[0]] = dx * dx;
  }
  const PetscReal *dx2 = pts.dx2.data() - q0[0];
  // The sums in registers: accumulated through pts they were stored and reloaded at every point.
  PetscReal sumAll = 0, sumInner = 0;
  size_t    m    = 0;
  PetscInt *off  = pts.offsets.data();
  PetscReal *raw = pts.raw.data();
  char     *wall = pts.wall.data();
  for (PetscInt k = q0[2]; k <= q1[2]; ++k) {
    const PetscReal dz = (k - s[2]) * h[2];
    for (PetscInt j = q0[1]; j <= q1[1]; ++j) {
      const PetscReal dy = (j - s[1]) * h[1];
      PetscInt        i0 = q0[0], i1 = q1[0];
      if (!unresolved) {
        // Only the chord of the support sphere along x can have weight (a cube of points around a
        // sphere is half empty); one point of margin each side, the weight itself decides at the rim.
        const PetscReal yz = dy * dy + dz * dz;
        if (yz >= rc2) continue;
        const PetscReal half = std::sqrt(rc2 - yz) / h[0];
        i0 = std::max(i0, (PetscInt)std::ceil(s[0] - half) - 1);
        i1 = std::min(i1, (PetscInt)std::floor(s[0] + half) + 1);
      }
      const PetscReal yz = dy * dy + dz * dz;
      // The row's wall flag (faces of y or z) or the wall faces' x indices (faces of x).
      const bool      rowWall = (loc == 1 && (j == wallAt[0] || j == wallAt[1])) || (loc == 2 && (k == wallAt[0] || k == wallAt[1]));
      const PetscInt  base    = (j - gs_[loc][1]) * sy + (k - gs_[loc][2]) * sz - gs_[loc][0];
      if (smooth) {  // the common case, written out: kernel::Weight with its divisions hoisted
        for (PetscInt i = i0; i <= i1; ++i) {
          const PetscReal r2 = dx2[i] + yz;
          if (r2 >= rc2) continue;
          const PetscReal q = 1 - r2 * irc2, w = (q * q) * (q * q);
          if (w <= 0) continue;
          Append(base + i, w, rowWall || (loc == 0 && (i == wallAt[0] || i == wallAt[1])), off, raw, wall, m, sumAll, sumInner);
        }
        continue;
      }
      for (PetscInt i = i0; i <= i1; ++i) {
        PetscReal w = 1;
        if (!unresolved) {
          const PetscReal r2 = dx2[i] + yz;
          if (r2 >= rc2) continue;
          w = std::exp(-r2 * i2H2);
        }
        if (w <= 0) continue;
        Append(base + i, w, rowWall || (loc == 0 && (i == wallAt[0] || i == wallAt[1])), off, raw, wall, m, sumAll, sumInner);
      }
    }
  }
  pts.n        = m;
  pts.sumAll   = sumAll;
  pts.sumInner = sumInner;
  return true;
}

bool KernelAverager::Support(int loc, const PetscReal x[3], PetscReal H, bool needAll, bool needInner, Span &span) {
  if (!Gather(loc, x, H, points_)) return false;
  const Points &pts = points_;
  if (wAll_.size() < pts.n) wAll_.resize(pts.raw.size()), wInner_.resize(pts.raw.size());
  // A point-sampled kernel gives a wall face half its weight: the face's control volume is half a cell's.
  const bool half   = settings_.shape == kernel::Shape::Smooth || settings_.shape == kernel::Shape::Truncated;
  PetscReal  sumAll = pts.sumAll;
  if (half && pts.sumAll != pts.sumInner) {
    sumAll = 0;
    for (size_t k = 0; k < pts.n; ++k) sumAll += pts.wall[k] ? 0.5 * pts.raw[k] : pts.raw[k];
  }
  if (needAll && sumAll > 0)
    for (size_t k = 0; k < pts.n; ++k) wAll_[k] = (half && pts.wall[k] ? 0.5 * pts.raw[k] : pts.raw[k]) / sumAll;
  if (needInner && pts.sumInner > 0)
    for (size_t k = 0; k < pts.n; ++k) wInner_[k] = pts.wall[k] ? 0 : pts.raw[k] / pts.sumInner;
  span.offsets = pts.offsets.data(), span.wAll = wAll_.data(), span.wInner = wInner_.data(), span.wall = pts.wall.data();
  span.n = pts.n, span.sumAll = sumAll, span.sumInner = pts.sumInner;
  return true;
}

bool KernelAverager::Normalise(int loc, const PetscReal x[3], const Span &span, bool inner, std::vector<PetscInt> &offsets, std::vector<PetscReal> &weights) const {
  offsets.clear();
  weights.clear();
  const PetscReal sum = inner ? span.sumInner : span.sumAll;
  if (sum > 0) {
    for (size_t k = 0; k < span.n; ++k) {
      if (inner && span.wall[k]) continue;
      offsets.push_back(span.offsets[k]);
      weights.push_back(inner ? span.wInner[k] : span.wAll[k]);
    }
    return true;
  }
  const Grid      &grid = sg_->Base();
  const PetscReal *h    = grid.Spacing();
  PetscInt         q[3];
  for (int e = 0; e < 3; ++e) {
    const PetscInt  N = sg_->Points(loc, e);
    const PetscReal s = (x[e] - grid.Lower()[e]) / h[e] - (loc == e ? 0 : 0.5);
    PetscInt        lo = 0, hi = N - 1;
    if (grid.Periodic(e)) lo = PETSC_MIN_INT, hi = PETSC_MAX_INT;
    else if (inner && loc == e) lo = 1, hi = N - 2;
    PetscReal se = s;
    if (grid.Periodic(e)) {
      const PetscReal mid = gs_[loc][e] + 0.5 * gm_[loc][e];
      if (se - mid > 0.5 * N) se -= N;
      else if (se - mid < -0.5 * N) se += N;
    }
    q[e] = std::min(std::max((PetscInt)std::lround(se), lo), hi);
    if (q[e] < gs_[loc][e] || q[e] >= gs_[loc][e] + gm_[loc][e]) return false;
  }
  offsets.assign(1, (q[0] - gs_[loc][0]) + (q[1] - gs_[loc][1]) * gm_[loc][0] + (q[2] - gs_[loc][2]) * gm_[loc][0] * gm_[loc][1]);
  weights.assign(1, 1.0);
  return true;
}

PetscErrorCode KernelAverager::LocalVectors(int loc, size_t count) {
  PetscFunctionBeginUser;
  while (pool_[loc].size() < count) {
    Vec v;
    PetscCall(DMCreateLocalVector(dm_[loc], &v));
    pool_[loc].push_back(v);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode KernelAverager::Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, const PetscReal *value, PetscInt stride, Vec out, bool walls, bool excluded) {
  PetscFunctionBeginUser;
  PetscCall(Deposit(loc, n, x, H, 1, &value, stride, &out, walls, excluded));
  PetscFunctionReturn(0);
}

PetscErrorCode KernelAverager::Deposit(int loc, PetscInt n, const PetscReal *x, const PetscReal *H, PetscInt nf, const PetscReal *const value[], PetscInt stride, Vec out[], bool walls,
                                       bool excluded) {
  PetscInt bad = 0, anyBad;

  PetscFunctionBeginUser;
  PetscCall(LocalVectors(loc, nf));
  arrays_.resize(nf);
  for (PetscInt f = 0; f < nf; ++f) {
    PetscCall(VecSet(pool_[loc][f], 0));
    PetscCall(VecGetArray(pool_[loc][f], &arrays_[f]));
  }
  values_.resize(nf);
  const bool  exclude = excluding_ && !excluded;
  const char *out_    = exclude ? excluded_[loc].data() : nullptr;  // the points left out
  const bool  tent    = settings_.shape == kernel::Shape::Linear && !exclude;  // excluded points: the generic path
  if (tent) SizeTent(n);
  for (PetscInt p = 0; p < n; ++p) {
    if (tent) {
      TentSpan t;
      if (!TentAt(loc, p, &x[3 * p], t)) {
        ++bad;
        continue;
      }
      if (walls ? t.okAll : t.okInner) {  // all fields in one pass over the tent's points (wall faces left out unless walls)
        for (PetscInt f = 0; f < nf; ++f) values_[f] = value[f][p * stride];
        ForEachTentPoint(t, walls ? t.g : t.gi, [&](PetscInt o, PetscReal w) {
          for (PetscInt f = 0; f < nf; ++f) arrays_[f][o] += values_[f] * w;
        });
        continue;
      }
    }
    Span sp;
    if (!Support(loc, &x[3 * p], H[p], walls, !walls, sp)) {
      ++bad;
      continue;
    }
    for (PetscInt f = 0; f < nf; ++f) values_[f] = value[f][p * stride];
    if (exclude && (walls ? sp.sumAll > 0 : sp.sumInner > 0)) {  // the same weights over the points that remain
      PetscReal kept = 0;
      bool      any  = false;
      for (size_t k = 0; k < sp.n; ++k) {
        if (!walls && sp.wall[k]) continue;
        if (out_[sp.offsets[k]]) any = true;
        else kept += walls ? sp.wAll[k] : sp.wInner[k];
      }
      if (any && kept > 0) {
        for (size_t k = 0; k < sp.n; ++k) {
          if ((!walls && sp.wall[k]) || out_[sp.offsets[k]]) continue;
          const PetscReal w = (walls ? sp.wAll[k] : sp.wInner[k]) / kept;
          const PetscInt  o = sp.offsets[k];
          for (PetscInt f = 0; f < nf; ++f) arrays_[f][o] += values_[f] * w;
        }
        continue;
      }
    }
    if (walls ? sp.sumAll > 0 : sp.sumInner > 0) {  // all fields in one pass over the support
      for (size_t k = 0; k < sp.n; ++k) {
        if (!walls && sp.wall[k]) continue;
        const PetscReal w = walls ? sp.wAll[k] : sp.wInner[k];
        const PetscInt  o = sp.offsets[k];
        for (PetscInt f = 0; f < nf; ++f) arrays_[f][o] += values_[f] * w;
      }
      continue;
    }
    if (!Normalise(loc, &x[3 * p], sp, !walls, offsets_, weights_)) {  // the kernel missed every point: the nearest
      ++bad;
      continue;
    }
    for (PetscInt f = 0; f < nf; ++f) {
      PetscScalar    *a = arrays_[f];
      const PetscReal v = values_[f];
      for (size_t k = 0; k < offsets_.size(); ++k) a[offsets_[k]] += v * weights_[k];
    }
  }
  for (PetscInt f = 0; f < nf; ++f) PetscCall(VecRestoreArray(pool_[loc][f], &arrays_[f]));
  PetscCallMPI(MPI_Allreduce(&bad, &anyBad, 1, MPIU_INT, MPI_SUM, sg_->Base().Comm()));
  PetscCheck(anyBad == 0, sg_->Base().Comm(), PETSC_ERR_PLIB, "coupling: %" PetscInt_FMT " particle kernels reach beyond the ghost layer (%" PetscInt_FMT " cells)", anyBad, width_);
  for (PetscInt f = 0; f < nf; ++f) PetscCall(DMLocalToGlobal(dm_[loc], pool_[loc][f], ADD_VALUES, out[f]));
  PetscFunctionReturn(0);
}

PetscErrorCode KernelAverager::Average(int loc, Vec field, Vec weight, PetscInt n, const PetscReal *x, const PetscReal *H, PetscReal *out, PetscInt stride, bool walls) {
  PetscFunctionBeginUser;
  PetscCall(Average(loc, 1, &field, &weight, &walls, n, x, H, &out, stride));
  PetscFunctionReturn(0);
}

PetscErrorCode KernelAverager::Average(int loc, PetscInt nf, const Vec field[], const Vec weight[], const bool walls[], PetscInt n, const PetscReal *x, const PetscReal *H,
                                       PetscReal *const out[], PetscInt stride) {
  PetscInt bad = 0, anyBad;

  PetscFunctionBeginUser;
  // Local copies: field f in pool slot f, its weight (if any) in slot nf + f.
  PetscCall(LocalVectors(loc, 2 * nf));
  arrays_.assign(2 * nf, nullptr);
  bool needAll = false, needInner = false;
  for (PetscInt f = 0; f < nf; ++f) {
    PetscCall(DMGlobalToLocal(dm_[loc], field[f], INSERT_VALUES, pool_[loc][f]));
    PetscCall(VecGetArray(pool_[loc][f], &arrays_[f]));
    if (weight[f]) {
      PetscCall(DMGlobalToLocal(dm_[loc], weight[f], INSERT_VALUES, pool_[loc][nf + f]));
      PetscCall(VecGetArray(pool_[loc][nf + f], &arrays_[nf + f]));
    }
    (walls[f] ? needAll : needInner) = true;
  }
  const bool tent = settings_.shape == kernel::Shape::Linear;
  if (tent) SizeTent(n);
  for (PetscInt p = 0; p < n; ++p) {
    if (tent) {
      TentSpan t;
      if (!TentAt(loc, p, &x[3 * p], t)) {
        ++bad;
        for (PetscInt f = 0; f < nf; ++f) out[f][p * stride] = 0;
        continue;
      }
      if ((!needAll || t.okAll) && (!needInner || t.okInner)) {  // field by field over the tent's points
        for (PetscInt f = 0; f < nf; ++f) {
          const PetscScalar *gv = arrays_[f], *c = arrays_[nf + f];
          PetscReal          num = 0, den = 0;
          ForEachTentPoint(t, walls[f] ? t.g : t.gi, [&](PetscInt o, PetscReal w) {
            const PetscReal wk = c ? w * PetscRealPart(c[o]) : w;
            num += wk * PetscRealPart(gv[o]);
            den += wk;
          });
          out[f][p * stride] = den > 0 ? num / den : 0;
        }
        continue;
      }
    }
    Span sp;
    bool ok = Support(loc, &x[3 * p], H[p], needAll, needInner, sp);
    if (ok && (!needAll || sp.sumAll > 0) && (!needInner || sp.sumInner > 0)) {
      // Field by field, the sums in registers; each field's sums take the same terms in the same order as
      // through Normalise below.
      for (PetscInt f = 0; f < nf; ++f) {
        const PetscScalar *g = arrays_[f], *c = arrays_[nf + f];
        PetscReal          num = 0, den = 0;
        if (walls[f]) {
          for (size_t k = 0; k < sp.n; ++k) {
            const PetscInt  o  = sp.offsets[k];
            const PetscReal wk = c ? sp.wAll[k] * PetscRealPart(c[o]) : sp.wAll[k];
            num += wk * PetscRealPart(g[o]);
            den += wk;
          }
        } else {
          for (size_t k = 0; k < sp.n; ++k) {
            if (sp.wall[k]) continue;
            const PetscInt  o  = sp.offsets[k];
            const PetscReal wk = c ? sp.wInner[k] * PetscRealPart(c[o]) : sp.wInner[k];
            num += wk * PetscRealPart(g[o]);
            den += wk;
          }
        }
        out[f][p * stride] = den > 0 ? num / den : 0;
      }
      continue;
    }
    if (ok && needAll) ok = Normalise(loc, &x[3 * p], sp, false, offsets_, weights_);
    if (ok && needInner) ok = Normalise(loc, &x[3 * p], sp, true, offsetsInner_, weightsInner_);
    if (!ok) {
      ++bad;
      for (PetscInt f = 0; f < nf; ++f) out[f][p * stride] = 0;
      continue;
    }
    for (PetscInt f = 0; f < nf; ++f) {
      const std::vector<PetscInt>  &o = walls[f] ? offsets_ : offsetsInner_;
      const std::vector<PetscReal> &w = walls[f] ? weights_ : weightsInner_;
      const PetscScalar            *g = arrays_[f], *c = arrays_[nf + f];
      PetscReal                     num = 0, den = 0;
      for (size_t k = 0; k < o.size(); ++k) {
        const PetscReal wk = c ? w[k] * PetscRealPart(c[o[k]]) : w[k];
        num += wk * PetscRealPart(g[o[k]]);
        den += wk;
      }
      out[f][p * stride] = den > 0 ? num / den : 0;
    }
  }
  for (PetscInt f = 0; f < 2 * nf; ++f)
    if (arrays_[f]) PetscCall(VecRestoreArray(pool_[loc][f], &arrays_[f]));
  PetscCallMPI(MPI_Allreduce(&bad, &anyBad, 1, MPIU_INT, MPI_SUM, sg_->Base().Comm()));
  PetscCheck(anyBad == 0, sg_->Base().Comm(), PETSC_ERR_PLIB, "coupling: %" PetscInt_FMT " particle kernels reach beyond the ghost layer (%" PetscInt_FMT " cells)", anyBad, width_);
  PetscFunctionReturn(0);
}

}  // namespace vofdem
