// Energy.hpp: the laser's deposit into the cells (docs/physics.md F8), the beam's power per column from Laser.cpp.
#include "vofdem/energy/Energy.hpp"

#include <petscdmda.h>
#include <petsc/private/petscimpl.h>  // PetscObjectStateGet: the deposit's key

#include <algorithm>
#include <cmath>
#include <vector>

namespace vofdem {

// The laser's deposit q (W/m^3) at time t (docs/physics.md F8). first_interface: down each column the metal
// takes eta of the column's power, shared by the metal volume each cell adds until one cell's worth of
// metal has been met (a cell full of metal takes it all; a column with less than a cell's worth takes that share); the metal of the ranks above comes from a scan
// over the process column. gradient: eta (P_col / footprint) |grad alpha| in every cell. P_col is what is left of the
// column's power after the particles above the melt took their share (SetBeamTaken; coupling/ParticleBeam.hpp).
PetscErrorCode Energy::LaserSource(PetscReal t) {
  struct {
    PetscInt s[3], m[3];
  } b;
  const PetscReal *h = grid_->Spacing(), *lo = grid_->Lower();
  const PetscReal  V = h[0] * h[1] * h[2];
  const PetscInt   nz = grid_->Cells()[2];
  PetscScalar   ***q, ***al;
  PetscReal        sums[2] = {0, 0};  // beam into the box, absorbed

  PetscFunctionBeginUser;
  PetscCall(DMDAGetCorners(dm_, &b.s[0], &b.s[1], &b.s[2], &b.m[0], &b.m[1], &b.m[2]));
  PetscCall(PetscLogEventBegin(evLaser_, 0, 0, 0, 0));
  // The deposit depends on the beam's power and centre and on alpha alone (FootprintPower), unless particles take
  // their share: a beam that neither moved nor changed over the same metal (alphaLocal_'s object state) leaves
  // q_ as the last call filled it (q_'s state unchanged since), the same bits.
  LaserKey key;
  key.valid = laser_.On() && !beamTaken_, key.power = laser_.On() ? laser_.Power(t) : 0;
  laser_.Centre(t, &key.x, &key.y);
  PetscCall(PetscObjectStateGet((PetscObject)alphaLocal_, &key.alpha));
  PetscCall(PetscObjectStateGet((PetscObject)q_, &key.q));
  PetscInt same = key.valid && key.power > 0 && laserKey_.valid && key.power == laserKey_.power && key.x == laserKey_.x && key.y == laserKey_.y && key.alpha == laserKey_.alpha &&
                  key.q == laserKey_.q;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &same, 1, MPIU_INT, MPI_LAND, comm_));
  if (same) {
    last_.beam = laserKey_.beam, last_.absorbed = laserKey_.absorbed;
    PetscCall(PetscLogEventEnd(evLaser_, 0, 0, 0, 0));
    PetscFunctionReturn(0);
  }
  laserKey_.valid = false;
  PetscCall(VecSet(q_, 0));
  last_.beam = last_.absorbed = 0;
  if (!laser_.On() || laser_.Power(t) == 0) {
    PetscCall(PetscLogEventEnd(evLaser_, 0, 0, 0, 0));
    PetscFunctionReturn(0);
  }
  const PetscInt        n = b.m[0] * b.m[1];
  const std::vector<PetscReal> *taken = beamTaken_ ? beamTaken_() : nullptr;  // per owned column, or none
  std::vector<PetscReal> slab(n, 0), above(n, 0), total(n, 0), power(n, 0);
  PetscCall(DMDAVecGetArrayRead(dm_, alphaLocal_, &al));
  PetscCall(DMDAVecGetArray(dm_, q_, &q));
  for (PetscInt y = b.s[1]; y < b.s[1] + b.m[1]; ++y)
    for (PetscInt x = b.s[0]; x < b.s[0] + b.m[0]; ++x) {
      const PetscInt c = (y - b.s[1]) * b.m[0] + (x - b.s[0]);
      power[c]         = laser_.FootprintPower(t, lo[0] + x * h[0], lo[0] + (x + 1) * h[0], lo[1] + y * h[1], lo[1] + (y + 1) * h[1]);
      for (PetscInt z = b.s[2]; z < b.s[2] + b.m[2]; ++z) slab[c] += al[z][y][x];
    }
  int columnRank;
  PetscCallMPI(MPI_Comm_rank(column_, &columnRank));
  PetscCallMPI(MPI_Exscan(slab.data(), above.data(), (int)n, MPIU_REAL, MPI_SUM, column_));
  if (columnRank == 0) std::fill(above.begin(), above.end(), 0);
  PetscCallMPI(MPI_Allreduce(slab.data(), total.data(), (int)n, MPIU_REAL, MPI_SUM, column_));
  const PetscReal eta = laser_.Absorptivity();
  for (PetscInt y = b.s[1]; y < b.s[1] + b.m[1]; ++y)
    for (PetscInt x = b.s[0]; x < b.s[0] + b.m[0]; ++x) {
      const PetscInt c = (y - b.s[1]) * b.m[0] + (x - b.s[0]);
      if (columnRank == 0) sums[0] += power[c];
      if (taken) power[c] -= (*taken)[c];  // what particles above took (SetBeamTaken)
      if (laser_.Deposition() == LaserDeposition::FirstInterface) {
        // The metal the beam meets, in cells: a column with less than one cell's worth takes that share of the
        // column's power and the rest leaves through the bottom (the rim of a drop smaller than a cell, alpha 3e-5,
        // took a whole column's power and reached 2e5 K when the share was not scaled so).
        if (!(total[c] > 0)) continue;  // no metal: the beam leaves through the bottom
        PetscReal cum = above[c];
        for (PetscInt z = b.s[2] + b.m[2] - 1; z >= b.s[2]; --z) {
          const PetscReal a = al[z][y][x], w = std::max((PetscReal)0, std::min(a, 1 - cum));
          cum += a;
          if (w > 0) q[z][y][x] = eta * power[c] * w / V, sums[1] += q[z][y][x] * V;
        }
      } else {
        for (PetscInt z = b.s[2]; z < b.s[2] + b.m[2]; ++z) {
          const PetscReal up = z + 1 < nz ? al[z + 1][y][x] : al[z][y][x], dn = z > 0 ? al[z - 1][y][x] : al[z][y][x];
          PetscReal       g2 = (up - dn) * (up - dn) / (4 * h[2] * h[2]);
          for (int d = 0; d < 2; ++d) {
            const PetscInt nd = grid_->Cells()[d];
            const PetscInt i = d == 0 ? x : y;
            const PetscReal p = i + 1 < nd ? (d == 0 ? al[z][y][x + 1] : al[z][y + 1][x]) : al[z][y][x];
            const PetscReal m = i > 0 ? (d == 0 ? al[z][y][x - 1] : al[z][y - 1][x]) : al[z][y][x];
            g2 += (p - m) * (p - m) / (4 * h[d] * h[d]);
          }
          q[z][y][x] = eta * power[c] / (h[0] * h[1]) * std::sqrt(g2);
          sums[1] += q[z][y][x] * V;
        }
      }
    }
  PetscCall(DMDAVecRestoreArray(dm_, q_, &q));
  PetscCall(DMDAVecRestoreArrayRead(dm_, alphaLocal_, &al));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPIU_REAL, MPI_SUM, comm_));
  last_.beam = sums[0], last_.absorbed = sums[1];
  PetscCall(PetscObjectStateGet((PetscObject)q_, &key.q));
  key.beam = sums[0], key.absorbed = sums[1];
  laserKey_ = key;
  PetscCall(PetscLogEventEnd(evLaser_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
