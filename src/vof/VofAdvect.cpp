// Reconstruction and split geometric advection of the VOF module (Vof.hpp; docs/physics.md F1b, F4).
#include "vofdem/vof/Vof.hpp"

#include "vofdem/vof/Plic.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace {

struct CellArray {  // ghosted local array of the alpha DMDA, global indices
  const PetscScalar *data;
  PetscInt           g0[3], stride[3];
  double at(PetscInt i, PetscInt j, PetscInt k) const {
    return PetscRealPart(data[(i - g0[0]) * stride[0] + (j - g0[1]) * stride[1] + (k - g0[2]) * stride[2]]);
  }
  double at(const PetscInt q[3]) const { return at(q[0], q[1], q[2]); }
};

// Youngs: minus the gradient of alpha in cell units from the 27-cell block, each difference weighted
// (1,2,1) x (1,2,1) across (the average of the 8 corner gradients). In cell units the plane's normal
// is this index-space gradient whatever the spacings (x_d = h_d xi_d).
void Youngs(const CellArray &a, const PetscInt q[3], double n[3]) {
  static const double w[3] = {1, 2, 1};
  n[0] = n[1] = n[2] = 0;
  for (int c = -1; c <= 1; ++c)
    for (int b = -1; b <= 1; ++b) {
      const double wt = w[b + 1] * w[c + 1];
      n[0] -= wt * (a.at(q[0] + 1, q[1] + b, q[2] + c) - a.at(q[0] - 1, q[1] + b, q[2] + c));
      n[1] -= wt * (a.at(q[0] + b, q[1] + 1, q[2] + c) - a.at(q[0] + b, q[1] - 1, q[2] + c));
      n[2] -= wt * (a.at(q[0] + b, q[1] + c, q[2] + 1) - a.at(q[0] + b, q[1] + c, q[2] - 1));
    }
}

const double kFull = 1 - 1e-8;

const int kHalf = 3;  // height-function columns of 2 kHalf + 1 = 7 cells

// Sum of alpha over the 7-cell column along d through q + o (o a transverse offset); false unless the
// column is a clean transition: its fluid end (side -sign) full and its other end empty (docs/physics.md F4:
// heights only where the interface is resolved).
bool ColumnSum(const CellArray &a, const PetscInt q[3], int d, int sign, const PetscInt o[3], double *H) {
  PetscInt p[3] = {q[0] + o[0], q[1] + o[1], q[2] + o[2]};
  double   sum  = 0;
  for (int s = -kHalf; s <= kHalf; ++s) {
    PetscInt r[3] = {p[0], p[1], p[2]};
    r[d] += s;
    sum += a.at(r);
  }
  *H = sum;
  PetscInt lo[3] = {p[0], p[1], p[2]}, hi[3] = {p[0], p[1], p[2]};
  lo[d] -= kHalf * sign;  // fluid end
  hi[d] += kHalf * sign;
  return a.at(lo) >= kFull && a.at(hi) <= 1 - kFull;
}

// The normal from column sums along d (heights in cells): the surface x_d = H(x_t) has the normal
// (-dH/dt, 1) times the side of the fluid, the transverse part the same for either side. Returns
// false when a column is not a clean transition; *slope = sum |dH/dt|.
bool ColumnNormal(const CellArray &a, const PetscInt q[3], int d, int sign, double m[3], double *slope) {
  m[d]   = sign;
  *slope = 0;
  for (int t = 0; t < 3; ++t) {
    if (t == d) continue;
    double   Hm, Hp, H0;
    PetscInt om[3] = {0, 0, 0}, op[3] = {0, 0, 0}, oz[3] = {0, 0, 0};
    om[t] = -1;
    op[t] = 1;
    if (!(ColumnSum(a, q, d, sign, om, &Hm) && ColumnSum(a, q, d, sign, op, &Hp) && ColumnSum(a, q, d, sign, oz, &H0))) return false;
    m[t] = -0.5 * (Hp - Hm);
    *slope += std::fabs(m[t]);
  }
  return true;
}

}  // namespace

bool Vof::Reconstruct(const LocalField &f, const PetscInt q[3], double n[3], double *c, bool *fromHeights) const {
  const CellArray a = {f.data, {f.g0[0], f.g0[1], f.g0[2]}, {f.stride[0], f.stride[1], f.stride[2]}};
  const double    v = a.at(q);
  *fromHeights      = false;
  if (v <= tiny_ || v >= 1 - tiny_) return false;
  Youngs(a, q, n);
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) return false;
  if (normals_ == VofNormals::Height) {
    // Heights along each direction the interface faces (Youngs' component not 0; the side of the
    // fluid from Youngs): of the directions whose 7-cell columns are all clean transitions, the one
    // with the smallest slopes (columns most nearly across the interface).
    double best[3] = {0, 0, 0}, bestSlope = PETSC_MAX_REAL;
    for (int d = 0; d < 3; ++d) {
      double m[3], slope;
      if (n[d] != 0 && ColumnNormal(a, q, d, n[d] > 0 ? 1 : -1, m, &slope) && slope < bestSlope) {
        bestSlope = slope;
        for (int e = 0; e < 3; ++e) best[e] = m[e];
      }
    }
    if (bestSlope < PETSC_MAX_REAL) {
      for (int e = 0; e < 3; ++e) n[e] = best[e];
      *fromHeights = true;
    }
  }
  // Where heights are not available (thin filaments, corners, high curvature): ELVIRA unless Youngs is asked.
  if (!*fromHeights && (normals_ == VofNormals::Elvira || (normals_ == VofNormals::Height && fallback_ == VofNormals::Elvira))) {
    double block[27];
    for (int z = -1, i = 0; z <= 1; ++z)
      for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x, ++i) block[i] = a.at(q[0] + x, q[1] + y, q[2] + z);
    const double young[3] = {n[0], n[1], n[2]};
    plic::Elvira(block, young, n);
  }
  *c = plic::Alpha(n, v);
  return true;
}

PetscErrorCode Vof::Sweep(int d, int stage, Vec const uLocal[3], PetscReal dt, PetscReal *fromHeights, PetscReal *reconstructions) {
  LocalField a, u, g, E, D;
  PetscInt   s[3], n[3], gs[3], gm[3];

  PetscFunctionBeginUser;
  const PetscReal h = grid_->Spacing()[d], r = dt / h;
  const double    cellVolume = grid_->Spacing()[0] * grid_->Spacing()[1] * grid_->Spacing()[2];
  PetscCall(DMDAGetCorners(da_, &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAGetGhostCorners(da_, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  PetscCall(VecGetArray(alphaLocal_, &a.data));
  for (int e = 0; e < 3; ++e) a.g0[e] = gs[e];
  a.stride[0] = 1;
  a.stride[1] = gm[0];
  a.stride[2] = gm[0] * gm[1];
  PetscCall(sg_->GetLocal(d, uLocal[d], &u));
  if (eps_) {  // eps and its change, with alpha's ghost layout (Vof.hpp SetFluidFraction)
    E = a, D = a;
    PetscCall(VecGetArray(epsLocal_, &E.data));
    PetscCall(VecGetArray(changeLocal_, &D.data));
  }
  // eps at face q (between cells q - e_d and q): the mean the flow's projection uses (FlowProjection.cpp).
  auto faceEps = [&](const PetscInt q[3]) {
    PetscInt m[3] = {q[0], q[1], q[2]};
    m[d] -= 1;
    return 0.5 * (PetscRealPart(E.at(m)) + PetscRealPart(E.at(q)));
  };
  // Face fluxes (fraction of a cell's volume crossing, positive along +d) of the owned cells' faces:
  // face index f lies between cells f-1 and f.
  PetscInt nf[3] = {n[0], n[1], n[2]};
  nf[d] += 1;
  flux_.assign((size_t)(nf[0] * nf[1] * nf[2]), 0.0);
  PetscInt idx = 0;
  for (PetscInt k = s[2]; k < s[2] + nf[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + nf[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + nf[0]; ++i, ++idx) {
        const PetscInt  q[3] = {i, j, k};
        const PetscReal vel  = PetscRealPart(u.at(q));
        if (vel == 0) continue;
        const double cour = vel * r;  // signed Courant number
        PetscInt     donor[3] = {i, j, k};
        if (vel > 0) donor[d] -= 1;
        const double v = PetscRealPart(a.at(donor));
        double       nrm[3], c;
        bool         heights;
        const int    open = OpenDonorFace(d, q, vel);  // donor outside an open face: what enters (VofOpenFaces.cpp)
        if (open >= 0) {
          flux_[idx] = cour * EnteringFraction(open, q);
        } else if (!Reconstruct(a, donor, nrm, &c, &heights)) {
          flux_[idx] = cour * v;  // full, empty or without a gradient: uniform
        } else {
          if (donor[d] >= s[d] && donor[d] < s[d] + n[d]) {  // the summary's share, each (donor, face) once over the ranks
            *reconstructions += 1;
            *fromHeights += heights;
          }
          double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
          if (vel > 0) lo[d] = 1 - cour;
          else hi[d] = -cour;
          flux_[idx] = cour * plic::BoxFraction(nrm, c, lo, hi);
        }
        // F1b: the fluid crossing is eps_f u_f dt/h of a cell; alpha's PLIC share of the slab it sweeps.
        if (eps_) flux_[idx] *= faceEps(q);
        if (!grid_->Periodic(d) && (q[d] == 0 || q[d] == grid_->Cells()[d])) {  // an open face (walls have no normal velocity)
          const double in = (q[d] == 0 ? 1 : -1) * flux_[idx] * cellVolume;
          openStep_[in > 0 ? 0 : 1] += std::fabs(in);
        }
      }
  {  // this sweep's phase-1 volume flux per face (m/s), for the consistent momentum (VofMomentum.cpp)
    LocalField pf;
    PetscInt   fs[3], fn[3];
    sg_->Owned(d, fs, fn);
    PetscCall(sg_->GetGlobal(d, phaseFlux_[d], &pf));
    for (PetscInt k = fs[2]; k < fs[2] + fn[2]; ++k)
      for (PetscInt j = fs[1]; j < fs[1] + fn[1]; ++j)
        for (PetscInt i = fs[0]; i < fs[0] + fn[0]; ++i)
          pf.at(i, j, k) = flux_[(size_t)((i - s[0]) + nf[0] * ((j - s[1]) + nf[1] * (k - s[2])))] / r;
    PetscCall(sg_->RestoreGlobal(d, phaseFlux_[d], &pf));
  }
  PetscCall(sg_->GetGlobal(3, alpha_, &g));
  PetscInt   sf[3] = {1, nf[0], nf[0] * nf[1]};
  PetscReal  worst = boundViolation_;
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscInt q[3] = {i, j, k}, f0 = (i - s[0]) * sf[0] + (j - s[1]) * sf[1] + (k - s[2]) * sf[2];
        PetscInt       qp[3] = {i, j, k};
        qp[d] += 1;
        const size_t   cell  = (size_t)((i - s[0]) + n[0] * ((j - s[1]) + n[1] * (k - s[2])));
        double         v;
        if (!eps_) {
          const double divU = r * (PetscRealPart(u.at(qp)) - PetscRealPart(u.at(q)));
          v                 = PetscRealPart(a.at(q)) - (flux_[f0 + sf[d]] - flux_[f0]) + (fullAtStart_[cell] ? divU : 0.0);
        } else {
          // F1b on m = eps alpha: the cell's eps goes from eps_n = eps - change to eps in thirds
          // (e0 before this sweep, e1 after); the c-term adds the swept fluid volume and this sweep's
          // third of the change, so a full cell ends each sweep exactly full (Vof.hpp).
          const double eN = PetscRealPart(E.at(q)), dE = PetscRealPart(D.at(q));
          const double e0 = eN - dE * (1 - (stage - 1) / 3.0), e1 = eN - dE * (1 - stage / 3.0);
          const double divQ = r * (faceEps(qp) * PetscRealPart(u.at(qp)) - faceEps(q) * PetscRealPart(u.at(q))) + dE / 3;
          v = (PetscRealPart(a.at(q)) * e0 - (flux_[f0 + sf[d]] - flux_[f0]) + (fullAtStart_[cell] ? divQ : 0.0)) / e1;
        }
        g.at(q) = v;
        // With particles the sweeps' intermediate excursions are put right after the last one (Redistribute):
        // the bound reported is that of the result.
        if (!eps_ || !redistribute_) worst = std::max(worst, std::max(-v, v - 1));
      }
  boundViolation_ = worst;
  if (eps_) {
    PetscCall(VecRestoreArray(changeLocal_, &D.data));
    PetscCall(VecRestoreArray(epsLocal_, &E.data));
  }
  PetscCall(sg_->RestoreGlobal(3, alpha_, &g));
  PetscCall(sg_->RestoreLocal(d, uLocal[d], &u));
  PetscCall(VecRestoreArray(alphaLocal_, &a.data));
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::Advect(Vec const u[3], PetscReal dt) {
  const PetscScalar *a;
  PetscInt           n;

  PetscFunctionBeginUser;
  if (!advect_) PetscFunctionReturn(0);  // a frozen interface (-vof_advect 0)
  for (int d = 0; d < 3; ++d) PetscCall(DMGlobalToLocal(sg_->Face(d), u[d], INSERT_VALUES, uLocal_[d]));
  PetscCall(FillGhosts());
  if (eps_) PetscCall(FluidFractionGhosts());
  // c_i from the state at the start of the step, the same in every sweep (exact conservation).
  PetscCall(VecGetLocalSize(alpha_, &n));
  PetscCall(VecGetArrayRead(alpha_, &a));
  for (PetscInt i = 0; i < n; ++i) fullAtStart_[(size_t)i] = PetscRealPart(a[i]) > 0.5;
  PetscCall(VecRestoreArrayRead(alpha_, &a));
  const int order[2][3] = {{0, 1, 2}, {2, 1, 0}};
  PetscReal counts[2]   = {0, 0}, total[2];
  bool moved = false;  // a sweep has been made this step (MomentumSweepStart)
  for (int p = 0; p < 3; ++p) {
    const int d = order[steps_ % 2][p];
    if (!eps_ && d != 0) {
      // No velocity along d anywhere (the span of a quasi-2-D case): the sweep would give every cell
      // back its alpha and every face its velocity exactly (zero fluxes, zero dilatation). Not with
      // particles: each sweep also takes a third of eps's change. The x-sweep always runs (a step
      // makes at least one sweep).
      PetscReal umax;
      PetscCall(VecNorm(u[d], NORM_INFINITY, &umax));
      if (umax == 0) continue;
    }
    if (momentumFlow_) PetscCall(MomentumSweepStart(moved));  // the sweep's start, for MomentumSweep
    moved = true;
    PetscCall(Sweep(d, p + 1, uLocal_, dt, &counts[0], &counts[1]));
    PetscCall(FillGhosts());
    if (momentumFlow_) PetscCall(MomentumSweep(d, dt));  // AdvectWithMomentum (VofMomentum.cpp)
    for (const SweepObserver &o : observers_) PetscCall(o(d, dt, u[d], phaseFlux_[d]));
  }
  if (eps_ && redistribute_) {
    PetscCall(Redistribute());
    PetscCall(FillGhosts());
  }
  PetscCallMPI(MPI_Allreduce(counts, total, 2, MPIU_REAL, MPIU_SUM, grid_->Comm()));
  heightShare_ = total[1] > 0 ? total[0] / total[1] : 0;
  if (HasOpenFaces()) {  // this step's phase-1 volume in and out through open faces (VofOpenFaces.cpp)
    PetscReal step[2];
    PetscCallMPI(MPI_Allreduce(openStep_, step, 2, MPIU_REAL, MPIU_SUM, grid_->Comm()));
    openVolume_[0] += step[0];
    openVolume_[1] += step[1];
    openStep_[0] = openStep_[1] = 0;
  }
  ++steps_;
  PetscFunctionReturn(0);
}

}  // namespace vofdem
