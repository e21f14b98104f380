// Curvature and balanced-force surface tension of the VOF module (Vof.hpp; docs/physics.md F2, F4).
//
// Curvature from height functions (Popinet 2009, J. Comput. Phys. 228): in a cell near the interface,
// 3 x 3 (in 3-D; 3 in 2-D) columns along the direction d most nearly normal to the interface, each from
// a full cell to an empty one within 4 cells, give heights H; kappa = -[H_aa (1 + H_b^2) + H_bb (1 + H_a^2) - 2 H_ab H_a H_b] / (1 + H_a^2 + H_b^2)^(3/2)
// with centred differences, positive for a drop of phase 1 (docs/physics.md F4: kappa = -div n, n = grad
// alpha / |grad alpha|). Directions are tried in order of |n_d|; every column must have its ends and the central column's interface must lie
// within a cell of this one. Where none is, the mean of the neighbours'
// height-function curvatures (3 x 3 x 3 block) stands in; where there is none either, the cell has no
// curvature and its faces get none from it (counted in the summary).
//
// Surface tension at a face between cells L and R along d: f = sigma kappa_f (alpha_R - alpha_L) / h_d,
// kappa_f the mean of the two cells' curvatures (or the one that has one). Flow adds it divided by the
// same face density as the pressure gradient (Flow::FaceForce), so a constant curvature is balanced by
// a pressure jump exactly (balanced force, Francois et al. 2006).
#include "vofdem/vof/Vof.hpp"

#include "vofdem/flow/Flow.hpp"

#include <cmath>

namespace vofdem {

namespace {

const double kNone = 1e300;        // "no curvature" in the curvature fields
const double kClean = 1 - 1e-8;    // a column end counts as full (empty) above (below 1 -) this

struct Cells {  // ghosted local array of the alpha DMDA, global indices
  const PetscScalar *data;
  PetscInt           g0[3], stride[3];
  double at(const PetscInt q[3]) const { return PetscRealPart(data[(q[0] - g0[0]) * stride[0] + (q[1] - g0[1]) * stride[1] + (q[2] - g0[2]) * stride[2]]); }
};

// Height of the interface in the column along d through q + a e_t1 + b e_t2, in cells from the centre
// of q's row, counted from the fluid side (-sign) towards the other: the column runs from the first
// full cell on the fluid side to the first empty one on the other, each at most 4 cells from q (the
// ghost width), so that a nearly full cell (0.999 at a 45-degree corner) lengthens the column instead
// of spoiling it. False when either end is not found.
bool Height(const Cells &c, const PetscInt q[3], int d, int t1, int t2, int a, int b, int sign, double *H) {
  PetscInt p[3] = {q[0], q[1], q[2]};
  p[t1] += a;
  p[t2] += b;
  auto at = [&](int s) {
    PetscInt r[3] = {p[0], p[1], p[2]};
    r[d] += sign * s;  // s < 0: towards the fluid
    return c.at(r);
  };
  int m = 0, e = 0;
  while (m <= 4 && at(-m) < kClean) ++m;
  while (e <= 4 && at(e) > 1 - kClean) ++e;
  if (m > 4 || e > 4) return false;
  double sum = 0;
  for (int s = -m; s <= e; ++s) sum += at(s);
  *H = sum - m - 0.5;
  return true;
}

// Height-function curvature of the cell q (1/m), or kNone.
double HeightCurvature(const Cells &c, const PetscInt q[3], const PetscReal h[3]) {
  static const double w[3] = {1, 2, 1};
  double              n[3] = {0, 0, 0};  // Youngs: minus the gradient, index space
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y) {
      const double wt = w[y + 1] * w[z + 1];
      PetscInt     a[3], b[3];
      for (int d = 0; d < 3; ++d) {
        for (int e = 0; e < 3; ++e) a[e] = b[e] = q[e];
        const int t1 = (d + 1) % 3, t2 = (d + 2) % 3;
        a[d] += 1;
        b[d] -= 1;
        a[t1] += y;
        b[t1] += y;
        a[t2] += z;
        b[t2] += z;
        n[d] -= wt * (c.at(a) - c.at(b));
      }
    }
  int order[3] = {0, 1, 2};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (std::fabs(n[order[j]]) > std::fabs(n[order[i]])) std::swap(order[i], order[j]);
  for (int o = 0; o < 3; ++o) {
    const int d = order[o];
    if (n[d] == 0) break;
    const int sign = n[d] > 0 ? 1 : -1, t1 = (d + 1) % 3, t2 = (d + 2) % 3;
    double    H[3][3];
    bool      ok = true;
    for (int a = -1; a <= 1 && ok; ++a)
      for (int b = -1; b <= 1 && ok; ++b) ok = Height(c, q, d, t1, t2, a, b, sign, &H[a + 1][b + 1]);
    // The interface must cross the central column within a cell of q (Popinet 2009: a cell takes the
    // curvature of heights that put the interface in it; a neighbour's half cell is allowed, so that a
    // face between a full and an empty cell gets one). H counts cells from the fluid end, q spans [3, 4].
    if (!ok || std::fabs(H[1][1]) > 1.5) continue;
    const double hd = h[d], ha = h[t1], hb = h[t2];
    const double Ha = (H[2][1] - H[0][1]) * hd / (2 * ha), Hb = (H[1][2] - H[1][0]) * hd / (2 * hb);
    const double Haa = (H[2][1] - 2 * H[1][1] + H[0][1]) * hd / (ha * ha), Hbb = (H[1][2] - 2 * H[1][1] + H[1][0]) * hd / (hb * hb);
    const double Hab = (H[2][2] - H[2][0] - H[0][2] + H[0][0]) * hd / (4 * ha * hb);
    const double g   = 1 + Ha * Ha + Hb * Hb;
    return -(Haa * (1 + Hb * Hb) + Hbb * (1 + Ha * Ha) - 2 * Hab * Ha * Hb) / (g * std::sqrt(g));
  }
  return kNone;
}

}  // namespace

PetscErrorCode Vof::SurfaceTension(Flow &flow) {
  PetscInt s[3], n[3], gs[3], gm[3];

  PetscFunctionBeginUser;
  if (!(sigma_ > 0) && dsigmadT_ == 0) PetscFunctionReturn(0);
  if (!kappa_) {
    PetscCall(DMCreateGlobalVector(da_, &kappa_));
    PetscCall(DMCreateLocalVector(da_, &kappaLocal_));
  }
  const PetscReal *h = grid_->Spacing();
  PetscCall(DMDAGetCorners(da_, &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAGetGhostCorners(da_, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  const PetscInt stride[3] = {1, gm[0], gm[0] * gm[1]};
  const PetscScalar *a;
  PetscScalar       *k;
  // 1. Height-function curvature of the owned cells near the interface.
  PetscCall(VecGetArrayRead(alphaLocal_, &a));
  const Cells c = {a, {gs[0], gs[1], gs[2]}, {stride[0], stride[1], stride[2]}};
  PetscCall(VecGetArray(kappa_, &k));
  PetscInt idx = 0;
  for (PetscInt z = s[2]; z < s[2] + n[2]; ++z)
    for (PetscInt y = s[1]; y < s[1] + n[1]; ++y)
      for (PetscInt x = s[0]; x < s[0] + n[0]; ++x, ++idx) {
        const PetscInt q[3] = {x, y, z};
        k[idx]              = HeightCurvature(c, q, h);
      }
  PetscCall(VecRestoreArray(kappa_, &k));
  // The ghost cells beyond a wall are never written by the scatter: they must read "none", else step 2
  // averages a curvature of 0 into every wall cell that needs its neighbours' (a 3-D hemisphere on a
  // 90-degree floor crept flat with it: ex37 -dim 3 -vof_contact_angle 90).
  PetscCall(VecSet(kappaLocal_, kNone));
  PetscCall(DMGlobalToLocal(da_, kappa_, INSERT_VALUES, kappaLocal_));
  // 2. Cells without one: the mean of their neighbours' (written to kappa_, read from the local copy).
  PetscReal missing = 0;
  {
    const PetscScalar *kl;
    PetscCall(VecGetArrayRead(kappaLocal_, &kl));
    PetscCall(VecGetArray(kappa_, &k));
    const Cells kc = {kl, {gs[0], gs[1], gs[2]}, {stride[0], stride[1], stride[2]}};
    idx            = 0;
    for (PetscInt z = s[2]; z < s[2] + n[2]; ++z)
      for (PetscInt y = s[1]; y < s[1] + n[1]; ++y)
        for (PetscInt x = s[0]; x < s[0] + n[0]; ++x, ++idx) {
          if (k[idx] != kNone) continue;
          const PetscInt q[3] = {x, y, z};
          const double   v    = c.at(q);
          if (!(v > tiny_ && v < 1 - tiny_)) continue;  // full and empty cells may stay without
          double sum = 0;
          int    cnt = 0;
          for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx) {
                const PetscInt r[3] = {x + dx, y + dy, z + dz};
                const double   kv   = kc.at(r);
                if (kv != kNone) sum += kv, ++cnt;
              }
          if (cnt) k[idx] = sum / cnt;
          else missing += 1;
        }
    PetscCall(VecRestoreArray(kappa_, &k));
    PetscCall(VecRestoreArrayRead(kappaLocal_, &kl));
  }
  PetscCall(DMGlobalToLocal(da_, kappa_, INSERT_VALUES, kappaLocal_));
  // 3. Face forces sigma(T_f) kappa_f (alpha_R - alpha_L) / h_d on the owned faces, and the Marangoni
  // force dsigma/dT (I - n n).grad T |grad alpha| (docs/physics.md F2) with the prescribed temperature
  // T = T0 + G.(x - lower corner) (-vof_temperature, -vof_temperature_gradient): grad alpha at the face
  // from the jump across it and, across, the mean of the two cells' centred differences.
  const PetscReal *lower = grid_->Lower();
  const bool       computed  = (bool)temperature_;
  const double     rho0 = flow.ReferenceDensity();
  const bool       densityScaled = marangoniScaling_ == 1 && rho0 != density_;
  const bool       marangoni = dsigmadT_ != 0 && (computed || gradT_[0] != 0 || gradT_[1] != 0 || gradT_[2] != 0);
  const PetscScalar *tl = nullptr, *ml = nullptr;
  if (computed) PetscCall(TemperatureLocals(&tl, &ml));
  const Cells        tc = {tl, {gs[0], gs[1], gs[2]}, {stride[0], stride[1], stride[2]}}, mc = {ml, {gs[0], gs[1], gs[2]}, {stride[0], stride[1], stride[2]}};
  const PetscScalar *kl;
  PetscCall(VecGetArrayRead(kappaLocal_, &kl));
  const Cells kc = {kl, {gs[0], gs[1], gs[2]}, {stride[0], stride[1], stride[2]}};
  for (int d = 0; d < 3; ++d) {
    Vec        f;
    LocalField F;
    PetscInt   fs[3], fn[3];
    PetscCall(flow.FaceForce(d, &f));
    sg_->Owned(d, fs, fn);
    PetscCall(sg_->GetGlobal(d, f, &F));
    const PetscInt N = grid_->Cells()[d];
    for (PetscInt z = fs[2]; z < fs[2] + fn[2]; ++z)
      for (PetscInt y = fs[1]; y < fs[1] + fn[1]; ++y)
        for (PetscInt x = fs[0]; x < fs[0] + fn[0]; ++x) {
          PetscInt R[3] = {x, y, z}, L[3] = {x, y, z};
          L[d] -= 1;
          double force = 0;
          if (grid_->Periodic(d) || (R[d] > 0 && R[d] < N)) {
            double xf[3], dT = 0, gT[3] = {gradT_[0], gradT_[1], gradT_[2]};  // face centre, temperature above T0 (T_sigma), grad T
            if (computed) {
              dT = 0.5 * (tc.at(L) + tc.at(R)) - sigmaTemperature_;
              for (int e = 0; e < 3; ++e) {
                if (e == d) gT[e] = (tc.at(R) - tc.at(L)) / h[d];
                else {
                  PetscInt Rp[3] = {R[0], R[1], R[2]}, Rm[3] = {R[0], R[1], R[2]}, Lp[3] = {L[0], L[1], L[2]}, Lm[3] = {L[0], L[1], L[2]};
                  Rp[e] += 1, Rm[e] -= 1, Lp[e] += 1, Lm[e] -= 1;
                  gT[e] = 0.25 * (tc.at(Rp) - tc.at(Rm) + tc.at(Lp) - tc.at(Lm)) / h[e];
                }
              }
            } else
              for (int e = 0; e < 3; ++e) {
                xf[e] = lower[e] + (e == d ? R[e] : R[e] + 0.5) * h[e];
                dT += gradT_[e] * (xf[e] - lower[e]);
              }
            const double jump = c.at(R) - c.at(L);
            if (jump != 0) {
              const double kL = kc.at(L), kR = kc.at(R);
              const double kf = kL != kNone && kR != kNone ? 0.5 * (kL + kR) : kL != kNone ? kL : kR != kNone ? kR : 0;
              force           = (sigma_ + dsigmadT_ * dT) * kf * jump / h[d];
            }
            // With the computed T a solid surface carries no capillary force: the normal force takes the smaller
            // liquid share of L and R, the Marangoni force the smallest of every cell its grad alpha reads (a
            // gas-gas face above solid metal reads that metal through its tangential differences).
            double wN = 1, wM = 1;
            if (computed) wN = wM = std::fmin(mc.at(L), mc.at(R));
            force *= wN;
            if (marangoni) {
              double g[3], g2 = 0, nG = 0;
              for (int e = 0; e < 3; ++e) {
                if (e == d) g[e] = jump / h[d];
                else {
                  PetscInt Rp[3] = {R[0], R[1], R[2]}, Rm[3] = {R[0], R[1], R[2]}, Lp[3] = {L[0], L[1], L[2]}, Lm[3] = {L[0], L[1], L[2]};
                  Rp[e] += 1, Rm[e] -= 1, Lp[e] += 1, Lm[e] -= 1;
                  g[e] = 0.25 * (c.at(Rp) - c.at(Rm) + c.at(Lp) - c.at(Lm)) / h[e];
                  if (computed) wM = std::fmin(wM, std::fmin(std::fmin(mc.at(Rp), mc.at(Rm)), std::fmin(mc.at(Lp), mc.at(Lm))));
                }
                g2 += g[e] * g[e];
              }
              if (g2 > 0 && wM > 0) {
                const double mag = std::sqrt(g2);
                for (int e = 0; e < 3; ++e) nG += g[e] / mag * gT[e];
                // -vof_marangoni_scaling density: 2 rho_f/(rho_1 + rho_0), the face density of the momentum equation
                // (the mean of the cells' mixture densities), so that the smeared force lands on the heavy side (its
                // sum across the interface is unchanged) instead of accelerating the light phase beside the interface.
                if (densityScaled) {
                  const double rL = c.at(L) * density_ + (1 - c.at(L)) * rho0, rR = c.at(R) * density_ + (1 - c.at(R)) * rho0;
                  wM *= (rL + rR) / (density_ + rho0);
                }
                force += wM * dsigmadT_ * (gT[d] - g[d] / mag * nG) * mag;
              }
            }
          }
          F.at(x, y, z) = force;
        }
    PetscCall(sg_->RestoreGlobal(d, f, &F));
  }
  PetscCall(VecRestoreArrayRead(kappaLocal_, &kl));
  if (computed) {
    PetscCall(VecRestoreArrayRead(mLocal_, &ml));
    PetscCall(VecRestoreArrayRead(tLocal_, &tl));
  }
  PetscCall(VecRestoreArrayRead(alphaLocal_, &a));
  PetscCallMPI(MPI_Allreduce(&missing, &missingCurvature_, 1, MPIU_REAL, MPIU_SUM, grid_->Comm()));
  PetscFunctionReturn(0);
}

// The computed temperature and liquid share on da_, ghosted (SetTemperature). Outside a non-periodic box the
// temperature's first ghost layer is extrapolated linearly (the tangential differences of the cells at the box
// are then those of the interior); the liquid share is 1 there (no solid).
PetscErrorCode Vof::TemperatureLocals(const PetscScalar **T, const PetscScalar **m) {
  PetscInt     s[3], n[3], gs[3], gm[3];
  PetscScalar *t;

  PetscFunctionBeginUser;
  PetscCall(VecCopy(temperature_(), tGlobal_));
  PetscCall(DMGlobalToLocal(da_, tGlobal_, INSERT_VALUES, tLocal_));
  PetscCall(VecCopy(liquid_(), tGlobal_));
  PetscCall(VecSet(mLocal_, 1));  // outside a non-periodic box: no solid
  PetscCall(DMGlobalToLocal(da_, tGlobal_, INSERT_VALUES, mLocal_));
  PetscCall(DMDAGetCorners(da_, &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAGetGhostCorners(da_, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  const PetscInt  stride[3] = {1, gm[0], gm[0] * gm[1]};
  const PetscInt *N         = grid_->Cells();
  PetscCall(VecGetArray(tLocal_, &t));
  for (int d = 0; d < 3; ++d) {
    if (grid_->Periodic(d)) continue;
    for (int side = 0; side < 2; ++side) {
      const PetscInt ghost = side ? N[d] : -1, in = side ? N[d] - 1 : 0, in2 = side ? N[d] - 2 : 1;
      if (ghost < gs[d] || ghost >= gs[d] + gm[d] || N[d] < 2) continue;
      const int a = (d + 1) % 3, b = (d + 2) % 3;
      for (PetscInt qb = gs[b]; qb < gs[b] + gm[b]; ++qb)
        for (PetscInt qa = gs[a]; qa < gs[a] + gm[a]; ++qa) {
          PetscInt q[3];
          q[a] = qa, q[b] = qb;
          auto at = [&](PetscInt c) -> PetscScalar & {
            q[d] = c;
            return t[(q[0] - gs[0]) * stride[0] + (q[1] - gs[1]) * stride[1] + (q[2] - gs[2]) * stride[2]];
          };
          const PetscScalar v = 2 * at(in) - at(in2);
          at(ghost)           = v;
        }
    }
  }
  PetscCall(VecRestoreArray(tLocal_, &t));
  PetscCall(VecGetArrayRead(tLocal_, T));
  PetscCall(VecGetArrayRead(mLocal_, m));
  (void)s, (void)n;
  PetscFunctionReturn(0);
}

PetscReal Vof::CapillaryTimeStep(PetscReal otherDensity) const {
  if (!(sigma_ > 0)) return PETSC_MAX_REAL;
  const PetscReal *h = grid_->Spacing(), hmin = std::fmin(h[0], std::fmin(h[1], h[2]));
  // Brackbill, Kothe & Zemach (1992): the capillary wave of wavelength 2h must not cross a cell in a step.
  return std::sqrt(0.5 * (density_ + otherDensity) * hmin * hmin * hmin / (2 * PETSC_PI * sigma_));
}

}  // namespace vofdem
