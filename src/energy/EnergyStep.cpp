// Energy.hpp: one step and the implicit system (docs/physics.md F7; the cells' properties: EnergyProperties.cpp, the laser's deposit: EnergyLaser.cpp).
#include "vofdem/energy/Energy.hpp"

#include "vofdem/base/Runtime.hpp"
#include "vofdem/grid/FaceProperties.hpp"

#include <petscdmda.h>
#include <petsc/private/petscimpl.h>  // PetscObjectStateGet: the caches' keys (every write access moves a vector's state)

#include <algorithm>
#include <cmath>
#include <vector>

namespace vofdem {

namespace {
constexpr PetscReal kStefanBoltzmann = 5.670374419e-8;  // W/(m^2 K^4)

inline PetscReal Pow4(PetscReal t) { return (t * t) * (t * t); }

struct Box {
  PetscInt s[3], m[3];
};

Box Owned(DM dm) {
  Box b;
  DMDAGetCorners(dm, &b.s[0], &b.s[1], &b.s[2], &b.m[0], &b.m[1], &b.m[2]);
  return b;
}

}  // namespace

namespace {

// |grad alpha| by central differences, zero gradient at the box's faces: the interface area per volume
// delta_s of the losses (docs/physics.md F7); it sums to 1/h over a column crossing a plane interface.
PetscReal InterfaceDensity(PetscScalar ***al, PetscInt x, PetscInt y, PetscInt z, const PetscInt *n, const PetscReal *h, const bool *periodic) {
  const PetscInt q[3] = {x, y, z};
  PetscReal      g2   = 0;
  for (int d = 0; d < 3; ++d) {
    PetscInt p[3] = {x, y, z}, m[3] = {x, y, z};
    p[d] += 1, m[d] -= 1;
    if (!periodic[d] && p[d] >= n[d]) p[d] = q[d];
    if (!periodic[d] && m[d] < 0) m[d] = q[d];
    const PetscReal diff = al[p[2]][p[1]][p[0]] - al[m[2]][m[1]][m[0]];
    g2 += diff * diff / (4 * h[d] * h[d]);
  }
  return std::sqrt(g2);
}

}  // namespace

// The Jacobian of the balance at the iterate T^k (Properties done), per volume and time:
//   J d = (a C/dt) d - div(k grad d) + (the slopes of the box faces' and the interfaces' losses) d,
// solved for the correction d with J d = -r/dt (Residual): in corrections, so that the system's round-off
// is that of the correction, not of C T/dt (about 1e12 W/m^3 in metal near its melting point).
PetscErrorCode Energy::Assemble(PetscReal a, PetscReal dt, int slot) {
  const Box        b = Owned(dm_);
  const PetscReal *h = grid_->Spacing();
  const PetscInt  *n = grid_->Cells();
  bool             periodic[3];
  PetscScalar   ***T, ***k, ***al, ***C, ***ep;
  const bool       losses = interfaceConvection_ > 0 || (interfaceRadiation_ && metal_.emissivity > 0);
  const PetscReal  ih2[3] = {1 / (h[0] * h[0]), 1 / (h[1] * h[1]), 1 / (h[2] * h[2])};

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evAssemble_, 0, 0, 0, 0));
  for (int d = 0; d < 3; ++d) periodic[d] = grid_->Periodic(d);
  // The matrix of the same inputs is the one A_[slot] holds (JacobianKey): left as it is, its preconditioner too
  // (PCSetUp sees the matrix unchanged). Radiation (a convective box face's or the interfaces') makes it follow T.
  JacobianKey key;
  key.valid = true, key.a = a, key.dt = dt, key.capacity = capacityVersion_;
  PetscCall(PetscObjectStateGet((PetscObject)kLocal_, &key.k));
  PetscCall(PetscObjectStateGet((PetscObject)epsLocal_, &key.eps));
  PetscCall(PetscObjectStateGet((PetscObject)alphaLocal_, &key.alpha));
  bool followsT = losses && interfaceRadiation_ && metal_.emissivity > 0;
  for (int f = 0; f < 6; ++f) followsT = followsT || (!periodic[f / 2] && face_[f].type == EnergyBoundary::Convective && face_[f].emissivity > 0);
  const JacobianKey &held = jacobianKey_[slot];
  PetscInt           same = !followsT && held.valid && held.a == a && held.dt == dt && held.capacity == key.capacity && held.k == key.k && held.eps == key.eps && held.alpha == key.alpha;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &same, 1, MPIU_INT, MPI_LAND, comm_));
  if (same) {
    PetscCall(PetscLogEventEnd(evAssemble_, 0, 0, 0, 0));
    PetscFunctionReturn(0);
  }
  jacobianKey_[slot].valid = false;  // until the assembly below is complete
  PetscCall(DMDAVecGetArrayRead(dm_, TLocal_, &T));
  PetscCall(DMDAVecGetArrayRead(dm_, kLocal_, &k));
  PetscCall(DMDAVecGetArrayRead(dm_, alphaLocal_, &al));
  PetscCall(DMDAVecGetArrayRead(dm_, C_, &C));
  PetscCall(DMDAVecGetArrayRead(dm_, epsLocal_, &ep));
  // One cell's row: the diagonal first, then its neighbours across the faces that are not the box's.
  const bool cached = cacheValid_;  // Residual at this state left the faces' k/h^2 and the interface densities
  size_t     c      = 0;
  auto row = [&](PetscInt x, PetscInt y, PetscInt z, MatStencil col[7], PetscScalar val[7]) {
    const PetscReal t = T[z][y][x], kc = k[z][y][x], e = ep[z][y][x];
    const size_t    cell = c++;
    PetscReal       diag = a * C[z][y][x] / dt;
    PetscInt        nc   = 1;
    for (int d = 0; d < 3; ++d)
      for (int side = 0; side < 2; ++side) {
        PetscInt nb[3] = {x, y, z};
        nb[d] += side ? 1 : -1;
        if (!periodic[d] && (nb[d] < 0 || nb[d] >= n[d])) {  // a box face
          const EnergyFace &f = face_[2 * d + side];
          switch (f.type) {
          case EnergyBoundary::Adiabatic: break;
          case EnergyBoundary::Flux: break;
          case EnergyBoundary::Temperature: diag += e * 2 * kc / (h[d] * h[d]); break;
          case EnergyBoundary::Convective: diag += e * (f.value + 4 * f.emissivity * kStefanBoltzmann * t * t * t) / h[d]; break;
          }
          continue;
        }
        const PetscReal kf = cached ? faceConductance_[6 * cell + 2 * d + side] : 0.5 * (e + ep[nb[2]][nb[1]][nb[0]]) * FaceConductivity(kc, k[nb[2]][nb[1]][nb[0]]) * ih2[d];
        diag += kf;
        col[nc] = {nb[2], nb[1], nb[0], 0}, val[nc] = -kf, ++nc;
      }
    if (losses) {
      const PetscReal ds = cached ? interfaceDensity_[cell] : e * InterfaceDensity(const_cast<PetscScalar ***>(al), x, y, z, n, h, periodic);
      if (ds > 0) {
        const PetscReal em = interfaceRadiation_ ? metal_.emissivity : 0;
        diag += ds * (interfaceConvection_ + 4 * em * kStefanBoltzmann * t * t * t);
      }
    }
    col[0] = {z, y, x, 0}, val[0] = diag;
    return nc;
  };
  // In place once the writer knows the rows (grid/AijRowWriter.hpp: AIJ matrices, the same bits), else through
  // MatSetValuesStencil, recording them; the hypre structured matrix always takes the second way.
  Mat           A      = A_[slot];
  AijRowWriter &writer = writer_[slot];
  const bool    inPlace = writer.Ready();
  for (int pass = inPlace ? 0 : 1; pass < 2; ++pass) {
    if (pass == 0) PetscCall(writer.Begin(A));
    else {
      PetscCall(MatZeroEntries(A));
      writer.Reset();
    }
    bool fits = true;
    c         = 0;
    for (PetscInt z = b.s[2]; z < b.s[2] + b.m[2]; ++z)
      for (PetscInt y = b.s[1]; y < b.s[1] + b.m[1]; ++y)
        for (PetscInt x = b.s[0]; x < b.s[0] + b.m[0]; ++x) {
          MatStencil     col[7];
          PetscScalar    val[7];
          const PetscInt nc = row(x, y, z, col, val);
          if (pass == 0) fits = fits && writer.Put(nc, col, val);
          else {
            PetscCall(MatSetValuesStencil(A, 1, col, nc, col, val, INSERT_VALUES));
            PetscCall(writer.Note(A, dm_, col[0], nc, col));
          }
        }
    if (pass == 0) {
      bool complete;
      PetscCall(writer.End(A, &complete));
      if (fits && complete) break;
      continue;
    }
    PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
    PetscCall(writer.Finish(A));
  }
  PetscCall(DMDAVecRestoreArrayRead(dm_, epsLocal_, &ep));
  PetscCall(DMDAVecRestoreArrayRead(dm_, C_, &C));
  PetscCall(DMDAVecRestoreArrayRead(dm_, alphaLocal_, &al));
  PetscCall(DMDAVecRestoreArrayRead(dm_, kLocal_, &k));
  PetscCall(DMDAVecRestoreArrayRead(dm_, TLocal_, &T));
  jacobianKey_[slot] = key;
  PetscCall(PetscLogEventEnd(evAssemble_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

// r = a E(T) - H - dt R(T) per cell (J/m^3), with R the exact (not linearised) fluxes, losses and deposit at
// the current T (Properties done); also the step's rates: through the box faces, lost, in all. The face
// conductances eps_f k_f/h^2 and the interface densities depend on k, eps and alpha alone: they are kept from the
// last fill while kLocal_, epsLocal_ and alphaLocal_ are unchanged (their object states), the same bits.
PetscErrorCode Energy::Residual(PetscReal a, PetscReal dt, PetscReal *maxResidual) {
  const Box          b = Owned(dm_);
  const PetscReal   *h = grid_->Spacing();
  const PetscInt    *n = grid_->Cells();
  const PetscReal    V = h[0] * h[1] * h[2];
  bool               periodic[3];
  const PetscScalar *T, *k, *ep, *E, *H, *q, *qp = nullptr;  // qp: the particles' heat (F9, SetParticleHeat)
  PetscScalar       *r, ***al = nullptr;
  PetscReal          rates[3] = {0, 0, 0}, rmax = 0;  // box faces, losses, residual sum (J)
  PetscInt           gs[3], gm[3];
  PetscObjectState   key[3];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evResidual_, 0, 0, 0, 0));
  for (int d = 0; d < 3; ++d) periodic[d] = grid_->Periodic(d);
  PetscCall(DMDAGetGhostCorners(dm_, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  PetscCall(PetscObjectStateGet((PetscObject)kLocal_, &key[0]));
  PetscCall(PetscObjectStateGet((PetscObject)epsLocal_, &key[1]));
  PetscCall(PetscObjectStateGet((PetscObject)alphaLocal_, &key[2]));
  const bool      losses = interfaceConvection_ > 0 || (interfaceRadiation_ && metal_.emissivity > 0);
  const size_t    cells  = (size_t)b.m[0] * b.m[1] * b.m[2];
  const bool      reuse  = facesFilled_ && faceConductance_.size() == 6 * cells && std::equal(key, key + 3, faceKey_);
  PetscCall(VecGetArrayRead(TLocal_, &T));
  PetscCall(VecGetArrayRead(kLocal_, &k));
  PetscCall(VecGetArrayRead(epsLocal_, &ep));
  PetscCall(VecGetArrayRead(Ecur_, &E));
  PetscCall(VecGetArrayRead(H_, &H));
  PetscCall(VecGetArrayRead(q_, &q));
  PetscCall(VecGetArray(r_, &r));
  if (particleSource_) PetscCall(VecGetArrayRead(particleSource_, &qp));
  if (losses && !reuse) PetscCall(DMDAVecGetArrayRead(dm_, alphaLocal_, &al));
  PetscReal       rsum   = 0;
  const PetscReal ih2[3] = {1 / (h[0] * h[0]), 1 / (h[1] * h[1]), 1 / (h[2] * h[2])};
  const PetscInt  off[6] = {-1, 1, -gm[0], gm[0], -gm[0] * gm[1], gm[0] * gm[1]};  // the neighbours in the ghosted arrays
  if (!reuse) faceConductance_.resize(6 * cells), interfaceDensity_.resize(cells);  // for Assemble at this state
  // A box face's flux into the cell through the fluid's share of the face, per cell volume (W/m^3).
  auto boxFlux = [&](int f, PetscReal e, PetscReal kc, PetscReal t) {
    const EnergyFace &bf = face_[f];
    const int         d  = f / 2;
    PetscReal         flux = 0;  // W/m^2 into the cell
    if (bf.type == EnergyBoundary::Temperature) flux = 2 * kc * (bf.value - t) / h[d];
    else if (bf.type == EnergyBoundary::Flux) flux = bf.value;
    else if (bf.type == EnergyBoundary::Convective) flux = bf.value * (bf.ambient - t) + bf.emissivity * kStefanBoltzmann * (Pow4(bf.ambient) - Pow4(t));
    return e * flux / h[d];
  };
  // The box faces of a cell with coordinate p along d (bits 2d, 2d + 1: its low and high face).
  auto boxFaces = [&](int d, PetscInt p) { return periodic[d] ? 0u : (p == 0 ? 1u << 2 * d : 0u) | (p == n[d] - 1 ? 2u << 2 * d : 0u); };
  const unsigned xLow = boxFaces(0, 0) & 1u, xHigh = boxFaces(0, n[0] - 1) & 2u;
  // The cells, with the conductances computed (fill) or read: one loop in two instances.
  auto sweep = [&](auto fillTag) {
    constexpr bool fill = decltype(fillTag)::value;
    size_t         c    = 0;
    for (PetscInt z = b.s[2]; z < b.s[2] + b.m[2]; ++z)
      for (PetscInt y = b.s[1]; y < b.s[1] + b.m[1]; ++y) {
        const unsigned yz = boxFaces(1, y) | boxFaces(2, z);
        PetscInt       l  = ((z - gs[2]) * gm[1] + (y - gs[1])) * gm[0] + (b.s[0] - gs[0]);  // the cell in the ghosted arrays
        for (PetscInt x = b.s[0]; x < b.s[0] + b.m[0]; ++x, ++c, ++l) {
          const unsigned  box = yz | (x == 0 ? xLow : 0u) | (x == n[0] - 1 ? xHigh : 0u);
          const PetscReal t = T[l], kc = k[l], e = ep[l];
          PetscReal       R = q[c] + (qp ? PetscRealPart(qp[c]) : 0), boundary = 0;
          PetscReal      *G = &faceConductance_[6 * c];
          // the faces in the order x-, x+, y-, y+, z-, z+ (R's sum in that order, the same bits in both branches)
          auto inner = [&](int f) {
            const PetscInt m = l + off[f];
            if (fill) G[f] = 0.5 * (e + ep[m]) * FaceConductivity(kc, k[m]) * ih2[f / 2];  // eps_f k_f/h^2
            R += G[f] * (T[m] - t);
          };
          if (!box) inner(0), inner(1), inner(2), inner(3), inner(4), inner(5);
          else
            for (int f = 0; f < 6; ++f) {
              if (!(box >> f & 1u)) {
                inner(f);
                continue;
              }
              boundary += boxFlux(f, e, kc, t);
              if (fill) G[f] = 0;
            }
          PetscReal loss = 0;
          if (fill) interfaceDensity_[c] = losses ? e * InterfaceDensity(al, x, y, z, n, h, periodic) : 0;  // the fluid's share
          if (losses) {
            const PetscReal ds = interfaceDensity_[c];
            const PetscReal em = interfaceRadiation_ ? metal_.emissivity : 0;
            loss               = ds * (interfaceConvection_ * (t - ambient_) + em * kStefanBoltzmann * (Pow4(t) - Pow4(ambient_)));
          }
          R += boundary - loss;
          rates[0] += boundary * V, rates[1] += loss * V;
          r[c] = a * E[c] - H[c] - dt * R;
          rsum += r[c] * V;
          rmax = std::max(rmax, (PetscReal)std::fabs(r[c]));
        }
      }
  };
  if (reuse) sweep(std::false_type());
  else sweep(std::true_type());
  if (al) PetscCall(DMDAVecRestoreArrayRead(dm_, alphaLocal_, &al));
  if (particleSource_) PetscCall(VecRestoreArrayRead(particleSource_, &qp));
  PetscCall(VecRestoreArray(r_, &r));
  PetscCall(VecRestoreArrayRead(q_, &q));
  PetscCall(VecRestoreArrayRead(H_, &H));
  PetscCall(VecRestoreArrayRead(Ecur_, &E));
  PetscCall(VecRestoreArrayRead(epsLocal_, &ep));
  PetscCall(VecRestoreArrayRead(kLocal_, &k));
  PetscCall(VecRestoreArrayRead(TLocal_, &T));
  std::copy(key, key + 3, faceKey_), facesFilled_ = true;
  rates[2] = rsum;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, rates, 3, MPIU_REAL, MPI_SUM, comm_));
  PetscCallMPI(MPI_Allreduce(&rmax, maxResidual, 1, MPIU_REAL, MPI_MAX, comm_));
  last_.boundaryRate = rates[0], last_.lossRate = rates[1], last_.balance = rates[2];
  last_.inputRate    = rates[0] - rates[1] + last_.absorbed;
  cacheValid_        = true;
  PetscCall(PetscLogEventEnd(evResidual_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

// T = T_base + lambda d (d in Tstar_), f = clamp(f_base + F' (T - T_F), 0, 1).
PetscErrorCode Energy::Update(PetscReal lambda) {
  const Box     bx = Owned(dm_);
  PetscScalar ***T, ***Tb, ***d, ***F, ***Fb, ***S, ***TF;

  PetscFunctionBeginUser;
  PetscCall(DMDAVecGetArray(dm_, T_, &T));
  PetscCall(DMDAVecGetArray(dm_, F_, &F));
  PetscCall(DMDAVecGetArrayRead(dm_, Tbase_, &Tb));
  PetscCall(DMDAVecGetArrayRead(dm_, Fbase_, &Fb));
  PetscCall(DMDAVecGetArrayRead(dm_, Tstar_, &d));
  PetscCall(DMDAVecGetArrayRead(dm_, slope_, &S));
  PetscCall(DMDAVecGetArrayRead(dm_, TF_, &TF));
  for (PetscInt z = bx.s[2]; z < bx.s[2] + bx.m[2]; ++z)
    for (PetscInt y = bx.s[1]; y < bx.s[1] + bx.m[1]; ++y)
      for (PetscInt x = bx.s[0]; x < bx.s[0] + bx.m[0]; ++x) {
        T[z][y][x] = Tb[z][y][x] + lambda * d[z][y][x];
        if (S[z][y][x] > 0) F[z][y][x] = std::min((PetscReal)1, std::max((PetscReal)0, Fb[z][y][x] + S[z][y][x] * (T[z][y][x] - TF[z][y][x])));
      }
  PetscCall(DMDAVecRestoreArrayRead(dm_, TF_, &TF));
  PetscCall(DMDAVecRestoreArrayRead(dm_, slope_, &S));
  PetscCall(DMDAVecRestoreArrayRead(dm_, Tstar_, &d));
  PetscCall(DMDAVecRestoreArrayRead(dm_, Fbase_, &Fb));
  PetscCall(DMDAVecRestoreArrayRead(dm_, Tbase_, &Tb));
  PetscCall(DMDAVecRestoreArray(dm_, F_, &F));
  PetscCall(DMDAVecRestoreArray(dm_, T_, &T));
  PetscFunctionReturn(0);
}

// The conservative close (docs/physics.md F7 b): whatever residual the iteration left, each cell's energy becomes
// E = E(T^k, f^k) - r/a = (H + dt R(T^k))/a, the balance with the fluxes, losses and deposit of the last iterate
// (Residual) exactly, so that the energy moved between cells and through the box's faces is conserved to round-off
// at any -energy_tolerance. T and f take the change dE = -r/a as one more update with the apparent capacity C
// (dT = dE/C, f moved with its slope, as in Update): they match E to second order in dE, and the next step's
// iteration starts from that (its H is this E). The tolerance bounds T's error alone.
PetscErrorCode Energy::CloseBalance(PetscReal a) {
  const Box     bx = Owned(dm_);
  PetscScalar ***T, ***F, ***E, ***r, ***C, ***S;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evClose_, 0, 0, 0, 0));
  PetscCall(DMDAVecGetArray(dm_, T_, &T));
  PetscCall(DMDAVecGetArray(dm_, F_, &F));
  PetscCall(DMDAVecGetArray(dm_, Ecur_, &E));
  PetscCall(DMDAVecGetArrayRead(dm_, r_, &r));
  PetscCall(DMDAVecGetArrayRead(dm_, C_, &C));
  PetscCall(DMDAVecGetArrayRead(dm_, slope_, &S));
  for (PetscInt z = bx.s[2]; z < bx.s[2] + bx.m[2]; ++z)
    for (PetscInt y = bx.s[1]; y < bx.s[1] + bx.m[1]; ++y)
      for (PetscInt x = bx.s[0]; x < bx.s[0] + bx.m[0]; ++x) {
        if (r[z][y][x] == 0) continue;
        const PetscReal dE = -r[z][y][x] / a, dT = dE / C[z][y][x];
        E[z][y][x] += dE;
        T[z][y][x] += dT;
        if (S[z][y][x] > 0) F[z][y][x] = std::min((PetscReal)1, std::max((PetscReal)0, F[z][y][x] + S[z][y][x] * dT));
      }
  PetscCall(DMDAVecRestoreArrayRead(dm_, slope_, &S));
  PetscCall(DMDAVecRestoreArrayRead(dm_, C_, &C));
  PetscCall(DMDAVecRestoreArrayRead(dm_, r_, &r));
  PetscCall(DMDAVecRestoreArray(dm_, Ecur_, &E));
  PetscCall(DMDAVecRestoreArray(dm_, F_, &F));
  PetscCall(DMDAVecRestoreArray(dm_, T_, &T));
  PetscCall(PetscLogEventEnd(evClose_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

// One step from time to time + dt: BDF2 a E^{n+1} - b E^n + c E^{n-1} = dt R(T^{n+1}) with the variable-step
// coefficients (w = dt/dt_old) a = (1 + 2w)/(1 + w), b = 1 + w, c = w^2/(1 + w); backward Euler (a = b = 1,
// c = 0) on the first step or with -energy_time_scheme euler.
PetscErrorCode Energy::Step(PetscReal time, PetscReal dt) {
  PetscReal a = 1, bcoef = 1, c = 0;

  PetscFunctionBeginUser;
  const bool bdf2 = bdf2_ && !Moving() && steps_ > 0 && dtOld_ > 0;  // after the interface's transport: backward Euler
  if (SubstrateMoving()) PetscCall(MoveSubstrate(dt, bdf2));          // EnergySubstrate.cpp
  PetscCall(RefreshFluidFraction());                                   // eps^{n+1}: the coupling's of this step
  if (bdf2) {
    const PetscReal w = dt / dtOld_;
    a = (1 + 2 * w) / (1 + w), bcoef = 1 + w, c = w * w / (1 + w);
  }
  PetscCall(VecAXPBYPCZ(H_, bcoef, -c, 0, E_, Eold_));  // H = b E^n - c E^{n-1}
  PetscCall(LaserSource(time + dt));
  PetscCall(Properties());  // the iteration starts from the state at n
  PetscReal rmax  = 0;
  PetscInt  it    = 0, linear = 0;
  const int slot  = SolverFor(dt);
  KSP       ksp   = ksp_[slot];
  PetscCall(Residual(a, dt, &rmax));
  while (rmax > tolerance_ * energyScale_ && it < maxIterations_) {
    PetscInt its;
    PetscCall(Assemble(a, dt, slot));
    PetscCall(KSPSetOperators(ksp, A_[slot], A_[slot]));
    // The preconditioner of the step's first Jacobian serves its later iterations (-energy_pc_rebuild step):
    // the operator changes there only through the mushy cells' slopes and k(T).
    if (pcRebuild_ == PcRebuild::Step) PetscCall(KSPSetReusePreconditioner(ksp, it > 0 ? PETSC_TRUE : PETSC_FALSE));
    // J d = -(r + a alpha rho_m L F' (T^k - T_F))/dt: the latent share linearised about T_F (LatentSlope)
    {
      const Box    bx = Owned(dm_);
      PetscScalar ***rhs, ***r, ***T, ***S, ***TF, ***al, ***ep;
      PetscCall(DMDAVecGetArray(dm_, rhs_, &rhs));
      PetscCall(DMDAVecGetArrayRead(dm_, r_, &r));
      PetscCall(DMDAVecGetArrayRead(dm_, T_, &T));
      PetscCall(DMDAVecGetArrayRead(dm_, slope_, &S));
      PetscCall(DMDAVecGetArrayRead(dm_, TF_, &TF));
      PetscCall(DMDAVecGetArrayRead(dm_, alpha_, &al));
      PetscCall(DMDAVecGetArrayRead(dm_, epsCells_, &ep));
      const PetscReal rl = metal_.density * metal_.latentHeat;
      for (PetscInt z = bx.s[2]; z < bx.s[2] + bx.m[2]; ++z)
        for (PetscInt y = bx.s[1]; y < bx.s[1] + bx.m[1]; ++y)
          for (PetscInt x = bx.s[0]; x < bx.s[0] + bx.m[0]; ++x)
            rhs[z][y][x] = -(r[z][y][x] + a * ep[z][y][x] * al[z][y][x] * rl * S[z][y][x] * (T[z][y][x] - TF[z][y][x])) / dt;
      PetscCall(DMDAVecRestoreArrayRead(dm_, epsCells_, &ep));
      PetscCall(DMDAVecRestoreArrayRead(dm_, alpha_, &al));
      PetscCall(DMDAVecRestoreArrayRead(dm_, TF_, &TF));
      PetscCall(DMDAVecRestoreArrayRead(dm_, slope_, &S));
      PetscCall(DMDAVecRestoreArrayRead(dm_, T_, &T));
      PetscCall(DMDAVecRestoreArrayRead(dm_, r_, &r));
      PetscCall(DMDAVecRestoreArray(dm_, rhs_, &rhs));
    }
    PetscCall(VecSet(Tstar_, 0));
    // The correction's system is the balance per time: a linear residual of e (W/m^3) leaves dt e in a cell's
    // balance, so a 2-norm below a tenth of the tolerance per dt leaves every cell well inside it (the rest is the
    // linearisation's error, which the next iteration takes).
    PetscCall(KSPSetTolerances(ksp, PETSC_DEFAULT, std::max(kspAtol_, 0.1 * tolerance_ * energyScale_ / dt), PETSC_DEFAULT, PETSC_DEFAULT));
    PetscCall(KSPSolve(ksp, rhs_, Tstar_));
    PetscCall(KSPGetIterationNumber(ksp, &its));
    linear += its;
    {  // a failed linear solve would feed the update garbage (T reached 7e296 K before the balance check saw it)
      KSPConvergedReason reason;
      PetscReal          res;
      PetscCall(KSPGetConvergedReason(ksp, &reason));
      PetscCall(KSPGetResidualNorm(ksp, &res));
      if (reason <= 0)
        VofdemRunError(comm_, "energy solve did not converge at t = %g s: %s after %" PetscInt_FMT " iterations, residual %g (-energy_ksp_monitor shows the history)", (double)(time + dt),
                       KSPConvergedReasons[reason], its, (double)res);
    }
    // The update (Update), with lambda halved while the largest residual grows.
    PetscCall(VecCopy(T_, Tbase_));
    PetscCall(VecCopy(F_, Fbase_));
    const PetscReal before = rmax;
    PetscReal       lambda = 1;
    for (int halving = 0;; ++halving, lambda *= 0.5) {
      PetscCall(Update(lambda));
      PetscCall(Properties());
      PetscCall(Residual(a, dt, &rmax));
      if (rmax <= before || halving == 8) break;
    }
    ++it;
  }
  if (rmax > tolerance_ * energyScale_)
    VofdemInputError(comm_, "option -energy_max_iterations: the enthalpy balance did not close in %d iterations at t = %g s (largest residual %.3e of the tolerance %.3e J/m^3); lower -dt or raise -energy_max_iterations",
                     (int)maxIterations_, (double)(time + dt), (double)rmax, (double)(tolerance_ * energyScale_));
  PetscCall(CloseBalance(a));
  // The account: a W^{n+1} - b W^n + c W^{n-1} = dt (input at n+1), the integrated input the scheme itself implies.
  PetscReal total;
  PetscCall(VecSum(Ecur_, &total));
  const PetscReal *h = grid_->Spacing();
  total *= h[0] * h[1] * h[2];
  PetscReal advected = 0;  // what the interface's sweeps carried through the box's faces this step (TransportSweep)
  PetscCallMPI(MPI_Allreduce(&advected_, &advected, 1, MPIU_REAL, MPIU_SUM, comm_));
  advected_ = 0;
  if (SubstrateMoving()) {  // both levels moved through the box's faces before the balance (MoveSubstrate)
    PetscReal old = 0;
    PetscCallMPI(MPI_Allreduce(&advectedOld_, &old, 1, MPIU_REAL, MPIU_SUM, comm_));
    advectedOld_ = 0;
    const PetscReal Wn = W_ + advected;
    W_ = (bcoef * Wn - c * (Wold_ + old) + dt * last_.inputRate) / a;
    Wold_ = Wn;  // the total of E^n moved, which Eold_ becomes below
  } else {
    const PetscReal W = (bcoef * W_ - c * Wold_ + dt * last_.inputRate) / a + advected;
    Wold_ = W_, W_ = W;
  }
  totalOlder_ = totalOld_, totalOld_ = total;
  PetscCall(VecCopy(E_, Eold_));
  PetscCall(VecCopy(Ecur_, E_));
  dtOld_ = dt, ++steps_;
  swept_ = false, sweep_ = 0;
  last_.iterations = it, last_.linearIterations = linear;
  PetscFunctionReturn(0);
}

}  // namespace vofdem
