// The coupled step's exchanges (Coupling.hpp): projection of the particles to the grid (K3, F5) and
// averaging of the fluid at the particles with the fluid-particle forces (K1, K2, K1b, F6, P1).
#include "vofdem/coupling/Coupling.hpp"
#include "vofdem/grid/FaceProperties.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

PetscInt Coupling::Substeps(PetscReal dt) const {
  const PetscReal dtDem = dem_->StableTimeStep();
  return std::max((PetscInt)1, (PetscInt)std::ceil(dt / dtDem * (1 - 1e-12)));
}

// Step 1: eps from the particles' volume; the fluid's share of the drag impulse of the last step.
// dt is the fluid step about to be taken (0 at set-up). The fluid is given the particles' displacement at
// the rate it happened, d(eps)/dt = (eps_particles - eps)/dtLast (F1): a step shorter than the last one
// takes its share dt/dtLast of what it has not been given yet, the rest follows in the next steps; a step as
// long or longer takes all of it (the fluid never runs ahead of the particles). Without this a final step
// shortened 5.4x to land on -final_time put 5.4x the displacement rate into the continuity (issue 55).
PetscErrorCode Coupling::Project(PetscReal dt) {
  ParticleArrays a;
  LocalField     eps, rho, A, Fw;
  PetscInt       s[3], n[3];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evProject_, 0, 0, 0, 0));
  const StaggeredGrid &sg = flow_->Staggered();
  const PetscReal     *h  = sg.Base().Spacing();
  const PetscReal      Vc = h[0] * h[1] * h[2];
  const ParticleSwarm &sw = dem_->Particles();
  PetscCall(sw.GetArrays(&a));
  H_.resize(a.n);
  scratch_.resize(a.n);
  lastForce_.assign(3 * (size_t)a.n, 0);
  explicitForce_.assign(implicitFluid_ ? 3 * (size_t)a.n : 0, 0);
  // The reactions of the explicit particle forces in the implicit fluid side of the drag (f_vm's m_a Du/Dt) and
  // of the capillary force (either side) are shared by face mass (DepositByFaceMass): by kernel weight on top of
  // the implicit relaxation, f_vm's share in a light gas threw particles out of ex44's box (60 spheres into water).
  const bool explicitForces = !implicitFluid_;
  const bool byMass         = Capillary() || implicitFluid_;
  PetscReal  localVolume    = 0;
  for (PetscInt p = 0; p < a.n; ++p) {
    H_[p]       = KernelWidth(2 * a.radius[p]);
    scratch_[p] = 4.0 / 3.0 * PETSC_PI * a.radius[p] * a.radius[p] * a.radius[p];
    localVolume += scratch_[p];
    if (dtLast_ > 0)
      for (int d = 0; d < 3; ++d) {
        lastForce_[3 * p + d] = (a.fluidImpulse[3 * p + d] + a.fluidExplicitImpulse[3 * p + d]) / dtLast_;
        if (implicitFluid_) explicitForce_[3 * p + d] = a.fluidExplicitImpulse[3 * p + d] / dtLast_;
      }
    for (int d = 0; d < 3; ++d) a.fluidImpulse[3 * p + d] = a.fluidExplicitImpulse[3 * p + d] = 0;
  }
  PetscCall(VecSet(volume_, 0));
  PetscCall(avg_.Deposit(3, a.n, a.x, H_.data(), scratch_.data(), 1, volume_));
  // Particles added since the last projection (an insertion; their fluid fields are still zero: fluid_viscosity is
  // set for every particle at each Average) displace the fluid where they appear, but in a closed box that volume has
  // to come from somewhere: taken as the pressure solve's mean it left every cell, and a pool lost the metal's share
  // of each inserted sphere (1.571e-13 m^3 per 0.1 mm sphere in a box 30 % full; the reduced nozzle track's metal 1e-3
  // off its books). So the rate the continuity takes gets, besides the new volume where it appears, the same volume
  // back from the cells without metal (alpha < 1e-12, by their fluid volume; all cells with one fluid): it sums to
  // zero, and no metal moves but where a new sphere pushes it.
  bool born = false;
  if (dtLast_ > 0 && a.fluidViscosity) {
    bornVolume_.assign((size_t)a.n, 0);
    PetscInt mine = 0, any = 0;
    for (PetscInt p = 0; p < a.n; ++p)
      if (a.fluidViscosity[p] == 0) bornVolume_[(size_t)p] = scratch_[p], ++mine;
    PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPIU_INT, MPI_SUM, comm_));
    born = any > 0;
    if (born) {
      if (!bornCells_) PetscCall(VecDuplicate(volume_, &bornCells_));
      PetscCall(VecSet(bornCells_, 0));
      PetscCall(avg_.Deposit(3, a.n, a.x, H_.data(), bornVolume_.data(), 1, bornCells_));
      // the cells that give it: without metal, weighted by their fluid volume eps V (sum over ranks)
      PetscReal          sums[2] = {0, 0};  // the new volume / V, the weights' sum
      const PetscScalar *bv, *ev, *av = nullptr;
      PetscInt           m;
      PetscCall(VecGetLocalSize(bornCells_, &m));
      PetscCall(VecGetArrayRead(bornCells_, &bv));
      PetscCall(VecGetArrayRead(flow_->FluidFraction(), &ev));
      if (phase_) PetscCall(VecGetArrayRead(phase_, &av));
      gasWeight_.assign((size_t)m, 0);
      for (PetscInt k = 0; k < m; ++k) {
        sums[0] += PetscRealPart(bv[k]) / Vc;
        if (!av || PetscRealPart(av[k]) < 1e-12) gasWeight_[(size_t)k] = PetscRealPart(ev[k]), sums[1] += gasWeight_[(size_t)k];
      }
      if (av) PetscCall(VecRestoreArrayRead(phase_, &av));
      PetscCall(VecRestoreArrayRead(flow_->FluidFraction(), &ev));
      PetscCall(VecRestoreArrayRead(bornCells_, &bv));
      PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPIU_REAL, MPIU_SUM, comm_));
      bornTotal_ = sums[0];
      if (sums[1] > 0)
        for (PetscReal &w : gasWeight_) w /= sums[1];
      else gasWeight_.clear();  // no cell without metal: the pressure solve takes the mean, as before
    }
  }
  PetscReal sums[4] = {localVolume, 0, 0, 0}, all[4];
  massForce_.assign(byMass ? 3 * (size_t)a.n : 0, 0);
  for (PetscInt p = 0; p < a.n; ++p)
    for (int d = 0; d < 3; ++d) {
      PetscReal cap = 0;
      if (Capillary() && dtLast_ > 0) cap = a.fluidCapillaryImpulse[3 * p + d] / dtLast_;
      if (Capillary()) a.fluidCapillaryImpulse[3 * p + d] = 0;
      if (byMass) massForce_[3 * p + d] = cap + (implicitFluid_ ? explicitForce_[3 * p + d] : 0);
      sums[1 + d] += lastForce_[3 * p + d] + cap;
    }
  PetscCallMPI(MPI_Allreduce(sums, all, 4, MPIU_REAL, MPIU_SUM, comm_));
  last_.particleVolume = all[0];
  for (int d = 0; d < 3; ++d) last_.dragSum[d] = all[1 + d];
  PetscCall(VecSum(volume_, &last_.projectedVolume));
  // eps = 1 - particle volume / cell volume, floored (docs/physics.md F: eps is the cell's fluid fraction).
  {
    Vec                e = flow_->FluidFraction();
    PetscScalar       *ea, *ca = nullptr;
    const PetscScalar *va;
    PetscInt           m, clipped = 0;
    PetscReal          lo = 1;
    PetscCall(VecGetLocalSize(e, &m));
    PetscCall(VecGetArray(e, &ea));
    PetscCall(VecGetArrayRead(volume_, &va));
    const PetscScalar *ba = nullptr;
    if (born) PetscCall(VecGetArrayRead(bornCells_, &ba));
    if (epsChange_) PetscCall(VecGetArray(epsChange_, &ca));
    const PetscReal share = dtLast_ > 0 && dt > 0 && dt < dtLast_ ? dt / dtLast_ : 1;
    for (PetscInt k = 0; k < m; ++k) {
      PetscReal v = 1 - PetscRealPart(va[k]) / Vc;
      if (v < minEps_) v = minEps_, ++clipped;
      lo = std::min(lo, v);
      if (!ba) {
        if (share < 1) v = PetscRealPart(ea[k]) + share * (v - PetscRealPart(ea[k]));
        if (ca) ca[k] = v - PetscRealPart(ea[k]);  // what the particles displaced since the last projection, this step's share (F1)
      } else {  // the new particles' volume at once, in eps and in the rate; the rest's displacement as above
        const PetscReal b = PetscRealPart(ba[k]) / Vc, moved = PetscRealPart(ea[k]) + share * (v + b - PetscRealPart(ea[k]));
        v = moved - b;
        if (ca) ca[k] = v - PetscRealPart(ea[k]) + (gasWeight_.empty() ? 0 : bornTotal_ * gasWeight_[(size_t)k]);
      }
      ea[k] = v;
    }
    if (epsChange_) PetscCall(VecRestoreArray(epsChange_, &ca));
    if (ba) PetscCall(VecRestoreArrayRead(bornCells_, &ba));
    PetscCall(VecRestoreArrayRead(volume_, &va));
    PetscCall(VecRestoreArray(e, &ea));
    PetscCallMPI(MPI_Allreduce(&clipped, &last_.clipped, 1, MPIU_INT, MPI_SUM, comm_));
    PetscCallMPI(MPI_Allreduce(&lo, &last_.minEps, 1, MPIU_REAL, MPIU_MIN, comm_));
    PetscCall(flow_->PropertiesChanged());
  }
  // The reaction: -F on the faces of each component, as an acceleration -F/(V (eps rho)_f) with the
  // face's (eps rho) of the flow's predictor (FaceAverage, grid/FaceProperties.hpp), so the fluid's momentum
  // changes by exactly -F dt.
  PetscCall(DMGlobalToLocal(sg.Cells(), flow_->FluidFraction(), INSERT_VALUES, cellLocal_));
  PetscCall(DMGlobalToLocal(sg.Cells(), flow_->Density(), INSERT_VALUES, rhoLocal_));
  PetscCall(sg.GetLocal(3, cellLocal_, &eps));
  PetscCall(sg.GetLocal(3, rhoLocal_, &rho));
  PetscReal source[3] = {0, 0, 0};
  std::vector<PetscReal> kv(implicitFluid_ ? a.n : 0);
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecSet(accel_[d], 0));
    PetscCall(VecSet(wallForce_[d], 0));
    if (implicitFluid_) {  // K_p and K_p v_p to the faces: the rate and the target of the relaxation
      LocalField C, W, U, F;
      for (PetscInt p = 0; p < a.n; ++p) kv[p] = a.fluidDrag[p] * a.v[3 * p + d];
      PetscCall(VecSet(rate_[d], 0));
      PetscCall(VecSet(target_[d], 0));
      const PetscReal *values[2] = {a.fluidDrag, kv.data()};
      Vec              outs[2]   = {rate_[d], target_[d]};
      PetscCall(avg_.Deposit(d, a.n, a.x, H_.data(), 2, values, 1, outs, true));
      PetscCall(sg.GetGlobal(d, rate_[d], &C));
      PetscCall(sg.GetGlobal(d, target_[d], &W));
      PetscCall(sg.GetGlobal(d, flow_->Velocity(d), &U));
      PetscCall(sg.GetGlobal(d, wallForce_[d], &F));
      sg.Owned(d, s, n);
      const PetscInt last = sg.Points(d, d) - 1;
      for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
        for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
          for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
            PetscInt q[3] = {i, j, k}, cm[3] = {i, j, k};
            if (!sg.Base().Periodic(d) && (q[d] == 0 || q[d] == last)) {
              // A wall face's share: the drag between the particles and the fluid at the wall's velocity, passed to
              // the wall (the boundary sets the velocity there); the fluid's relaxation does not act there.
              const PetscReal K = PetscRealPart(C.at(q)), f = K > 0 ? K * (PetscRealPart(W.at(q)) / K - PetscRealPart(U.at(q))) : 0;
              source[d] += f;
              F.at(q) = -f;
              C.at(q) = 0, W.at(q) = 0;
              continue;
            }
            const PetscReal K = PetscRealPart(C.at(q));
            if (!(K > 0)) {
              C.at(q) = 0, W.at(q) = 0;
              continue;
            }
            cm[d] -= 1;
            const PetscReal eL = PetscRealPart(eps.at(cm)), eR = PetscRealPart(eps.at(q));
            const PetscReal bL = eL / PetscRealPart(rho.at(cm)), bR = eR / PetscRealPart(rho.at(q));
            const FaceProperties face = FaceAverage(eL, eR, bL, bR);
            const PetscReal eF = face.eps, bF = face.beta;
            const PetscReal w = PetscRealPart(W.at(q)) / K;
            source[d] += K * (w - PetscRealPart(U.at(q)));  // the fluid's drag at the start of the step, N
            W.at(q) = w;
            C.at(q) = K / (Vc * eF * eF / bF);
          }
      PetscCall(sg.RestoreGlobal(d, wallForce_[d], &F));
      PetscCall(sg.RestoreGlobal(d, flow_->Velocity(d), &U));
      PetscCall(sg.RestoreGlobal(d, target_[d], &W));
      PetscCall(sg.RestoreGlobal(d, rate_[d], &C));
      if (!explicitForces) {
        PetscCall(DepositByFaceMass(d, a, eps, rho, &source[d]));
        continue;
      }
    }
    // The wall faces take their share (walls: their half control volumes), which passes to the wall (wallForce_).
    PetscCall(avg_.Deposit(d, a.n, a.x, H_.data(), lastForce_.data() + d, 3, accel_[d], true));
    PetscCall(sg.GetGlobal(d, accel_[d], &A));
    PetscCall(sg.GetGlobal(d, wallForce_[d], &Fw));
    sg.Owned(d, s, n);
    const PetscInt last = sg.Points(d, d) - 1, sd = eps.stride[d];  // sd: from a face's cell q to cm = q - e_d
    const bool     wall = !sg.Base().Periodic(d);
    auto           toWall = [&](PetscInt i, PetscInt j, PetscInt k) {
      PetscScalar &v = A.at(i, j, k);
      source[d] -= PetscRealPart(v);
      Fw.at(i, j, k) = v;
      v              = 0;
    };
    // Row by row with unit stride along x; the wall faces' shares to the wall; the source summed in the
    // same order as point by point.
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
        const PetscInt qd = d == 1 ? j : k;
        if (wall && d != 0 && (qd == 0 || qd == last)) {
          for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) toWall(i, j, k);
          continue;
        }
        PetscScalar       *Ar = &A.at(s[0], j, k);
        const PetscScalar *er = &eps.at(s[0], j, k), *rr = &rho.at(s[0], j, k);
        PetscInt           i0 = 0, i1 = n[0];
        if (wall && d == 0) {
          i0 = s[0] == 0 ? 1 : 0, i1 = s[0] + n[0] - 1 == last ? n[0] - 1 : n[0];
          if (i0 == 1) toWall(s[0], j, k);
          if (i1 == n[0] - 1) toWall(s[0] + n[0] - 1, j, k);
        }
        PetscReal sum = source[d];  // first the row's sum (same order), then the conversion, which vectorises
        for (PetscInt i = i0; i < i1; ++i) sum -= PetscRealPart(Ar[i]);
        source[d] = sum;
        for (PetscInt i = i0; i < i1; ++i) {
          const PetscReal eL = PetscRealPart(er[i - sd]), eR = PetscRealPart(er[i]);
          const PetscReal bL = eL / PetscRealPart(rr[i - sd]), bR = eR / PetscRealPart(rr[i]);
          const FaceProperties face = FaceAverage(eL, eR, bL, bR);
          const PetscReal eF = face.eps, bF = face.beta;
          Ar[i] = -PetscRealPart(Ar[i]) / (Vc * eF * eF / bF);
        }
      }
    PetscCall(sg.RestoreGlobal(d, wallForce_[d], &Fw));
    PetscCall(sg.RestoreGlobal(d, accel_[d], &A));
    if (byMass) PetscCall(DepositByFaceMass(d, a, eps, rho, &source[d]));  // after the conversion above
  }
  PetscCall(sg.RestoreLocal(3, rhoLocal_, &rho));
  PetscCall(sg.RestoreLocal(3, cellLocal_, &eps));
  PetscCallMPI(MPI_Allreduce(source, last_.sourceSum, 3, MPIU_REAL, MPIU_SUM, comm_));
  PetscCall(sw.RestoreArrays(&a));
  PetscCall(PetscLogEventEnd(evProject_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

// eps at the faces (weights of the velocity average, K1) and the pressure gradient at the faces (K2). A wall face
// has half a control volume, between the wall and the first cell's centre, whose velocity the boundary sets: there
// the gradient is the one that holds that fluid at rest against gravity and the particles' share deposited on the
// face (F2 without inertia and viscous stress: eps dp/dx_d = eps rho g_d - f_d, f_d = wallForce_/(V/2)), so that
// the particles there read the pressure the wall carries, and the pressure at the wall is p(cell) -/+ (h/2) dp/dx_d.
PetscErrorCode Coupling::FaceFields() {
  LocalField eps, p, E, G, R, Fw;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  const StaggeredGrid &sg = flow_->Staggered();
  const PetscReal     *h  = sg.Base().Spacing();
  const PetscReal     *g  = flow_->Gravity();
  const PetscReal      Vh = 0.5 * h[0] * h[1] * h[2];
  PetscCall(DMGlobalToLocal(sg.Cells(), flow_->FluidFraction(), INSERT_VALUES, cellLocal_));
  PetscCall(DMGlobalToLocal(sg.Cells(), flow_->Pressure(), INSERT_VALUES, rhoLocal_));  // rhoLocal_ as scratch
  PetscCall(sg.GetLocal(3, cellLocal_, &eps));
  PetscCall(sg.GetLocal(3, rhoLocal_, &p));
  PetscCall(sg.GetGlobal(3, flow_->Density(), &R));
  for (int d = 0; d < 3; ++d) {
    PetscCall(sg.GetGlobal(d, faceEps_[d], &E));
    PetscCall(sg.GetGlobal(d, gradP_[d], &G));
    PetscCall(sg.GetGlobal(d, wallForce_[d], &Fw));
    sg.Owned(d, s, n);
    const PetscInt last = sg.Points(d, d) - 1, sd = eps.stride[d];  // sd: from a face's cell q to cm = q - e_d
    const bool     wall = !sg.Base().Periodic(d);
    // A wall face (i, j, k) next to the cell c of the local array's offset: eps and the half control volume's gradient.
    auto atWall = [&](PetscInt i, PetscInt j, PetscInt k, PetscInt c) {
      const PetscInt  cell[3] = {i - (d == 0 && i == last), j - (d == 1 && j == last), k - (d == 2 && k == last)};
      const PetscReal e = PetscRealPart((&eps.at(s[0], j, k))[c]), r = PetscRealPart(R.at(cell));
      E.at(i, j, k) = e;
      G.at(i, j, k) = r * g[d] - PetscRealPart(Fw.at(i, j, k)) / Vh / e;
    };
    // Row by row with unit stride along x (the x walls' faces, if any, at the row's ends).
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
        PetscScalar       *Er = &E.at(s[0], j, k), *Gr = &G.at(s[0], j, k);
        const PetscScalar *er = &eps.at(s[0], j, k), *pr = &p.at(s[0], j, k);
        const PetscInt     qd = d == 1 ? j : k;
        PetscInt           i0 = 0, i1 = n[0];
        if (wall && d != 0 && (qd == 0 || qd == last)) {  // a wall row: all its faces on the wall
          for (PetscInt i = 0; i < n[0]; ++i) atWall(s[0] + i, j, k, qd == 0 ? i : i - sd);
          continue;
        }
        if (wall && d == 0) {
          if (s[0] == 0) atWall(s[0], j, k, 0), i0 = 1;
          if (s[0] + n[0] - 1 == last) atWall(s[0] + n[0] - 1, j, k, n[0] - 1 - sd), i1 = n[0] - 1;
        }
        for (PetscInt i = i0; i < i1; ++i) {
          Er[i] = 0.5 * (er[i] + er[i - sd]);
          Gr[i] = (pr[i] - pr[i - sd]) / h[d];
        }
      }
    PetscCall(sg.RestoreGlobal(d, wallForce_[d], &Fw));
    PetscCall(sg.RestoreGlobal(d, gradP_[d], &G));
    PetscCall(sg.RestoreGlobal(d, faceEps_[d], &E));
  }
  PetscCall(sg.RestoreGlobal(3, flow_->Density(), &R));
  PetscCall(sg.RestoreLocal(3, rhoLocal_, &p));
  PetscCall(sg.RestoreLocal(3, cellLocal_, &eps));
  PetscFunctionReturn(0);
}

// Step 3: the fluid at each particle and the forces the DEM sub-steps apply.
PetscErrorCode Coupling::Average(PetscReal dt) {
  ParticleArrays a;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evAverage_, 0, 0, 0, 0));
  PetscCall(FaceFields());
  const ParticleSwarm &sw = dem_->Particles();
  PetscCall(sw.GetArrays(&a));
  const PetscInt n = a.n;
  PetscCheck((PetscInt)H_.size() == n, PETSC_COMM_SELF, PETSC_ERR_ORDER, "coupling: Average() needs the particles of the last Project()");
  std::vector<PetscReal> u(3 * n), gp(3 * n), e(n), rf(n), mf(n), st(interfaceForces_ ? 3 * n : 0);
  std::vector<PetscReal> al(Capillary() ? n : 0), ga(Capillary() ? 3 * n : 0);  // alpha and grad alpha (CouplingCapillary.cpp)
  if (Capillary()) PetscCall(AlphaGradient());
  // du_d/dx_e at the particles, e = d + 1 + k (mod 3): [3 k n + 3 p + d] (CouplingRotation.cpp)
  std::vector<PetscReal> gr(Rotation() ? 6 * n : 0);
  if (Rotation()) PetscCall(VelocityGradients());
  for (int d = 0; d < 3; ++d) {
    // One pass per location (the kernel weights are the costly part): the velocity (eps-weighted, wall
    // faces included), the pressure gradient (unweighted, K2; wall faces included, as the force deposit)
    // and the interface's face force (surface tension and Marangoni per unit volume, P1; unweighted, not
    // computed on wall faces).
    Vec        fields[6], weights[6] = {faceEps_[d], nullptr, nullptr, nullptr, nullptr, nullptr};
    bool       walls[6] = {true, false, false, false, false, false};
    PetscReal *outs[6]  = {u.data() + d, nullptr, nullptr, nullptr, nullptr, nullptr};
    PetscInt   nf       = 1;
    fields[0]           = flow_->Velocity(d);
    const bool needGradP = pressureForce_ || (addedMass_ > 0 && addedMassAccel_ == FluidAcceleration::Pressure);
    if (needGradP) fields[nf] = gradP_[d], walls[nf] = true, outs[nf++] = gp.data() + d;  // wall faces: their half volumes (FaceFields)
    if (interfaceForces_) {
      PetscCall(flow_->FaceForce(d, &fields[nf]));
      outs[nf++] = st.data() + d;
    }
    if (Capillary()) fields[nf] = gradAlpha_[d], outs[nf++] = ga.data() + d;
    for (int k = 0; Rotation() && k < 2; ++k) fields[nf] = gradU_[d][k], walls[nf] = true, outs[nf++] = gr.data() + 3 * k * n + d;
    PetscCall(avg_.Average(d, nf, fields, weights, walls, n, a.x, H_.data(), outs, 3));
  }
  // eps at the particle: by default the plain kernel average, so that eps times the (eps-weighted) velocity
  // read is the kernel average of the superficial velocity eps u, as the drag laws assume; the eps-weighted
  // average of K1 reads eps high by var(eps)/eps and at a bed's edges by more (ex34, -coupling_fraction_average).
  // The local mixture's density and viscosity are eps-weighted (K1; docs/physics.md F: with a free surface rho
  // and mu follow alpha). One pass for the three.
  {
    // With the capillary force, also the liquid fraction alpha, unweighted: F of Capillary.hpp is the
    // plain kernel's marginal.
    const Vec  fields[4]  = {flow_->FluidFraction(), flow_->Density(), flow_->Viscosity(), alpha_};
    const Vec  weights[4] = {weightedFraction_ ? flow_->FluidFraction() : nullptr, flow_->FluidFraction(), flow_->FluidFraction(), nullptr};
    const bool walls[4]   = {true, true, true, true};
    PetscReal *outs[4]    = {e.data(), rf.data(), mf.data(), al.data()};
    PetscCall(avg_.Average(3, Capillary() ? 4 : 3, fields, weights, walls, n, a.x, H_.data(), outs, 1));
  }
  for (PetscInt p = 0; p < n; ++p) {
    const PetscReal d = 2 * a.radius[p], V = PETSC_PI * d * d * d / 6, rho = rf[p], mu = mf[p];
    PetscReal       uf[3], slip2 = 0;
    for (int c = 0; c < 3; ++c) {
      uf[c] = u[3 * p + c];
      slip2 += (uf[c] - a.v[3 * p + c]) * (uf[c] - a.v[3 * p + c]);
    }
    // K1b: the fluid read back the particle's own reaction -F_last, spread by its kernel: C F/mu, with
    // the Oseen coefficient at the slip it causes (a few fixed-point passes: C falls as the slip grows).
    // The estimate is that of an isolated particle in unbounded fluid: among neighbours (eps below
    // -coupling_self_correction_min_eps) the fluid around a particle is held by continuity, and in a
    // packed bed the correction's gain C K/mu exceeds 1, so that it would feed on itself: it is left out there.
    const bool dilute = e[p] >= selfMinEps_;
    for (int it = 0; selfCorrection_ && dilute && it < 4; ++it) {
      const PetscReal C = SelfCoefficient(H_[p], std::sqrt(slip2) * H_[p] * rho / mu);
      slip2 = 0;
      for (int c = 0; c < 3; ++c) {
        uf[c] = u[3 * p + c] + C * lastForce_[3 * p + c] / mu;
        slip2 += (uf[c] - a.v[3 * p + c]) * (uf[c] - a.v[3 * p + c]);
      }
    }
    a.fluidDrag[p] = drag::Coefficient(law_, d, e[p], std::sqrt(slip2), rho, mu, dragSwitch_);
    // Added mass (P1): m_a = C_vm rho V, taken implicitly by the kick (Dem.cpp); m_a Du/Dt explicitly, Du/Dt
    // (-coupling_added_mass_acceleration) by default from the change of the (undisturbed) fluid velocity read
    // over the step; or from the fluid's momentum balance without viscous and particle forces, (-grad p +
    // f_st)/rho + g, zero in fluid at rest whatever the particle does (the velocity read contains the fluid
    // the particle pushes: at a free surface, where that is light gas, a floating sphere's bobbing grew until
    // it left the surface, ex41); or none. A particle that has not been read yet (m_a still 0: new, or the
    // set-up) gets no acceleration in the velocity form.
    const PetscReal ma = addedMass_ * rho * V, dUdt = dt > 0 && a.fluidAddedMass[p] > 0 ? 1 / dt : 0;
    const PetscReal *g = flow_->Gravity();
    // The capillary force (-coupling_contact_angle) the DEM kicks take at the particle's current height above
    // the surface plane read here (Dem.cpp HalfKick), and sum for the fluid's reaction.
    if (Capillary()) SurfacePlane(H_[p], al[p], &ga[3 * p], &a.x[3 * p], &a.fluidSurfacePlane[4 * p]);
    // Magnus lift (explicit, with the slip the drag sees) and the rotational drag's K_r and Omega_f (RotationLaws.hpp).
    PetscReal lift[3] = {0, 0, 0};
    if (Rotation()) {
      PetscReal gp9[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 2; ++k) gp9[3 * c + (c + 1 + k) % 3] = gr[3 * k * n + 3 * p + c];
      RotationForces(a, p, gp9, uf, rho, mu, lift);
    }
    a.fluidViscosity[p] = lubrication_ && !freeSurface_ ? flow_->ReferenceViscosity() : mu;  // P8 (uniform: exactly the flow's)
    for (int c = 0; c < 3; ++c) {
      const PetscReal fvm = ma == 0 || addedMassAccel_ == FluidAcceleration::None ? 0
                            : addedMassAccel_ == FluidAcceleration::Pressure ? ma * ((-gp[3 * p + c] + (interfaceForces_ ? st[3 * p + c] : 0)) / rho + g[c])
                                                                             : ma * (uf[c] - a.fluidVelocity[3 * p + c]) * dUdt;
      a.fluidVelocity[3 * p + c] = uf[c];
      a.fluidForce[3 * p + c]    = (pressureForce_ ? -V * gp[3 * p + c] : 0) + (interfaceForces_ ? V * st[3 * p + c] : 0) + fvm + lift[c];
      // f_vm's and the lift's explicit impulse over the coming sub-steps, which the fluid receives with the opposite sign (F5).
      a.fluidExplicitImpulse[3 * p + c] += (fvm + lift[c]) * dt;
    }
    a.fluidAddedMass[p] = ma;
  }
  PetscCall(sw.RestoreArrays(&a));
  PetscCall(PetscLogEventEnd(evAverage_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode Coupling::WallPressureGradient(int d, int side, PetscReal *mean) const {
  LocalField G;
  PetscInt   s[3], n[3];
  PetscReal  sum[2] = {0, 0}, all[2];

  PetscFunctionBeginUser;
  const StaggeredGrid &sg = flow_->Staggered();
  const PetscInt       q  = side ? sg.Points(d, d) - 1 : 0;
  PetscCall(sg.GetGlobal(d, gradP_[d], &G));
  sg.Owned(d, s, n);
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscInt at[3] = {i, j, k};
        if (at[d] == q) sum[0] += PetscRealPart(G.at(at)), sum[1] += 1;
      }
  PetscCall(sg.RestoreGlobal(d, gradP_[d], &G));
  PetscCallMPI(MPI_Allreduce(sum, all, 2, MPIU_REAL, MPIU_SUM, comm_));
  *mean = all[1] > 0 ? all[0] / all[1] : 0;
  PetscFunctionReturn(0);
}

}  // namespace vofdem
