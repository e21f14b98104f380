// Boundedness of alpha with particles (Vof.hpp; docs/physics.md F1b). With eps varying in space and time the
// split sweeps on m = eps alpha can leave a cell slightly over-full (alpha > 1) or over-drained (alpha < 0):
// the Weymouth-Yue term keeps only the cells that were full at the step's start exactly full. Clipping would
// lose that liquid; instead each cell's excess (or deficit) is handed to its 26 neighbours in proportion to
// the room (or the liquid) they have, so sum eps alpha V is unchanged to round-off and the moved volume stays
// within one cell of where the sweeps put it. Walls: neighbours outside a non-periodic box take nothing. What moved,
// pair by pair, goes to the redistribution's observers (the energy moves the phases' enthalpy with it).
#include "vofdem/vof/Vof.hpp"

#include <petscdmda.h>

#include <algorithm>
#include <cmath>

namespace vofdem {

PetscErrorCode Vof::AddPhaseVolume(Vec volume, Vec before, Vec after) {
  PetscScalar       *a;
  const PetscScalar *v, *b, *e;
  PetscInt           n;

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing();
  const PetscReal  V = h[0] * h[1] * h[2];
  // The flow's cell vectors have alpha_'s layout (the same ownership, one dof, x fastest): flat arrays.
  PetscCall(VecGetLocalSize(alpha_, &n));
  PetscCall(VecGetArray(alpha_, &a));
  PetscCall(VecGetArrayRead(volume, &v));
  PetscCall(VecGetArrayRead(before, &b));
  PetscCall(VecGetArrayRead(after, &e));
  for (PetscInt c = 0; c < n; ++c) {
    const PetscReal add = PetscRealPart(v[c]), eb = PetscRealPart(b[c]), ea = PetscRealPart(e[c]);
    if (add != 0 || eb != ea) a[c] = (PetscRealPart(a[c]) * eb + add / V) / ea;
  }
  PetscCall(VecRestoreArrayRead(after, &e));
  PetscCall(VecRestoreArrayRead(before, &b));
  PetscCall(VecRestoreArrayRead(volume, &v));
  PetscCall(VecRestoreArray(alpha_, &a));
  PetscCall(FillGhosts());
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::BoundAt(Vec after) {
  PetscFunctionBeginUser;
  PetscCall(Redistribute(after));
  PetscCall(FillGhosts());
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::Redistribute(Vec epsAt) {
  PetscInt        s[3], n[3];
  PetscScalar  ***a, ***e, ***room, ***fill, ***giveL, ***takeL;
  const PetscInt *N = grid_->Cells();

  PetscFunctionBeginUser;
  if (!roomG_) {
    for (Vec *v : {&roomG_, &fillG_, &giveG_, &takeG_}) PetscCall(DMCreateGlobalVector(da_, v));
    for (Vec *v : {&roomL_, &fillL_, &giveL_, &takeL_}) PetscCall(DMCreateLocalVector(da_, v));
  }
  PetscCall(DMDAGetCorners(da_, &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  bool periodic[3];
  for (int d = 0; d < 3; ++d) periodic[d] = grid_->Periodic(d);
  // Is neighbour (i+di, j+dj, k+dk) a cell of the domain (periodic directions wrap in the ghosts)?
  auto inside = [&](PetscInt i, PetscInt j, PetscInt k) {
    const PetscInt q[3] = {i, j, k};
    for (int d = 0; d < 3; ++d)
      if (!periodic[d] && (q[d] < 0 || q[d] >= N[d])) return false;
    return true;
  };
  // Pass 1: clip, and each cell's room (eps (1 - alpha), for excess) and liquid (eps alpha, for deficits), in
  // cell volumes; the excess or deficit eps (alpha - clip) is kept in give (positive) or take (positive).
  if (!cellScratch_) PetscCall(FluidFractionGhosts());  // its scratch (before the first sweeps: a melt at the first step)
  PetscCall(VecCopy(epsAt ? epsAt : eps_, cellScratch_));
  PetscCall(DMDAVecGetArray(da_, alpha_, &a));
  PetscCall(DMDAVecGetArrayRead(da_, cellScratch_, &e));
  PetscCall(DMDAVecGetArray(da_, roomG_, &room));
  PetscCall(DMDAVecGetArray(da_, fillG_, &fill));
  PetscScalar ***give, ***take;
  PetscCall(DMDAVecGetArray(da_, giveG_, &give));
  PetscCall(DMDAVecGetArray(da_, takeG_, &take));
  PetscReal outside = 0;
  const bool report = !movedObservers_.empty();
  moves_.clear();
  auto move = [&](PetscInt i, PetscInt j, PetscInt k, PetscInt di, PetscInt dj, PetscInt dk, PetscReal dv) {
    if (report && dv != 0) moves_.push_back({{i, j, k}, {i + di, j + dj, k + dk}, dv});
  };
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscReal v = PetscRealPart(a[k][j][i]), ep = PetscRealPart(e[k][j][i]);
        const PetscReal c = std::min((PetscReal)1, std::max((PetscReal)0, v));
        give[k][j][i]     = v > 1 ? ep * (v - 1) : 0;
        take[k][j][i]     = v < 0 ? -ep * v : 0;
        outside           = std::max(outside, std::max(v - 1, -v));
        a[k][j][i]        = c;
        room[k][j][i]     = ep * (1 - c);
        fill[k][j][i]     = ep * c;
      }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &outside, 1, MPIU_REAL, MPIU_MAX, grid_->Comm()));
  if (!(outside > 0)) {  // nothing to do: alpha unchanged (the clip above was the identity), nothing moved
    PetscCall(DMDAVecRestoreArray(da_, takeG_, &take));
    PetscCall(DMDAVecRestoreArray(da_, giveG_, &give));
    PetscCall(DMDAVecRestoreArray(da_, fillG_, &fill));
    PetscCall(DMDAVecRestoreArray(da_, roomG_, &room));
    PetscCall(DMDAVecRestoreArrayRead(da_, cellScratch_, &e));
    PetscCall(DMDAVecRestoreArray(da_, alpha_, &a));
    PetscFunctionReturn(0);
  }
  PetscCall(DMDAVecRestoreArray(da_, fillG_, &fill));
  PetscCall(DMDAVecRestoreArray(da_, roomG_, &room));
  PetscCall(DMGlobalToLocal(da_, roomG_, INSERT_VALUES, roomL_));
  PetscCall(DMGlobalToLocal(da_, fillG_, INSERT_VALUES, fillL_));
  // Pass 2: a donor's share per unit of room (liquid) of its neighbours, capped at 1 (all their room);
  // what it cannot place stays with it (alpha outside [0, 1] by that, reported by Summarize).
  PetscScalar ***roomN, ***fillN;
  PetscCall(DMDAVecGetArrayRead(da_, roomL_, &roomN));
  PetscCall(DMDAVecGetArrayRead(da_, fillL_, &fillN));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscReal x = PetscRealPart(give[k][j][i]), y = PetscRealPart(take[k][j][i]);
        if (x == 0 && y == 0) continue;
        PetscReal R = 0, F = 0;
        for (PetscInt dk = -1; dk <= 1; ++dk)
          for (PetscInt dj = -1; dj <= 1; ++dj)
            for (PetscInt di = -1; di <= 1; ++di) {
              if ((di == 0 && dj == 0 && dk == 0) || !inside(i + di, j + dj, k + dk)) continue;
              R += PetscRealPart(roomN[k + dk][j + dj][i + di]);
              F += PetscRealPart(fillN[k + dk][j + dj][i + di]);
            }
        const PetscReal gx = R > 0 ? std::min((PetscReal)1, x / R) : 0, gy = F > 0 ? std::min((PetscReal)1, y / F) : 0;
        if (report && (gx > 0 || gy > 0))  // the donor's (taker's) side of its moves, the products pass 3 forms
          for (PetscInt dk = -1; dk <= 1; ++dk)
            for (PetscInt dj = -1; dj <= 1; ++dj)
              for (PetscInt di = -1; di <= 1; ++di) {
                if ((di == 0 && dj == 0 && dk == 0) || !inside(i + di, j + dj, k + dk)) continue;
                move(i, j, k, di, dj, dk, -gx * PetscRealPart(roomN[k + dk][j + dj][i + di]));
                move(i, j, k, di, dj, dk, gy * PetscRealPart(fillN[k + dk][j + dj][i + di]));
              }
        // The part not placed goes back into the cell.
        const PetscReal ep = PetscRealPart(e[k][j][i]);
        if (ep > 0) a[k][j][i] = PetscRealPart(a[k][j][i]) + (x - gx * R - (y - gy * F)) / ep;
        give[k][j][i] = gx, take[k][j][i] = gy;
      }
  PetscCall(DMDAVecRestoreArray(da_, takeG_, &take));
  PetscCall(DMDAVecRestoreArray(da_, giveG_, &give));
  PetscCall(DMGlobalToLocal(da_, giveG_, INSERT_VALUES, giveL_));
  PetscCall(DMGlobalToLocal(da_, takeG_, INSERT_VALUES, takeL_));
  // Pass 3: each cell receives its room times the shares of its donor neighbours and gives its liquid
  // times the shares of its taker neighbours (the same neighbour sets as pass 2: the sums match exactly).
  PetscCall(DMDAVecGetArrayRead(da_, giveL_, &giveL));
  PetscCall(DMDAVecGetArrayRead(da_, takeL_, &takeL));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        PetscReal gx = 0, gy = 0;
        for (PetscInt dk = -1; dk <= 1; ++dk)
          for (PetscInt dj = -1; dj <= 1; ++dj)
            for (PetscInt di = -1; di <= 1; ++di) {
              if ((di == 0 && dj == 0 && dk == 0) || !inside(i + di, j + dj, k + dk)) continue;
              gx += PetscRealPart(giveL[k + dk][j + dj][i + di]);
              gy += PetscRealPart(takeL[k + dk][j + dj][i + di]);
              move(i, j, k, di, dj, dk, PetscRealPart(giveL[k + dk][j + dj][i + di]) * PetscRealPart(roomN[k][j][i]));
              move(i, j, k, di, dj, dk, -PetscRealPart(takeL[k + dk][j + dj][i + di]) * PetscRealPart(fillN[k][j][i]));
            }
        const PetscReal ep = PetscRealPart(e[k][j][i]);
        if (ep > 0 && (gx != 0 || gy != 0)) a[k][j][i] = PetscRealPart(a[k][j][i]) + (gx * PetscRealPart(roomN[k][j][i]) - gy * PetscRealPart(fillN[k][j][i])) / ep;
        const PetscReal v = PetscRealPart(a[k][j][i]);
        boundViolation_   = std::max(boundViolation_, std::max(v - 1, -v));  // what is left (Summarize)
      }
  PetscCall(DMDAVecRestoreArrayRead(da_, takeL_, &takeL));
  PetscCall(DMDAVecRestoreArrayRead(da_, giveL_, &giveL));
  PetscCall(DMDAVecRestoreArrayRead(da_, fillL_, &fillN));
  PetscCall(DMDAVecRestoreArrayRead(da_, roomL_, &roomN));
  PetscCall(DMDAVecRestoreArrayRead(da_, cellScratch_, &e));
  PetscCall(DMDAVecRestoreArray(da_, alpha_, &a));
  for (const RedistributionObserver &o : movedObservers_) PetscCall(o(moves_));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
