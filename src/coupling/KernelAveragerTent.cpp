// The tent (Linear shape) of KernelAverager, separable: the support of the grid smoothings (DiffusionSmoother:
// tent deposit and read, then diffusion or a Gaussian filter on the grid), used for every particle and
// location at every coupled step, so kept to index arithmetic and a few products per point.
#include "vofdem/coupling/KernelAverager.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

void KernelAverager::SizeTent(PetscInt n) {
  if (settings_.shape != kernel::Shape::Linear || tentState_.size() >= (size_t)n) return;
  const size_t m = (size_t)n;  // grown before the particle loops, not in them
  tentKey_.resize(3 * m), tentState_.resize(m, 0), tentAxes_.resize(m);
}

// Per direction, x's continuous index in the cells' numbering (v = 0) and in that of the faces normal to the
// direction (v = 1), the index below it and the factors max(1 - |t - s|, 0) of the points either side,
// divided by their sum (one to round-off: the tent's two factors add up to one).
void KernelAverager::TentAxesAt(const PetscReal x[3], TentAxes &a) const {
  const Grid      &grid = sg_->Base();
  const PetscReal *h    = grid.Spacing();
  for (int e = 0; e < 3; ++e) {
    const PetscReal t = (x[e] - grid.Lower()[e]) / h[e];
    for (int v = 0; v < 2; ++v) {
      const PetscReal s = t - (v ? 0 : 0.5);
      const PetscInt  b = (PetscInt)std::floor(s);
      const PetscReal f0 = std::max(1 - std::fabs(b - s), 0.0), f1 = std::max(1 - std::fabs(b + 1 - s), 0.0);
      a.s[e][v]     = s;
      a.below[e][v] = b;
      a.g[e][v][0]  = f0 / (f0 + f1);
      a.g[e][v][1]  = f1 / (f0 + f1);
    }
  }
}

bool KernelAverager::TentAt(int loc, PetscInt p, const PetscReal x[3], TentSpan &t) {
  if (tentState_.size() <= (size_t)p) SizeTent(p + 1);  // callers size it first
  PetscReal *key = &tentKey_[3 * p];
  if (!(tentState_[p] && key[0] == x[0] && key[1] == x[1] && key[2] == x[2])) {
    TentAxesAt(x, tentAxes_[p]);
    key[0] = x[0], key[1] = x[1], key[2] = x[2];
    tentState_[p] = 1;
  }
  const TentAxes &a    = tentAxes_[p];
  const Grid     &grid = sg_->Base();
  t.okAll = t.okInner = true;
  t.base              = 0;
  t.stride[0] = 1, t.stride[1] = gm_[loc][0], t.stride[2] = gm_[loc][0] * gm_[loc][1];
  for (int e = 0; e < 3; ++e) {
    const PetscInt N = sg_->Points(loc, e);
    const int      v = loc == e;  // faces normal to e sit at integer indices
    PetscInt       below = a.below[e][v], lo = 0, hi = N - 1;
    PetscReal      g0 = a.g[e][v][0], g1 = a.g[e][v][1];
    const bool     periodic = grid.Periodic(e);
    if (periodic) {
      // A particle held by this rank may have been wrapped to the far side of the box since it last
      // migrated: use its image nearest this rank's points.
      const PetscReal mid = gs_[loc][e] + 0.5 * gm_[loc][e];
      PetscReal       s   = a.s[e][v];
      const bool      up = s - mid < -0.5 * N, down = s - mid > 0.5 * N;
      if (up || down) {
        s += up ? N : -N;
        below = (PetscInt)std::floor(s);
        const PetscReal f0 = std::max(1 - std::fabs(below - s), 0.0), f1 = std::max(1 - std::fabs(below + 1 - s), 0.0);
        g0 = f0 / (f0 + f1), g1 = f1 / (f0 + f1);
      }
      lo = PETSC_MIN_INT, hi = PETSC_MAX_INT;
    }
    const PetscInt q0 = std::max(below, lo), q1 = std::min(below + 1, hi);
    if (q0 < gs_[loc][e] || q1 >= gs_[loc][e] + gm_[loc][e]) return false;
    t.base += (q0 - gs_[loc][e]) * t.stride[e];
    if (q1 < q0) {  // the box's points all on one side of a particle outside it
      t.n[e] = 0, t.okAll = t.okInner = false;
      continue;
    }
    if (q1 > q0) t.n[e] = 2, t.g[e][0] = g0, t.g[e][1] = g1;
    else {  // clamped to the box: its one point takes all
      const PetscReal gq = q0 == below ? g0 : g1;
      t.n[e] = 1, t.g[e][0] = gq > 0 ? 1 : 0, t.g[e][1] = 0;
      if (!(gq > 0)) t.okAll = t.okInner = false;
    }
    t.gi[e][0] = t.g[e][0], t.gi[e][1] = t.g[e][1];
    if (loc == e && !periodic) {  // the wall faces 0 and N - 1 of the own direction leave the inner weights
      const bool w0 = q0 == 0 || q0 == N - 1, w1 = t.n[e] == 2 && (q1 == 0 || q1 == N - 1);
      if (w0 || w1) {
        const PetscReal r0 = w0 ? 0 : t.g[e][0], r1 = w1 ? 0 : t.g[e][1];
        // one point left: it takes all (r/r = 1); none: the generic path
        t.gi[e][0] = r0 > 0 ? (r1 > 0 ? r0 : 1) : 0;
        t.gi[e][1] = r1 > 0 ? (r0 > 0 ? r1 : 1) : 0;
        if (!(r0 > 0 || r1 > 0)) t.okInner = false;
      }
    }
  }
  return true;
}

}  // namespace vofdem
