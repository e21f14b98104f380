#include "vofdem/coupling/DiffusionOperator.hpp"

#include <algorithm>

namespace vofdem {

PetscErrorCode DiffusionOperator::Create(DM dm, const PetscReal a[3], const PetscInt lo[3], const PetscInt hi[3], const bool periodic[3], Mat *shell) {
  PetscInt M, N, P;

  PetscFunctionBeginUser;
  dm_ = dm;
  for (int e = 0; e < 3; ++e) a_[e] = a[e], lo_[e] = lo[e], hi_[e] = hi[e], periodic_[e] = periodic[e];
  PetscCall(DMCreateLocalVector(dm, &local_));
  PetscCall(DMDAGetCorners(dm, &s_[0], &s_[1], &s_[2], &n_[0], &n_[1], &n_[2]));
  PetscCall(DMDAGetGhostCorners(dm, &gs_[0], &gs_[1], &gs_[2], &gm_[0], &gm_[1], &gm_[2]));
  PetscCall(DMDAGetInfo(dm, nullptr, &M, &N, &P, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  zeros_.assign(gm_[0], 0.0);
  ghosted_ = gm_[0] != n_[0] || gm_[1] != n_[1] || gm_[2] != n_[2];
  const PetscInt mine = n_[0] * n_[1] * n_[2], all = M * N * P;
  PetscCall(MatCreateShell(PetscObjectComm((PetscObject)dm), mine, mine, all, all, this, shell));
  PetscCall(MatShellSetOperation(*shell, MATOP_MULT, (void (*)(void))Mult));
  PetscFunctionReturn(0);
}

PetscErrorCode DiffusionOperator::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&local_));
  PetscFunctionReturn(0);
}

// y = A x row by row along x: the neighbour rows in y and z are read through pointers (a row of zeros
// where the neighbour is beyond a wall), the x neighbours and the diagonal depend on i only at the ends.
PetscErrorCode DiffusionOperator::Mult(Mat A, Vec x, Vec y) {
  DiffusionOperator *op;
  const PetscScalar *xl;
  PetscScalar       *ya;

  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &op));
  // Without ghost points (one rank, no periodic direction) the global vector is the local one: no copy.
  const Vec src = op->ghosted_ ? op->local_ : x;
  if (op->ghosted_) PetscCall(DMGlobalToLocal(op->dm_, x, INSERT_VALUES, op->local_));
  PetscCall(VecGetArrayRead(src, &xl));
  PetscCall(VecGetArray(y, &ya));
  const PetscInt *s = op->s_, *n = op->n_, *gs = op->gs_, *gm = op->gm_, *lo = op->lo_, *hi = op->hi_;
  const PetscReal *a = op->a_;
  const bool      *per = op->periodic_;
  const PetscInt   sy = gm[0], sz = gm[0] * gm[1];
  const PetscReal *zero = op->zeros_.data() - gs[0];
  PetscInt         out  = 0;
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
      const PetscReal *xc = xl + (j - gs[1]) * sy + (k - gs[2]) * sz - gs[0];
      PetscScalar     *yr = ya + out - s[0];
      out += n[0];
      // Identity rows: wall faces of this location's own direction (y or z here; x below, per point).
      if ((!per[1] && (j < lo[1] || j > hi[1])) || (!per[2] && (k < lo[2] || k > hi[2]))) {
        for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) yr[i] = xc[i];
        continue;
      }
      const bool       jm = per[1] || j - 1 >= lo[1], jp = per[1] || j + 1 <= hi[1];
      const bool       km = per[2] || k - 1 >= lo[2], kp = per[2] || k + 1 <= hi[2];
      const PetscReal *xs = jm ? xc - sy : zero, *xn = jp ? xc + sy : zero, *xb = km ? xc - sz : zero, *xt = kp ? xc + sz : zero;
      const PetscReal  cs = jm ? a[1] : 0, cn = jp ? a[1] : 0, cb = km ? a[2] : 0, ct = kp ? a[2] : 0;
      // The diagonal 1 + the coefficients of the neighbours present, summed as Assemble sums them.
      PetscReal d[2][2];
      for (int im = 0; im < 2; ++im)
        for (int ip = 0; ip < 2; ++ip) {
          PetscReal v = 1;
          if (im) v += a[0];
          if (ip) v += a[0];
          if (jm) v += a[1];
          if (jp) v += a[1];
          if (km) v += a[2];
          if (kp) v += a[2];
          d[im][ip] = v;
        }
      const PetscReal dIn = d[1][1], ax = a[0];
      // One point along x, with the wall tests (the ends of the row).
      auto point = [&](PetscInt i) {
        if (!per[0] && (i < lo[0] || i > hi[0])) {
          yr[i] = xc[i];
          return;
        }
        const bool im = per[0] || i - 1 >= lo[0], ip = per[0] || i + 1 <= hi[0];
        PetscReal  v  = d[im][ip] * xc[i];
        if (im) v -= ax * xc[i - 1];
        if (ip) v -= ax * xc[i + 1];
        yr[i] = v - cs * xs[i] - cn * xn[i] - cb * xb[i] - ct * xt[i];
      };
      // The interior of the row, where both x neighbours take part: straight-line code the compiler vectorises.
      const PetscInt i0 = per[0] ? s[0] : std::max(s[0], lo[0] + 1), i1 = per[0] ? s[0] + n[0] - 1 : std::min(s[0] + n[0] - 1, hi[0] - 1);
      for (PetscInt i = s[0]; i < std::min(i0, s[0] + n[0]); ++i) point(i);
      {
        PetscScalar *__restrict yy = yr;
        const PetscReal *__restrict c = xc, *__restrict ps = xs, *__restrict pn = xn, *__restrict pb = xb, *__restrict pt = xt;
        for (PetscInt i = i0; i <= i1; ++i) yy[i] = dIn * c[i] - ax * c[i - 1] - ax * c[i + 1] - cs * ps[i] - cn * pn[i] - cb * pb[i] - ct * pt[i];
      }
      for (PetscInt i = std::max(i1 + 1, i0); i < s[0] + n[0]; ++i) point(i);
    }
  PetscCall(VecRestoreArray(y, &ya));
  PetscCall(VecRestoreArrayRead(src, &xl));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
