// The particle-fluid coupling (-physics dem,flow; options -coupling_*): semi-resolved CFD-DEM of
// docs/physics.md K1-K3, F5, P1. One fluid step of size dt (Simulation::Step calls the parts in order):
//  1. projection (K3): the particles' volume gives the fluid fraction eps = 1 - (volume/V_cell), and
//     the fluid's momentum source -F_p (F5) on the faces of each velocity component is either
//     (-coupling_fluid_drag explicit, the default) the drag impulse the particles received over the previous step,
//     divided by its length, as the acceleration -F_p/(eps rho)_f the flow adds in its predictor
//     (Flow::SetFaceAcceleration; momentum exchanged exactly, stable while the fluid's relaxation time
//     eps rho/beta exceeds dt), or (implicit) the drag K_p (u - v_p) of each particle with
//     the fluid velocity u taken implicitly: K_p and K_p v_p are projected to the faces and the flow
//     relaxes u toward their ratio at the rate K/(V (eps rho)_f) (Flow::SetFaceRelaxation), which dense
//     beds of a light fluid need for stability (CFDEM's implicit coupling likewise); the exchange is then
//     exact in steady state and lags by a step in between. The projection's coefficient carries the
//     drag's 1/(1 + dt c) (FlowDragProjection.cpp), so a dense bed builds its pressure drop in a few
//     steps (without it, over about dt K/(V eps rho) steps: hundreds in ex34). The explicit forces (f_vm's
//     m_a Du/Dt, the capillary force), summed apart in the swarm's fluid_explicit_impulse, reach the fluid as
//     a face acceleration in both modes;
//  2. the flow step;
//  3. averaging (K1, K2) at every particle: fluid velocity, density and viscosity (eps-weighted:
//     with a free surface the local mixture of the two phases), eps (plain average, or eps-weighted
//     with -coupling_fraction_average weighted), pressure gradient and the interface's face force
//     (unweighted); the added mass C_vm rho V (P1, taken implicitly by the DEM kick, the fluid's
//     acceleration Du/Dt explicitly from the change of the averaged velocity); the drag coefficient K of the chosen law (DragLaws.hpp) from the slip, after the
//     self-disturbance correction (K1b); the pressure-gradient force -V grad p (with the hydrostatic
//     pressure in p it is the buoyancy, P1); with -coupling_contact_angle and a free surface, Princen's
//     capillary force from the averaged liquid fraction and its gradient (Capillary.hpp, P1); with -coupling_lift or
//     -coupling_rotational_drag, half the fluid's vorticity Omega_f = curl(u)/2 from the kernel averages of the grid's
//     velocity derivatives (K2, unweighted; CouplingRotation.cpp), the Magnus lift (explicit, its reaction joins F_p
//     like f_vm's, F5) and the rotational drag torque -K_r (omega - Omega_f) (implicit in the kicks; its reaction
//     torque on the fluid is neglected, as in CFDEM and Kratos: the fluid gets no couple) (RotationLaws.hpp, P1);
//     with -coupling_lubrication, the viscosity each particle reads for the DEM's lubrication (P8);
//  4. DEM sub-steps of at most the DEM's stable step, with the drag K (u - v) taken implicitly in
//     every half kick (Dem.cpp), so particles whose response time m/K is shorter than the fluid step
//     neither limit nor destabilise it; the drag impulse is summed for the next step's step 1.
// Momentum is conserved exactly: the fluid receives, one step later, exactly the impulse the particles
// received, shared by kernel weights that sum to one.
// Self-disturbance (K1b): a particle's reaction force, spread by the kernel, moves the fluid it then
// reads; in Stokes flow the velocity read back is C F/mu, C = Kernel.hpp's SelfDisturbanceCoefficient
// for the particle's kernel. The undisturbed velocity is estimated as u_read + C F_last/mu, F_last the
// drag the fluid was given this step.
#pragma once

#include "vofdem/coupling/Capillary.hpp"
#include "vofdem/coupling/DragLaws.hpp"
#include "vofdem/coupling/KernelAverager.hpp"
#include "vofdem/coupling/RotationLaws.hpp"
#include "vofdem/coupling/Smoothing.hpp"
#include "vofdem/dem/Dem.hpp"
#include "vofdem/flow/Flow.hpp"

#include <string>
#include <vector>

namespace vofdem {

struct CouplingSummary {
  PetscReal minEps = 1, particleVolume = 0, projectedVolume = 0;  // after the last projection
  PetscReal dragSum[3] = {0, 0, 0};                                // N, drag on all particles, last step (mean)
  PetscReal sourceSum[3] = {0, 0, 0};                              // N, the fluid's momentum source from them (C3: -dragSum)
  PetscInt  substeps = 0;                                          // DEM sub-steps of the last fluid step
  PetscInt  clipped = 0;                                           // cells whose eps was raised to the floor
};

class Coupling {
public:
  PetscErrorCode SetFromOptions(MPI_Comm comm);
  PetscErrorCode SetUp(Flow &flow, Dem &dem);
  // Input check before the particles are made: a particle of diameter d must fit in the box.
  PetscErrorCode CheckParticleSize(const Grid &grid, PetscReal d) const;
  // The parts of one coupled step, called in this order by Simulation::Step (CouplingStep.cpp):
  // Project() (step 1), the flow step, Average() (step 3), Substeps() DEM steps of dt/Substeps(dt)
  // (step 4), Finish(dt).
  // dt: the fluid step about to be taken, whose d(eps)/dt is the particles' displacement rate of the last
  // step (CouplingStep.cpp); 0 at set-up.
  PetscErrorCode Project(PetscReal dt = 0);
  // dt: the fluid step just taken (the interval since the last Average, for the fluid acceleration
  // Du/Dt of the added mass); 0 at set-up (no acceleration).
  PetscErrorCode Average(PetscReal dt = 0);
  PetscInt       Substeps(PetscReal dt) const;
  void           Finish(PetscReal dt) { dtLast_ = dt; }
  PetscErrorCode View(PetscViewer viewer, PetscReal dt) const;  // settings and diagnostics (banner)
  PetscErrorCode Summarize(CouplingSummary *s) const { *s = last_; return 0; }
  PetscErrorCode Save(PetscViewer viewer) const;
  PetscErrorCode Load(PetscViewer viewer);
  PetscErrorCode Destroy();

  // With a free surface (-physics dem,flow,vof): the particles also feel the kernel average of the
  // flow's face force (surface tension and Marangoni, P1), which the VOF module fills every step.
  void SetInterfaceForces(bool on) { interfaceForces_ = on; }
  void SetPhaseFraction(Vec alpha) { phase_ = alpha; }  // the VOF's alpha (not owned): new particles' volume comes from cells without metal
  // The particles' wettability (-coupling_contact_angle, Capillary.hpp): the liquid fraction alpha (the
  // VOF's phase 1, a global cell vector laid out as the flow's cells, owned by the VOF) and its surface
  // tension; with the option set, the capillary force joins the fluid force. Call after SetUp.
  PetscErrorCode SetFreeSurface(Vec alpha, PetscReal sigma);
  bool           ContactAngleSet() const { return contactAngleSet_ == PETSC_TRUE; }
  // The change of eps made by the last Project() (global cell vector; zero at set-up), which the flow's
  // projection (F1) and the VOF transport (F1b) read; nullptr with -coupling_eps_rate 0.
  Vec FluidFractionChange() const { return epsChange_; }
  bool EpsRate() const { return epsRate_ == PETSC_TRUE; }
  // -coupling_lubrication: the DEM's lubrication (P8) takes the fluid's viscosity (Dem::SetFluidLubrication).
  bool Lubrication() const { return lubrication_ == PETSC_TRUE; }

  // The kernel width of a particle of diameter d: max(kappa d, -coupling_kernel_min_width cells).
  PetscReal KernelWidth(PetscReal d) const;
  // The particle-grid maps (K1, K3) and their kernel, for the other exchanges of the same particles (heat:
  // ParticleHeat.hpp), so that every exchange uses the one kernel. Valid after SetUp.
  Smoothing                      &Averager() { return avg_; }
  const KernelAverager::Settings &KernelSettings() const { return kernel_; }
  // The mean over the owned and other ranks' wall faces of direction d (side 0: lower, 1: upper) of the pressure
  // gradient dp/dx_d the particles read there (the wall face's half control volume, FaceFields), as of the last
  // Average(). Collective. With it, the pressure at the wall is p(first cell) -/+ h/2 of it (ex34: the drop from
  // the floor).
  PetscErrorCode WallPressureGradient(int d, int side, PetscReal *mean) const;

private:
  PetscErrorCode FaceFields();  // eps at faces and the pressure gradient at faces, from the flow
  PetscErrorCode AlphaGradient();  // the liquid fraction's gradient at the faces (CouplingCapillary.cpp)
  // The derivatives of each velocity component u_d along the two other directions at its own faces (central
  // differences, one-sided at walls), into gradU_[d][0..1] for e = d+1, d+2 (mod 3) (CouplingRotation.cpp).
  PetscErrorCode VelocityGradients();
  bool           Rotation() const { return lift_ != rotation::Lift::None || rotationalDrag_; }
  // Per particle p: the rotation forces from the averaged derivatives g (9 per particle, g[3c+e] = du_c/dx_e), the
  // fluid velocity uf the drag used, rho and mu (CouplingRotation.cpp). Sets fluid_rotation, fluid_rotational_drag;
  // returns the lift in F.
  void RotationForces(ParticleArrays &a, PetscInt p, const PetscReal *g, const PetscReal uf[3], PetscReal rho, PetscReal mu, PetscReal F[3]) const;
  // The local free surface a particle at x with kernel width H sees, from the kernel averages of alpha and of
  // its gradient, as the plane of field::fluidSurfacePlane (CouplingCapillary.cpp).
  void           SurfacePlane(PetscReal H, PetscReal alphaAvg, const PetscReal grad[3], const PetscReal x[3], PetscReal plane[4]) const;
  // The fluid's share -F of the forces in massForce_ on the faces of component d, by face mass, added to accel_[d]
  // (eps and rho: the cells' local fields; source: the diagnostic sum). CouplingMassDeposit.cpp.
  PetscErrorCode DepositByFaceMass(int d, const ParticleArrays &a, LocalField &eps, LocalField &rho, PetscReal *source);

  Flow          *flow_ = nullptr;
  Dem           *dem_ = nullptr;
  Smoothing      avg_;  // kernel sums or diffusion (-coupling_smoothing)
  MPI_Comm       comm_ = MPI_COMM_NULL;

  // options
  KernelAverager::Settings kernel_;
  std::string              kernelName_ = "smooth";
  Smoothing::Settings      smoothing_;
  PetscReal                kappa_ = 1.5, minWidthCells_ = 1.0;
  drag::Law                law_ = drag::Find("schillernaumann");  // -coupling_drag (DragLawTable.cpp)
  PetscReal                dragSwitch_ = 0.8;
  PetscBool                pressureForce_ = PETSC_TRUE, selfCorrection_ = PETSC_TRUE;
  PetscReal                minEps_ = 0.1, selfMinEps_ = 0.9;
  PetscBool                implicitFluid_ = PETSC_FALSE;  // -coupling_fluid_drag implicit
  PetscBool                weightedFraction_ = PETSC_FALSE;  // -coupling_fraction_average weighted
  PetscReal                addedMass_ = 0.5;             // C_vm (P1)
  enum class FluidAcceleration { Velocity, Pressure, None };
  FluidAcceleration        addedMassAccel_ = FluidAcceleration::Velocity;  // -coupling_added_mass_acceleration: Du/Dt in f_vm
  PetscBool                epsRate_ = PETSC_TRUE;         // d(eps)/dt in the continuity equation (F1)
  rotation::Lift           lift_ = rotation::Lift::None;  // -coupling_lift
  PetscBool                rotationalDrag_ = PETSC_FALSE;  // -coupling_rotational_drag
  PetscBool                rotationalDragDennis_ = PETSC_FALSE;  // -coupling_rotational_drag_correction
  PetscBool                lubrication_ = PETSC_FALSE;     // -coupling_lubrication
  bool                     interfaceForces_ = false;
  PetscReal                contactAngle_ = 90;  // deg, -coupling_contact_angle (one angle for all particles)
  PetscBool                contactAngleSet_ = PETSC_FALSE;
  bool                     freeSurface_ = false;  // SetFreeSurface was called
  Vec                      alpha_ = nullptr;    // the VOF's, not owned; nullptr: no capillary force
  PetscReal                sigma_ = 0;          // N/m, the VOF's surface tension
  capillary::Marginal      marginal_;           // the kernel's interface marginal F (Capillary.hpp)
  Vec                      gradAlpha_[3] = {nullptr, nullptr, nullptr};
  Vec                      massWork_[3]  = {nullptr, nullptr, nullptr};  // DepositByFaceMass's scratch
  Vec                      gradU_[3][2]  = {{nullptr, nullptr}, {nullptr, nullptr}, {nullptr, nullptr}};  // VelocityGradients
  Vec                      faceLocal_[3] = {nullptr, nullptr, nullptr};  // ghosted velocity, VelocityGradients' input
  bool Capillary() const { return alpha_ != nullptr; }
  std::vector<PetscReal>   selfTable_;  // H C of Kernel.hpp at Re_H = 10^(-3 + k/20), k = 0..140
  PetscReal                SelfCoefficient(PetscReal H, PetscReal ReH) const;  // C (1/m) by log interpolation

  // fields
  Vec faceEps_[3] = {nullptr, nullptr, nullptr}, gradP_[3] = {nullptr, nullptr, nullptr}, accel_[3] = {nullptr, nullptr, nullptr};
  Vec rate_[3] = {nullptr, nullptr, nullptr}, target_[3] = {nullptr, nullptr, nullptr};  // implicit fluid drag (Flow::SetFaceRelaxation)
  // The particles' force (N) deposited on each wall face of direction d (Project; zero elsewhere): the wall face's half
  // control volume, whose velocity the boundary sets, passes it to the wall; its pressure gradient (FaceFields) balances it.
  Vec wallForce_[3] = {nullptr, nullptr, nullptr};
  Vec cellLocal_ = nullptr, rhoLocal_ = nullptr, volume_ = nullptr, epsChange_ = nullptr;
  Vec bornCells_ = nullptr;                // the volume of the particles added since the last projection (Project)
  Vec phase_ = nullptr;                    // the VOF's alpha, or nullptr (one fluid)
  std::vector<PetscReal> bornVolume_;      // per particle: its volume if it is new, else 0
  std::vector<PetscReal> gasWeight_;       // per local cell: its share of the cells without metal that give the new volume
  PetscReal              bornTotal_ = 0;   // the new particles' volume over the cell volume, all ranks
  std::vector<PetscReal> H_, scratch_, lastForce_;  // per local particle, between Project and Average
  std::vector<PetscReal> explicitForce_;             // the explicit forces' part of lastForce_ (implicit fluid drag)
  std::vector<PetscReal> massForce_, capMass_, capShare_;  // per local particle: the force of the last step whose reaction
                                                          // is shared by face mass, the averaged face (eps rho), -F/that (DepositByFaceMass)

  // state (saved): the length of the last step, whose drag impulse the next step projects
  PetscReal dtLast_ = 0;
  CouplingSummary last_;
  PetscLogEvent   evProject_ = 0, evAverage_ = 0;
};

}  // namespace vofdem
