// The interface module (VOF), switched on by -physics flow,vof; options under -vof_.
//
// alpha, the volume fraction of the heavy phase (metal), is a cell field (docs/physics.md F1b) on a DMDA
// with the cell grid's ownership ranges and a 4-wide ghost layer: a flux at a rank's first face needs
// the reconstruction of the neighbour's cell, whose height-function normal reaches 3 cells further.
//
// Reconstruction (F4): PLIC, a plane n.x = c per cell (Plic.hpp), n from Youngs' gradient or from
// height functions (-vof_normals), which fall back to Youngs where a column is not a clean transition.
// Advection: direction-split geometric fluxes (Weymouth & Yue 2010, J. Comput. Phys. 229): in each
// sweep along d
//   alpha <- alpha - dt/h (F_{i+1/2} - F_{i-1/2}) + c_i dt/h (u_{i+1/2} - u_{i-1/2}),
// F = u * (fluid fraction of the volume the face sweeps, cut by the upwind cell's plane), c_i = 1 where
// alpha > 1/2 at the start of the step (else 0). The c-terms of the sweeps add up to c_i dt div(u) = 0,
// so volume is conserved to round-off, and a full or empty cell stays exactly full or empty; with the
// Courant number of each sweep <= 1/2 alpha stays in [0, 1] without clipping. The sweep order
// alternates (x,y,z then z,y,x).
#pragma once

#include "vofdem/grid/CellMove.hpp"
#include "vofdem/grid/StaggeredGrid.hpp"

#include <functional>
#include <string>
#include <vector>

namespace vofdem {

class Flow;
class OptionReader;

// Interface normals of the PLIC reconstruction (docs/physics.md F4; VofAdvect.cpp): Height from height
// functions where a 7-cell column is a clean transition, with a fallback elsewhere (-vof_height_fallback:
// Elvira or Youngs); Elvira everywhere; Youngs (gradient of alpha) everywhere.
enum class VofNormals { Youngs, Height, Elvira };
// How momentum moves with the interface (docs/physics.md F2; VofMomentum.cpp): Consistent transports
// rho u on the faces with the mass fluxes of the geometric VOF sweeps; Advective leaves the flow's
// non-conservative -(U.grad)U (kept to show what consistency buys, ex36).
enum class VofMomentum { Consistent, Advective };

struct VofSummary {
  PetscReal volume = 0;          // m^3: sum eps alpha dV (eps = 1 without particles)
  PetscReal otherVolume = 0;     // m^3: sum eps (1 - alpha) dV, phase 0
  PetscReal minAlpha = 0, maxAlpha = 0;  // now
  PetscReal boundViolation = 0;  // max(-alpha, alpha - 1, 0) seen after any sweep since SetUp (no clipping is done)
  PetscReal interfaceCells = 0;  // cells with 1e-12 < alpha < 1 - 1e-12 (as a real: a sum over ranks)
  PetscReal heightNormals = 0;   // fraction of the last step's PLIC reconstructions (one per donor cell and face) whose normal came from heights
  PetscReal missingCurvature = 0;  // interface cells that got no curvature in the last SurfaceTension
  // Open faces (inflow, outflow; VofOpenFaces.cpp): phase-1 volume (sum eps alpha dV units) that entered and
  // left through them since the start, from the sweeps' geometric face fluxes; the same on every rank.
  bool      openFaces = false;
  PetscReal inflowVolume = 0, outflowVolume = 0;  // m^3
};

class Vof {
public:
  // Is x inside the heavy phase? (Initial conditions: SetFraction samples it.) Negative: inside.
  using Shape = PetscReal (*)(void *ctx, const PetscReal x[3]);

  PetscErrorCode SetFromOptions(const Grid &grid);
  PetscErrorCode SetUp(const StaggeredGrid &sg);
  // Advances alpha from t to t + dt with the MAC face velocities u[d] (global vectors of sg.Face(d)).
  PetscErrorCode Advect(Vec const u[3], PetscReal dt);
  // Stable time step for the velocities u: each sweep's Courant number max|u_d| dt/h_d <= -vof_cfl.
  PetscErrorCode StableTimeStep(Vec const u[3], PetscReal *dt, std::string *basis) const;
  PetscErrorCode Summarize(VofSummary *s) const;  // collective
  PetscErrorCode View(PetscViewer viewer) const;
  // HDF5: alpha (natural ordering) and the scheme's state (sweep-order parity, bound violation so
  // far, height-normal share): a continued run is bitwise the uninterrupted one.
  PetscErrorCode Save(PetscViewer viewer) const;
  PetscErrorCode Load(PetscViewer viewer);
  PetscErrorCode Destroy();

  // Optional with a Shape: for the cell [lo, hi], 0 if no point inside the cell is inside the shape,
  // 1 if every point is, -1 if it cannot tell (the cell is then sampled).
  using CellClass = int (*)(void *ctx, const PetscReal lo[3], const PetscReal hi[3]);

  // alpha from a shape function: the fraction of samples[d] points per direction (cell-centred
  // sub-cells) where shape < 0; samples in a direction the shape does not depend on may be 1. With
  // `classify`, cells it decides are set without sampling (the same values, as it must only decide
  // what every sample would say).
  PetscErrorCode SetFraction(Shape shape, void *ctx, const PetscInt samples[3], CellClass classify = nullptr);
  // The scene's initial fraction: the heavy phase fills -vof_boxes and -vof_spheres.
  PetscErrorCode SetInitialShapes();
  // The flow's density and viscosity from alpha (phase 1: -vof_density, -vof_viscosity; phase 0: the
  // flow's -flow_density, -flow_viscosity), then flow.PropertiesChanged().
  PetscErrorCode UpdateProperties(Flow &flow) const;
  // Advect with mass-consistent momentum transport (VofMomentum.cpp; docs/physics.md F2): call instead of
  // Advect, before UpdateProperties, with the flow at u^n. After each split sweep of alpha, every
  // velocity component is moved along that sweep's direction by the sweep's own mass fluxes; the
  // result goes to the flow through SetAdvectionAcceleration, so that its predictor starts from the
  // transported velocity with the face density rho_f^{n+1}.
  PetscErrorCode AdvectWithMomentum(Flow &flow, PetscReal dt);
  // Refuses flow options the VOF's choices cannot work with (VofMomentum.cpp) and leaves open faces
  // (inflow, outflow) at 90 degrees (VofContactAngle.cpp); after both SetFromOptions.
  PetscErrorCode CheckFlowOptions(const Flow &flow);
  // True when AdvectWithMomentum is to be used this step (-vof_momentum consistent, interface moving).
  bool ConsistentMomentum() const { return momentum_ == VofMomentum::Consistent && advect_; }
  PetscReal Density() const { return density_; }
  // Particles in the fluid (-physics dem,flow,vof; docs/physics.md F1b, VofFluidFraction.cpp): eps, the flow's
  // fluid fraction (global cell vector), and its change over the coming step (the coupling's, which the
  // flow's projection also reads: dt div(eps u) = -change). alpha is then the fraction of the fluid
  // volume eps V of a cell, and Advect transports eps alpha: each sweep moves eps_f u_f times the PLIC
  // fraction of the swept slab, and the Weymouth-Yue term c_i carries the swept fluid volume plus a third
  // of the change, so that a full cell stays full while its eps moves and the volumes of both phases,
  // sum eps alpha V and sum eps (1 - alpha) V, change only by c_i times the continuity residual.
  // nullptr: eps = 1 (bitwise the scheme without particles).
  void SetFluidFraction(Vec eps, Vec change) { eps_ = eps; epsChange_ = change; }
  // Surface tension (-vof_surface_tension sigma > 0; VofSurfaceTension.cpp): height-function
  // curvature and the balanced face force sigma kappa_f (alpha_R - alpha_L)/h into flow.FaceForce();
  // with -vof_dsigma_dT and -vof_temperature_gradient (a prescribed linear temperature) or the computed one
  // (SetTemperature) sigma varies along the interface and the Marangoni force is added.
  PetscErrorCode SurfaceTension(Flow &flow);
  // The computed temperature for the surface forces (docs/physics.md F2), from another module (the energy):
  // T() and liquid() return global vectors with the cells' layout, T in K and each cell's liquid share in
  // [0, 1] (1 in gas and liquid metal, 0 where the metal is solid). sigma(T) = sigma + dsigma/dT (T_f - T_sigma)
  // at the face temperature T_f (the mean of its two cells; T_sigma: -vof_surface_tension_temperature), the
  // Marangoni force from grad T on the same stencil as grad alpha, and both forces weighted at each face by the
  // smaller liquid share of its two cells (a solid surface carries no capillary force). Set before SetUp;
  // -vof_temperature_gradient is then refused.
  void SetTemperature(std::function<Vec()> T, std::function<Vec()> liquid) { temperature_ = std::move(T), liquid_ = std::move(liquid); }
  bool HasTemperature() const { return (bool)temperature_; }
  PetscReal      SurfaceTensionCoefficient() const { return sigma_; }
  // The capillary time-step limit sqrt(rho_mean h^3 / (2 pi sigma)) (PETSC_MAX_REAL without sigma).
  PetscReal CapillaryTimeStep(PetscReal otherDensity) const;
  Vec       Curvature() const { return kappa_; }  // 1/m, 1e300 where none (after SurfaceTension)
  Vec Fraction() const { return alpha_; }  // global vector of FractionDM()
  // What moves with the interface's sweeps (the energy, docs/physics.md F7 a) runs its own sweep after each of
  // alpha's: observer(d, dt, u_d, F_d) with u_d the face velocities the sweep used and F_d its phase-1 volume
  // flux per face (m/s), both global on the staggered grid's Face(d); alpha is already moved.
  using SweepObserver = std::function<PetscErrorCode(int d, PetscReal dt, Vec u, Vec phaseFlux)>;
  void AddSweepObserver(SweepObserver observer) { observers_.push_back(std::move(observer)); }
  // With particles the sweeps' excursions of alpha out of [0, 1] are handed to neighbours after the last sweep
  // (Redistribute). Each move of phase 1 between an owned cell and one of its 26 neighbours is reported to the rank
  // that owns either: dv > 0 cell volumes of phase 1 from `other` into `cell` and as much of phase 0 back, dv < 0 the
  // reverse; the two ranks (or the two cells of one rank) see it with opposite signs and the same bits.
  using Move = CellMove;
  using RedistributionObserver = std::function<PetscErrorCode(const std::vector<Move> &moves)>;
  void AddRedistributionObserver(RedistributionObserver observer) { movedObservers_.push_back(std::move(observer)); }
  // Phase-1 volume put into the cells (melted particles, docs/physics.md P12; before the step's sweeps): with the fluid
  // fraction going from before to after (global cell vectors of the flow's cells; alpha is relative to `before`),
  // alpha = (before alpha V + volume)/(after V) (volume: m^3 per cell, a global cell vector). Then, if `bound`, the
  // excess over 1 goes to neighbours with room at `after` (Redistribute, reported to the redistribution's observers);
  // sum eps alpha V grows by the volume's sum to round-off. Collective.
  PetscErrorCode AddPhaseVolume(Vec volume, Vec before, Vec after);
  PetscErrorCode BoundAt(Vec after);  // the excursions of alpha out of [0, 1] to neighbours at eps = after (Redistribute)
  // c_i of the step's sweeps (Weymouth and Yue: alpha > 1/2 at the step's start), owned cells, x fastest.
  const std::vector<char> &FullAtStart() const { return fullAtStart_; }
  DM  FractionDM() const { return da_; }
  VofNormals Normals() const { return normals_; }
  // Static contact angle of box face f (xlo, xhi, ylo, yhi, zlo, zhi), degrees through phase 1
  // (-vof_contact_angle; 90: the neutral zero-gradient wall). VofContactAngle.cpp.
  PetscReal ContactAngle(int face) const { return contactAngle_[face]; }
  // True when a face is inflow or outflow (known after CheckFlowOptions): phase 1 can enter or leave.
  bool HasOpenFaces() const;

private:
  PetscErrorCode FillGhosts();  // alpha_ -> alphaLocal_, boundary layers by zero gradient, then inflow faces' entering fraction, then the contact angles
  PetscErrorCode MirrorBoundary(Vec local) const;  // a local vector of da_: boundary layers by zero gradient
  // Contact angles (VofContactAngle.cpp): the options (inside SetFromOptions' block), the check
  // against the flow's face types (CheckFlowOptions), and the ghost layers of alpha beyond every
  // face whose angle is not 90 degrees (FillGhosts, after MirrorBoundary).
  PetscErrorCode ReadContactAngleOptions(OptionReader &opt);
  PetscErrorCode CheckContactAngleFaces(const Flow &flow);
  PetscErrorCode ContactAngleGhosts(Vec local);
  // Open faces (VofOpenFaces.cpp): -vof_bc_<face>_alpha[_band] (inside SetFromOptions' block), the
  // check against the flow's face types (CheckFlowOptions), the ghost layers beyond inflow faces
  // (FillGhosts, after MirrorBoundary), the fraction of phase 1 in the fluid entering through face
  // `face` at the boundary face or ghost cell q (tangential indices used), and the donor-outside test
  // of a sweep's boundary face q along d with velocity vel (the open face, or -1).
  PetscErrorCode ReadOpenFaceOptions(OptionReader &opt);
  PetscErrorCode CheckOpenFaces(const Flow &flow);
  PetscErrorCode OpenFaceGhosts(Vec local) const;
  double         EnteringFraction(int face, const PetscInt q[3]) const;
  int            OpenDonorFace(int d, const PetscInt q[3], PetscReal vel) const;
  PetscErrorCode SaveOpenFaces(PetscViewer viewer) const;
  // The transported velocity's ghosts beyond inflow faces, tangential components: the inflow's own
  // value (the fluid coming in), instead of the flow's reflection about it.
  PetscErrorCode InflowVelocityGhosts(const Flow &flow, int c, Vec local) const;
  // The flow's hook (Flow::SetPropertyGhosts): eps mu and eps/rho beyond inflow faces from the entering fraction.
  static PetscErrorCode InflowPropertyGhosts(const void *ctx, const Flow &flow, Vec epsLocal, Vec emLocal, Vec betaLocal);
  PetscErrorCode LoadOpenFaces(PetscViewer viewer);
  PetscErrorCode FluidFractionGhosts();  // eps_, epsChange_ -> epsLocal_, changeLocal_ (VofFluidFraction.cpp)
  // Sweep `stage` (1-3) of a step along d.
  PetscErrorCode Sweep(int d, int stage, Vec const uLocal[3], PetscReal dt, PetscReal *fromHeights, PetscReal *reconstructions);
  // The PLIC plane of the cell at q in cell units (n, c); false for a full, empty or flat-field cell.
  PetscErrorCode MomentumSweep(int d, PetscReal dt);  // VofMomentum.cpp
  PetscErrorCode MomentumSweepStart(bool later);       // VofMomentum.cpp: the densities of the sweep's start (later: not the step's first sweep)
  PetscErrorCode Redistribute(Vec eps = nullptr);  // alpha back into [0, 1] with particles, conservatively, at eps (default eps_) (VofRedistribute.cpp)
  bool Reconstruct(const LocalField &a, const PetscInt q[3], double n[3], double *c, bool *fromHeights) const;

  const Grid          *grid_ = nullptr;
  const StaggeredGrid *sg_   = nullptr;
  DM                   da_   = nullptr;
  Vec                  alpha_ = nullptr, alphaLocal_ = nullptr;
  Vec                  uLocal_[3] = {nullptr, nullptr, nullptr};
  Vec                  kappa_ = nullptr, kappaLocal_ = nullptr;  // SurfaceTension
  std::vector<char>    fullAtStart_;  // c_i of the current step, owned cells
  std::vector<SweepObserver> observers_;
  std::vector<RedistributionObserver> movedObservers_;
  std::vector<Move>          moves_;  // Redistribute's, for movedObservers_
  std::vector<double>  flux_;         // face fluxes of one sweep
  Vec                  eps_ = nullptr, epsChange_ = nullptr;  // SetFluidFraction (not owned)
  Vec                  epsLocal_ = nullptr, changeLocal_ = nullptr, cellScratch_ = nullptr;  // on da_
  Vec                  phaseFlux_[3] = {nullptr, nullptr, nullptr};  // phase-1 volume flux of the last sweep along d per face (m/s), global on sg.Face(d)
  // AdvectWithMomentum's state: the flow (null otherwise), the sweep's mass fluxes and the velocity
  // being transported (ghosted, face DMDAs), alpha at the start of the sweep, the result for the flow.
  Flow                *momentumFlow_ = nullptr;
  Vec                  massLocal_[3] = {nullptr, nullptr, nullptr}, velocity_[3] = {nullptr, nullptr, nullptr}, velocityLocal_[3] = {nullptr, nullptr, nullptr};
  Vec                  momentumAcc_[3] = {nullptr, nullptr, nullptr};
  std::vector<PetscReal> cellRho_[2];  // MomentumSweep: cell mixture densities before and after the sweep
  Vec                  roomG_ = nullptr, fillG_ = nullptr, giveG_ = nullptr, takeG_ = nullptr;  // Redistribute's work, on da_
  Vec                  roomL_ = nullptr, fillL_ = nullptr, giveL_ = nullptr, takeL_ = nullptr;

  // options
  VofNormals  normals_ = VofNormals::Height;
  PetscReal   cfl_     = 0.5;
  VofNormals  fallback_ = VofNormals::Elvira;  // -vof_height_fallback: where heights are not available
  PetscReal   tiny_    = 1e-12;  // alpha below tiny (above 1 - tiny) is fluxed as uniform: no plane is fitted to round-off
  PetscReal   density_ = 1000, viscosity_ = 1e-3;  // phase 1 (alpha = 1)
  PetscReal   sigma_ = 0;                         // surface tension coefficient at T0, N/m
  PetscReal   dsigmadT_ = 0, gradT_[3] = {0, 0, 0};   // Marangoni: dsigma/dT (N/(m K)), prescribed grad T (K/m)
  PetscReal   sigmaTemperature_ = -1;                 // K: where sigma holds (-vof_surface_tension_temperature; computed T)
  bool        gradTGiven_ = false;
  int         marangoniScaling_ = 1;                 // -vof_marangoni_scaling: 0 none, 1 density
  std::function<Vec()> temperature_, liquid_;        // SetTemperature
  PetscErrorCode TemperatureLocals(const PetscScalar **T, const PetscScalar **m);  // VofSurfaceTension.cpp
  Vec         tGlobal_ = nullptr, tLocal_ = nullptr, mLocal_ = nullptr;  // SurfaceTension's copies of them, on da_
  PetscBool   advect_ = PETSC_TRUE;               // -vof_advect 0: a frozen interface (V3)
  PetscBool   redistribute_ = PETSC_TRUE;         // -vof_redistribute (with particles)
  VofMomentum momentum_ = VofMomentum::Consistent;  // -vof_momentum
  PetscReal   missingCurvature_ = 0;
  PetscReal   contactAngle_[6] = {90, 90, 90, 90, 90, 90};  // degrees, per box face
  bool        contactNamed_[6] = {false, false, false, false, false, false};  // named in -vof_contact_angle_faces
  Vec         contactGhost_[6] = {nullptr, nullptr, nullptr, nullptr, nullptr, nullptr};  // per angled face: its ghost layers, reflected into the box
  Vec         contactLocal_ = nullptr;  // scratch local vector of da_
  int         openType_[6] = {0, 0, 0, 0, 0, 0};  // 0 closed (wall, slip, periodic), 1 inflow, 2 outflow (CheckOpenFaces)
  PetscReal   openAlpha_[6] = {0, 0, 0, 0, 0, 0};  // -vof_bc_<face>_alpha: entering (inflow) or backflow (outflow) fraction
  bool        openAlphaGiven_[6] = {false, false, false, false, false, false};
  std::vector<PetscReal> openBand_[6];            // -vof_bc_<face>_alpha_band: lo,hi[,lo,hi] along the face's tangential axes (m)
  PetscReal   openVolume_[2] = {0, 0};            // phase-1 volume in, out through open faces since the start (global)
  PetscReal   openStep_[2] = {0, 0};              // this rank's part of the current step's in, out
  std::vector<PetscReal> boxes_, spheres_;        // initial shapes of phase 1
  PetscInt    samples_ = 8;                       // per direction and cell, for the initial fraction
  // state
  PetscInt    steps_ = 0;        // alternates the sweep order
  PetscReal   boundViolation_ = 0;
  PetscReal   heightShare_ = 0;
};

}  // namespace vofdem
