// The energy equation on the grid's cells (docs/physics.md F3, F7, F8; docs/modules/energy.md), for metal
// (fraction alpha) and gas in a cell whose fluid fraction is eps:
//   d(eps E)/dt = div(eps k grad T) - delta_s [h_c (T - T_a) + e sigma_SB (T^4 - T_a^4)] + q_laser,
//   E = alpha rho_m h_m(T) + (1 - alpha) rho_g h_g(T),  h_m = int cp_m dT + f_l(T) L,
// with conductivities averaged harmonically at faces, box faces adiabatic, at a fixed temperature, with a
// fixed flux, or convective (with radiation). In time: BDF2 (backward Euler on the first step, or
// throughout with -energy_time_scheme euler), implicit in T. Latent heat enters through E(T): each
// cell's state is its temperature T and its metal's melt fraction f, E = E(T, f); each iteration solves the
// balance linearised in T with the latent heat's share f = f^k + F' (T - F^{-1}(f^k)) (the source-based
// scheme of Voller and Swaminathan, 1991; F' the mushy slope unless the cell is consistently solid or
// liquid), then clamps f to [0, 1], until every cell's balance closes to -energy_tolerance; the step's close then
// sets E from the last iterate's fluxes exactly (CloseBalance: conservative at any tolerance). The linear systems
// are symmetric: CG with Jacobi for short steps, hypre PFMG (structured) or BoomerAMG for long ones (-energy_pc),
// options prefix energy_.
// With a flow: transport by the VOF sweeps' phase fluxes (F7 a), the Darcy term and held solid metal (F2, MushyDrag).
// With particles (SetFluidFraction): every cell quantity is per cell volume and counts the fluid's share eps, the
// conductances eps_f k_f (eps_f the two cells' mean, as the flow's projection), box faces and interface losses
// through the fluid's share eps of the cell, the sweeps' fluxes eps_f u and the dilatation with d(eps)/dt.
#pragma once

#include "vofdem/energy/Laser.hpp"
#include "vofdem/energy/ThermalMaterial.hpp"
#include "vofdem/grid/AijRowWriter.hpp"
#include "vofdem/grid/CellMove.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/grid/StaggeredGrid.hpp"
#include "vofdem/io/Xdmf.hpp"

#include <petscksp.h>

#include <functional>
#include <string>
#include <vector>

namespace vofdem {

enum class EnergyBoundary { Adiabatic, Temperature, Flux, Convective };

struct EnergyFace {
  EnergyBoundary type = EnergyBoundary::Adiabatic;
  PetscReal      value = 0;       // K (temperature), W/m^2 into the box (flux), W/(m^2 K) (convective)
  PetscReal      ambient = 300;   // K (convective and radiation)
  PetscReal      emissivity = 0;  // radiation to the ambient (convective faces)
};

// One step's account and the state now (the monitor line).
struct EnergySummary {
  PetscReal total = 0;          // sum eps E dV, J
  PetscReal inputRate = 0;      // W into the cells at the end of the step: box faces + laser - losses
  PetscReal boundaryRate = 0;   // W through the box faces
  PetscReal lossRate = 0;       // W lost at interfaces (convection and radiation)
  PetscReal absorbed = 0;       // W of the laser deposited in the cells
  PetscReal beam = 0;           // W of the laser entering the box
  PetscReal balance = 0;        // J: the residuals the step's close put back into the cells (the iteration's remainder)
  PetscReal balanceRelative = 0;  // balance / |total|
  PetscReal accounted = 0;      // J: the integrated input by the scheme's own quadrature, plus the initial total
  PetscReal peak = 0, minimum = 0;  // K
  PetscReal meltVolume = 0;     // m^3 of metal above the pool isotherm's melt fraction (sum alpha f_l dV)
  PetscReal pool[3] = {0, 0, 0};  // extent in x, y, z of the -energy_pool_isotherm (length, width, depth), m
  PetscInt  iterations = 0;     // of the last step's enthalpy iteration
  PetscInt  linearIterations = 0;
};

class Energy {
public:
  PetscErrorCode SetFromOptions(const Grid &grid);
  PetscErrorCode SetUp();
  // With a moving interface (before SetUp): the metal fraction alpha is the interface's (a global vector of sg's
  // cells, followed after each sweep), and the energy moves with the sweeps (TransportSweep).
  void AttachInterface(const StaggeredGrid &sg, std::function<Vec()> alpha) { sg_ = &sg, interfaceAlpha_ = std::move(alpha); }
  bool Moving() const { return sg_ != nullptr; }
  // After the interface's sweep along d (u_d its face velocities, F_d its metal volume flux per face, c its
  // cells' Weymouth-Yue indicator): the metal and gas enthalpy fluxes F_d rho_m h_m(T_f) and (u_d - F_d) rho_g
  // h_g(T_f), T_f the van Leer face temperature (the donor's where the stencil mixes phases), and the dilatation term with h at the step's start
  // (docs/physics.md F7 a). A uniform T stays uniform; a closed box keeps its energy.
  PetscErrorCode TransportSweep(int d, PetscReal dt, Vec u, Vec phaseFlux, const std::vector<char> &full);
  // After the sweeps: the interface's redistribution of alpha between neighbours (particles; grid/CellMove.hpp),
  // with the metal's enthalpy at the giver's T and the gas's at the taker's (EnergyTransport.cpp).
  PetscErrorCode FollowRedistribution(const std::vector<CellMove> &moves);
  // Enthalpy put into the cells between steps (melted particles, docs/physics.md P12): dE J per cell (a global vector
  // of the cells), and gas moved between cells, gas m^3 per cell (summing to zero; nullptr: none), with the enthalpy
  // the losing cells' gas has at their T shared among the gaining cells by volume; T and f then follow from E, the
  // interface's alpha and the coupling's eps as they are now. Collective.
  PetscErrorCode AddEnthalpy(Vec dE, Vec gas);
  PetscErrorCode Step(PetscReal time, PetscReal dt);  // advances T from time to time + dt
  // With a moving interface: the Darcy term of the mushy zone and the solid metal (docs/physics.md F2) as a rate
  // per face of the staggered grid, c = D_c s_f^2/((1 - s_f)^3 + D_cs)/rho_f (1/s; s = alpha (1 - f_l) the
  // solid metal fraction, s_f the mean of the face's two cells, rho_f the face density of the momentum
  // equation), +inf at the faces of a cell held at rest (alpha >= -energy_freeze_alpha and f_l = 0); and
  // each cell's liquid share m (f_l where there is metal, 1 in gas) for the surface forces. rate[d]: global
  // vectors of the staggered grid's Face(d); liquid: of its cells.
  PetscErrorCode MushyDrag(Vec rate[3], Vec liquid);
  PetscInt       HeldCells() const { return heldCells_; }  // in the last MushyDrag (all ranks)
  PetscErrorCode Summarize(EnergySummary *s);         // the last step's account, the state now
  PetscErrorCode View(PetscViewer viewer) const;
  PetscReal      ExplicitLimit() const { return explicitLimit_; }  // s: what an explicit scheme would need
  PetscReal      StepLimit() const;  // s: the laser's (the beam moves a fraction of its radius) and the moving substrate's (0: none)
  bool           SubstrateMoving() const { return substrateVelocity_[0] != 0 || substrateVelocity_[1] != 0; }
  PetscErrorCode CheckBoiling(PetscReal time);                       // stops the run past the boiling point
  PetscErrorCode Save(PetscViewer viewer) const;
  PetscErrorCode Load(PetscViewer viewer);
  PetscErrorCode Destroy();
  // ParaView (-energy_output_every N): energy_<step>.h5 with T, the melt fraction alpha f and alpha, indexed by energy.xmf.
  PetscErrorCode SetOutputDir(const std::string &dir);
  PetscErrorCode WriteOutput(PetscInt step, PetscReal time);
  Vec            Temperature() const { return T_; }
  // Heat exchanged with particles (docs/physics.md F9; coupling/ParticleHeat.hpp): a source per cell (W/m^3, a global
  // vector of the cells) that each step's balance adds, and the energy the particles hold (J now, and J they brought:
  // their initial enthalpy and that of particles added since), which the account counts (Summarize). nullptr: none.
  // The fluid fraction eps of the cells and its change over the step (global vectors of the cells; not owned), from
  // the coupling that owns the particles (coupling/ParticleHeat.hpp); before the first step. nullptr: eps = 1.
  PetscErrorCode SetFluidFraction(Vec eps, Vec change);
  void SetParticleHeat(Vec source, std::function<PetscErrorCode(PetscReal *held, PetscReal *brought)> held) { particleSource_ = source, particleHeld_ = std::move(held); }
  // The beam's power per owned column (x fastest over this rank's x-y corners, W) that something above the melt took
  // before it (particles: coupling/ParticleBeam.hpp); the column's interface absorbs eta of what is left. nullptr: all.
  void SetBeamTaken(std::function<const std::vector<PetscReal> *()> taken) { beamTaken_ = std::move(taken); }
  Vec            MeltFraction();  // f_l per cell (alpha-weighted: the metal's), for output
  // Each cell's heat capacity per cell volume at its state now, eps [alpha rho_m dh_m/dT + (1 - alpha) rho_g cp_g]
  // (J/(m^3 K); the melt law's latent share included), into out (a global vector of the cells).
  PetscErrorCode HeatCapacity(Vec out) const;
  PetscErrorCode SolidFraction(Vec out) const;  // each cell's solid metal, alpha (1 - f), of its fluid (a global vector of the cells)
  PetscErrorCode HeldMask(Vec out) const;       // 1 in the cells the last MushyDrag held at rest, else 0 (a global vector of the cells)
  const Laser   &Beam() const { return laser_; }
  const ThermalMaterial &Metal() const { return metal_; }
  const ThermalMaterial &Gas() const { return gas_; }
  PetscInt       SavedVectors() const { return 4; }

private:
  PetscErrorCode ReadMaterials();
  PetscErrorCode FaceOptions(PetscOptionItems *items);
  PetscErrorCode SetInitial();
  PetscErrorCode RefreshFluidFraction();            // epsCells_, epsLocal_ from the coupling's eps (1 without)
  PetscErrorCode InitialEnergy();                   // E^0 = E^{-1} from T, f, alpha and eps; the account's start
  PetscErrorCode Properties();                      // E(T, f), C, F', F^{-1}(f), k at the state; T, k scattered to the local vectors
  PetscErrorCode LaserSource(PetscReal time);       // q_ (W/m^3), absorbed_, beam_
  PetscErrorCode Assemble(PetscReal a, PetscReal dt, int slot);  // the Jacobian at the current iterate into A_[slot]
  PetscErrorCode CreateSolver(int slot, const std::string &pc);
  PetscErrorCode SetUpSubstrate();                  // EnergySubstrate.cpp
  PetscErrorCode MoveSubstrate(PetscReal dt, bool history);  // the step's explicit sweeps of the moving substrate (and of E^{n-1})
  PetscErrorCode SweepSubstrate(int d, PetscReal dt, Vec E, Vec T, Vec F, PetscReal *entered);
  PetscErrorCode TemperatureOf(Vec E, Vec T, Vec F);
  PetscReal      SubstrateStepLimit() const;
  int            SolverFor(PetscReal dt) const;  // kJacobi or kMultigrid
  PetscErrorCode Residual(PetscReal a, PetscReal dt, PetscReal *maxResidual);  // r = a E - H - dt R(T)
  PetscErrorCode Update(PetscReal lambda);          // the enthalpy update with a fraction lambda of the correction
  PetscErrorCode CloseBalance(PetscReal a);         // E = (H + dt R)/a exactly from the last Residual; T, f from E
  PetscErrorCode CreateTransportScratch();          // the sweeps' ghosted work vectors, once
  PetscErrorCode FollowInterface(PetscReal later);  // alpha from the interface; T, f of the touched_ cells from E/eps
  PetscReal      CellTemperature(PetscReal E, PetscReal alpha, PetscReal guess) const;  // T with E(T, f_l(T)) = E
  XdmfEntry      OutputEntry(PetscInt step, PetscReal time) const;
  PetscErrorCode PoolExtent(PetscReal iso, PetscReal ext[3]);
  PetscReal      CellEnergy(PetscReal alpha, PetscReal T, PetscReal f) const;
  PetscReal      CellSensibleCapacity(PetscReal alpha, PetscReal T) const;
  PetscReal      LatentSlope(PetscReal T, PetscReal f, PetscReal *TF) const;  // F' and F^{-1}(f) of the linearisation
  PetscReal      CellConductivity(PetscReal alpha, PetscReal T) const;

  const Grid     *grid_ = nullptr;
  MPI_Comm        comm_ = MPI_COMM_NULL;
  ThermalMaterial metal_, gas_;
  std::string     metalName_ = "in718", gasName_ = "argon";
  Laser           laser_;
  EnergyFace      face_[6];
  PetscReal       gradient0_[3] = {0, 0, 0};  // K/m: -energy_initial_gradient
  PetscReal       T0_ = 300, boxT_ = 300, substrateT_ = 300, substrateTop_ = -PETSC_MAX_REAL;
  PetscReal       boxLower_[3] = {0, 0, 0}, boxUpper_[3] = {0, 0, 0};
  bool            box_ = false;
  PetscReal       metalTop_ = PETSC_MAX_REAL;  // m: metal below (no interface module)
  PetscReal       ambient_ = 300, interfaceConvection_ = 0;
  PetscBool       interfaceRadiation_ = PETSC_TRUE;
  bool            bdf2_ = true;
  PetscReal       tolerance_ = 1e-6;  // of a cell's residual, relative to rho_m (cp_m (T_l - T_s) + L)
  PetscInt        maxIterations_ = 50;
  PetscReal       kspAtol_ = 0;  // -energy_ksp_atol: the floor of each solve's absolute tolerance
  enum class PcRebuild { Iteration, Step } pcRebuild_ = PcRebuild::Step;  // -energy_pc_rebuild
  PetscReal       boilingMargin_ = 0, poolIsotherm_ = -1;
  PetscReal       mushyConstant_ = 1e8, mushyEpsilon_ = 1e-3, freezeAlpha_ = 0.5;  // the Darcy term (MushyDrag)
  PetscBool       holdSolid_ = PETSC_TRUE;
  bool            pfmg_ = true, autoPc_ = true, jacobiPc_ = false;  // -energy_pc
  PetscReal       explicitLimit_ = 0, energyScale_ = 1;

  DM        dm_ = nullptr;
  Vec       T_ = nullptr, E_ = nullptr, Eold_ = nullptr, H_ = nullptr, C_ = nullptr, Ecur_ = nullptr, k_ = nullptr, q_ = nullptr, alpha_ = nullptr;
  Vec       r_ = nullptr, rhs_ = nullptr, Tstar_ = nullptr, fl_ = nullptr;
  Vec       F_ = nullptr, slope_ = nullptr, TF_ = nullptr, Tbase_ = nullptr, Fbase_ = nullptr;  // f, F', F^{-1}(f), the iterate before an update
  Vec       TLocal_ = nullptr, kLocal_ = nullptr, alphaLocal_ = nullptr;
  static constexpr int kMultigrid = 0, kJacobi = 1;  // the solver slots
  PetscReal substrateCfl_ = 0.25;                   // -energy_substrate_cfl: the moving substrate's cells per step
  PetscReal substrateVelocity_[2] = {0, 0};         // -energy_substrate_velocity, m/s
  DM        wide_ = nullptr;                         // the cells with two ghosts (the substrate's van Leer stencil)
  Vec       wideGlobal_ = nullptr, wideT_ = nullptr, wideF_ = nullptr, Tinflow_ = nullptr, Told_ = nullptr, Fold_ = nullptr;
  Mat       A_[2]   = {nullptr, nullptr};
  KSP       ksp_[2] = {nullptr, nullptr};
  MPI_Comm  column_ = MPI_COMM_NULL;  // the ranks of one process column in z, top first

  // The account: steps done, the previous step, the accounted energy of the last two steps.
  PetscInt      steps_ = 0;
  PetscReal     dtOld_ = 0, W_ = 0, Wold_ = 0, totalOld_ = 0, totalOlder_ = 0;
  EnergySummary last_;

  const StaggeredGrid *sg_ = nullptr;  // with a moving interface
  std::function<Vec()> interfaceAlpha_;  // the interface's alpha (once it is set up)
  AijRowWriter         writer_[2];  // Assemble: the rows in place after the first (AIJ matrices)
  std::vector<PetscReal> faceConductance_, interfaceDensity_;  // Residual's k_f/h^2 per cell face and delta_s, for Assemble
  bool                 cacheValid_ = false;                   // they belong to the current state (Properties clears it)
  bool                 facesFilled_ = false;                  // Residual filled them, at the object states faceKey_ of
  PetscObjectState     faceKey_[3] = {0, 0, 0};               // kLocal_, epsLocal_, alphaLocal_
  bool                 kFilled_ = false;                      // Properties filled k_ (and kLocal_), at alpha_'s state kAlphaState_
  PetscObjectState     kAlphaState_ = 0;
  bool                 epsUnit_ = false;                      // epsCells_, epsLocal_ hold eps = 1 (no particles; RefreshFluidFraction)
  PetscInt             capacityVersion_ = 0;                  // Properties: how often some cell's C changed (Assemble's key)
  // Assemble: the inputs of the Jacobian in A_[slot] as last assembled (a, dt, the object states of kLocal_, epsLocal_,
  // alphaLocal_, capacityVersion_); the same inputs leave the matrix as it is, unless it depends on T (radiation).
  struct JacobianKey {
    bool             valid = false;
    PetscReal        a = 0, dt = 0;
    PetscObjectState k = 0, eps = 0, alpha = 0;
    PetscInt         capacity = 0;
  } jacobianKey_[2];
  // LaserSource: the beam (power, centre) and the object states of alphaLocal_ and q_ of the deposit q_ holds, its sums.
  struct LaserKey {
    bool             valid = false;
    PetscReal        power = 0, x = 0, y = 0, beam = 0, absorbed = 0;
    PetscObjectState alpha = 0, q = 0;
  } laserKey_;
  std::vector<char>    touched_;  // TransportSweep: the owned cells a sweep changed
  PetscLogEvent        evLaser_ = 0, evProperties_ = 0, evResidual_ = 0, evAssemble_ = 0, evClose_ = 0, evTransport_ = 0, evMushy_ = 0;  // -log_view
  Vec                  Tsg_ = nullptr, TsgLocal_ = nullptr, Fsg_ = nullptr, FsgLocal_ = nullptr, AsgLocal_ = nullptr, uLocal_[3] = {nullptr, nullptr, nullptr},
                       fluxLocal_[3] = {nullptr, nullptr, nullptr}, Xstart_ = nullptr;
  bool                 swept_ = false;
  PetscReal            advectedOld_ = 0;  // J the substrate's sweep of E^{n-1} carried through the box's faces (this rank's)
  PetscReal            advected_ = 0;  // J through the box's faces in this step's sweeps (this rank's; the account)
  Vec                  sLocal_ = nullptr, rhoLocal_ = nullptr, sGlobal_ = nullptr, rhoGlobal_ = nullptr;  // MushyDrag: the solid fraction (held: -1) and the density, ghosted
  PetscInt             heldCells_ = 0;  // this step's sweeps have begun (Xstart_ holds the step's dilatation enthalpy)

  PetscInt               outputEvery_ = 0;
  std::string            outputDir_;
  std::vector<XdmfEntry> outputEntries_;

  Vec       epsFluid_ = nullptr, epsChange_ = nullptr;  // SetFluidFraction (not owned)
  Vec       epsCells_ = nullptr, epsLocal_ = nullptr, EpsSgLocal_ = nullptr;  // eps (1 without particles), ghosted on dm_ and on sg's cells
  int       sweep_ = 0;  // TransportSweep: the step's sweeps so far (eps after the k-th is eps^n + k/3 of its change)

  std::function<const std::vector<PetscReal> *()>       beamTaken_;  // SetBeamTaken
  Vec                                                   particleSource_ = nullptr;  // SetParticleHeat
  std::function<PetscErrorCode(PetscReal *, PetscReal *)> particleHeld_;
};

}  // namespace vofdem
