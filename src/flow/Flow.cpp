#include "vofdem/flow/Flow.hpp"

#include "vofdem/io/XdmfCheckpoint.hpp"
#include "vofdem/grid/FaceProperties.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"

#include <petscviewerhdf5.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vofdem {

namespace {

const std::vector<std::string> &LimiterNames() {
  static const std::vector<std::string> names = {"upwind", "central", "minmod", "vanleer", "mc", "superbee", "koren"};
  return names;
}

}  // namespace

PetscErrorCode Flow::SetFromOptions(const Grid &grid) {
  PetscFunctionBeginUser;
  grid_         = &grid;
  MPI_Comm comm = grid.Comm();
  PetscOptionsBegin(comm, "flow_", "Flow: incompressible volume-averaged Navier-Stokes (docs/physics.md F1, F2)", "Flow");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.Real("-density", "Fluid density (uniform; the VOF module makes it a field)", "kg/m^3", &density_, RealRange::Positive()));
    PetscCall(opt.Real("-viscosity", "Dynamic viscosity (uniform)", "Pa s", &viscosity_, RealRange::Positive()));
    PetscCall(opt.RealVector("-initial_velocity", "Uniform initial velocity x,y,z", "m/s", velocity0_, 3));
    PetscCall(opt.Real("-cfl", "Convective Courant number of the time step: dt = cfl / max(|u|/hx + |v|/hy + |w|/hz); AB2 advection (upwind at extrema) is neutral at 0.5 and unstable above. With the VOF's mass-consistent momentum: dt = cfl / max over directions of max|u_d|/h_d", "-", &cfl_, RealRange::LeftOpen(0, 0.5)));
    std::vector<std::string> cm = {"cell"};
    PetscCall(opt.NameList("-courant", "How -flow_cfl measures the velocity: cell (per cell the faster of its two faces per direction, summed, the largest cell) or box (the box's largest |u_d| per direction, summed; never a longer step)",
                           {"cell", "box"}, &cm));
    if (cm.size() != 1) VofdemInputError(comm, "option -flow_courant: give cell or box");
    courant_ = cm[0] == "cell" ? CourantMeasure::Cell : CourantMeasure::Box;
    std::vector<std::string> lim = {limiterName_};
    PetscCall(opt.NameList("-advection", "Advection scheme: TVD limiter minmod, vanleer, mc, superbee, koren (bounded, second order), central (unbounded), upwind (first order)",
                           LimiterNames(), &lim));
    if (lim.size() != 1) VofdemInputError(comm, "option -flow_advection: give one scheme");
    limiterName_ = lim[0];
    const auto &names = LimiterNames();
    limiter_ = (Limiter)(std::find(names.begin(), names.end(), lim[0]) - names.begin());
    std::vector<std::string> visc = {"implicit"};
    PetscCall(opt.NameList("-viscous", "Viscous term: implicit (Crank-Nicolson, KSP prefix flow_viscous_) or explicit (Adams-Bashforth, viscous time-step limit)",
                           {"implicit", "explicit"}, &visc));
    if (visc.size() != 1) VofdemInputError(comm, "option -flow_viscous: give implicit or explicit");
    implicitViscosity_ = visc[0] == "implicit" ? PETSC_TRUE : PETSC_FALSE;
    std::vector<std::string> trans = {"auto"};
    PetscCall(opt.NameList("-viscous_transpose",
                           "The transpose viscous term div(mu grad U^T), non-zero where eps mu varies: explicit (in AB2; it then limits the step, FlowViscousLimit.cpp), "
                           "implicit (with -flow_viscous implicit: the three components in one Crank-Nicolson solve, KSP prefix flow_viscous_coupled_, no limit) "
                           "or auto (implicit while the viscosity itself is not uniform, two phases; explicit otherwise)",
                           {"explicit", "implicit", "auto"}, &trans));
    if (trans.size() != 1) VofdemInputError(comm, "option -flow_viscous_transpose: give explicit, implicit or auto");
    transposeMode_ = trans[0] == "implicit" ? TransposeMode::Implicit : trans[0] == "explicit" ? TransposeMode::Explicit : TransposeMode::Auto;
    if (transposeMode_ == TransposeMode::Implicit && !implicitViscosity_) VofdemInputError(comm, "option -flow_viscous_transpose implicit: needs -flow_viscous implicit");
    PetscCall(opt.String("-profile_output", "CSV file for the velocity along the three lines through the box centre at the end of the run (default: none)", &profilePath_));
    PetscCall(opt.Int("-output_every", "Write the grid fields (XDMF + HDF5, flow.xmf in -output_dir: cell-centred velocity, pressure, density) every this many steps (0: never)",
                      &outputEvery_, 0));
  }
  PetscOptionsEnd();
  PetscCall(bc_.SetFromOptions(grid));
  PetscCall(solid_.SetFromOptions(grid));
  // The projection's boundaries follow from the velocity's: an outflow face fixes the pressure
  // (the increment phi is 0 there), every other face fixes the normal velocity (Neumann).
  PetscCall(pressure_.Create(grid));
  for (int f = 0; f < 6; ++f) {
    const FlowBoundaryType t = bc_.Face(f).type;
    if (t != FlowBoundaryType::Periodic) PetscCall(pressure_.SetBoundary(f, t == FlowBoundaryType::Outflow ? PressureBoundary::Dirichlet : PressureBoundary::Neumann, 0));
  }
  // hypre's structured PFMG was 6x faster than tuned BoomerAMG on these grids (docs/petsc-notes.md)
  // but wants even cell counts: it is the default where every count is even, or one across z (a 2-D case:
  // 1.3x faster on the rising bubble at h = 1/80, the same digits; not one across x or y, which the
  // hyprestruct matrix cannot take, PressureSolver.cpp).
  bool even = true;
  for (int d = 0; d < 3; ++d) even = even && (grid.Cells()[d] % 2 == 0 || (d == 2 && grid.Cells()[d] == 1));
  pressure_.SetPreconditioner(even ? PressurePreconditioner::PFMG : PressurePreconditioner::BoomerAMG);
  PetscCall(pressure_.SetFromOptions());
  for (int f = 0; f < 6; ++f) {
    const FlowBoundaryType t    = bc_.Face(f).type;
    const PressureBoundary want = t == FlowBoundaryType::Periodic ? PressureBoundary::Periodic
                                : t == FlowBoundaryType::Outflow  ? PressureBoundary::Dirichlet : PressureBoundary::Neumann;
    if (pressure_.BoundaryType(f) != want || pressure_.BoundaryValue(f) != 0)
      VofdemInputError(comm, "option -flow_pressure_bc_%s: with -physics flow the pressure boundaries follow -flow_bc_%s (%s); do not set them", PressureSolver::FaceName(f),
                       FlowBoundary::FaceName(f), FlowBoundary::TypeName(t));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::SetUp(const PetscReal gravity[3]) {
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) gravity_[d] = gravity[d];
  PetscCall(sg_.Create(*grid_));
  PetscCall(solid_.SetUp(sg_));
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMCreateGlobalVector(sg_.Face(d), &u_[d]));
    PetscCall(DMCreateLocalVector(sg_.Face(d), &uLocal_[d]));
    PetscCall(VecDuplicate(u_[d], &H_[d]));
    PetscCall(VecDuplicate(u_[d], &Hold_[d]));
    PetscCall(VecDuplicate(u_[d], &L_[d]));
    PetscCall(VecDuplicate(u_[d], &rhsFace_[d]));
    PetscCall(VecSet(u_[d], velocity0_[d]));
    PetscCall(bc_.ApplyNormal(sg_, d, u_[d]));
    PetscCall(ZeroBlocked(d, u_[d]));
    PetscCall(PetscObjectSetName((PetscObject)u_[d], d == 0 ? "flow_u" : d == 1 ? "flow_v" : "flow_w"));
    // Both: Step swaps H_ and Hold_, and an HDF5 Save must write Hold_ under the name Load reads.
    for (Vec v : {H_[d], Hold_[d]}) PetscCall(PetscObjectSetName((PetscObject)v, d == 0 ? "flow_explicit_u" : d == 1 ? "flow_explicit_v" : "flow_explicit_w"));
  }
  DM c = sg_.Cells();
  for (Vec *v : {&rho_, &mu_, &eps_, &p_, &phi_, &beta_, &divRhs_}) PetscCall(DMCreateGlobalVector(c, v));
  for (Vec *v : {&epsLocal_, &betaLocal_, &emLocal_, &pLocal_, &phiLocal_}) PetscCall(DMCreateLocalVector(c, v));
  PetscCall(PetscObjectSetName((PetscObject)rho_, "flow_density"));
  PetscCall(PetscObjectSetName((PetscObject)mu_, "flow_viscosity"));
  PetscCall(PetscObjectSetName((PetscObject)eps_, "flow_fluid_fraction"));
  PetscCall(PetscObjectSetName((PetscObject)p_, "flow_pressure"));
  PetscCall(PetscObjectSetName((PetscObject)phi_, "flow_pressure_increment"));
  PetscCall(VecSet(rho_, density_));
  PetscCall(VecSet(mu_, viscosity_));
  PetscCall(VecSet(eps_, 1));
  bc_.SetFluidFraction(eps_);  // inflows are superficial velocities (FlowBoundary::ApplyNormal)
  PetscCall(VecSet(p_, 0));
  PetscCall(VecSet(phi_, 0));
  for (int f = 0; f < 6; ++f)
    if (bc_.Face(f).type == FlowBoundaryType::Outflow) PetscCall(VecSet(p_, bc_.Face(f).pressure));  // the level; see View
  // The previous increment is the initial guess of the next solve. It can be far larger than the
  // next rhs (the first step of a still tank puts the whole hydrostatic pressure into it), which
  // PETSc's default divergence test (1e4 ||b||) would take for divergence before iterating.
  {
    PetscBool given;
    PetscCall(PetscOptionsHasName(nullptr, "flow_pressure_", "-ksp_divtol", &given));
    if (!given) PetscCall(PetscOptionsSetValue(nullptr, "-flow_pressure_ksp_divtol", "1e300"));
    PetscCall(PetscOptionsHasName(nullptr, "flow_pressure_", "-ksp_atol", &userPressureAtol_));
  }
  if (solid_.Any()) PetscCall(pressure_.SetSolid(solid_.Cells()));
  PetscCall(pressure_.SetUp());
  if (implicitViscosity_) {
    PetscCall(viscous_.Create(sg_, bc_));
    viscous_.SetSolid(&solid_);
    PetscCall(viscous_.SetFromOptions());
    if (transposeMode_ != TransposeMode::Explicit) PetscCall(CoupledSetUp());
  }
  PetscCall(PetscLogEventRegister("FlowExplicit", DM_CLASSID, &evExplicit_));
  PetscCall(PetscLogEventRegister("FlowPredict", DM_CLASSID, &evPredict_));
  PetscCall(PetscLogEventRegister("FlowProject", DM_CLASSID, &evProject_));
  PetscCall(PetscLogEventRegister("FlowGhosts", DM_CLASSID, &evGhosts_));
  PetscCall(PetscLogEventRegister("FlowViscousAsm", DM_CLASSID, &evViscousAssemble_));
  PetscCall(UpdateLocals(true));  // the monitor reads the ghosted fields before the first step
  PetscFunctionReturn(0);
}

// The pressure that balances gravity (-div((eps/rho) G p) = -div(eps g)): the incremental scheme
// starts from it, so that a fluid at rest stays at rest instead of being kicked by the whole
// hydrostatic pressure arriving as the first increment (which also stirs the fluid near side walls
// through the viscous step). Done by the first Step, with the density of that moment; not after Load
// (the loaded pressure is the run's), so that a restart builds its preconditioner as the run did.
PetscErrorCode Flow::InitialPressure() {
  const PetscReal g2 = gravity_[0] * gravity_[0] + gravity_[1] * gravity_[1] + gravity_[2] * gravity_[2];

  PetscFunctionBeginUser;
  pressureReady_ = true;
  PetscCall(BoundaryPressure());
  if (g2 == 0) PetscFunctionReturn(0);
  PetscCall(UpdateLocals(propertiesDirty_));
  Vec keep[3];
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecDuplicate(u_[d], &keep[d]));
    PetscCall(VecCopy(u_[d], keep[d]));
    PetscCall(VecShift(u_[d], gravity_[d]));  // one unit of time of free fall
    PetscCall(bc_.ApplyNormal(sg_, d, u_[d]));
    PetscCall(ZeroBlocked(d, u_[d]));  // solids do not fall
  }
  PetscCall(Project(1, nullptr));  // p += phi, the hydrostatic pressure
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecCopy(keep[d], u_[d]));
    PetscCall(VecDestroy(&keep[d]));
  }
  PetscCall(UpdateLocals(false));
  PetscFunctionReturn(0);
}

// The projection solves for increments that vanish on outflow faces, so the pressure an outflow face
// keeps is the one the initial field gives it. With one outflow pressure (or several equal ones) that
// is the constant set in SetUp. Outflow faces at different pressures (a pressure-driven channel, a
// seepage test) need the field that takes each face's value: -div(beta grad p) = 0 with those
// Dirichlet values (Neumann elsewhere), solved once here; the increments then keep every face at its
// own pressure and the pressure difference drives the flow.
PetscErrorCode Flow::BoundaryPressure() {
  PetscReal lo = PETSC_MAX_REAL, hi = PETSC_MIN_REAL;

  PetscFunctionBeginUser;
  for (int f = 0; f < 6; ++f)
    if (bc_.Face(f).type == FlowBoundaryType::Outflow) lo = std::fmin(lo, bc_.Face(f).pressure), hi = std::fmax(hi, bc_.Face(f).pressure);
  if (!(hi > lo)) PetscFunctionReturn(0);
  PetscCall(UpdateLocals(propertiesDirty_));
  auto values = [&](bool faces) -> PetscErrorCode {
    PetscFunctionBeginUser;
    for (int f = 0; f < 6; ++f)
      if (bc_.Face(f).type == FlowBoundaryType::Outflow) PetscCall(pressure_.SetBoundary(f, PressureBoundary::Dirichlet, faces ? bc_.Face(f).pressure : 0));
    PetscCall(pressure_.SetCoefficient(beta_, "flow: eps/rho"));  // the Dirichlet faces' part of the rhs
    coefficientPending_ = false;
    PetscFunctionReturn(0);
  };
  PetscCall(values(true));
  PetscCall(VecSet(divRhs_, 0));
  // Once, and tighter than the step's solves: the error left in this field is never corrected (the
  // increments only remove divergence) and would drive a cross flow of its size for ever.
  PetscReal rtol, atol, dtol;
  PetscInt  maxIt;
  PetscCall(KSPGetTolerances(pressure_.Solver(), &rtol, &atol, &dtol, &maxIt));
  PetscCall(KSPSetTolerances(pressure_.Solver(), std::fmin(rtol, 1e-13), 0, dtol, std::max(maxIt, (PetscInt)1000)));
  PetscCall(pressure_.Solve(divRhs_, p_));
  PetscCall(KSPSetTolerances(pressure_.Solver(), rtol, atol, dtol, maxIt));
  PetscCall(values(false));
  PetscCall(UpdateLocals(false));
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::FaceForce(int d, Vec *f) {
  PetscFunctionBeginUser;
  if (!faceForce_[d]) {
    PetscCall(VecDuplicate(u_[d], &faceForce_[d]));
    PetscCall(VecSet(faceForce_[d], 0));
  }
  *f = faceForce_[d];
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::PropertiesChanged() {
  PetscFunctionBeginUser;
  propertiesDirty_ = true;
  PetscFunctionReturn(0);
}

// Ghosted copies of the fields the kernels read; with `properties`, also beta = eps/rho and eps*mu,
// the pressure operator and (next assembly) the viscous matrix.
PetscErrorCode Flow::UpdateLocals(bool properties) {
  PetscFunctionBeginUser;
  if (properties) PetscCall(UpdatePropertyLocals());
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMGlobalToLocal(sg_.Face(d), u_[d], INSERT_VALUES, uLocal_[d]));
    PetscCall(bc_.FillVelocityGhosts(sg_, d, uLocal_[d]));
  }
  PetscCall(DMGlobalToLocal(sg_.Cells(), p_, INSERT_VALUES, pLocal_));
  PetscCall(bc_.FillCellGhosts(sg_, pLocal_));
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::UpdatePropertyLocals() {
  PetscFunctionBeginUser;
  {
    PetscReal lo;
    PetscCall(VecMin(rho_, nullptr, &lo));
    if (!(lo > 0)) VofdemInputError(grid_->Comm(), "flow: the density must be positive everywhere (found %g kg/m^3)", (double)lo);
    PetscCall(VecMin(mu_, nullptr, &lo));
    if (!(lo > 0)) VofdemInputError(grid_->Comm(), "flow: the viscosity must be positive everywhere (found %g Pa s)", (double)lo);
    PetscReal hi;
    PetscCall(VecMax(mu_, nullptr, &hi));
    viscosityJump_ = hi - lo > 1e-12 * hi;  // not round-off of mixing equal phases (ex31: mu the same in both)
    PetscCall(VecMin(eps_, nullptr, &lo));
    if (!(lo > 0)) VofdemInputError(grid_->Comm(), "flow: the fluid fraction eps must be positive everywhere (found %g)", (double)lo);
    PetscCall(VecPointwiseDivide(beta_, eps_, rho_));
    PetscCall(VecPointwiseMult(divRhs_, eps_, mu_));  // divRhs_ as scratch for eps*mu
    PetscCall(DMGlobalToLocal(sg_.Cells(), divRhs_, INSERT_VALUES, emLocal_));
    PetscCall(bc_.FillCellGhosts(sg_, emLocal_));
    PetscCall(DMGlobalToLocal(sg_.Cells(), beta_, INSERT_VALUES, betaLocal_));
    PetscCall(bc_.FillCellGhosts(sg_, betaLocal_));
    PetscCall(DMGlobalToLocal(sg_.Cells(), eps_, INSERT_VALUES, epsLocal_));
    PetscCall(bc_.FillCellGhosts(sg_, epsLocal_));
    if (propertyGhosts_) PetscCall(propertyGhosts_(propertyGhostsCtx_, *this, epsLocal_, emLocal_, betaLocal_));
    // The projection sets the pressure coefficient from beta_ before its solve (SetPressureCoefficient);
    // with a relaxation it forms its own (FlowDragProjection.cpp).
    coefficientPending_ = true;
    propertiesDirty_ = false;
    viscousStale_ = PETSC_TRUE;  // the viscous matrix must be rebuilt, not only its diagonal
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::Step(PetscReal t, PetscReal dt) {
  PetscFunctionBeginUser;
  if (!pressureReady_) PetscCall(InitialPressure());
  PetscCall(PetscLogEventBegin(evGhosts_, 0, 0, 0, 0));
  PetscCall(UpdateLocals(propertiesDirty_));
  PetscCall(PetscLogEventEnd(evGhosts_, 0, 0, 0, 0));
  if (implicitViscosity_ && (viscousStale_ || viscous_.AssembledDt() != dt || viscous_.Damped())) {  // damping: new rates each step
    PetscCall(PetscLogEventBegin(evViscousAssemble_, 0, 0, 0, 0));
    PetscCall(viscous_.Assemble(dt, epsLocal_, betaLocal_, emLocal_, viscousStale_));
    PetscCall(PetscLogEventEnd(evViscousAssemble_, 0, 0, 0, 0));
    viscousStale_ = PETSC_FALSE;
  }
  PetscCall(ComputeExplicitTerms());
  PetscCall(Predict(t, dt));
  PetscCall(Project(dt, nullptr));
  for (int d = 0; d < 3; ++d) std::swap(H_[d], Hold_[d]);
  haveOld_ = PETSC_TRUE;
  dtOld_   = dt;
  last_.pressureIterations   = pressure_.Iterations();
  last_.pressureResidual     = pressure_.ResidualNorm();
  last_.preconditionerReused = pressure_.PreconditionerReused();
  last_.viscousIterations    = CoupledNow() ? coupledIterations_ : implicitViscosity_ ? viscous_.Iterations() : 0;
  PetscReal rate = 0;
  if (courant_ == CourantMeasure::Cell) PetscCall(ConvectiveRate(true, &rate));  // FlowCourant.cpp
  else
    for (int d = 0; d < 3; ++d) {
      PetscReal m;
      PetscCall(VecNorm(u_[d], NORM_INFINITY, &m));
      rate += m / grid_->Spacing()[d];
    }
  last_.cfl = rate * dt;
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::ProjectInitialVelocity() {
  PetscFunctionBeginUser;
  PetscCall(UpdateLocals(propertiesDirty_));
  for (int d = 0; d < 3; ++d) {
    PetscCall(bc_.ApplyNormal(sg_, d, u_[d]));
    PetscCall(ZeroBlocked(d, u_[d]));
  }
  // A unit "time step": phi is a potential, not a pressure; the pressure is left unchanged.
  Vec keep;
  PetscCall(VecDuplicate(p_, &keep));
  PetscCall(VecCopy(p_, keep));
  PetscCall(Project(1, nullptr));
  PetscCall(VecCopy(keep, p_));
  PetscCall(VecDestroy(&keep));
  PetscCall(VecSet(phi_, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::StableTimeStep(PetscReal *dt, std::string *basis, bool ownAdvection) {
  PetscReal rate = 0;

  PetscFunctionBeginUser;
  const PetscReal *h = grid_->Spacing();
  // Another module moving the momentum (the VOF's mass-consistent sweeps, one direction at a time): the Courant
  // number per direction, not the sum AB2 needs. The sweeps alone would allow 1/2, but a cell that converging flow
  // fills from both sides in one sweep can overshoot there (ex36 with surface tension: alpha 1 + 1.1e-4 at 0.475);
  // -flow_cfl keeps the margin.
  PetscCall(ConvectiveRate(ownAdvection, &rate));  // FlowCourant.cpp
  *dt    = rate > 0 ? cfl_ / rate : PETSC_MAX_REAL;
  *basis = ownAdvection ? "flow convective CFL " + std::to_string((double)cfl_) + (courant_ == CourantMeasure::Box ? " (box measure)" : "") : "flow Courant number " + std::to_string((double)cfl_) + " per direction (momentum moved by the VOF sweeps)";
  const PetscReal g = std::sqrt(gravity_[0] * gravity_[0] + gravity_[1] * gravity_[1] + gravity_[2] * gravity_[2]);
  const PetscReal hmin = std::fmin(h[0], std::fmin(h[1], h[2]));
  if (g > 0 && std::sqrt(cfl_ * hmin / g) < *dt) {
    // From rest, gravity reaches |u| dt = cfl h within the step.
    *dt    = std::sqrt(cfl_ * hmin / g);
    *basis = "flow gravity (sqrt(cfl h/|g|))";
  }
  PetscReal viscous;  // AB2 is stable while dt times the explicit viscous terms' largest rate is <= 1
  PetscCall(ViscousRate(&viscous));
  if (viscous > 0 && 1 / viscous < *dt) {
    *dt    = 1 / viscous;
    *basis = implicitViscosity_ ? "flow explicit transpose viscous term (FlowViscousLimit.cpp)" : "flow explicit viscosity (FlowViscousLimit.cpp)";
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::Summarize(FlowSummary *s) {
  LocalField u, beta, eps;
  PetscInt   st[3], n[3];
  PetscReal  ke = 0, mx = 0;

  PetscFunctionBeginUser;
  *s = last_;
  const PetscReal *h = grid_->Spacing();
  const PetscReal  V = h[0] * h[1] * h[2];
  PetscCall(sg_.GetLocal(3, betaLocal_, &beta));
  PetscCall(sg_.GetLocal(3, epsLocal_, &eps));
  for (int d = 0; d < 3; ++d) {
    PetscCall(sg_.GetGlobal(d, u_[d], &u));
    sg_.Owned(d, st, n);
    const PetscInt last = sg_.Points(d, d) - 1;
    for (PetscInt k = st[2]; k < st[2] + n[2]; ++k)
      for (PetscInt j = st[1]; j < st[1] + n[1]; ++j)
        for (PetscInt i = st[0]; i < st[0] + n[0]; ++i) {
          PetscInt        q[3] = {i, j, k}, cm[3] = {i, j, k};
          cm[d] -= 1;
          const PetscReal v = PetscRealPart(u.at(q));
          mx = std::fmax(mx, std::fabs(v));
          const PetscReal bL = PetscRealPart(beta.at(cm)), bR = PetscRealPart(beta.at(q));
          const FaceProperties face = FaceAverage(PetscRealPart(eps.at(cm)), PetscRealPart(eps.at(q)), bL, bR);
          const PetscReal eF = face.eps, bF = face.beta;
          // A boundary face carries half a control volume.
          const PetscReal w = (!grid_->Periodic(d) && (q[d] == 0 || q[d] == last)) ? 0.5 : 1;
          ke += w * 0.5 * eF * eF / bF * v * v * V;
        }
    PetscCall(sg_.RestoreGlobal(d, u_[d], &u));
  }
  PetscCall(sg_.RestoreLocal(3, epsLocal_, &eps));
  PetscCall(sg_.RestoreLocal(3, betaLocal_, &beta));
  PetscCallMPI(MPI_Allreduce(&ke, &s->kinetic, 1, MPIU_REAL, MPIU_SUM, grid_->Comm()));
  PetscCallMPI(MPI_Allreduce(&mx, &s->maxSpeed, 1, MPIU_REAL, MPI_MAX, grid_->Comm()));
  // The divergence the projection left (computed here, only when monitored).
  for (int d = 0; d < 3; ++d) PetscCall(DMGlobalToLocal(sg_.Face(d), u_[d], INSERT_VALUES, uLocal_[d]));
  PetscCall(Divergence(nullptr, 1, &s->maxDivergence));
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "flow: density %g kg/m^3, viscosity %g Pa s (Re per m/s and m: %g), advection %s (TVD), viscosity %s, CFL %g%s\n",
                                   (double)density_, (double)viscosity_, (double)(density_ / viscosity_), limiterName_.c_str(),
                                   implicitViscosity_ ? "implicit" : "explicit", (double)cfl_, courant_ == CourantMeasure::Box ? " (box measure)" : ""));
  PetscCall(bc_.View(viewer));
  PetscCall(solid_.View(viewer));
  PetscCall(pressure_.View(viewer));
  if (implicitViscosity_) PetscCall(viscous_.View(viewer));
  PetscReal muLo = 0, muHi = 0;
  PetscCall(VecMin(mu_, nullptr, &muLo));
  PetscCall(VecMax(mu_, nullptr, &muHi));
  if (implicitViscosity_ && (transposeMode_ == TransposeMode::Implicit || (transposeMode_ == TransposeMode::Auto && muHi - muLo > 1e-12 * muHi))) {
    KSPType type;
    PetscCall(KSPGetType(coupledKsp_, &type));
    PetscCall(PetscViewerASCIIPrintf(viewer, "flow viscous transpose: implicit%s, the three components in one solve, %s + jacobi (-flow_viscous_coupled_ksp_type)\n",
                                     transposeMode_ == TransposeMode::Auto ? " where the viscosity varies (auto)" : "", type));
  }
  PetscFunctionReturn(0);
}

// Everything the next step's arithmetic depends on: velocity, pressure, the last increment (the
// pressure solve's initial guess), the explicit terms of the previous step (AB2), its dt, the
// material fields, and the pressure preconditioner's reference coefficient and reuse decision; also
// the ParaView index written so far (-flow_output_every), so that a restart continues it.
PetscErrorCode Flow::SavedBytes(PetscInt64 *bytes) const {
  PetscInt n;

  PetscFunctionBeginUser;
  *bytes = 0;
  for (Vec v : {u_[0], u_[1], u_[2], Hold_[0], Hold_[1], Hold_[2], p_, phi_, rho_, mu_, eps_}) {
    PetscCall(VecGetSize(v, &n));
    *bytes += 8 * (PetscInt64)n;
  }
  *bytes += 64 * 1024 + 3 * 8 * (PetscInt64)outputEntries_.size();  // scalars, the preconditioner's state, the output index
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::Save(PetscViewer viewer) const {
  Vec scalars;

  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) PetscCall(VecView(u_[d], viewer));
  for (int d = 0; d < 3; ++d) PetscCall(VecView(Hold_[d], viewer));
  for (Vec v : {p_, phi_, rho_, mu_, eps_}) PetscCall(VecView(v, viewer));
  PetscBool hdf5;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERHDF5, &hdf5));
  if (hdf5) {  // properties changed since the pressure coefficient was last set (a free surface moved at the end of the step)
    // An HDF5 attribute, so that checkpoints written before it load as they did; a binary viewer
    // (in-memory Save/Load, ex27) has no attributes and keeps the former behaviour (none pending).
    const PetscInt pending = propertiesDirty_ || coefficientPending_ ? 1 : 0;
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, nullptr, "flow_properties_pending", PETSC_INT, &pending));
  }
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(grid_->Comm(), &rank));
  PetscCall(VecCreateMPI(grid_->Comm(), rank == 0 ? 3 : 0, 3, &scalars));
  PetscCall(PetscObjectSetName((PetscObject)scalars, "flow_scheme_state"));
  if (rank == 0) {
    PetscCall(VecSetValue(scalars, 0, dtOld_, INSERT_VALUES));
    PetscCall(VecSetValue(scalars, 1, haveOld_ ? 1.0 : 0.0, INSERT_VALUES));
    PetscCall(VecSetValue(scalars, 2, pressure_.PreconditionerReused() ? 1.0 : 0.0, INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(scalars));
  PetscCall(VecAssemblyEnd(scalars));
  PetscCall(VecView(scalars, viewer));
  PetscCall(VecDestroy(&scalars));
  PetscCall(SaveXdmfIndex(viewer, grid_->Comm(), "flow_output_entries", outputEntries_));  // the ParaView index so far (-flow_output_every)
  PetscCall(pressure_.Save(viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::Load(PetscViewer viewer) {
  Vec scalars;

  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) PetscCall(VecLoad(u_[d], viewer));
  for (int d = 0; d < 3; ++d) PetscCall(VecLoad(Hold_[d], viewer));
  for (Vec v : {p_, phi_, rho_, mu_, eps_}) PetscCall(VecLoad(v, viewer));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(grid_->Comm(), &rank));
  PetscCall(VecCreateMPI(grid_->Comm(), rank == 0 ? 3 : 0, 3, &scalars));
  PetscCall(PetscObjectSetName((PetscObject)scalars, "flow_scheme_state"));
  PetscCall(VecLoad(scalars, viewer));
  PetscReal s[3] = {0, 0, 0};
  if (rank == 0) {
    const PetscScalar *a;
    PetscCall(VecGetArrayRead(scalars, &a));
    for (int k = 0; k < 3; ++k) s[k] = PetscRealPart(a[k]);
    PetscCall(VecRestoreArrayRead(scalars, &a));
  }
  PetscCallMPI(MPI_Bcast(s, 3, MPIU_REAL, 0, grid_->Comm()));
  PetscCall(VecDestroy(&scalars));
  dtOld_   = s[0];
  haveOld_ = s[1] > 0 ? PETSC_TRUE : PETSC_FALSE;
  {  // the ParaView index so far, on every rank
    std::vector<std::pair<PetscInt, PetscReal>> saved;
    PetscCall(LoadXdmfIndex(viewer, grid_->Comm(), "flow_output_entries", &saved));
    outputEntries_.clear();
    for (const auto &st : saved) outputEntries_.push_back(OutputEntry(st.first, st.second));
  }
  pressureReady_ = true;
  // The fields above are the material the preconditioner reference is compared with: set them up
  // first (this builds a preconditioner from the current coefficient), then restore the saved
  // reference, which rebuilds the one the saved run was using.
  // When the saving run's properties had changed after its last coefficient (VOF and particles move rho
  // and eps between steps), its next step compares the coefficient of that step with the reference:
  // so does this one (checkpoints without the flag: none pending).
  PetscInt  pending = 0, none = 0;
  PetscBool hdf5;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERHDF5, &hdf5));
  if (hdf5) PetscCall(PetscViewerHDF5ReadAttribute(viewer, nullptr, "flow_properties_pending", PETSC_INT, &none, &pending));
  PetscCall(UpdateLocals(true));
  PetscCall(pressure_.Load(viewer));
  if (pending) propertiesDirty_ = true;
  else {
    coefficientPending_ = false;  // the saved run had set this coefficient: its operator, with the restored preconditioner
    PetscCall(pressure_.SetOperatorAfterLoad(beta_, "flow: eps/rho"));
    PetscCall(pressure_.RestoreReuseFlag(s[2] > 0 ? PETSC_TRUE : PETSC_FALSE));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::Destroy() {
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d)
    for (Vec *v : {&u_[d], &uLocal_[d], &H_[d], &Hold_[d], &L_[d], &rhsFace_[d], &faceForce_[d]}) PetscCall(VecDestroy(v));
  for (Vec *v : {&rho_, &mu_, &eps_, &p_, &phi_, &beta_, &divRhs_, &epsLocal_, &betaLocal_, &emLocal_, &pLocal_, &phiLocal_}) PetscCall(VecDestroy(v));
  for (Vec *v : {&dragBeta_, &dragBetaLocal_, &rateLocal_[0], &rateLocal_[1], &rateLocal_[2], &dampLocal_[0], &dampLocal_[1], &dampLocal_[2]}) PetscCall(VecDestroy(v));
  PetscCall(VecDestroy(&cellVelocity_));
  PetscCall(DMDestroy(&velocityDM_));
  PetscCall(pressure_.Destroy());
  PetscCall(solid_.Destroy());
  if (implicitViscosity_) PetscCall(viscous_.Destroy());
  PetscCall(CoupledDestroy());
  PetscCall(sg_.Destroy());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
