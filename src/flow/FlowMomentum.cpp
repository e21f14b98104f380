// The momentum predictor of Flow (Flow.hpp): explicit terms at time level n and the provisional
// velocity u*. docs/physics.md (F2); discretisation on the MAC grid described in Flow.hpp.
#include "vofdem/flow/Flow.hpp"
#include "vofdem/grid/FaceProperties.hpp"

#include <cmath>

namespace vofdem {

namespace {

struct TermFields {
  LocalField u[3];      // ghosted velocities
  LocalField em, beta, eps;  // ghosted cell fields: eps*mu, eps/rho, eps
  LocalField H, L;      // outputs (global, component d)
  bool       transpose = true;  // the transpose term in H (false: it is implicit, FlowViscousCoupled.cpp)
};

// Explicit terms for component d at the owned faces [s, s+n) that are not boundary faces:
//   H = -(div(U u) - u div U) + div(eps mu (grad U)^T)_d / (eps rho)_f     (m/s^2)
//   L = div(eps mu grad u_d)                                               (N/m^3, unscaled)
// Control volume of a d-face: between the centres of its two cells along d, one cell across in
// the other directions. Its faces normal to d sit at cell centres, the others on cell edges.
// Hot loop: every neighbour is a fixed offset from the point's index in its own array (the arrays
// of the staggered locations differ in size), computed once per component.
// ADV false: another module moves the momentum; the advective part is not computed at all.
template <Limiter LIM, bool ADV>
void MomentumTerms(int d, const TermFields &F, const PetscInt s[3], const PetscInt n[3], const PetscReal h[3]) {
  const LocalField &ud = F.u[d];
  const int         t1 = (d + 1) % 3, t2 = (d + 2) % 3;  // the tangential directions
  const int         te[2] = {t1, t2};
  // offsets in the arrays of u_d, u_e (tangential e), cells, and the output
  const PetscInt ds = ud.stride[d], cs_d = F.em.stride[d];
  PetscInt       us[2], ues_e[2], ues_d[2], cs_e[2];
  for (int a = 0; a < 2; ++a) {
    us[a]    = ud.stride[te[a]];
    ues_e[a] = F.u[te[a]].stride[te[a]];
    ues_d[a] = F.u[te[a]].stride[d];
    cs_e[a]  = F.em.stride[te[a]];
  }
  const PetscReal ih[3] = {1 / h[0], 1 / h[1], 1 / h[2]};
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
      const PetscScalar *u   = &ud.at(s[0], j, k);
      const PetscScalar *ua  = &F.u[t1].at(s[0], j, k);
      const PetscScalar *ub  = &F.u[t2].at(s[0], j, k);
      const PetscScalar *em  = &F.em.at(s[0], j, k);
      const PetscScalar *be  = &F.beta.at(s[0], j, k);
      const PetscScalar *ep  = &F.eps.at(s[0], j, k);
      PetscScalar       *Ho  = &F.H.at(s[0], j, k);
      PetscScalar       *Lo  = &F.L.at(s[0], j, k);
      const PetscScalar *uet[2] = {ua, ub};
      for (PetscInt i = 0; i < n[0]; ++i) {
        const PetscReal uP = u[i];
        const PetscReal emC = em[i], emM = em[i - cs_d];
        PetscReal       adv = 0, lap, trans;
        {  // e = d: control-volume faces at the two cell centres
          const PetscReal uE = u[i + ds], uW = u[i - ds];
          if constexpr (ADV) {
            const PetscReal uEE = u[i + 2 * ds], uWW = u[i - 2 * ds];
            const PetscReal Up = 0.5 * (uP + uE), Um = 0.5 * (uW + uP);
            const PetscReal fP = Up >= 0 ? LimitedFace<LIM>(uW, uP, uE) : LimitedFace<LIM>(uEE, uE, uP);
            const PetscReal fM = Um >= 0 ? LimitedFace<LIM>(uWW, uW, uP) : LimitedFace<LIM>(uE, uP, uW);
            adv = ((Up * fP - Um * fM) - uP * (Up - Um)) * ih[d];
          }
          lap = (emC * (uE - uP) - emM * (uP - uW)) * ih[d] * ih[d];
          trans = lap;  // the transpose term equals the gradient term along d
        }
        for (int a = 0; a < 2; ++a) {  // e tangential: control-volume faces on the cell edges
          const int          e  = te[a];
          const PetscInt     o  = us[a];
          const PetscScalar *ue = uet[a] + i;
          const PetscReal    uE = u[i + o], uW = u[i - o];
          // advecting u_e: e-faces q_e+1 (plus) and q_e (minus), cells q_d-1 and q_d
          const PetscReal uea = ue[ues_e[a]], ueam = ue[ues_e[a] - ues_d[a]], ueb = ue[0], uebm = ue[-ues_d[a]];
          const PetscReal Up = 0.5 * (uea + ueam), Um = 0.5 * (ueb + uebm);
          const PetscScalar *c = em + i;
          const PetscReal emP = 0.25 * (emC + emM + c[cs_e[a]] + c[cs_e[a] - cs_d]);
          const PetscReal emN = 0.25 * (emC + emM + c[-cs_e[a]] + c[-cs_e[a] - cs_d]);
          if constexpr (ADV) {
            const PetscReal uEE = u[i + 2 * o], uWW = u[i - 2 * o];
            const PetscReal fP = Up >= 0 ? LimitedFace<LIM>(uW, uP, uE) : LimitedFace<LIM>(uEE, uE, uP);
            const PetscReal fM = Um >= 0 ? LimitedFace<LIM>(uWW, uW, uP) : LimitedFace<LIM>(uE, uP, uW);
            adv += ((Up * fP - Um * fM) - uP * (Up - Um)) * ih[e];
          }
          lap += (emP * (uE - uP) - emN * (uP - uW)) * ih[e] * ih[e];
          trans += (emP * (uea - ueam) - emN * (ueb - uebm)) * ih[d] * ih[e];
        }
        const PetscReal bL = be[i - cs_d], bR = be[i];
        const FaceProperties face = FaceAverage(ep[i - cs_d], ep[i], bL, bR);
        const PetscReal eF = face.eps, bF = face.beta;
        Ho[i] = (ADV ? -adv : 0) + (F.transpose ? trans * bF / (eF * eF) : 0);  // (eps rho)_f = eps_f^2 / b_f
        Lo[i] = lap;
      }
    }
}

}  // namespace

PetscErrorCode Flow::ComputeExplicitTerms() {
  TermFields F;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evExplicit_, 0, 0, 0, 0));
  for (int d = 0; d < 3; ++d) PetscCall(sg_.GetLocal(d, uLocal_[d], &F.u[d]));
  PetscCall(sg_.GetLocal(3, emLocal_, &F.em));
  PetscCall(sg_.GetLocal(3, betaLocal_, &F.beta));
  PetscCall(sg_.GetLocal(3, epsLocal_, &F.eps));
  const bool advect = advectionAcceleration_[0] == nullptr;  // false: another module transports momentum (Flow::SetAdvectionAcceleration)
  F.transpose       = !CoupledNow();
  const PetscReal *h = grid_->Spacing();
  for (int d = 0; d < 3; ++d) {
    PetscCall(sg_.GetGlobal(d, H_[d], &F.H));
    PetscCall(sg_.GetGlobal(d, L_[d], &F.L));
    sg_.Owned(d, s, n);
    if (!grid_->Periodic(d)) {  // boundary faces of this component are set by the boundary conditions
      const PetscInt last = sg_.Points(d, d) - 1;
      for (PetscInt plane : {(PetscInt)0, last}) {  // their terms are zero (the faces are not advanced)
        if (plane < s[d] || plane >= s[d] + n[d]) continue;
        PetscInt q[3];
        const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
        q[d] = plane;
        for (q[e2] = s[e2]; q[e2] < s[e2] + n[e2]; ++q[e2])
          for (q[e1] = s[e1]; q[e1] < s[e1] + n[e1]; ++q[e1]) F.H.at(q) = F.L.at(q) = 0;
      }
      const PetscInt a = std::max(s[d], (PetscInt)1), b = std::min(s[d] + n[d], last);
      s[d] = a;
      n[d] = std::max(b - a, (PetscInt)0);
    }
    switch (limiter_) {
    case Limiter::Upwind: advect ? MomentumTerms<Limiter::Upwind, true>(d, F, s, n, h) : MomentumTerms<Limiter::Upwind, false>(d, F, s, n, h); break;
    case Limiter::Central: advect ? MomentumTerms<Limiter::Central, true>(d, F, s, n, h) : MomentumTerms<Limiter::Central, false>(d, F, s, n, h); break;
    case Limiter::Minmod: advect ? MomentumTerms<Limiter::Minmod, true>(d, F, s, n, h) : MomentumTerms<Limiter::Minmod, false>(d, F, s, n, h); break;
    case Limiter::VanLeer: advect ? MomentumTerms<Limiter::VanLeer, true>(d, F, s, n, h) : MomentumTerms<Limiter::VanLeer, false>(d, F, s, n, h); break;
    case Limiter::MC: advect ? MomentumTerms<Limiter::MC, true>(d, F, s, n, h) : MomentumTerms<Limiter::MC, false>(d, F, s, n, h); break;
    case Limiter::Superbee: advect ? MomentumTerms<Limiter::Superbee, true>(d, F, s, n, h) : MomentumTerms<Limiter::Superbee, false>(d, F, s, n, h); break;
    case Limiter::Koren: advect ? MomentumTerms<Limiter::Koren, true>(d, F, s, n, h) : MomentumTerms<Limiter::Koren, false>(d, F, s, n, h); break;
    }
    PetscCall(sg_.RestoreGlobal(d, L_[d], &F.L));
    PetscCall(sg_.RestoreGlobal(d, H_[d], &F.H));
  }
  PetscCall(sg_.RestoreLocal(3, epsLocal_, &F.eps));
  PetscCall(sg_.RestoreLocal(3, betaLocal_, &F.beta));
  PetscCall(sg_.RestoreLocal(3, emLocal_, &F.em));
  for (int d = 0; d < 3; ++d) PetscCall(sg_.RestoreLocal(d, uLocal_[d], &F.u[d]));
  if (solid_.Any()) PetscCall(SolidWallTerms());
  PetscCall(PetscLogEventEnd(evExplicit_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

// MomentumTerms read the held 0 of a blocked neighbour face one cell away; for a wall face the wall
// is half a cell away (SolidMask.hpp): a(0 - u) becomes a(-u - u), i.e. L -= a u once more, with
// the coefficient ViscousSolver::Row uses (there doubled on the diagonal), so both halves agree.
PetscErrorCode Flow::SolidWallTerms() {
  LocalField em, u, L;

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing();
  PetscCall(sg_.GetLocal(3, emLocal_, &em));
  for (int d = 0; d < 3; ++d) {  // on every rank, with or without wall faces (see Flow::ZeroBlocked)
    PetscCall(sg_.GetGlobal(d, u_[d], &u));
    PetscCall(sg_.GetGlobal(d, L_[d], &L));
    for (const SolidMask::WallFace &w : solid_.Walls(d)) {
      PetscInt cm[3] = {w.q[0], w.q[1], w.q[2]}, c1[3] = {w.q[0], w.q[1], w.q[2]}, c3[3];
      cm[d] -= 1;
      c1[w.e] += w.side ? 1 : -1;
      for (int k = 0; k < 3; ++k) c3[k] = c1[k];
      c3[d] -= 1;
      const PetscReal a = 0.25 * PetscRealPart(em.at(w.q) + em.at(cm) + em.at(c1) + em.at(c3)) / (h[w.e] * h[w.e]);
      L.data[w.offset] -= a * u.data[w.offset];
    }
    PetscCall(sg_.RestoreGlobal(d, L_[d], &L));
    PetscCall(sg_.RestoreGlobal(d, u_[d], &u));
  }
  PetscCall(sg_.RestoreLocal(3, emLocal_, &em));
  PetscFunctionReturn(0);
}

// u* from u^n (Flow.hpp). With implicit viscosity the rhs of the Crank-Nicolson system is
//   (eps rho)_f [u^n/dt + AB2(H) + g + f^{n+1/2} - (1/rho)_f G p] + 1/2 L u^n + (boundary part)
// and with explicit viscosity L/(eps rho)_f joins H in the AB2 extrapolation.
PetscErrorCode Flow::Predict(PetscReal t, PetscReal dt) {
  LocalField u, H, Ho, L, R, beta, eps, p, A;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evPredict_, 0, 0, 0, 0));
  const PetscReal  r  = haveOld_ ? dt / dtOld_ : 0;  // first step: forward Euler in H
  const PetscReal  c1 = 1 + 0.5 * r, c0 = -0.5 * r;
  const PetscReal *h = grid_->Spacing(), *lo = grid_->Lower();
  const bool coupled = CoupledNow();
  if (coupled) {  // 1/2 (T(U^n) + T(0)) joins the rhs: CN with the boundary part at both levels (FlowViscousCoupled.cpp)
    PetscCall(CoupledBoundaryPart());
    PetscCall(TransposeOf(u_, transOut_));  // with the outflow faces as the operator sees them
    for (int d = 0; d < 3; ++d) PetscCall(VecAXPY(transOut_[d], 1, transZero_[d]));
  }
  PetscCall(sg_.GetLocal(3, betaLocal_, &beta));
  PetscCall(sg_.GetLocal(3, epsLocal_, &eps));
  PetscCall(sg_.GetLocal(3, pLocal_, &p));
  // After the solve: the implicit drag split from the predictor, and the normal velocity at the boundaries.
  const auto finish = [&](int d) -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (relaxRate_[d]) {  // SetFaceRelaxation: implicit linear drag, split from the predictor
      PetscScalar       *uu;
      const PetscScalar *c, *w, *cd = nullptr;
      PetscInt           m;
      PetscCall(VecGetLocalSize(u_[d], &m));
      PetscCall(VecGetArray(u_[d], &uu));
      PetscCall(VecGetArrayRead(relaxRate_[d], &c));
      PetscCall(VecGetArrayRead(relaxTarget_[d], &w));
      if (damping_[d]) PetscCall(VecGetArrayRead(damping_[d], &cd));
      if (cd && implicitViscosity_)  // the damping is in the viscous matrix: held faces to 0 exactly
        for (PetscInt k = 0; k < m; ++k) uu[k] = std::isinf(PetscRealPart(cd[k])) ? 0 : (uu[k] + dt * c[k] * w[k]) / (1 + dt * c[k]);
      else if (cd)
        for (PetscInt k = 0; k < m; ++k) uu[k] = std::isinf(PetscRealPart(cd[k])) ? 0 : (uu[k] + dt * c[k] * w[k]) / (1 + dt * (c[k] + cd[k]));
      else
        for (PetscInt k = 0; k < m; ++k) uu[k] = (uu[k] + dt * c[k] * w[k]) / (1 + dt * c[k]);
      if (cd) PetscCall(VecRestoreArrayRead(damping_[d], &cd));
      PetscCall(VecRestoreArrayRead(relaxTarget_[d], &w));
      PetscCall(VecRestoreArrayRead(relaxRate_[d], &c));
      PetscCall(VecRestoreArray(u_[d], &uu));
    } else if (damping_[d]) {  // SetFaceDamping alone: a drag toward rest, +inf holds the face
      PetscScalar       *uu;
      const PetscScalar *cd;
      PetscInt           m;
      PetscCall(VecGetLocalSize(u_[d], &m));
      PetscCall(VecGetArray(u_[d], &uu));
      PetscCall(VecGetArrayRead(damping_[d], &cd));
      if (implicitViscosity_)  // in the viscous matrix: held faces to 0 exactly
        for (PetscInt k = 0; k < m; ++k) uu[k] = std::isinf(PetscRealPart(cd[k])) ? 0 : uu[k];
      else
        for (PetscInt k = 0; k < m; ++k) uu[k] = std::isinf(PetscRealPart(cd[k])) ? 0 : uu[k] / (1 + dt * cd[k]);
      PetscCall(VecRestoreArrayRead(damping_[d], &cd));
      PetscCall(VecRestoreArray(u_[d], &uu));
    }
    PetscCall(bc_.ApplyNormal(sg_, d, u_[d]));
    PetscFunctionReturn(0);
  };
  for (int d = 0; d < 3; ++d) {
    if (!implicitViscosity_) {
      // L joins H: H := H + L/(eps rho)_f, so that the history holds the whole explicit term.
      LocalField Hd, Ld;
      PetscCall(sg_.GetGlobal(d, H_[d], &Hd));
      PetscCall(sg_.GetGlobal(d, L_[d], &Ld));
      sg_.Owned(d, s, n);
      for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
        for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
          for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
            PetscInt q[3] = {i, j, k}, cm[3] = {i, j, k};
            cm[d] -= 1;
            const PetscReal bL = PetscRealPart(beta.at(cm)), bR = PetscRealPart(beta.at(q));
            const FaceProperties face = FaceAverage(PetscRealPart(eps.at(cm)), PetscRealPart(eps.at(q)), bL, bR);
            const PetscReal eF = face.eps, bF = face.beta;
            Hd.at(q) += Ld.at(q) * bF / (eF * eF);
          }
      PetscCall(sg_.RestoreGlobal(d, L_[d], &Ld));
      PetscCall(sg_.RestoreGlobal(d, H_[d], &Hd));
    }
    PetscCall(sg_.GetGlobal(d, u_[d], &u));
    PetscCall(sg_.GetGlobal(d, H_[d], &H));
    PetscCall(sg_.GetGlobal(d, haveOld_ ? Hold_[d] : H_[d], &Ho));
    PetscCall(sg_.GetGlobal(d, L_[d], &L));
    PetscCall(sg_.GetGlobal(d, rhsFace_[d], &R));
    LocalField F, A, V;  // FaceForce(), when a module asked for it
    if (faceForce_[d]) PetscCall(sg_.GetGlobal(d, faceForce_[d], &F));
    if (faceAcceleration_[d]) PetscCall(sg_.GetGlobal(d, faceAcceleration_[d], &A));
    if (advectionAcceleration_[d]) PetscCall(sg_.GetGlobal(d, advectionAcceleration_[d], &V));
    sg_.Owned(d, s, n);
    const PetscInt  last = sg_.Points(d, d) - 1, cs = beta.stride[d];  // cs: the cell below a face
    const bool      walls = !grid_->Periodic(d);
    // Hot loop over rows along x: pointers into each array (faces and cells differ in size).
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j) {
        PetscScalar       *uq = &u.at(s[0], j, k), *Rq = &R.at(s[0], j, k);
        const PetscScalar *Hq = &H.at(s[0], j, k), *Hoq = &Ho.at(s[0], j, k), *Lq = &L.at(s[0], j, k);
        const PetscScalar *bq = &beta.at(s[0], j, k), *eq = &eps.at(s[0], j, k), *pq = &p.at(s[0], j, k);
        const PetscScalar *Fq = faceForce_[d] ? &F.at(s[0], j, k) : nullptr;
        const PetscScalar *aq = faceAcceleration_[d] ? &A.at(s[0], j, k) : nullptr;
        const PetscScalar *vq = advectionAcceleration_[d] ? &V.at(s[0], j, k) : nullptr;
        const PetscInt     qd = d == 1 ? j : k;  // the face index along d when d is not x
        const bool         rowOnWall = walls && d != 0 && (qd == 0 || qd == last);
        for (PetscInt i = 0; i < n[0]; ++i) {
          if (rowOnWall || (walls && d == 0 && (s[0] + i == 0 || s[0] + i == last))) {
            Rq[i] = uq[i];  // identity rows of the viscous matrix; ApplyNormal sets the value
            continue;
          }
          const PetscReal bL = PetscRealPart(bq[i - cs]), bR = PetscRealPart(bq[i]);
          const FaceProperties face = FaceAverage(PetscRealPart(eq[i - cs]), PetscRealPart(eq[i]), bL, bR);
          const PetscReal eF = face.eps, bF = face.beta;
          const PetscReal invRho = bF / eF, epsRho = eF * eF / bF;
          PetscReal       acc = c1 * PetscRealPart(Hq[i]) + c0 * PetscRealPart(Hoq[i]) + gravity_[d];
          acc -= invRho * PetscRealPart(pq[i] - pq[i - cs]) / h[d];
          if (Fq) acc += invRho * PetscRealPart(Fq[i]);  // balanced with the pressure gradient
          if (aq) acc += PetscRealPart(aq[i]);
          if (vq) acc += PetscRealPart(vq[i]);
          if (forcing_) {
            const PetscInt q[3] = {s[0] + i, j, k};
            PetscReal      x[3];
            for (int c = 0; c < 3; ++c) x[c] = lo[c] + (c == d ? q[c] : q[c] + 0.5) * h[c];
            acc += forcing_(forcingCtx_, t + 0.5 * dt, x, d);
          }
          if (implicitViscosity_) {
            Rq[i] = epsRho * (PetscRealPart(uq[i]) / dt + acc) + 0.5 * PetscRealPart(Lq[i]);
            // Initial guess of the viscous solve: the explicit (Euler) prediction, which leaves CG
            // only the change of the viscous term over the step (about a third of the iterations
            // that u^n as the guess took on the 64^3 cavity).
            uq[i] += dt * (acc + PetscRealPart(Lq[i]) / epsRho);
          } else Rq[i] = uq[i] + dt * acc;
        }
      }
    if (faceForce_[d]) PetscCall(sg_.RestoreGlobal(d, faceForce_[d], &F));
    if (faceAcceleration_[d]) PetscCall(sg_.RestoreGlobal(d, faceAcceleration_[d], &A));
    if (advectionAcceleration_[d]) PetscCall(sg_.RestoreGlobal(d, advectionAcceleration_[d], &V));
    PetscCall(sg_.RestoreGlobal(d, rhsFace_[d], &R));
    PetscCall(sg_.RestoreGlobal(d, L_[d], &L));
    PetscCall(sg_.RestoreGlobal(d, haveOld_ ? Hold_[d] : H_[d], &Ho));
    PetscCall(sg_.RestoreGlobal(d, H_[d], &H));
    PetscCall(sg_.RestoreGlobal(d, u_[d], &u));
    PetscCall(ZeroBlocked(d, rhsFace_[d]));  // identity rows of the viscous matrix: u = 0
    PetscCall(ZeroBlocked(d, u_[d]));        // and the initial guess
    if (coupled) {
      PetscCall(VecAXPY(rhsFace_[d], 1, viscous_.BoundaryRhs(d)));
      PetscCall(VecAXPY(rhsFace_[d], 0.5, transOut_[d]));  // zero on boundary and blocked rows
      continue;  // solved with the others below
    }
    if (implicitViscosity_) {
      PetscCall(VecAXPY(rhsFace_[d], 1, viscous_.BoundaryRhs(d)));
      PetscCall(viscous_.Solve(d, rhsFace_[d], u_[d]));
    } else {
      PetscCall(VecCopy(rhsFace_[d], u_[d]));
    }
    PetscCall(finish(d));
  }
  if (coupled) {
    PetscCall(CoupledSolve(rhsFace_));
    for (int d = 0; d < 3; ++d) PetscCall(finish(d));
  }
  PetscCall(sg_.RestoreLocal(3, pLocal_, &p));
  PetscCall(sg_.RestoreLocal(3, epsLocal_, &eps));
  PetscCall(sg_.RestoreLocal(3, betaLocal_, &beta));
  PetscCall(PetscLogEventEnd(evPredict_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
