// Mass-consistent momentum transport of the VOF module (Vof.hpp AdvectWithMomentum; docs/physics.md F2).
//
// Why: at density ratios of 1000-8000 a velocity advected on its own (the flow's -(U.grad)U) and a
// density moved by the geometric VOF fluxes disagree where the interface crosses a face: the heavy
// phase's momentum lands in a light control volume (or the reverse) and the light side is kicked to
// speeds of the heavy one's momentum over the light density. Moving rho u with the same mass fluxes
// that move rho (Rudman 1998, Int. J. Numer. Meth. Fluids 28; Bussmann et al. 2002; Arrufat et al.
// 2021, J. Comput. Phys. 425) makes a discontinuity of momentum travel with the discontinuity of
// density: a uniform velocity stays uniform to round-off whatever the density jump.
//
// On the MAC grid: the control volume of a d-face spans half of each of its two cells, so its density
// is rho_f = (rho_L + rho_R)/2 (the arithmetic mean, the one the flow's predictor and projection use).
// Its mass fluxes are the means of the cell-face mass fluxes it straddles:
//   through the cell centre between d-faces: (m_d[i] + m_d[i+1]) / 2,
//   through the edge across e != d:          (m_e[cell i-1] + m_e[cell i]) / 2 at that e-face,
// with the cell-face mass flux m = rho_0 u + (rho_1 - rho_0) F_1, F_1 the phase-1 volume flux of a
// split sweep (VofAdvect.cpp). The transport is split like alpha's (Weymouth & Yue 2010; Pal et al.
// 2021 do the same for momentum): after the sweep along e moved alpha from alpha' to alpha'', each
// velocity component is moved along e with that sweep's fluxes,
//   rho'' u'' = rho' u' - dt/h_e (m_P u_P - m_M u_M) + u^n D,   D = rho'' - rho' + dt/h_e (m_P - m_M),
// rho', rho'' the control volume's densities from alpha', alpha'' (as the flow computes them). D is
// the part of the mass change the fluxes do not explain (the sweep's dilatation term, c_i dt du_e/dx_e
// in alpha); it carries the velocity of the start of the step, the same in every sweep, so that the
// D's, which add up to dt div(u) = 0 over the three sweeps, add no momentum: rho u is conserved to the
// projection's tolerance. Written for u'',
//   u'' = u' + (dt/h_e [m_M (u_M - u') - m_P (u_P - u')] + D (u^n - u')) / rho'':
// a uniform u stays uniform to round-off, and since each sweep takes out of a cell no more than it
// holds, the upwind update is a convex combination (bounded) however light the control volume, up to
// the small D (u^n - u') term. Transporting over the whole step at once instead (unsplit, with the
// summed fluxes) is not: a light volume that the
// x-sweep fills and the y-sweep empties loses more mass than it started with, and at ratio 8000 the
// round-off of u grows to order one within 60 steps (measured with ex36).
// u_P, u_M: the flow's TVD face value (its -flow_advection limiter), upwind by the sign of m; the
// upwind value where the volume's effective Courant number is too large for it (kTvdCourant). Forward
// Euler in time (the sweeps' fluxes are one step's), so the flow takes it outside its AB2 history
// (Flow::SetAdvectionAcceleration).
// Assumes eps = 1 (particles with a free surface are refused); the flow's boundary faces are not
// advanced (their rows are set by the boundary conditions).
#include "vofdem/vof/Vof.hpp"

#include "vofdem/base/Runtime.hpp"
#include "vofdem/flow/Flow.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vofdem {

namespace {

struct SweepFields {
  LocalField u, m;         // ghosted: the component being moved (u'), the sweep's face mass fluxes
  LocalField r0, r1;       // ghosted cell mixture densities before (from alpha') and after (alpha'') the sweep (the VOF's DMDA layout)
  LocalField out, un;      // global: u'' (written), u^n (the flow's, read)
  PetscReal  rho0, rho1;
};

// The TVD face values keep a forward-Euler update bounded while the control volume's effective Courant
// number dt m / (h rho) stays below 1/(1 + psi_max/2) = 1/2 (psi <= 2 for every limiter offered). In one
// phase that is the sweep's Courant number (<= -vof_cfl <= 1/2); where heavy fluid crosses a light
// volume it can reach rho_1/rho_0 times that, and the limited correction on the outflow face, multiplied
// by it, grew the capillary currents of a translating drop at ratio 1000 to order one (ex36 with
// -vof_surface_tension 1). There the upwind value is taken, decided per face (decided per volume,
// the two volumes of a face could take different fluxes through it: ex36's drop in still gas gained 2 %
// momentum in one crossing).
const PetscReal kTvdCourant = 0.5;

inline PetscReal MixtureDensity(PetscReal rho0, PetscReal rho1, PetscReal a) {  // as UpdateProperties
  const PetscReal f = std::min(std::max(a, (PetscReal)0), (PetscReal)1);
  return f * rho1 + (1 - f) * rho0;
}

// The cells' mixture densities of a ghosted alpha array (the VOF's DMDA), once per sweep: every face
// of the three components reads them up to eight times (computing them there was a sixth of the dam
// break's step). Only cells within 2 of the owned ones are read (a face's volume and its neighbours
// along e); the 4-deep ghost layers beyond them are skipped.
void CellDensities(DM da, const Vec alphaLocal, PetscReal rho0, PetscReal rho1, std::vector<PetscReal> *rho) {
  const PetscScalar *a;
  PetscInt           n, s[3], m[3], gs[3], gm[3], lo[3], hi[3];
  PetscCallAbort(PETSC_COMM_SELF, DMDAGetCorners(da, &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  PetscCallAbort(PETSC_COMM_SELF, DMDAGetGhostCorners(da, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  for (int d = 0; d < 3; ++d) {
    lo[d] = std::max(s[d] - 2, gs[d]) - gs[d];
    hi[d] = std::min(s[d] + m[d] + 2, gs[d] + gm[d]) - gs[d];
  }
  PetscCallAbort(PETSC_COMM_SELF, VecGetLocalSize(alphaLocal, &n));
  PetscCallAbort(PETSC_COMM_SELF, VecGetArrayRead(alphaLocal, &a));
  rho->resize((size_t)n);
  for (PetscInt k = lo[2]; k < hi[2]; ++k)
    for (PetscInt j = lo[1]; j < hi[1]; ++j) {
      const PetscInt row = (j + gm[1] * k) * gm[0];
      for (PetscInt i = lo[0]; i < hi[0]; ++i) (*rho)[(size_t)(row + i)] = MixtureDensity(rho0, rho1, PetscRealPart(a[row + i]));
    }
  PetscCallAbort(PETSC_COMM_SELF, VecRestoreArrayRead(alphaLocal, &a));
}

// Component c moved along e at the owned faces [s, s+n) of c that are not boundary faces. Neighbours
// are reached by linear offsets (a stride per field and direction) rather than index triples: the
// triples, shifted along a run-time direction, kept the loop on the stack (it was a fifth of the dam
// break's step with PFMG). The arithmetic is the same, term by term.
template <Limiter LIM>
void MomentumSweepKernel(int c, int e, const SweepFields &F, const PetscInt s[3], const PetscInt n[3], PetscReal r) {
  auto offset = [](const LocalField &f, PetscInt i, PetscInt j, PetscInt k) {
    return (i - f.g0[0]) * f.stride[0] + (j - f.g0[1]) * f.stride[1] + (k - f.g0[2]) * f.stride[2];
  };
  const PetscInt ue = F.u.stride[e], me = F.m.stride[e], mc = F.m.stride[c], re = F.r1.stride[e], rc = F.r1.stride[c];
  const PetscScalar *u = F.u.data, *m = F.m.data, *r0 = F.r0.data, *r1 = F.r1.data, *un = F.un.data;
  PetscScalar       *out = F.out.data;
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
      PetscInt iu = offset(F.u, s[0], j, k), im = offset(F.m, s[0], j, k), ir = offset(F.r1, s[0], j, k), io = offset(F.out, s[0], j, k);
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i, ++iu, ++im, ++ir, ++io) {
        auto      U = [&](int o) { return PetscRealPart(u[iu + o * ue]); };
        PetscReal mP, mM;  // mass fluxes through the + and - faces of the control volume along e
        if (e == c) {
          mP = 0.5 * PetscRealPart(m[im] + m[im + me]);
          mM = 0.5 * PetscRealPart(m[im - me] + m[im]);
        } else {  // e-faces with e-index q_e (minus) and q_e + 1 (plus) of the cells q - e_c and q
          mM = 0.5 * PetscRealPart(m[im] + m[im - mc]);
          mP = 0.5 * PetscRealPart(m[im + me] + m[im - mc + me]);
        }
        const PetscReal uP = U(0), uE = U(1), uW = U(-1);
        // rho'' of this control volume (cells q - e_c and q) and of its neighbours along e (o = -1, 0, 1)
        auto rhoAt = [&](int o) { return 0.5 * (PetscRealPart(r1[ir + o * re]) + PetscRealPart(r1[ir - rc + o * re])); };
        const PetscReal rho = rhoAt(0);
        // Per face (so that both volumes sharing it take the same flux: conservation), TVD only where
        // the face's effective Courant number is small for both volumes.
        const bool tvdP = r * std::fabs(mP) <= kTvdCourant * std::min(rho, rhoAt(1));
        const bool tvdM = r * std::fabs(mM) <= kTvdCourant * std::min(rho, rhoAt(-1));
        const PetscReal fP = !tvdP ? (mP >= 0 ? uP : uE) : mP >= 0 ? LimitedFace<LIM>(uW, uP, uE) : LimitedFace<LIM>(U(2), uE, uP);
        const PetscReal fM = !tvdM ? (mM >= 0 ? uW : uP) : mM >= 0 ? LimitedFace<LIM>(U(-2), uW, uP) : LimitedFace<LIM>(uE, uP, uW);
        const PetscReal rho0 = 0.5 * (PetscRealPart(r0[ir - rc]) + PetscRealPart(r0[ir]));
        const PetscReal dil  = rho - rho0 + r * (mP - mM);  // the sweep's dilatation mass (see the top)
        out[io] = uP + (r * (mM * (fM - uP) - mP * (fP - uP)) + dil * (PetscRealPart(un[io]) - uP)) / rho;
      }
    }
}

// The owned faces of component c that are advanced (the boundary faces of a non-periodic c are not).
void AdvancedFaces(const StaggeredGrid &sg, const Grid &grid, int c, PetscInt s[3], PetscInt n[3]) {
  sg.Owned(c, s, n);
  if (grid.Periodic(c)) return;
  const PetscInt last = sg.Points(c, c) - 1, a = std::max(s[c], (PetscInt)1), b = std::min(s[c] + n[c], last);
  s[c] = a;
  n[c] = std::max(b - a, (PetscInt)0);
}

}  // namespace

PetscErrorCode Vof::CheckFlowOptions(const Flow &flow) {
  PetscFunctionBeginUser;
  if (ConsistentMomentum() && flow.AdvectionLimiter() == Limiter::Central)
    VofdemInputError(grid_->Comm(), "option -flow_advection central: unbounded and unstable with the forward-Euler momentum transport of -vof_momentum consistent; "
                                    "choose a limiter (e.g. vanleer) or -vof_momentum advective");
  PetscCall(CheckContactAngleFaces(flow));
  PetscCall(CheckOpenFaces(flow));
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::AdvectWithMomentum(Flow &flow, PetscReal dt) {
  PetscFunctionBeginUser;
  if (!momentumAcc_[0]) {
    for (int d = 0; d < 3; ++d) {
      PetscCall(DMCreateGlobalVector(sg_->Face(d), &momentumAcc_[d]));
      PetscCall(DMCreateGlobalVector(sg_->Face(d), &velocity_[d]));
      PetscCall(DMCreateLocalVector(sg_->Face(d), &massLocal_[d]));
      PetscCall(DMCreateLocalVector(sg_->Face(d), &velocityLocal_[d]));
    }
  }
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecCopy(flow.Velocity(d), velocity_[d]));
    PetscCall(DMGlobalToLocal(sg_->Face(d), velocity_[d], INSERT_VALUES, velocityLocal_[d]));
    PetscCall(flow.Boundary().FillVelocityGhosts(*sg_, d, velocityLocal_[d]));
    PetscCall(InflowVelocityGhosts(flow, d, velocityLocal_[d]));  // VofOpenFaces.cpp
  }
  Vec u[3] = {flow.Velocity(0), flow.Velocity(1), flow.Velocity(2)};
  momentumFlow_ = &flow;
  PetscCall(Advect(u, dt));  // calls MomentumSweep after each sweep
  momentumFlow_ = nullptr;
  // The flow's predictor adds dt * acc to u^n: acc = (u'' - u^n)/dt; 0 on the boundary faces.
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecWAXPY(momentumAcc_[d], -1, flow.Velocity(d), velocity_[d]));
    PetscCall(VecScale(momentumAcc_[d], 1 / dt));
  }
  flow.SetAdvectionAcceleration(momentumAcc_);
  PetscFunctionReturn(0);
}

// Before a sweep: the cell densities of alpha' (ghosts filled). Only the first sweep of a step computes
// them; a later sweep starts from the alpha'' of the one before, whose densities MomentumSweep made.
PetscErrorCode Vof::MomentumSweepStart(bool later) {
  PetscFunctionBeginUser;
  if (!later) CellDensities(da_, alphaLocal_, momentumFlow_->ReferenceDensity(), density_, &cellRho_[0]);
  else std::swap(cellRho_[0], cellRho_[1]);
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::MomentumSweep(int e, PetscReal dt) {
  SweepFields F;
  PetscInt    s[3], n[3], gs[3], gm[3];

  PetscFunctionBeginUser;
  Flow &flow = *momentumFlow_;
  F.rho0     = flow.ReferenceDensity();
  F.rho1     = density_;
  // m = rho_0 u_e + (rho_1 - rho_0) F_1 of this sweep, with ghosts (velocity_[e] used as scratch is
  // not possible: it is being transported; the flow's own vector is not touched either).
  PetscCall(VecAXPBYPCZ(momentumAcc_[e], F.rho0, F.rho1 - F.rho0, 0, flow.Velocity(e), phaseFlux_[e]));
  PetscCall(DMGlobalToLocal(sg_->Face(e), momentumAcc_[e], INSERT_VALUES, massLocal_[e]));
  PetscCall(sg_->GetLocal(e, massLocal_[e], &F.m));
  PetscCall(DMDAGetGhostCorners(da_, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  // cellRho_[0] holds the densities of the sweep's start (MomentumSweepStart); the end's from alpha'':
  CellDensities(da_, alphaLocal_, F.rho0, F.rho1, &cellRho_[1]);
  F.r0.data = cellRho_[0].data();
  F.r1.data = cellRho_[1].data();
  for (int c = 0; c < 3; ++c) F.r0.g0[c] = F.r1.g0[c] = gs[c];
  F.r0.stride[0] = F.r1.stride[0] = 1;
  F.r0.stride[1] = F.r1.stride[1] = gm[0];
  F.r0.stride[2] = F.r1.stride[2] = gm[0] * gm[1];
  const PetscReal r = dt / grid_->Spacing()[e];
  for (int c = 0; c < 3; ++c) {
    PetscCall(sg_->GetLocal(c, velocityLocal_[c], &F.u));
    PetscCall(sg_->GetGlobal(c, velocity_[c], &F.out));
    PetscCall(sg_->GetGlobal(c, flow.Velocity(c), &F.un));
    AdvancedFaces(*sg_, *grid_, c, s, n);
    switch (flow.AdvectionLimiter()) {
    case Limiter::Upwind: MomentumSweepKernel<Limiter::Upwind>(c, e, F, s, n, r); break;
    case Limiter::Central: break;  // refused by CheckFlowOptions
    case Limiter::Minmod: MomentumSweepKernel<Limiter::Minmod>(c, e, F, s, n, r); break;
    case Limiter::VanLeer: MomentumSweepKernel<Limiter::VanLeer>(c, e, F, s, n, r); break;
    case Limiter::MC: MomentumSweepKernel<Limiter::MC>(c, e, F, s, n, r); break;
    case Limiter::Superbee: MomentumSweepKernel<Limiter::Superbee>(c, e, F, s, n, r); break;
    case Limiter::Koren: MomentumSweepKernel<Limiter::Koren>(c, e, F, s, n, r); break;
    }
    PetscCall(sg_->RestoreGlobal(c, flow.Velocity(c), &F.un));
    PetscCall(sg_->RestoreGlobal(c, velocity_[c], &F.out));
    PetscCall(sg_->RestoreLocal(c, velocityLocal_[c], &F.u));
  }
  PetscCall(sg_->RestoreLocal(e, massLocal_[e], &F.m));
  for (int c = 0; c < 3; ++c) {  // u'' with ghosts for the next sweep
    PetscCall(DMGlobalToLocal(sg_->Face(c), velocity_[c], INSERT_VALUES, velocityLocal_[c]));
    PetscCall(flow.Boundary().FillVelocityGhosts(*sg_, c, velocityLocal_[c]));
    PetscCall(InflowVelocityGhosts(flow, c, velocityLocal_[c]));
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
