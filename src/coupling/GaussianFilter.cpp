#include "vofdem/coupling/GaussianFilter.hpp"

#include "vofdem/core/Runtime.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

std::vector<PetscReal> GaussianFilter::Taps(PetscReal h, PetscReal spread) {
  if (!(spread > 0)) return {1.0};
  const PetscInt         R = std::max((PetscInt)1, (PetscInt)std::ceil(4 * std::sqrt(spread) / h));
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
  // (taps truncated at about one b: variance ~0.29 b^2 = 4.6 spread): bisection to round-off.
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
  acc_.assign((size_t)std::max(cn[0], (PetscInt)1), 0.0);
  PetscFunctionReturn(0);
}

PetscErrorCode GaussianFilter::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&local_));
  PetscCall(VecDestroy(&copy_));
  PetscCall(DMDestroy(&dm_));
  PetscFunctionReturn(0);
}

// Row by row (x fastest): the x pass sums along the row; the y and z passes add whole source rows times a
// tap, contiguous in x. Folding only where the taps reach past the active range. A direction that is
// neither split nor periodic needs no ghosts: the pass reads a plain copy instead of a ghost update.
PetscErrorCode GaussianFilter::Apply(Vec v) {
  PetscInt s[3], n[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetCorners(dm_, &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  for (int e = 0; e < 3; ++e) {
    if (!R_[e]) continue;
    const PetscScalar ***in;
    PetscScalar       ***out;
    const bool          ghosts = needGhosts_[e];
    if (ghosts) {
      PetscCall(DMGlobalToLocal(dm_, v, INSERT_VALUES, local_));
      PetscCall(DMDAVecGetArrayRead(dm_, local_, &in));
    } else {
      PetscCall(VecCopy(v, copy_));
      PetscCall(DMDAVecGetArrayRead(dm_, copy_, &in));
    }
    PetscCall(DMDAVecGetArray(dm_, v, &out));
    const PetscInt   R = R_[e];
    const PetscReal *g = taps_[e].data() + R;  // g[t], t in [-R, R]
    // The points written: the active range (wall faces keep their value).
    PetscInt a[3], b[3];
    for (int d = 0; d < 3; ++d) {
      a[d] = periodic_[d] ? s[d] : std::max(s[d], lo_[d]);
      b[d] = periodic_[d] ? s[d] + n[d] : std::min(s[d] + n[d], hi_[d] + 1);
    }
    const bool     foldAll = !periodic_[e];
    const PetscInt safeLo = lo_[e] + R, safeHi = hi_[e] - R;  // no folding for taps from these points
    for (PetscInt k = a[2]; k < b[2]; ++k)
      for (PetscInt j = a[1]; j < b[1]; ++j) {
        PetscScalar *row = &out[k][j][0];
        if (e == 0) {
          const PetscScalar *src = &in[k][j][0];
          for (PetscInt i = a[0]; i < b[0]; ++i) {
            PetscScalar sum = 0;
            if (!foldAll || (i >= safeLo && i <= safeHi))
              for (PetscInt t = -R; t <= R; ++t) sum += g[t] * src[i + t];
            else
              for (PetscInt t = -R; t <= R; ++t) sum += g[t] * src[Fold(0, i + t)];
            row[i] = sum;
          }
          continue;
        }
        PetscScalar *acc = acc_.data() - a[0];
        for (PetscInt i = a[0]; i < b[0]; ++i) acc[i] = 0;
        const PetscInt q = e == 1 ? j : k;
        for (PetscInt t = -R; t <= R; ++t) {
          const PetscInt     r   = foldAll ? Fold(e, q + t) : q + t;
          const PetscScalar *src = e == 1 ? &in[k][r][0] : &in[r][j][0];
          const PetscReal    w   = g[t];
          for (PetscInt i = a[0]; i < b[0]; ++i) acc[i] += w * src[i];
        }
        for (PetscInt i = a[0]; i < b[0]; ++i) row[i] = acc[i];
      }
    PetscCall(DMDAVecRestoreArray(dm_, v, &out));
    PetscCall(DMDAVecRestoreArrayRead(dm_, ghosts ? local_ : copy_, &in));
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
