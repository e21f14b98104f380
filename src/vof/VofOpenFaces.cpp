// Open faces of the VOF module (Vof.hpp): phase 1 entering through inflow faces and either phase
// leaving (or coming back) through outflow faces (issue 8; docs/physics.md F4).
//
// What enters: -vof_bc_<face>_alpha A on an inflow face is the fraction of phase 1 in the fluid that
// the flow's inflow velocity brings in (default 0: phase 0 enters); with -vof_bc_<face>_alpha_band
// lo,hi[,lo2,hi2] it enters only through that band of the face (a jet), with A defaulting to 1 there
// and phase 0 entering elsewhere. The band is along the face's first tangential axis (x < y < z
// without the normal: y for an x face, x for y and z faces), the optional second pair along the other.
// An outflow face is inletOutlet-like: fluid leaves with its own alpha (the donor of the geometric
// flux is the cell inside), and where the flow comes back in (backflow) it brings -vof_bc_<face>_alpha
// (default 0: phase 0, the gas).
//
// How: the flux through a boundary face whose donor is outside the box is u dt/h times the entering
// fraction of that face's cell-sized patch, the exact phase-1 share of the slab it sweeps (the band is
// a prism along the normal, the flow's velocity is uniform over the face): no reconstruction is
// needed outside. Every other flux, the outgoing ones included, is the PLIC flux of the sweep
// (VofAdvect.cpp), so the volume in the box changes by exactly what crosses the open faces, plus the
// Weymouth-Yue dilatation term c_i dt div(u) that vanishes with the projection's divergence. The
// fluxes crossing open faces are summed per step (in and out separately, reduced over ranks once
// per step) and reported by Summarize; Save/Load carry the sums.
// The ghost layers beyond an inflow face hold the entering fraction (band cells their covered
// share), so Youngs' and the height-function normals and the curvature of the cells inside see the
// phase that is coming in; beyond an outflow face they stay zero-gradient (MirrorBoundary).
// Momentum (VofMomentum.cpp) takes the sweeps' phase-1 fluxes, these included: the mass entering is
// rho(A) u_in per unit area and time, the momentum it brings rho(A) u_in u_in (the tangential
// components' ghosts hold the inflow's value: InflowVelocityGhosts).
// The flow's ghost cells of density and viscosity beyond an inflow face (zero-gradient in
// FlowBoundary::FillCellGhosts) take the entering mixture through Flow::SetPropertyGhosts; they are
// read by the viscous stress of the face's edges (the normal velocity there is prescribed). Beyond an
// outflow face they stay zero-gradient: the density of the fluid leaving.
#include "vofdem/vof/Vof.hpp"
#include "vofdem/vof/GhostSlab.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/flow/Flow.hpp"
#include "vofdem/flow/FlowBoundary.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace vofdem {

namespace {

// The face's tangential axes in the order the band gives them.
void TangentialAxes(int d, int t[2]) {
  t[0] = d == 0 ? 1 : 0;
  t[1] = d == 2 ? 1 : 2;
}

}  // namespace

PetscErrorCode Vof::ReadOpenFaceOptions(OptionReader &opt) {
  PetscFunctionBeginUser;
  const MPI_Comm comm = grid_->Comm();
  for (int f = 0; f < 6; ++f) {
    const std::string base = std::string("-bc_") + FlowBoundary::FaceName(f);
    PetscBool         given = PETSC_FALSE, bandGiven = PETSC_FALSE;
    openAlpha_[f]           = 0;
    PetscCall(opt.Real((base + "_alpha").c_str(),
                       "Fraction of phase 1 in the fluid entering through this face: at an inflow face what the inflow brings (default 0, phase 0), at an outflow face what backflow brings "
                       "(default 0); fluid leaving takes its own alpha",
                       "-", &openAlpha_[f], RealRange::Closed(0, 1), &given));
    openAlphaGiven_[f] = given;
    openBand_[f].clear();
    PetscCall(opt.RealList((base + "_alpha_band").c_str(),
                           "Inflow face: phase 1 (-vof_bc_<face>_alpha, default 1 with a band) enters only through lo,hi along the face's first tangential axis (x<y<z without "
                           "the normal), optionally lo2,hi2 along the second; phase 0 elsewhere",
                           "m", &openBand_[f], 4, RealRange::Any(), &bandGiven));
    if (!bandGiven) continue;
    const std::vector<PetscReal> &b = openBand_[f];
    if (b.size() != 2 && b.size() != 4)
      VofdemInputError(comm, "option -vof_bc_%s_alpha_band: give lo,hi or lo,hi,lo2,hi2 (m), got %d numbers", FlowBoundary::FaceName(f), (int)b.size());
    for (size_t k = 0; k < b.size(); k += 2)
      if (!(b[k] < b[k + 1])) VofdemInputError(comm, "option -vof_bc_%s_alpha_band: lo %g must be below hi %g", FlowBoundary::FaceName(f), (double)b[k], (double)b[k + 1]);
    if (!given) openAlpha_[f] = 1;  // a band of liquid in phase 0
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::CheckOpenFaces(const Flow &flow) {
  PetscFunctionBeginUser;
  const MPI_Comm comm = grid_->Comm();
  for (int f = 0; f < 6; ++f) {
    const FlowBoundaryType t = flow.Boundary().Face(f).type;
    openType_[f]             = t == FlowBoundaryType::Inflow ? 1 : t == FlowBoundaryType::Outflow ? 2 : 0;
    const char *name         = FlowBoundary::FaceName(f);
    if (!openType_[f] && (openAlphaGiven_[f] || !openBand_[f].empty()))
      VofdemInputError(comm, "option -vof_bc_%s_alpha%s: face %s is %s (-flow_bc_%s); only inflow and outflow faces let a phase in", name, openAlphaGiven_[f] ? "" : "_band", name,
                       FlowBoundary::TypeName(t), name);
    if (openType_[f] == 2 && !openBand_[f].empty())
      VofdemInputError(comm, "option -vof_bc_%s_alpha_band: face %s is outflow; a band is for an inflow face (backflow takes -vof_bc_%s_alpha)", name, name, name);
  }
  PetscFunctionReturn(0);
}

bool Vof::HasOpenFaces() const {
  for (int t : openType_)
    if (t) return true;
  return false;
}

double Vof::EnteringFraction(int face, const PetscInt q[3]) const {
  const std::vector<PetscReal> &b = openBand_[face];
  if (openType_[face] != 1 || b.empty()) return openAlpha_[face];
  int t[2];
  TangentialAxes(face / 2, t);
  const PetscReal *lo = grid_->Lower(), *h = grid_->Spacing();
  const PetscInt  *N  = grid_->Cells();
  double           frac = openAlpha_[face];
  for (size_t k = 0; 2 * k < b.size(); ++k) {
    const int e = t[k];
    PetscInt  i = q[e];  // a ghost index beyond a side face: the cell it mirrors (zero gradient) or wraps to
    i           = grid_->Periodic(e) ? ((i % N[e]) + N[e]) % N[e] : std::min(std::max(i, (PetscInt)0), N[e] - 1);
    const double x0 = lo[e] + i * h[e], x1 = lo[e] + (i + 1) * h[e];
    if (b[2 * k] <= x0 && x1 <= b[2 * k + 1]) continue;  // covered: exactly the band's alpha
    frac *= std::max(0.0, std::min(x1, (double)b[2 * k + 1]) - std::max(x0, (double)b[2 * k])) / h[e];
  }
  return frac;
}

int Vof::OpenDonorFace(int d, const PetscInt q[3], PetscReal vel) const {
  if (grid_->Periodic(d)) return -1;
  const int f = q[d] == 0 && vel > 0 ? 2 * d : q[d] == grid_->Cells()[d] && vel < 0 ? 2 * d + 1 : -1;
  return f >= 0 && openType_[f] ? f : -1;
}

PetscErrorCode Vof::OpenFaceGhosts(Vec local) const {
  PetscScalar ***a;
  PetscInt       gs[3], gm[3];

  PetscFunctionBeginUser;
  bool any = false;
  for (int f = 0; f < 6; ++f) any = any || openType_[f] == 1;
  if (!any) PetscFunctionReturn(0);
  PetscCall(DMDAGetGhostCorners(da_, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  PetscCall(DMDAVecGetArray(da_, local, &a));
  const PetscInt *N = grid_->Cells();
  for (int f = 0; f < 6; ++f) {
    if (openType_[f] != 1) continue;
    PetscInt lo[3], hi[3];
    GhostSlabBeyondFace(f, gs, gm, N, lo, hi);
    for (PetscInt k = lo[2]; k < hi[2]; ++k)
      for (PetscInt j = lo[1]; j < hi[1]; ++j)
        for (PetscInt i = lo[0]; i < hi[0]; ++i) {
          const PetscInt q[3] = {i, j, k};
          a[k][j][i]          = EnteringFraction(f, q);
        }
  }
  PetscCall(DMDAVecRestoreArray(da_, local, &a));
  PetscFunctionReturn(0);
}

// The flow's density and viscosity ghosts beyond inflow faces: the mixture of the entering fraction
// (as UpdateProperties mixes them), times the ghost's eps (zero-gradient, the flow's).
PetscErrorCode Vof::InflowPropertyGhosts(const void *ctx, const Flow &flow, Vec epsLocal, Vec emLocal, Vec betaLocal) {
  const Vof           &v  = *static_cast<const Vof *>(ctx);
  const StaggeredGrid &sg = flow.Staggered();
  LocalField           e, m, b;
  PetscInt             gs[3], gm[3];

  PetscFunctionBeginUser;
  const PetscReal rho0 = flow.ReferenceDensity(), mu0 = flow.ReferenceViscosity();
  const PetscInt *N = v.grid_->Cells();
  PetscCall(DMDAGetGhostCorners(sg.Cells(), &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  PetscCall(sg.GetLocal(3, epsLocal, &e));
  PetscCall(sg.GetLocal(3, emLocal, &m));
  PetscCall(sg.GetLocal(3, betaLocal, &b));
  for (int f = 0; f < 6; ++f) {
    if (v.openType_[f] != 1) continue;
    PetscInt lo[3], hi[3];
    GhostSlabBeyondFace(f, gs, gm, N, lo, hi);
    for (PetscInt k = lo[2]; k < hi[2]; ++k)
      for (PetscInt j = lo[1]; j < hi[1]; ++j)
        for (PetscInt i = lo[0]; i < hi[0]; ++i) {
          const PetscInt  q[3] = {i, j, k};
          const PetscReal a = v.EnteringFraction(f, q), eps = PetscRealPart(e.at(q));
          m.at(q)              = eps * (a * v.viscosity_ + (1 - a) * mu0);
          b.at(q)              = eps / (a * v.density_ + (1 - a) * rho0);
        }
  }
  PetscCall(sg.RestoreLocal(3, betaLocal, &b));
  PetscCall(sg.RestoreLocal(3, emLocal, &m));
  PetscCall(sg.RestoreLocal(3, epsLocal, &e));
  PetscFunctionReturn(0);
}

// The face value the momentum sweep takes upwind of an inflow face is the first ghost's: for a
// tangential component the flow's ghost is the reflection 2 v_in - v_inside (its viscous stress needs
// that), which would bring in minus the velocity inside; the fluid coming in has v_in. So the
// transported copy's ghost layers beyond an inflow face hold v_in (the normal component's already hold
// the inflow velocity). Only with open faces, on the VOF's private copy of the velocity.
PetscErrorCode Vof::InflowVelocityGhosts(const Flow &flow, int c, Vec local) const {
  LocalField u;
  PetscInt   gs[3], gm[3];

  PetscFunctionBeginUser;
  bool any = false;
  for (int f = 0; f < 6; ++f) any = any || (openType_[f] == 1 && f / 2 != c);
  if (!any) PetscFunctionReturn(0);
  const StaggeredGrid &sg = *sg_;
  const FlowBoundary  &bc = flow.Boundary();
  const PetscReal     *lo = grid_->Lower(), *h = grid_->Spacing();
  PetscCall(DMDAGetGhostCorners(sg.Face(c), &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  PetscCall(sg.GetLocal(c, local, &u));
  for (int f = 0; f < 6; ++f) {
    const int d = f / 2;
    if (openType_[f] != 1 || d == c) continue;
    const PetscInt last = sg.Points(c, d) - 1;  // c's points along d are cells (d != c): 0 .. N_d - 1
    PetscInt       a[3] = {gs[0], gs[1], gs[2]}, b[3] = {gs[0] + gm[0], gs[1] + gm[1], gs[2] + gm[2]};
    if (f % 2 == 0) b[d] = std::min(b[d], (PetscInt)0);
    else a[d] = std::max(a[d], last + 1);
    for (PetscInt k = a[2]; k < b[2]; ++k)
      for (PetscInt j = a[1]; j < b[1]; ++j)
        for (PetscInt i = a[0]; i < b[0]; ++i) {
          const PetscInt q[3] = {i, j, k};
          PetscReal      x[3];
          for (int e = 0; e < 3; ++e) x[e] = lo[e] + (e == c ? q[e] : q[e] + 0.5) * h[e];
          x[d]    = f % 2 ? grid_->Upper()[d] : lo[d];  // on the face (a parabolic profile's value there)
          u.at(q) = bc.Prescribed(f, c, x);
        }
  }
  PetscCall(sg.RestoreLocal(c, local, &u));
  PetscFunctionReturn(0);
}

// The sums in and out are global (reduced every step), so rank 0 writes them and every rank reads them.
PetscErrorCode Vof::SaveOpenFaces(PetscViewer viewer) const {
  Vec         v;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(grid_->Comm(), &rank));
  PetscCall(VecCreateMPI(grid_->Comm(), rank == 0 ? 2 : 0, 2, &v));
  PetscCall(PetscObjectSetName((PetscObject)v, "vof_open_face_volumes"));
  if (rank == 0) {
    PetscCall(VecSetValue(v, 0, openVolume_[0], INSERT_VALUES));
    PetscCall(VecSetValue(v, 1, openVolume_[1], INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(v));
  PetscCall(VecAssemblyEnd(v));
  PetscCall(VecView(v, viewer));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::LoadOpenFaces(PetscViewer viewer) {
  Vec         v;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(grid_->Comm(), &rank));
  PetscCall(VecCreateMPI(grid_->Comm(), rank == 0 ? 2 : 0, 2, &v));
  PetscCall(PetscObjectSetName((PetscObject)v, "vof_open_face_volumes"));
  PetscCall(VecLoad(v, viewer));
  if (rank == 0) {
    const PetscScalar *a;
    PetscCall(VecGetArrayRead(v, &a));
    for (int k = 0; k < 2; ++k) openVolume_[k] = PetscRealPart(a[k]);
    PetscCall(VecRestoreArrayRead(v, &a));
  }
  PetscCallMPI(MPI_Bcast(openVolume_, 2, MPIU_REAL, 0, grid_->Comm()));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
