// Set-up, initial fraction, ghost layers, time-step limit and summaries of the VOF module (Vof.hpp).
#include "vofdem/vof/Vof.hpp"
#include "vofdem/vof/GhostSlab.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/flow/FlowBoundary.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace vofdem {

PetscErrorCode Vof::SetFromOptions(const Grid &grid) {
  PetscFunctionBeginUser;
  grid_ = &grid;
  PetscOptionsBegin(grid.Comm(), "vof_", "VOF: volume fraction alpha of the heavy phase, PLIC, split geometric advection (docs/physics.md F1b, F4)", "Vof");
  {
    OptionReader             opt(PetscOptionsObject);
    auto name = [](VofNormals v) { return std::string(v == VofNormals::Height ? "height" : v == VofNormals::Elvira ? "elvira" : "youngs"); };
    auto kind = [](const std::string &v) { return v == "height" ? VofNormals::Height : v == "elvira" ? VofNormals::Elvira : VofNormals::Youngs; };
    std::vector<std::string> nm = {name(normals_)}, fb = {name(fallback_)};
    PetscCall(opt.NameList("-normals",
                           "Interface normals: height (height functions, second order where a 7-cell column is a clean transition, else -vof_height_fallback), elvira (ELVIRA: the best of 27 "
                           "column-difference planes over the 3x3x3 block) or youngs (gradient of alpha)",
                           {"height", "elvira", "youngs"}, &nm));
    if (nm.size() != 1) VofdemInputError(grid.Comm(), "option -vof_normals: give one method (height, elvira or youngs)");
    normals_ = kind(nm[0]);
    PetscCall(opt.NameList("-height_fallback", "With -vof_normals height: the normals where no 7-cell column is a clean transition (thin filaments, corners)", {"elvira", "youngs"}, &fb));
    if (fb.size() != 1) VofdemInputError(grid.Comm(), "option -vof_height_fallback: give one method (elvira or youngs)");
    fallback_ = kind(fb[0]);
    PetscCall(opt.Real("-density", "Density of phase 1 (alpha = 1, the heavy phase); phase 0 has -flow_density", "kg/m^3", &density_, RealRange::Positive()));
    PetscCall(opt.Real("-viscosity", "Dynamic viscosity of phase 1; phase 0 has -flow_viscosity", "Pa s", &viscosity_, RealRange::Positive()));
    PetscCall(opt.Real("-surface_tension", "Surface tension coefficient sigma (0: none); height-function curvature, balanced-force face force", "N/m", &sigma_, RealRange::NonNegative()));
    PetscCall(opt.Real("-dsigma_dT", "Temperature coefficient of the surface tension (Marangoni force, docs/physics.md F2)", "N/(m K)", &dsigmadT_));
    PetscBool gradSet = PETSC_FALSE;
    PetscCall(opt.RealVector("-temperature_gradient", "Prescribed uniform temperature gradient (T = T0 + G.(x - lower corner), sigma holding at T0) for the Marangoni force without the energy module",
                             "K/m", gradT_, 3, RealRange::Any(), &gradSet));
    gradTGiven_ = gradSet;
    std::vector<std::string> scaling = {"density"};
    PetscCall(opt.NameList("-marangoni_scaling", "Marangoni force per face: density (times 2 rho_f/(rho_1 + rho_0): on the heavy side of the smeared interface, its sum unchanged) or none",
                           {"density", "none"}, &scaling));
    if (scaling.size() != 1) VofdemInputError(grid.Comm(), "option -vof_marangoni_scaling: give one of density, none");
    marangoniScaling_ = scaling[0] == "density" ? 1 : 0;
    PetscCall(opt.Real("-surface_tension_temperature", "With the energy module: the temperature at which -vof_surface_tension holds (sigma(T) = sigma + dsigma/dT (T - this))", "K",
                       &sigmaTemperature_, RealRange::Any()));
    std::vector<std::string> mom = {momentum_ == VofMomentum::Consistent ? "consistent" : "advective"};
    PetscCall(opt.NameList("-momentum",
                           "Momentum transport: consistent (rho u moved with the mass fluxes of the VOF sweeps, stable at large density ratios) or advective (the flow's -(U.grad)U, for comparison)",
                           {"consistent", "advective"}, &mom));
    if (mom.size() != 1) VofdemInputError(grid.Comm(), "option -vof_momentum: give one method (consistent or advective)");
    momentum_ = mom[0] == "consistent" ? VofMomentum::Consistent : VofMomentum::Advective;
    PetscCall(opt.Bool("-advect", "Move the interface with the flow (0: a frozen interface, for verification)", &advect_));
    PetscCall(opt.RealList("-boxes", "Phase 1 at the start: boxes x0,y0,z0,x1,y1,z1[,...]", "m", &boxes_, 6 * 64));
    PetscCall(opt.RealList("-spheres", "Phase 1 at the start: spheres cx,cy,cz,r[,...]", "m", &spheres_, 4 * 64));
    PetscCall(opt.Int("-init_samples", "Sample points per cell and direction for the initial fraction of -vof_boxes/-vof_spheres", &samples_, 1, 64));
    if (boxes_.size() % 6) VofdemInputError(grid.Comm(), "option -vof_boxes: give 6 numbers per box (x0,y0,z0,x1,y1,z1), got %d", (int)boxes_.size());
    if (spheres_.size() % 4) VofdemInputError(grid.Comm(), "option -vof_spheres: give 4 numbers per sphere (cx,cy,cz,r), got %d", (int)spheres_.size());
    PetscCall(opt.Bool("-redistribute", "With particles (eps < 1): hand a cell's alpha above 1 or below 0 after the sweeps to its 26 neighbours in proportion to their room (their liquid), conserving eps alpha V (0: leave it)", &redistribute_));
    PetscCall(opt.Real("-cfl", "Courant number of each split sweep, max |u_d| dt / h_d; at most 1/2 keeps alpha in [0, 1] (Weymouth & Yue 2010)", "-", &cfl_,
                       RealRange::LeftOpen(0, 0.5)));
    PetscCall(ReadContactAngleOptions(opt));
    PetscCall(ReadOpenFaceOptions(opt));
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::SetUp(const StaggeredGrid &sg) {
  const PetscInt *l[3];
  PetscInt        m[3];

  PetscFunctionBeginUser;
  sg_ = &sg;
  DM cells = sg.Cells();
  PetscCall(DMDAGetInfo(cells, nullptr, nullptr, nullptr, nullptr, &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(DMDAGetOwnershipRanges(cells, &l[0], &l[1], &l[2]));
  const PetscInt width = 4;
  for (int d = 0; d < 3; ++d)
    for (PetscInt r = 0; r < m[d]; ++r)
      if ((grid_->Periodic(d) || m[d] > 1) && l[d][r] < width)  // PETSc's DMDA needs the ghost width within each rank's cells
        VofdemInputError(grid_->Comm(), "option -grid_cells: the VOF module needs at least %d cells per rank along a %s direction, but %c has %" PetscInt_FMT " cells on %" PetscInt_FMT " ranks (more cells, or -grid_ranks)",
                         (int)width, grid_->Periodic(d) ? "periodic" : "split", "xyz"[d], grid_->Cells()[d], m[d]);
  DMBoundaryType bt[3];
  for (int d = 0; d < 3; ++d) bt[d] = grid_->Periodic(d) ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_GHOSTED;
  const PetscInt *N = grid_->Cells();
  PetscCall(DMDACreate3d(grid_->Comm(), bt[0], bt[1], bt[2], DMDA_STENCIL_BOX, N[0], N[1], N[2], m[0], m[1], m[2], 1, width, l[0], l[1], l[2], &da_));
  PetscCall(DMSetUp(da_));
  PetscCall(DMCreateGlobalVector(da_, &alpha_));
  PetscCall(PetscObjectSetName((PetscObject)alpha_, "vof_alpha"));
  PetscCall(DMCreateLocalVector(da_, &alphaLocal_));
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMCreateLocalVector(sg.Face(d), &uLocal_[d]));
    PetscCall(DMCreateGlobalVector(sg.Face(d), &phaseFlux_[d]));
  }
  PetscInt s[3], n[3];
  PetscCall(DMDAGetCorners(da_, &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  fullAtStart_.assign((size_t)(n[0] * n[1] * n[2]), 0);
  if (temperature_) {  // the computed temperature (SetTemperature) replaces the prescribed one
    if (gradTGiven_)
      VofdemInputError(grid_->Comm(), "option -vof_temperature_gradient: the temperature comes from the energy module here; remove the prescribed gradient");
    if (dsigmadT_ != 0 && !(sigmaTemperature_ > 0))
      VofdemInputError(grid_->Comm(), "option -vof_surface_tension_temperature: with -vof_dsigma_dT and the energy module, give the temperature (K) at which -vof_surface_tension holds");
    PetscCall(DMCreateGlobalVector(da_, &tGlobal_));
    PetscCall(DMCreateLocalVector(da_, &tLocal_));
    PetscCall(VecDuplicate(tLocal_, &mLocal_));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::Destroy() {
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecDestroy(&uLocal_[d]));
    PetscCall(VecDestroy(&phaseFlux_[d]));
    PetscCall(VecDestroy(&massLocal_[d]));
    PetscCall(VecDestroy(&velocity_[d]));
    PetscCall(VecDestroy(&velocityLocal_[d]));
    PetscCall(VecDestroy(&momentumAcc_[d]));
  }
  for (Vec &v : contactGhost_) PetscCall(VecDestroy(&v));
  PetscCall(VecDestroy(&contactLocal_));
  PetscCall(VecDestroy(&kappa_));
  for (Vec *v : {&tGlobal_, &tLocal_, &mLocal_}) PetscCall(VecDestroy(v));
  PetscCall(VecDestroy(&kappaLocal_));
  PetscCall(VecDestroy(&alphaLocal_));
  PetscCall(VecDestroy(&alpha_));
  for (Vec *v : {&epsLocal_, &changeLocal_, &cellScratch_, &roomG_, &fillG_, &giveG_, &takeG_, &roomL_, &fillL_, &giveL_, &takeL_}) PetscCall(VecDestroy(v));
  PetscCall(DMDestroy(&da_));
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::SetFraction(Shape shape, void *ctx, const PetscInt samples[3], CellClass classify) {
  PetscScalar ***a;
  PetscInt       s[3], n[3];

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing(), *lo = grid_->Lower();
  PetscCall(DMDAGetCorners(da_, &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAVecGetArray(da_, alpha_, &a));
  const PetscReal total = (PetscReal)(samples[0] * samples[1] * samples[2]);
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscInt q[3] = {i, j, k};
        PetscInt       inside = 0;
        if (classify) {
          PetscReal cl[3], ch[3];
          for (int d = 0; d < 3; ++d) {
            cl[d] = lo[d] + q[d] * h[d];
            ch[d] = lo[d] + (q[d] + 1) * h[d];
          }
          const int c = classify(ctx, cl, ch);
          if (c >= 0) {
            a[k][j][i] = c;
            continue;
          }
        }
        for (PetscInt c = 0; c < samples[2]; ++c)
          for (PetscInt b = 0; b < samples[1]; ++b)
            for (PetscInt e = 0; e < samples[0]; ++e) {
              const PetscInt r[3] = {e, b, c};
              PetscReal      x[3];
              for (int d = 0; d < 3; ++d) x[d] = lo[d] + (q[d] + (r[d] + 0.5) / samples[d]) * h[d];
              inside += shape(ctx, x) < 0;
            }
        a[k][j][i] = inside / total;
      }
  PetscCall(DMDAVecRestoreArray(da_, alpha_, &a));
  PetscCall(FillGhosts());
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::FillGhosts() {
  PetscFunctionBeginUser;
  PetscCall(DMGlobalToLocal(da_, alpha_, INSERT_VALUES, alphaLocal_));
  PetscCall(MirrorBoundary(alphaLocal_));
  PetscCall(OpenFaceGhosts(alphaLocal_));      // nothing unless a face is inflow (VofOpenFaces.cpp)
  PetscCall(ContactAngleGhosts(alphaLocal_));  // nothing unless a face's angle is not 90 degrees
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::MirrorBoundary(Vec local) const {
  PetscScalar *a;
  PetscInt     gs[3], gm[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetGhostCorners(da_, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  PetscCall(VecGetArray(local, &a));
  const PetscInt *N = grid_->Cells();
  // Walls and open faces: zero normal gradient (a 90 degree contact angle); direction by direction
  // over the whole ghosted extent, so edges and corners come out consistent. Rows along x are copied
  // whole where the mirror is across y or z (the ghost layers are 4 deep: with 2 cells across, as in
  // the quasi-2-D dam break, they are most of the array).
  auto row = [&](PetscInt j, PetscInt k) { return (size_t)((j - gs[1]) + gm[1] * (k - gs[2])) * (size_t)gm[0]; };
  for (int d = 0; d < 3; ++d) {
    if (grid_->Periodic(d)) continue;
    for (int side = 0; side < 2; ++side) {  // only the layers outside the box, where this rank has them
      PetscInt lo[3], hi[3];
      GhostSlabBeyondFace(2 * d + side, gs, gm, N, lo, hi);
      const PetscInt src = side == 0 ? 0 : N[d] - 1;
      for (PetscInt k = lo[2]; k < hi[2]; ++k)
        for (PetscInt j = lo[1]; j < hi[1]; ++j) {
          PetscScalar *dst = a + row(j, k) - gs[0];
          if (d == 0) {
            for (PetscInt i = lo[0]; i < hi[0]; ++i) dst[i] = dst[src];
          } else if (hi[0] > lo[0]) {
            const PetscScalar *from = a + (d == 1 ? row(src, k) : row(j, src)) - gs[0];
            std::memcpy(dst + lo[0], from + lo[0], (size_t)(hi[0] - lo[0]) * sizeof(PetscScalar));
          }
        }
    }
  }
  PetscCall(VecRestoreArray(local, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::StableTimeStep(Vec const u[3], PetscReal *dt, std::string *basis) const {
  PetscReal rate = 0;

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing();
  for (int d = 0; d < 3; ++d) {
    PetscReal mx;
    PetscCall(VecNorm(u[d], NORM_INFINITY, &mx));
    rate = std::max(rate, mx / h[d]);
  }
  *dt = rate > 0 ? cfl_ / rate : PETSC_MAX_REAL;
  if (basis) *basis = "VOF sweep Courant number (-vof_cfl)";
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::Summarize(VofSummary *out) const {
  const PetscScalar *a;
  PetscInt           n;

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing();
  const PetscScalar *e = nullptr;
  PetscCall(VecGetLocalSize(alpha_, &n));
  PetscCall(VecGetArrayRead(alpha_, &a));
  if (eps_) PetscCall(VecGetArrayRead(eps_, &e));  // the same layout as alpha (F1b: volumes are eps alpha V)
  PetscReal sum = 0, mn = PETSC_MAX_REAL, mx = PETSC_MIN_REAL, cells = 0, other = 0;
  for (PetscInt i = 0; i < n; ++i) {
    const PetscReal v = PetscRealPart(a[i]), f = e ? PetscRealPart(e[i]) : 1;
    sum += e ? f * v : v;
    other += f * (1 - v);
    mn = std::min(mn, v);
    mx = std::max(mx, v);
    cells += v > tiny_ && v < 1 - tiny_;  // not round-off off full or empty
  }
  if (eps_) PetscCall(VecRestoreArrayRead(eps_, &e));
  PetscCall(VecRestoreArrayRead(alpha_, &a));
  PetscReal loc[3] = {sum, cells, other}, glob[3], lmax[3] = {-mn, mx, boundViolation_}, gmax[3];
  PetscCallMPI(MPI_Allreduce(loc, glob, 3, MPIU_REAL, MPIU_SUM, grid_->Comm()));
  PetscCallMPI(MPI_Allreduce(lmax, gmax, 3, MPIU_REAL, MPI_MAX, grid_->Comm()));
  out->volume         = glob[0] * h[0] * h[1] * h[2];
  out->interfaceCells = glob[1];
  out->otherVolume    = glob[2] * h[0] * h[1] * h[2];
  out->minAlpha       = -gmax[0];
  out->maxAlpha       = gmax[1];
  out->boundViolation = std::max({gmax[2], gmax[0], gmax[1] - 1, (PetscReal)0});
  out->heightNormals  = heightShare_;  // already global (Advect)
  out->missingCurvature = missingCurvature_;
  out->openFaces        = HasOpenFaces();
  out->inflowVolume     = openVolume_[0];  // already global (Advect)
  out->outflowVolume    = openVolume_[1];
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::Save(PetscViewer viewer) const {
  Vec         scalars;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCall(VecView(alpha_, viewer));
  PetscReal bound;  // each rank holds its own; the file holds the largest
  PetscCallMPI(MPI_Allreduce(&boundViolation_, &bound, 1, MPIU_REAL, MPI_MAX, grid_->Comm()));
  PetscCallMPI(MPI_Comm_rank(grid_->Comm(), &rank));
  PetscCall(VecCreateMPI(grid_->Comm(), rank == 0 ? 3 : 0, 3, &scalars));
  PetscCall(PetscObjectSetName((PetscObject)scalars, "vof_scheme_state"));
  if (rank == 0) {
    PetscCall(VecSetValue(scalars, 0, (PetscScalar)steps_, INSERT_VALUES));
    PetscCall(VecSetValue(scalars, 1, bound, INSERT_VALUES));
    PetscCall(VecSetValue(scalars, 2, heightShare_, INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(scalars));
  PetscCall(VecAssemblyEnd(scalars));
  PetscCall(VecView(scalars, viewer));
  PetscCall(VecDestroy(&scalars));
  if (HasOpenFaces()) PetscCall(SaveOpenFaces(viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::Load(PetscViewer viewer) {
  Vec         scalars;
  PetscMPIInt rank;
  PetscReal   s[3] = {0, 0, 0};

  PetscFunctionBeginUser;
  PetscCall(VecLoad(alpha_, viewer));
  PetscCallMPI(MPI_Comm_rank(grid_->Comm(), &rank));
  PetscCall(VecCreateMPI(grid_->Comm(), rank == 0 ? 3 : 0, 3, &scalars));
  PetscCall(PetscObjectSetName((PetscObject)scalars, "vof_scheme_state"));
  PetscCall(VecLoad(scalars, viewer));
  if (rank == 0) {
    const PetscScalar *a;
    PetscCall(VecGetArrayRead(scalars, &a));
    for (int k = 0; k < 3; ++k) s[k] = PetscRealPart(a[k]);
    PetscCall(VecRestoreArrayRead(scalars, &a));
  }
  PetscCallMPI(MPI_Bcast(s, 3, MPIU_REAL, 0, grid_->Comm()));
  PetscCall(VecDestroy(&scalars));
  steps_          = (PetscInt)s[0];
  boundViolation_ = s[1];  // the largest seen on any rank: a bound, the same on every rank count
  heightShare_    = s[2];
  if (HasOpenFaces()) PetscCall(LoadOpenFaces(viewer));
  PetscCall(FillGhosts());
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "vof: PLIC with %s normals, split geometric advection (Weymouth & Yue), sweep Courant number <= %g; phase 1 density %g kg/m^3, viscosity %g Pa s; surface tension %g N/m; %s momentum transport; %d box(es), %d sphere(s) of phase 1 at the start\n",
                                   normals_ == VofNormals::Youngs ? "Youngs" : normals_ == VofNormals::Elvira ? "ELVIRA" : fallback_ == VofNormals::Elvira ? "height-function (ELVIRA fallback)" : "height-function (Youngs fallback)", (double)cfl_, (double)density_, (double)viscosity_, (double)sigma_,
                                   momentum_ == VofMomentum::Consistent ? "mass-consistent" : "advective (non-conservative)", (int)(boxes_.size() / 6), (int)(spheres_.size() / 4)));
  for (int f = 0; f < 6; ++f)
    if (contactAngle_[f] != 90) PetscCall(PetscViewerASCIIPrintf(viewer, "vof: contact angle %g degrees (through phase 1) on face %s\n", (double)contactAngle_[f], FlowBoundary::FaceName(f)));
  for (int f = 0; f < 6; ++f) {
    if (openType_[f] == 1 && openBand_[f].empty())
      PetscCall(PetscViewerASCIIPrintf(viewer, "vof: inflow face %s brings phase 1 at fraction %g\n", FlowBoundary::FaceName(f), (double)openAlpha_[f]));
    else if (openType_[f] == 1)
      PetscCall(PetscViewerASCIIPrintf(viewer, "vof: inflow face %s brings phase 1 at fraction %g through the band %g..%g m%s, phase 0 elsewhere\n", FlowBoundary::FaceName(f),
                                       (double)openAlpha_[f], (double)openBand_[f][0], (double)openBand_[f][1], openBand_[f].size() == 4 ? " (and a second band along the other axis)" : ""));
    else if (openType_[f] == 2)
      PetscCall(PetscViewerASCIIPrintf(viewer, "vof: outflow face %s: fluid leaves with its own alpha, backflow brings fraction %g\n", FlowBoundary::FaceName(f), (double)openAlpha_[f]));
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
