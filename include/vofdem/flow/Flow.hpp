// The flow module: volume-averaged incompressible Navier-Stokes on the MAC grid (docs/physics.md F1, F2),
// switched on by -physics flow; options under -flow_.
//
// Momentum, divided by eps*rho (non-conservative form; with continuity F1 it equals F2):
//   dU/dt + U.grad U = 1/(eps rho) div(eps mu (grad U + grad U^T)) - (1/rho) grad p + g + f
// Time integration (second order): incremental pressure-correction projection,
//   u* - u^n = dt [ AB2(H) + 1/2 (L u* + L u^n)/(eps rho) - (1/rho) G p^{n-1/2} + g + f^{n+1/2} ]
//   -div((eps/rho) G phi) = -div(eps u*)/dt,  u^{n+1} = u* - dt (1/rho) G phi,  p^{n+1/2} = p^{n-1/2} + phi
// H = -(U.grad)U (TVD, Advection.hpp, in the form div(Uu) - u div U) + div(eps mu grad U^T)/(eps rho);
// L = div(eps mu grad u), implicit (Crank-Nicolson, KSP prefix flow_viscous_) or, with
// -flow_viscous explicit, in AB2 too. AB2 with variable steps: (1 + r/2) H^n - r/2 H^{n-1}, r = dt/dt_old.
// The transpose part T = div(eps mu grad U^T) leaves H for the Crank-Nicolson side with -flow_viscous_transpose
// implicit, and by default (auto) while mu is not uniform (two phases): the three components are then solved
// together (FlowViscousCoupled.cpp), because explicit T limits the step far below the capillary limit at
// metal/gas density ratios (results/hard-cases.md).
// Faces: (1/rho)_f = b_f/eps_f with b_f the harmonic mean of eps/rho (what PressureSolver assembles),
// eps_f the mean of eps: the projected velocity has div(eps u) = 0 to the solver tolerance.
#pragma once

#include "vofdem/flow/Advection.hpp"
#include "vofdem/flow/FlowBoundary.hpp"
#include "vofdem/flow/PressureSolver.hpp"
#include "vofdem/flow/SolidMask.hpp"
#include "vofdem/grid/StaggeredGrid.hpp"
#include "vofdem/flow/ViscousSolver.hpp"
#include "vofdem/io/Xdmf.hpp"

#include <string>
#include <vector>

namespace vofdem {

struct FlowSummary {
  PetscReal kinetic = 0;      // J: sum of rho |U|^2 / 2 dV (eps-weighted)
  PetscReal maxSpeed = 0;     // m/s
  PetscReal maxDivergence = 0;  // 1/s: max |div(eps U)| after the projection
  PetscReal cfl = 0;          // dt * max(|u|/hx + |v|/hy + |w|/hz) of the last step
  PetscInt  pressureIterations = 0, viscousIterations = 0;
  PetscReal pressureResidual = 0;
  PetscBool preconditionerReused = PETSC_FALSE;
};

class Flow {
public:
  // An acceleration source f (m/s^2) for component d at point x and time t (manufactured solutions).
  using Forcing = PetscReal (*)(void *ctx, PetscReal t, const PetscReal x[3], int d);

  PetscErrorCode SetFromOptions(const Grid &grid);
  PetscErrorCode SetUp(const PetscReal gravity[3]);
  const PetscReal *Gravity() const { return gravity_; }  // m/s^2, as given to SetUp
  PetscErrorCode Step(PetscReal t, PetscReal dt);  // advances from t to t + dt
  // Stable time step at the current velocity and properties: convective -flow_cfl, gravity's
  // start-up limit, and the explicit viscous terms' limit (FlowViscousLimit.cpp: the transpose term
  // always, the whole viscous term with -flow_viscous explicit); collective. ownAdvection false:
  // another module transports the momentum (the VOF's mass-consistent sweeps), so the AB2 advection's
  // limit over the sum of directions does not apply; -flow_cfl then bounds each direction's Courant number.
  PetscErrorCode StableTimeStep(PetscReal *dt, std::string *basis, bool ownAdvection = true);
  PetscErrorCode Summarize(FlowSummary *s);  // collective; also measures div(eps U)
  PetscErrorCode View(PetscViewer viewer) const;
  PetscErrorCode Save(PetscViewer viewer) const;
  PetscErrorCode Load(PetscViewer viewer);
  PetscErrorCode SavedBytes(PetscInt64 *bytes) const;  // about how many bytes Save writes (all ranks)
  PetscErrorCode Destroy();

  // Fields, for initial conditions and coupling. Velocity(d): global vector of Staggered().Face(d);
  // the cell fields are global vectors of Staggered().Cells(). After changing density, viscosity or
  // eps, call PropertiesChanged().
  Vec Velocity(int d) const { return u_[d]; }
  Vec Pressure() const { return p_; }
  Vec Density() const { return rho_; }
  Vec Viscosity() const { return mu_; }
  Vec FluidFraction() const { return eps_; }
  PetscErrorCode PropertiesChanged();
  void SetForcing(Forcing f, void *ctx) { forcing_ = f; forcingCtx_ = ctx; }
  // A force per unit volume at the faces (N/m^3; for surface tension, docs/physics.md F2), global vectors of
  // Staggered().Face(d), created on the first call (zero) and kept by Flow. Predict adds it divided by
  // the same face density as the pressure gradient, (1/rho)_f f_d, so that a force that is a discrete
  // gradient on the pressure's stencil (a balanced-force surface tension) is cancelled exactly by the
  // pressure. The caller fills it before each Step; it is not part of Save (recomputed from the state).
  PetscErrorCode FaceForce(int d, Vec *f);
  // An extra acceleration (m/s^2) per face, added in Predict like gravity: the particles' reaction
  // -F_p/(eps rho)_f of docs/physics.md (F5), set by the coupling. a[d]: a global vector of Staggered().Face(d),
  // owned by the caller; nullptr: none.
  void SetFaceAcceleration(Vec a[3]) { for (int d = 0; d < 3; ++d) faceAcceleration_[d] = a ? a[d] : nullptr; }
  // Momentum transport supplied by another module, replacing the flow's own -(U.grad)U: the VOF
  // module's mass-consistent transport of rho u (docs/physics.md F2; VofMomentum.cpp). a[d] (m/s^2, global
  // vectors of Staggered().Face(d), owned by the caller) is added in Predict once (forward Euler, not
  // in the AB2 history, which then holds only the transpose viscous term); nullptr: the flow's own.
  void SetAdvectionAcceleration(Vec a[3]) { for (int d = 0; d < 3; ++d) advectionAcceleration_[d] = a ? a[d] : nullptr; }
  // The ghost cells of the properties beyond the box are zero-gradient (FlowBoundary::FillCellGhosts);
  // this hook, if set, may then overwrite them: the VOF module's inflow faces give the entering phase's
  // density and viscosity (VofOpenFaces.cpp). It gets the ghosted local vectors of eps, eps mu, eps/rho.
  using PropertyGhosts = PetscErrorCode (*)(const void *ctx, const Flow &flow, Vec epsLocal, Vec emLocal, Vec betaLocal);
  void SetPropertyGhosts(PropertyGhosts f, const void *ctx) { propertyGhosts_ = f; propertyGhostsCtx_ = ctx; }
  Limiter AdvectionLimiter() const { return limiter_; }
  // A linear drag toward a velocity w per face, rate c (1/s), taken implicitly right after the
  // predictor (operator splitting): u* <- (u* + dt c w)/(1 + dt c). The coupling's fluid side of the
  // drag in dense beds (F5), whose relaxation time eps rho/beta can be far below dt. c[d], w[d]: global
  // vectors of Staggered().Face(d), owned by the caller (zero on the faces the boundary conditions set);
  // nullptr: none.
  void SetFaceRelaxation(Vec c[3], Vec w[3]) {
    for (int d = 0; d < 3; ++d) relaxRate_[d] = c ? c[d] : nullptr, relaxTarget_[d] = c ? w[d] : nullptr;
  }
  // A linear drag toward rest per face, rate c (1/s), taken with the relaxation above:
  // u* <- (u* + dt c_r w)/(1 + dt (c_r + c)); c = +inf holds the face at rest (u* = 0 exactly). The Darcy
  // term of a mushy zone and solid metal (docs/physics.md F2), set by the energy module. The projection's
  // coefficient takes the sum of the rates (FlowDragProjection.cpp): a cell whose faces are all held
  // leaves the pressure equation (identity row), and its faces take no correction. c[d]: global vectors of
  // Staggered().Face(d), owned by the caller; nullptr: none.
  void SetFaceDamping(Vec c[3]);
  // The change of eps over the coming step (a global cell vector, owned by the caller, set by the
  // coupling; nullptr: none): the projection then makes div(eps U) = -(change)/dt (docs/physics.md F1), the
  // fluid the particles displace. The summary's divergence is div(eps U) + change/dt of the last step.
  void SetFluidFractionChange(Vec change) { epsChange_ = change; }
  // Makes the velocity field satisfy the boundary conditions and div(eps U) = 0 (an initial projection).
  PetscErrorCode ProjectInitialVelocity();
  // Sets the pressure to the one that balances gravity (done by the first Step unless Load came first).
  PetscErrorCode InitialPressure();

  const StaggeredGrid &Staggered() const { return sg_; }
  const FlowBoundary  &Boundary() const { return bc_; }
  const SolidMask     &Solid() const { return solid_; }
  PetscReal            ReferenceDensity() const { return density_; }
  PetscReal            ReferenceViscosity() const { return viscosity_; }
  const std::string   &ProfilePath() const { return profilePath_; }
  // Velocity along the three lines through the box centre, as CSV (line,s,x,y,z,u,v,w) on rank 0.
  PetscErrorCode WriteProfile(const std::string &path) const;
  // ParaView output (-flow_output_every, FlowOutput.cpp): the folder (-output_dir), then at each step.
  PetscErrorCode SetOutputDir(const std::string &dir);
  PetscErrorCode WriteOutput(PetscInt step, PetscReal time);  // collective; writes when step is a multiple
  // Another module's cell field (a global vector with the cells' layout, named: the dataset name) to
  // write with the flow's fields (e.g. the VOF fraction); not owned. Register before the first output.
  void AddOutputField(Vec cellField) { outputExtra_.push_back(cellField); }
  // Component d interpolated to point x (collective; every rank gets the value).
  PetscErrorCode SampleVelocity(const PetscReal x[3], PetscReal u[3]) const;

private:
  PetscErrorCode UpdateLocals(bool properties);  // ghosted velocities and pressure, and the properties' if asked
  PetscErrorCode UpdatePropertyLocals();         // eps mu, eps/rho, eps ghosted; the pressure coefficient
  PetscErrorCode ViscousRate(PetscReal *rate);  // 1/s: the explicit viscous terms' bound (FlowViscousLimit.cpp)
  PetscErrorCode ConvectiveRate(bool ownAdvection, PetscReal *rate);  // 1/s: the Courant number per unit step (FlowCourant.cpp)
  PetscErrorCode ComputeExplicitTerms();  // H_ (and L u^n) at time level n
  PetscErrorCode Predict(PetscReal t, PetscReal dt);
  PetscErrorCode Project(PetscReal dt, Vec *uField);
  PetscErrorCode Divergence(Vec rhsOut, PetscReal scale, PetscReal *maxAbs) const;
  PetscErrorCode BoundaryPressure();  // outflow faces at different pressures: the initial field between them
  PetscErrorCode ZeroBlocked(int d, Vec faceVector) const;  // the faces touching solid cells
  PetscErrorCode SolidWallTerms();  // the wall half a cell away in the explicit viscous term (SolidMask.hpp)
  // -flow_viscous_transpose implicit (FlowViscousCoupled.cpp): the three components in one Crank-Nicolson solve.
  PetscErrorCode TransposeTerm(Vec local[3], Vec out[3]);  // div(eps mu grad U^T) at the interior faces, N/m^3
  PetscErrorCode TransposeOf(Vec u[3], Vec out[3]);  // of global face velocities (outflow faces as ApplyNormal sets them, ghosts filled)
  PetscErrorCode CoupledSetUp();
  PetscErrorCode CoupledBoundaryPart();
  PetscErrorCode CoupledSolve(Vec rhs[3]);
  PetscErrorCode CoupledDestroy();
  PetscErrorCode PlaceCoupled(Vec whole, Vec part[3], bool read = false);
  PetscErrorCode ResetCoupled(Vec whole, Vec part[3], bool read = false);
  static PetscErrorCode CoupledMult(Mat A, Vec x, Vec y);
  static PetscErrorCode CoupledDiagonal(Mat A, Vec diag);
  enum class TransposeMode { Explicit, Implicit, Auto };
  TransposeMode transposeMode_ = TransposeMode::Auto;
  // The coupled solve this step: implicit viscosity and the transpose term implicit (auto: while mu varies).
  bool CoupledNow() const { return implicitViscosity_ && (transposeMode_ == TransposeMode::Implicit || (transposeMode_ == TransposeMode::Auto && viscosityJump_)); }
  Vec       transLocal_[3] = {nullptr, nullptr, nullptr}, transIn_[3] = {nullptr, nullptr, nullptr}, transOut_[3] = {nullptr, nullptr, nullptr}, transZero_[3] = {nullptr, nullptr, nullptr};
  Vec       coupledX_[3] = {nullptr, nullptr, nullptr}, coupledY_[3] = {nullptr, nullptr, nullptr};
  Vec       coupledSolution_ = nullptr, coupledRhs_ = nullptr;
  Mat       coupledOp_ = nullptr;
  KSP       coupledKsp_ = nullptr;
  PetscInt  coupledIterations_ = 0;

  const Grid    *grid_ = nullptr;
  StaggeredGrid  sg_;
  FlowBoundary   bc_;
  SolidMask      solid_;
  PressureSolver pressure_;
  ViscousSolver  viscous_;

  // options
  PetscReal   density_ = 1000, viscosity_ = 1e-3, cfl_ = 0.4, velocity0_[3] = {0, 0, 0};
  Limiter     limiter_ = Limiter::VanLeer;
  std::string limiterName_ = "vanleer";
  enum class CourantMeasure { Box, Cell } courant_ = CourantMeasure::Cell;  // -flow_courant
  PetscBool   implicitViscosity_ = PETSC_TRUE;
  PetscBool   userPressureAtol_ = PETSC_FALSE;  // else Project sets a scale-aware absolute tolerance
  std::string profilePath_;
  PetscInt    outputEvery_ = 0;  // -flow_output_every
  std::string outputDir_;
  std::vector<XdmfEntry> outputEntries_;
  std::vector<Vec>       outputExtra_;  // AddOutputField
  XdmfEntry OutputEntry(PetscInt step, PetscReal time) const;  // the index entry of flow_<step>.h5 (FlowOutput.cpp)
  DM          velocityDM_ = nullptr;  // cell layout with 3 components, for the output
  Vec         cellVelocity_ = nullptr;
  PetscReal   gravity_[3] = {0, 0, 0};

  // fields
  Vec u_[3] = {nullptr, nullptr, nullptr}, uLocal_[3] = {nullptr, nullptr, nullptr};
  Vec H_[3] = {nullptr, nullptr, nullptr}, Hold_[3] = {nullptr, nullptr, nullptr}, L_[3] = {nullptr, nullptr, nullptr};
  Vec rhsFace_[3] = {nullptr, nullptr, nullptr};
  Vec rho_ = nullptr, mu_ = nullptr, eps_ = nullptr, p_ = nullptr, phi_ = nullptr, beta_ = nullptr, divRhs_ = nullptr;
  Vec epsLocal_ = nullptr, betaLocal_ = nullptr, emLocal_ = nullptr, pLocal_ = nullptr, phiLocal_ = nullptr;

  // time-scheme state (saved)
  PetscReal dtOld_ = 0;
  PetscBool haveOld_ = PETSC_FALSE;
  bool      pressureReady_ = false;  // InitialPressure done, or the pressure loaded
  Forcing   forcing_ = nullptr;
  Vec       faceForce_[3] = {nullptr, nullptr, nullptr};  // FaceForce(); null unless asked for
  Vec       faceAcceleration_[3] = {nullptr, nullptr, nullptr};
  Vec       advectionAcceleration_[3] = {nullptr, nullptr, nullptr};  // SetAdvectionAcceleration
  PropertyGhosts propertyGhosts_ = nullptr;  // SetPropertyGhosts
  const void    *propertyGhostsCtx_ = nullptr;
  Vec       relaxRate_[3] = {nullptr, nullptr, nullptr}, relaxTarget_[3] = {nullptr, nullptr, nullptr};
  Vec       damping_[3] = {nullptr, nullptr, nullptr};  // SetFaceDamping
  bool      Relaxing() const { return relaxRate_[0] || damping_[0]; }
  // With a relaxation: the projection's coefficient eps/(rho (1 + dt c)) (FlowDragProjection.cpp)
  Vec            dragBeta_ = nullptr, dragBetaLocal_ = nullptr, rateLocal_[3] = {nullptr, nullptr, nullptr}, dampLocal_[3] = {nullptr, nullptr, nullptr};
  PetscErrorCode DragProjectionCoefficient(PetscReal dt);
  Vec       epsChange_ = nullptr;  // SetFluidFractionChange
  PetscReal epsChangeDt_ = 0;     // the step it belongs to (set by Project)
  void     *forcingCtx_ = nullptr;
  // last step, for the monitor
  FlowSummary last_;
  PetscBool   viscousStale_ = PETSC_TRUE;  // properties changed since the viscous matrix was assembled
  bool        propertiesDirty_ = true;
  // beta_ changed since the pressure operator was last set: the projection sets it (and decides on
  // reusing the preconditioner) right before its solve, never a query such as StableTimeStep, so that a
  // banner or a time-step choice leaves the solver's state as the step alone would (restarts, issue 55).
  bool        coefficientPending_ = false;
  bool        viscosityJump_ = false;  // mu not uniform (two phases): the transpose term's limit applies (FlowViscousLimit.cpp)
  PetscLogEvent evExplicit_ = 0, evPredict_ = 0, evProject_ = 0, evGhosts_ = 0, evViscousAssemble_ = 0;
};

}  // namespace vofdem
