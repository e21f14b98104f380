// Energy.hpp: the energy carried by the interface's sweeps (docs/physics.md F7 a). After alpha's sweep along d,
//   E'' = E' - dt/h (Phi_P - Phi_M) + dt/h (u_P - u_M) X,   Phi = F rho_m h_m(T_f, f_up) + (u - F) rho_g h_g(T_f),
//   X = c rho_m h_m(T^n, f^n) + (1 - c) rho_g h_g(T^n),
// with F the sweep's metal volume flux, c alpha's Weymouth-Yue indicator and T_f the van Leer (TVD) face
// temperature from the upwind side where the stencil is one phase, the donor cell's temperature where it is not. With alpha'' = alpha' - dt/h (F_P - F_M) + c dt/h (u_P - u_M), a uniform T
// gives E'' = alpha'' rho_m h_m + (1 - alpha'') rho_g h_g exactly: T stays uniform whatever the jump of rho cp.
// X is frozen over the step's sweeps, so that their dilatation terms add up to X div u. T and f then follow from
// E'' and alpha'' (f = f_l(T)).
// With particles (SetFluidFraction) E is per cell volume, eps times the fluid's; the gas's flux is (eps_f u - F) and the
// dilatation X [dt/h (eps_P u_P - eps_M u_M) + (eps^{n+1} - eps^n)/3], as alpha's (vof/VofAdvect.cpp, F1b): a uniform T
// stays uniform as particles move, and the sweeps' dilatations add up to X times what the projection left of
// div(eps u) + d(eps)/dt. T after the k-th sweep from E''/eps_k, eps_k = eps^n + k/3 of the change, alpha's level.
#include "vofdem/energy/Energy.hpp"

#include "vofdem/base/Runtime.hpp"
#include "vofdem/grid/CellStencil.hpp"

#include <petscdmda.h>

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace {
constexpr PetscReal kPureBand = 1e-6;  // a cell within this of alpha 0 or 1 counts (partly) as one phase (TransportSweep)
}  // namespace

PetscReal Energy::CellTemperature(PetscReal E, PetscReal a, PetscReal guess) const {
  auto f  = [&](PetscReal T) { return CellEnergy(a, T, metal_.MeltFraction(T)) - E; };
  auto df = [&](PetscReal T) { return CellSensibleCapacity(a, T) + a * metal_.density * metal_.latentHeat * metal_.MeltSlope(T); };
  // alpha below -rho_g c_g/(rho_m c_m) (a sweep's intermediate excursion next to particles, which the interface's
  // redistribution puts right after the step's last sweep, Vof::Advect): the mixture's capacity is not positive and
  // E(T) falls with T, so it has no temperature of its own; the guess is kept (the bracket below ran off to 2e305 K
  // in config/scenes/nozzle-track-reduced.yaml, and the redistribution then moved metal at that temperature).
  if (a < 0 && !(CellSensibleCapacity(a, guess) > 0)) return guess;
  {  // Newton from the guess first: away from the ramp's ends it closes in a step or two
    PetscReal T = guess, fT = f(T);
    for (int it = 0; it < 4 && fT != 0; ++it) {
      const PetscReal d = df(T);
      if (!(d > 0)) break;
      const PetscReal n = T - fT / d, fn = f(n);
      if (!(std::fabs(fn) < std::fabs(fT))) break;  // not converging: bracket below
      if (n == T || std::fabs(n - T) <= 4 * PETSC_MACHINE_EPSILON * std::fabs(T)) return n;
      T = n, fT = fn;
    }
    if (fT == 0) return T;
    guess = T;
  }
  PetscReal lo = guess, hi = guess, step = 1e-6 * std::max((PetscReal)1, std::fabs(guess));
  while (f(lo) > 0) lo -= step, step *= 2;
  step = 1e-6 * std::max((PetscReal)1, std::fabs(guess));
  while (f(hi) < 0) hi += step, step *= 2;
  PetscReal T = std::min(hi, std::max(lo, guess));
  for (int it = 0; it < 200; ++it) {
    const PetscReal fT = f(T);
    if (fT == 0) return T;
    (fT < 0 ? lo : hi) = T;
    const PetscReal d = df(T);
    PetscReal       n = d > 0 ? T - fT / d : 0.5 * (lo + hi);
    if (!(n > lo && n < hi)) n = 0.5 * (lo + hi);
    if (n == T || hi - lo <= 2 * PETSC_MACHINE_EPSILON * std::fabs(T)) return n;
    T = n;
  }
  return T;
}

PetscErrorCode Energy::CreateTransportScratch() {
  const StaggeredGrid &sg = *sg_;

  PetscFunctionBeginUser;
  if (Tsg_) PetscFunctionReturn(0);
  PetscCall(DMCreateGlobalVector(sg.Cells(), &Tsg_));
  PetscCall(VecDuplicate(Tsg_, &Fsg_));
  PetscCall(DMCreateLocalVector(sg.Cells(), &TsgLocal_));
  PetscCall(VecDuplicate(TsgLocal_, &FsgLocal_));
  PetscCall(VecDuplicate(TsgLocal_, &AsgLocal_));
  PetscCall(VecDuplicate(TsgLocal_, &EpsSgLocal_));
  for (int e = 0; e < 3; ++e) {
    PetscCall(DMCreateLocalVector(sg.Face(e), &uLocal_[e]));
    PetscCall(DMCreateLocalVector(sg.Face(e), &fluxLocal_[e]));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::TransportSweep(int d, PetscReal dt, Vec u, Vec phaseFlux, const std::vector<char> &full) {
  const StaggeredGrid &sg = *sg_;
  const PetscReal      r  = dt / grid_->Spacing()[d];
  LocalField           T, F, uf, pf, E, X, A, P;
  PetscInt             s[3], n[3];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evTransport_, 0, 0, 0, 0));
  PetscCall(CreateTransportScratch());
  sg.Owned(3, s, n);
  if (!swept_) {  // the step's first sweep: X from the state at its start
    PetscScalar ***Tn, ***Fn, ***Xn;
    PetscCall(DMDAVecGetArrayRead(dm_, T_, &Tn));
    PetscCall(DMDAVecGetArrayRead(dm_, F_, &Fn));
    PetscCall(DMDAVecGetArray(dm_, Xstart_, &Xn));
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
          const size_t    cell = (size_t)((i - s[0]) + n[0] * ((j - s[1]) + n[1] * (k - s[2])));
          const PetscReal t = Tn[k][j][i];
          Xn[k][j][i]       = full[cell] ? metal_.density * (metal_.Sensible(t) + metal_.latentHeat * Fn[k][j][i]) : gas_.density * gas_.Sensible(t);
        }
    PetscCall(DMDAVecRestoreArray(dm_, Xstart_, &Xn));
    PetscCall(DMDAVecRestoreArrayRead(dm_, F_, &Fn));
    PetscCall(DMDAVecRestoreArrayRead(dm_, T_, &Tn));
    swept_ = true;
  }
  PetscCall(VecCopy(T_, Tsg_));  // the same layout on the staggered grid's cells (2 ghosts: the TVD stencil)
  PetscCall(VecCopy(F_, Fsg_));
  PetscCall(DMGlobalToLocal(sg.Cells(), Tsg_, INSERT_VALUES, TsgLocal_));
  PetscCall(DMGlobalToLocal(sg.Cells(), Fsg_, INSERT_VALUES, FsgLocal_));
  PetscCall(DMGlobalToLocal(sg.Face(d), u, INSERT_VALUES, uLocal_[d]));
  PetscCall(DMGlobalToLocal(sg.Face(d), phaseFlux, INSERT_VALUES, fluxLocal_[d]));
  PetscCall(VecCopy(alpha_, Tsg_));  // alpha at the sweep's start, ghosted like T (the face rule below)
  PetscCall(DMGlobalToLocal(sg.Cells(), Tsg_, INSERT_VALUES, AsgLocal_));
  if (epsFluid_) {  // eps^{n+1}, ghosted like T (the face means); at the step's first sweep
    if (sweep_ == 0) {
      PetscCall(VecCopy(epsFluid_, Tsg_));
      PetscCall(DMGlobalToLocal(sg.Cells(), Tsg_, INSERT_VALUES, EpsSgLocal_));
    }
  }
  const int stage = ++sweep_;
  PetscCall(sg.GetLocal(3, TsgLocal_, &T));
  PetscCall(sg.GetLocal(3, FsgLocal_, &F));
  PetscCall(sg.GetLocal(3, AsgLocal_, &A));
  PetscCall(FillNearestOutside(sg, T));
  PetscCall(FillNearestOutside(sg, F));
  PetscCall(FillNearestOutside(sg, A));
  const bool         particles = epsFluid_ != nullptr;
  const PetscScalar *change    = nullptr;  // eps^{n+1} - eps^n of the owned cells (nullptr: eps constant)
  if (particles) {
    PetscCall(sg.GetLocal(3, EpsSgLocal_, &P));
    PetscCall(FillNearestOutside(sg, P));  // zero gradient, as alpha's (a wall's face has no normal velocity)
    if (epsChange_) PetscCall(VecGetArrayRead(epsChange_, &change));
  }
  // eps at face f (between cells f - e_d and f): the mean the flow's projection and alpha's sweep use
  auto faceEps = [&](const PetscInt f[3]) {
    if (!particles) return (PetscReal)1;
    PetscInt m[3] = {f[0], f[1], f[2]};
    m[d] -= 1;
    return 0.5 * (P.at(m) + P.at(f));
  };
  PetscCall(sg.GetLocal(d, uLocal_[d], &uf));
  PetscCall(sg.GetLocal(d, fluxLocal_[d], &pf));
  PetscCall(sg.GetGlobal(3, E_, &E));  // E_ and Xstart_ are global vectors of the same layout
  PetscCall(sg.GetGlobal(3, Xstart_, &X));
  const PetscReal rm = metal_.density, rg = gas_.density, L = metal_.latentHeat;
  auto            flux = [&](const PetscInt f[3]) {  // Phi dt/h through face f (between cells f-1 and f along d)
    const PetscReal vel = uf.at(f), fm = pf.at(f);
    if (vel == 0 && fm == 0) return (PetscReal)0;
    PetscInt L1[3] = {f[0], f[1], f[2]}, L2[3] = {f[0], f[1], f[2]}, R1[3] = {f[0], f[1], f[2]}, R2[3] = {f[0], f[1], f[2]};
    L1[d] -= 1, L2[d] -= 2, R2[d] += 1;
    const bool pos = vel >= 0;
    // The face temperature: van Leer's where the stencil is one phase throughout; the donor cell's where it is
    // not (a mixture temperature blended into a phase's flux would move metal enthalpy at a temperature the
    // donor's metal does not have: at a rho cp jump of 4000 the gas side would be driven out of bounds).
    // Between the two a weight w, so that alpha's round-off (another rank count's pressure solve moves it by 1e-16)
    // moves T_f by as little: w = 1 - m/kPureBand for a stencil of one phase whose most mixed cell holds a share m
    // of the other phase below kPureBand, 0 otherwise (an exact test of purity would switch on that round-off).
    const PetscInt *s1 = pos ? L2 : R2, *s2 = pos ? L1 : R1, *s3 = pos ? R1 : L1;
    const PetscReal a1 = A.at(s1), a2 = A.at(s2), a3 = A.at(s3);
    const PetscReal m  = std::max({std::min(a1, 1 - a1), std::min(a2, 1 - a2), std::min(a3, 1 - a3), (PetscReal)0});
    const PetscReal w  = (std::fabs(a1 - a2) < 0.5 && std::fabs(a2 - a3) < 0.5) ? std::max((PetscReal)0, 1 - m / kPureBand) : 0;
    const PetscReal tf = w > 0 ? w * VanLeerFaceValue(T.at(s1), T.at(s2), T.at(s3)) + (1 - w) * T.at(s2) : T.at(s2);
    const PetscReal fup = pos ? F.at(L1) : F.at(R1);
    const PetscReal gas = (particles ? faceEps(f) * vel : vel) - fm;  // a face that carries one phase needs that phase's enthalpy alone
    return r * ((fm != 0 ? fm * rm * (metal_.Sensible(tf) + L * fup) : 0) + (gas != 0 ? gas * rg * gas_.Sensible(tf) : 0));
  };
  // Along d innermost, so that each face's flux is computed once and serves both its cells. What crosses the box's
  // faces (open ones: outflow, inflow) joins the account (energy_accounted_J) as input.
  const int       a = (d + 1) % 3, b = (d + 2) % 3;
  const PetscInt  N = grid_->Cells()[d];
  const bool      open = !grid_->Periodic(d);
  const PetscReal volume = grid_->Spacing()[0] * grid_->Spacing()[1] * grid_->Spacing()[2];
  PetscReal       entered = 0;
  touched_.assign((size_t)n[0] * n[1] * n[2], 0);  // cells whose E (and alpha) this sweep changed: T, f follow for them alone
  for (PetscInt qb = s[b]; qb < s[b] + n[b]; ++qb)
    for (PetscInt qa = s[a]; qa < s[a] + n[a]; ++qa) {
      PetscInt lo[3], hi[3];
      lo[a] = hi[a] = qa, lo[b] = hi[b] = qb, lo[d] = s[d];
      PetscReal below = flux(lo);
      if (open && s[d] == 0) entered += below * volume;
      for (PetscInt q = s[d]; q < s[d] + n[d]; ++q) {
        lo[d] = q, hi[d] = q + 1;
        const PetscReal above = flux(hi);
        const size_t    cell  = (size_t)((lo[0] - s[0]) + n[0] * ((lo[1] - s[1]) + n[1] * (lo[2] - s[2])));
        const PetscReal third = change ? PetscRealPart(change[cell]) / 3 : 0;  // this sweep's share of eps's change
        if (uf.at(hi) == 0 && pf.at(hi) == 0 && uf.at(lo) == 0 && pf.at(lo) == 0 && third == 0) {  // no flux, no dilatation: E, alpha unchanged
          if (open && q + 1 == N) entered -= above * volume;
          below = above;
          continue;
        }
        touched_[cell] = 1;
        const PetscReal dilatation = particles ? r * (faceEps(hi) * uf.at(hi) - faceEps(lo) * uf.at(lo)) + third : r * (uf.at(hi) - uf.at(lo));
        E.at(lo) += -(above - below) + dilatation * X.at(lo);
        if (open && q + 1 == N) entered -= above * volume;
        below = above;
      }
    }
  advected_ += entered;  // this rank's; summed over ranks in Step
  PetscCall(sg.RestoreGlobal(3, Xstart_, &X));
  PetscCall(sg.RestoreGlobal(3, E_, &E));
  PetscCall(sg.RestoreLocal(d, fluxLocal_[d], &pf));
  PetscCall(sg.RestoreLocal(d, uLocal_[d], &uf));
  if (particles) {
    if (change) PetscCall(VecRestoreArrayRead(epsChange_, &change));
    PetscCall(sg.RestoreLocal(3, EpsSgLocal_, &P));
  }
  PetscCall(sg.RestoreLocal(3, AsgLocal_, &A));
  PetscCall(sg.RestoreLocal(3, FsgLocal_, &F));
  PetscCall(sg.RestoreLocal(3, TsgLocal_, &T));
  PetscCall(FollowInterface(1 - stage / 3.0));  // of eps's change, what is still to come after this sweep
  PetscCall(PetscLogEventEnd(evTransport_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

// The moved interface, and T, f from E and alpha in the cells touched_ marks; eps is eps^{n+1} less `later` of its change.
PetscErrorCode Energy::FollowInterface(PetscReal later) {
  PetscScalar ***Tg, ***Fg, ***Eg, ***al, ***ep = nullptr, ***dp = nullptr;
  PetscInt       s[3], n[3];

  PetscFunctionBeginUser;
  sg_->Owned(3, s, n);
  PetscCall(VecCopy(interfaceAlpha_(), alpha_));
  PetscCall(DMGlobalToLocal(dm_, alpha_, INSERT_VALUES, alphaLocal_));
  PetscCall(DMDAVecGetArray(dm_, T_, &Tg));
  PetscCall(DMDAVecGetArray(dm_, F_, &Fg));
  PetscCall(DMDAVecGetArrayRead(dm_, E_, &Eg));
  PetscCall(DMDAVecGetArrayRead(dm_, alpha_, &al));
  if (epsFluid_) PetscCall(DMDAVecGetArrayRead(dm_, epsFluid_, &ep));
  if (epsFluid_ && epsChange_) PetscCall(DMDAVecGetArrayRead(dm_, epsChange_, &dp));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        if (!touched_[(size_t)((i - s[0]) + n[0] * ((j - s[1]) + n[1] * (k - s[2])))]) continue;
        const PetscReal e = ep ? ep[k][j][i] - (dp ? dp[k][j][i] * later : 0) : 1;  // eps at alpha's level
        Tg[k][j][i]       = CellTemperature(Eg[k][j][i] / e, al[k][j][i], Tg[k][j][i]);  // alpha as the interface left it (E was moved with it)
        Fg[k][j][i]       = metal_.MeltFraction(Tg[k][j][i]);
      }
  if (dp) PetscCall(DMDAVecRestoreArrayRead(dm_, epsChange_, &dp));
  if (ep) PetscCall(DMDAVecRestoreArrayRead(dm_, epsFluid_, &ep));
  PetscCall(DMDAVecRestoreArrayRead(dm_, alpha_, &al));
  PetscCall(DMDAVecRestoreArrayRead(dm_, E_, &Eg));
  PetscCall(DMDAVecRestoreArray(dm_, F_, &Fg));
  PetscCall(DMDAVecRestoreArray(dm_, T_, &Tg));
  PetscFunctionReturn(0);
}

// After the sweeps, the interface's redistribution (vof/VofRedistribute.cpp) moved phase-1 volume dv between
// neighbours and as much gas back: the cell that takes metal gains dv (rho_m h_m at the giver's T) and loses
// dv rho_g h_g at its own T. Each move is seen from both cells with opposite signs and the same bits, so the sum is
// unchanged to round-off; a uniform T stays uniform as alpha does.
PetscErrorCode Energy::FollowRedistribution(const std::vector<CellMove> &moves) {
  const StaggeredGrid &sg = *sg_;
  LocalField           T, F, E;
  PetscInt             s[3], n[3];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evTransport_, 0, 0, 0, 0));
  PetscCall(CreateTransportScratch());  // a melt before the first sweeps
  sg.Owned(3, s, n);
  PetscCall(VecCopy(T_, Tsg_));
  PetscCall(VecCopy(F_, Fsg_));
  PetscCall(DMGlobalToLocal(sg.Cells(), Tsg_, INSERT_VALUES, TsgLocal_));
  PetscCall(DMGlobalToLocal(sg.Cells(), Fsg_, INSERT_VALUES, FsgLocal_));
  PetscCall(sg.GetLocal(3, TsgLocal_, &T));
  PetscCall(sg.GetLocal(3, FsgLocal_, &F));
  PetscCall(sg.GetGlobal(3, E_, &E));
  const PetscReal rm = metal_.density, rg = gas_.density, L = metal_.latentHeat;
  auto metal = [&](const PetscInt q[3]) { return rm * (metal_.Sensible(T.at(q)) + L * F.at(q)); };
  auto gas   = [&](const PetscInt q[3]) { return rg * gas_.Sensible(T.at(q)); };
  touched_.assign((size_t)n[0] * n[1] * n[2], 0);
  for (const CellMove &m : moves) {
    E.at(m.cell) += m.dv > 0 ? m.dv * (metal(m.other) - gas(m.cell)) : m.dv * (metal(m.cell) - gas(m.other));
    touched_[(size_t)((m.cell[0] - s[0]) + n[0] * ((m.cell[1] - s[1]) + n[1] * (m.cell[2] - s[2])))] = 1;
  }
  PetscCall(sg.RestoreGlobal(3, E_, &E));
  PetscCall(sg.RestoreLocal(3, FsgLocal_, &F));
  PetscCall(sg.RestoreLocal(3, TsgLocal_, &T));
  PetscCall(FollowInterface(0));
  PetscCall(PetscLogEventEnd(evTransport_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::AddEnthalpy(Vec dE, Vec gas) {
  PetscScalar ***E, ***d, ***g = nullptr, ***T;
  PetscInt       s[3], n[3];
  PetscReal      pool[2] = {0, 0};  // the moved gas's enthalpy (J) and the gaining cells' volume (m^3)

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing();
  const PetscReal  V = h[0] * h[1] * h[2];
  sg_->Owned(3, s, n);
  touched_.assign((size_t)n[0] * n[1] * n[2], 0);
  PetscCall(DMDAVecGetArray(dm_, E_, &E));
  PetscCall(DMDAVecGetArrayRead(dm_, dE, &d));
  PetscCall(DMDAVecGetArrayRead(dm_, T_, &T));
  if (gas) PetscCall(DMDAVecGetArrayRead(dm_, gas, &g));
  auto loop = [&](auto &&f) {
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) f(i, j, k, (size_t)((i - s[0]) + n[0] * ((j - s[1]) + n[1] * (k - s[2]))));
  };
  if (g) {
    loop([&](PetscInt i, PetscInt j, PetscInt k, size_t) {
      const PetscReal v = g[k][j][i];
      if (v < 0) pool[0] += -v * gas_.density * gas_.Sensible(T[k][j][i]);
      else pool[1] += v;
    });
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, pool, 2, MPIU_REAL, MPI_SUM, comm_));
  }
  loop([&](PetscInt i, PetscInt j, PetscInt k, size_t c) {
    PetscReal add = d[k][j][i];
    if (g && g[k][j][i] < 0) add -= -g[k][j][i] * gas_.density * gas_.Sensible(T[k][j][i]);
    else if (g && g[k][j][i] > 0 && pool[1] > 0) add += pool[0] * g[k][j][i] / pool[1];
    if (add != 0 || (g && g[k][j][i] != 0)) E[k][j][i] += add / V, touched_[c] = 1;
  });
  if (g) PetscCall(DMDAVecRestoreArrayRead(dm_, gas, &g));
  PetscCall(DMDAVecRestoreArrayRead(dm_, T_, &T));
  PetscCall(DMDAVecRestoreArrayRead(dm_, dE, &d));
  PetscCall(DMDAVecRestoreArray(dm_, E_, &E));
  PetscCall(FollowInterface(0));  // alpha with the new metal, eps as the coupling left it
  PetscFunctionReturn(0);
}

}  // namespace vofdem
