// Energy.hpp: the state a melt-pool user reads (docs/modules/energy.md): peak temperature, the pool's
// length, width and depth (the extent of an isotherm, the liquidus by default, found to sub-cell accuracy
// by linear interpolation between cell centres), the melted volume, and the boiling-point stop.
#include "vofdem/energy/Energy.hpp"

#include "vofdem/base/Runtime.hpp"

#include <petscdmda.h>

#include <algorithm>
#include <cmath>

namespace vofdem {

// Along each grid line in d, where T crosses iso between two metal cell centres (or at a box face where a
// cell above iso touches it): the extreme crossings; the extent is their difference (z: from the metal top).
PetscErrorCode Energy::PoolExtent(PetscReal iso, PetscReal ext[3]) {
  const PetscReal *h = grid_->Spacing(), *lo = grid_->Lower(), *up = grid_->Upper();
  const PetscInt  *n = grid_->Cells();
  PetscScalar   ***T, ***al;
  PetscInt         s[3], m[3];
  PetscReal        lowest[3], highest[3];  // reduced: -min, max

  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) lowest[d] = -PETSC_MAX_REAL, highest[d] = -PETSC_MAX_REAL;
  PetscCall(DMGlobalToLocal(dm_, T_, INSERT_VALUES, TLocal_));
  PetscCall(DMDAGetCorners(dm_, &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  PetscCall(DMDAVecGetArrayRead(dm_, TLocal_, &T));
  PetscCall(DMDAVecGetArrayRead(dm_, alphaLocal_, &al));
  auto note = [&](int d, PetscReal x) { lowest[d] = std::max(lowest[d], -x), highest[d] = std::max(highest[d], x); };
  for (PetscInt z = s[2]; z < s[2] + m[2]; ++z)
    for (PetscInt y = s[1]; y < s[1] + m[1]; ++y)
      for (PetscInt x = s[0]; x < s[0] + m[0]; ++x) {
        if (!(al[z][y][x] > 0.5)) continue;
        const PetscInt  c[3] = {x, y, z};
        const PetscReal t    = T[z][y][x];
        for (int d = 0; d < 3; ++d) {
          const PetscReal centre = lo[d] + (c[d] + 0.5) * h[d];
          if (t >= iso && c[d] == 0 && !grid_->Periodic(d)) note(d, lo[d]);
          if (t >= iso && c[d] == n[d] - 1 && !grid_->Periodic(d)) note(d, up[d]);
          if (c[d] + 1 >= n[d]) continue;  // the +d neighbour (a ghost of this rank's local box)
          PetscInt nb[3] = {x, y, z};
          nb[d] += 1;
          if (!(al[nb[2]][nb[1]][nb[0]] > 0.5)) {  // metal ends: a hot cell under the surface reaches it
            if (t >= iso && d == 2) note(d, std::min(metalTop_, centre + 0.5 * h[d]));
            continue;
          }
          const PetscReal tn = T[nb[2]][nb[1]][nb[0]];
          if ((t >= iso) != (tn >= iso)) note(d, centre + h[d] * (iso - t) / (tn - t));
        }
      }
  PetscCall(DMDAVecRestoreArrayRead(dm_, alphaLocal_, &al));
  PetscCall(DMDAVecRestoreArrayRead(dm_, TLocal_, &T));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, lowest, 3, MPIU_REAL, MPI_MAX, comm_));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, highest, 3, MPIU_REAL, MPI_MAX, comm_));
  for (int d = 0; d < 3; ++d) ext[d] = highest[d] > -PETSC_MAX_REAL ? highest[d] + lowest[d] : 0;  // max - min
  PetscFunctionReturn(0);
}

Vec Energy::MeltFraction() {
  PetscScalar ***T, ***al, ***f;
  PetscInt       s[3], m[3];

  DMDAGetCorners(dm_, &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]);
  DMDAVecGetArrayRead(dm_, F_, &T);
  DMDAVecGetArrayRead(dm_, alpha_, &al);
  DMDAVecGetArray(dm_, fl_, &f);
  for (PetscInt z = s[2]; z < s[2] + m[2]; ++z)
    for (PetscInt y = s[1]; y < s[1] + m[1]; ++y)
      for (PetscInt x = s[0]; x < s[0] + m[0]; ++x) f[z][y][x] = al[z][y][x] * T[z][y][x];  // the state's f
  DMDAVecRestoreArray(dm_, fl_, &f);
  DMDAVecRestoreArrayRead(dm_, alpha_, &al);
  DMDAVecRestoreArrayRead(dm_, F_, &T);
  return fl_;
}

PetscErrorCode Energy::HeatCapacity(Vec out) const {
  PetscScalar ***T, ***al, ***ep = nullptr, ***c;
  PetscInt       s[3], m[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetCorners(dm_, &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  PetscCall(DMDAVecGetArrayRead(dm_, T_, &T));
  PetscCall(DMDAVecGetArrayRead(dm_, alpha_, &al));
  if (epsFluid_) PetscCall(DMDAVecGetArrayRead(dm_, epsFluid_, &ep));
  PetscCall(DMDAVecGetArray(dm_, out, &c));
  for (PetscInt z = s[2]; z < s[2] + m[2]; ++z)
    for (PetscInt y = s[1]; y < s[1] + m[1]; ++y)
      for (PetscInt x = s[0]; x < s[0] + m[0]; ++x) {
        const PetscReal t = T[z][y][x], a = al[z][y][x];
        c[z][y][x] = (ep ? ep[z][y][x] : 1) * (a * metal_.density * metal_.Capacity(t) + (1 - a) * gas_.density * gas_.cp.At(t));
      }
  PetscCall(DMDAVecRestoreArray(dm_, out, &c));
  if (ep) PetscCall(DMDAVecRestoreArrayRead(dm_, epsFluid_, &ep));
  PetscCall(DMDAVecRestoreArrayRead(dm_, alpha_, &al));
  PetscCall(DMDAVecRestoreArrayRead(dm_, T_, &T));
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::SolidFraction(Vec out) const {
  PetscFunctionBeginUser;
  PetscCall(VecCopy(F_, out));
  PetscCall(VecScale(out, -1));
  PetscCall(VecShift(out, 1));                    // 1 - f
  PetscCall(VecPointwiseMult(out, out, alpha_));  // alpha (1 - f)
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::HeldMask(Vec out) const {
  PetscFunctionBeginUser;
  PetscCall(VecSet(out, 0));
  if (!sGlobal_) PetscFunctionReturn(0);  // no MushyDrag yet (no flow)
  const PetscScalar *s;
  PetscScalar       *o;
  PetscInt           n;
  PetscCall(VecGetLocalSize(out, &n));
  PetscCall(VecGetArrayRead(sGlobal_, &s));
  PetscCall(VecGetArray(out, &o));
  for (PetscInt c = 0; c < n; ++c) o[c] = PetscRealPart(s[c]) < 0 ? 1 : 0;  // MushyDrag marks a held cell -1
  PetscCall(VecRestoreArray(out, &o));
  PetscCall(VecRestoreArrayRead(sGlobal_, &s));
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::Summarize(EnergySummary *s) {
  const PetscReal *h = grid_->Spacing();
  const PetscReal  V = h[0] * h[1] * h[2];

  PetscFunctionBeginUser;
  *s = last_;
  PetscCall(VecSum(E_, &s->total));
  s->total *= V;
  s->accounted = W_;
  if (particleHeld_) {  // the particles' enthalpy (F9): what they give the cells is no input, what they hold is energy
    PetscReal held, brought;
    PetscCall(particleHeld_(&held, &brought));
    s->total += held, s->accounted += brought;
  }
  PetscCall(VecMax(T_, nullptr, &s->peak));
  PetscCall(VecMin(T_, nullptr, &s->minimum));
  if (epsFluid_) PetscCall(VecDot(MeltFraction(), epsCells_, &s->meltVolume));  // the metal's share of the fluid's share eps
  else PetscCall(VecSum(MeltFraction(), &s->meltVolume));
  s->meltVolume *= V;
  PetscCall(PoolExtent(poolIsotherm_, s->pool));
  s->balanceRelative = s->balance / std::max(std::fabs(s->total), (PetscReal)1e-300);
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::CheckBoiling(PetscReal time) {
  PetscScalar ***T, ***al;
  PetscInt       s[3], m[3];
  PetscReal      peak = 0;

  PetscFunctionBeginUser;
  if (!(metal_.boilingPoint > 0)) PetscFunctionReturn(0);
  PetscCall(DMDAGetCorners(dm_, &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  PetscCall(DMDAVecGetArrayRead(dm_, T_, &T));
  PetscCall(DMDAVecGetArrayRead(dm_, alpha_, &al));
  for (PetscInt z = s[2]; z < s[2] + m[2]; ++z)
    for (PetscInt y = s[1]; y < s[1] + m[1]; ++y)
      for (PetscInt x = s[0]; x < s[0] + m[0]; ++x)
        if (al[z][y][x] > 0) peak = std::max(peak, (PetscReal)T[z][y][x]);
  PetscCall(DMDAVecRestoreArrayRead(dm_, alpha_, &al));
  PetscCall(DMDAVecRestoreArrayRead(dm_, T_, &T));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &peak, 1, MPIU_REAL, MPI_MAX, comm_));
  if (peak > metal_.boilingPoint + boilingMargin_)
    VofdemInputError(comm_, "energy: the metal reached %.1f K at t = %g s, past its boiling point %g K by more than -energy_boiling_margin %g K; vofdem has no evaporation model: lower -laser_power or raise the margin",
                     (double)peak, (double)time, (double)metal_.boilingPoint, (double)boilingMargin_);
  PetscFunctionReturn(0);
}

}  // namespace vofdem
