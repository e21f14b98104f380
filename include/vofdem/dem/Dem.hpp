// The particle module (-physics dem): spheres of several types (Materials.hpp) on a DMSwarm, gravity,
// Hertz-Mindlin or linear contacts with damping, tangential springs and Coulomb friction (docs/physics.md
// P3, P4), rolling resistance (P5), JKR, SJKR or van der Waals adhesion (P6, P7), lubrication (P8),
// against each other, the box faces and the walls of -dem_walls (Walls.hpp); velocity Verlet with a
// Rayleigh-time step (P9); Verlet lists with a skin, ghost particles across ranks (Halo.hpp),
// migration with a particle-count check, periodic directions (PeriodicImages.hpp), load balancing
// (DemBalance.cpp), Morton order (MortonOrder.hpp); insertion and deletion (ParticleSources.hpp);
// output, stress and Save/Load (DemOutput.hpp, DemSaveLoad.cpp).
#pragma once

#include "vofdem/dem/Bonds.hpp"
#include "vofdem/dem/Clumps.hpp"
#include "vofdem/dem/ContactRecord.hpp"
#include "vofdem/dem/DemOutput.hpp"
#include "vofdem/dem/Halo.hpp"
#include "vofdem/dem/HertzMindlin.hpp"
#include "vofdem/dem/Materials.hpp"
#include "vofdem/dem/MortonOrder.hpp"
#include "vofdem/dem/NeighbourList.hpp"
#include "vofdem/dem/ParticleSources.hpp"
#include "vofdem/dem/ParticleSwarm.hpp"
#include "vofdem/dem/SurfaceForce.hpp"
#include "vofdem/dem/Walls.hpp"
#include "vofdem/grid/Grid.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace vofdem {

class RankArchive;

// Global totals over all ranks, for monitors and tests.
struct DemSummary {
  PetscInt  particles    = 0;
  PetscReal kinetic      = 0;  // translational kinetic energy, J
  PetscReal rotational   = 0;  // rotational kinetic energy, J
  PetscReal elastic      = 0;  // energy stored in the normal Hertz springs of all contacts (JKR contacts not counted), J
  PetscReal mass         = 0;  // total particle mass, kg
  PetscInt  pairContacts = 0;
  PetscInt  wallContacts = 0;
  PetscReal coordination = 0;  // mean number of particle contacts per particle
  PetscReal maxOverlap   = 0;  // largest overlap / diameter (particles and walls)
  PetscReal wallForce[6][3] = {};  // force of the particles on each face (x-, x+, y-, y+, z-, z+), N
  PetscBool  sources  = PETSC_FALSE;  // insertion sources or deletion boxes exist (ParticleSources)
  PetscInt64 inserted = 0, deleted = 0;  // particles inserted by the sources and deleted so far
  PetscReal  massInserted = 0, massDeleted = 0;  // kg
  PetscBool  bonds = PETSC_FALSE;                 // -dem_cohesion bond (P13)
  PetscInt64 bondsMade = 0, bondsIntact = 0, bondsBroken = 0;
  PetscReal  bondSigma = 0, bondTau = 0;          // largest sigma / strength and tau / strength of the intact bonds at the last evaluation
  std::vector<WallLoad> walls;     // force and torque on each wall of -dem_walls (Walls.hpp)
};

class Dem {
public:
  PetscErrorCode SetFromOptions(MPI_Comm comm);
  // Creates the swarm on the grid's vertex DMDA, fills the insertion region, evaluates forces.
  // The grid is not const: -dem_balance may repartition it (DemBalance.cpp).
  PetscErrorCode SetUp(Grid &grid, const PetscReal gravity[3], std::uint64_t seed);
  // Largest stable step: -dem_dt_factor times the Rayleigh time (P9), or less where JKR bonds at rest or
  // the contacts as they are (loaded, damped) are stiffer than that covers (HertzMindlin.hpp SpinStep).
  // Bonds (P13) may bind it too (Bonds::StepLimit).
  PetscReal StableTimeStep() const { return std::min(std::min(std::min(dtFactor_ * rayleighTime_, jkrStepLimit_), contactStepLimit_), bondStepLimit_); }
  PetscReal RayleighTime() const { return rayleighTime_; }
  // What StableTimeStep() is a fraction of, for the banner.
  const char *TimeStepBasis() const {
    if (bondStepLimit_ < std::min(std::min(dtFactor_ * rayleighTime_, jkrStepLimit_), contactStepLimit_))
      return "dem bonds (the lightest sphere in 12 bonds of the largest section, omega dt = 1; Bonds::StepLimit)";
    if (contactStepLimit_ < std::min(dtFactor_ * rayleighTime_, jkrStepLimit_))
      return "dem contacts as they are (the stable step of the sphere whose contacts spin stiffest, HertzMindlin.hpp SpinStep; -dem_contact_step_every)";
    if (jkrStepLimit_ < dtFactor_ * rayleighTime_) return "dem JKR bonds at rest (0.8 x the stable step of a sphere spinning in 12 bonds, HertzMindlin.hpp SpinStep)";
    return linear_ ? "dem (-dem_dt_factor x contact time/10 of the linear spring, P4)" : "dem (-dem_dt_factor x Rayleigh time, P9)";
  }
  PetscErrorCode Step(PetscReal dt);  // one velocity-Verlet step
  // Collective: removes the local particles of indices `local` (this rank's; their springs go with them) through a
  // rebuild, and counts them in the deletion books (ParticleSources: deleted, mass deleted). For a coupling that
  // takes particles into the fluid (melting, docs/physics.md P12). Their neighbours keep the forces of the last
  // evaluation for the next half kick.
  PetscErrorCode RemoveParticles(const std::vector<PetscInt> &local);
  // Collective (DemTouching.cpp), for a coupling that moves something through the contacts (contact conduction,
  // docs/physics.md P11): the particle pairs of the neighbour list that touch at the particles' positions now
  // (the ghosts' sent with the values), with their contact radius: Hertz's sqrt(R* delta), or with
  // -dem_cohesion jkr the JKR radius the pair's spring holds while it is bonded. Pairs come lower id first (a, b;
  // an index >= n is the ghost n + g), so that the two ranks of a pair see the same numbers. values (width per local
  // particle, the swarm's order) go to the ghosts with the positions: ghostValues, width per ghost.
  struct TouchingPair {
    PetscInt  a, b;
    PetscReal contactRadius;  // m
  };
  PetscErrorCode TouchingPairs(int width, const PetscReal *values, std::vector<PetscReal> *ghostValues, std::vector<TouchingPair> *pairs) const;
  PetscErrorCode Summarize(DemSummary *s) const;
  // Collective: writes every particle, in id order, as the CSV that -dem_particles_file reads
  // (x,y,z,vx,vy,vz,wx,wy,wz), through rank 0; the file is written to a temporary name and renamed.
  PetscErrorCode SaveParticles(const std::string &path) const;
  const std::string &SaveParticlesPath() const { return savePath_; }
  // Collective (ContactHistoryFile.cpp): the springs of the touching particle pairs and box-face contacts
  // (tangential, rolling, JKR radius and bond) as the CSV -dem_contact_history_file reads, the particles by
  // their rows in SaveParticles' file.
  PetscErrorCode SaveContactHistory(const std::string &path) const;
  const std::string &SaveContactHistoryPath() const { return saveHistoryPath_; }
  PetscErrorCode View(PetscViewer viewer) const;
  PetscErrorCode Destroy();
  // Collective, HDF5 viewer (DemSaveLoad.cpp): all DEM state, under the group "dem". Load after
  // SetUp() with the saving run's options; bitwise continuation on the same rank count.
  PetscErrorCode Save(PetscViewer viewer);
  PetscErrorCode Load(PetscViewer viewer);
  // Collective: about how many bytes Save writes (all ranks), for the checkpoint's disk-space check.
  PetscErrorCode SavedBytes(PetscInt64 *bytes) const;
  // Output and analysis (DemOutput.cpp). SetOutputDir: after SetUp, with -output_dir (may be
  // empty); WriteOutput: after SetUp and after each step, writes what is due at this step.
  PetscErrorCode SetOutputDir(const std::string &dir);
  PetscErrorCode WriteOutput(PetscReal time);
  // Love-Weber stress of the -dem_stress_* region, compression positive: xx yy zz xy xz yz, Pa.
  PetscErrorCode Stress(PetscReal sigma[6]) const;
  // Extra monitor columns (empty unless a stress region is set): CSV header, then values.
  std::string    MonitorHeader() const;
  PetscErrorCode MonitorValues(std::string *csv, std::string *screen) const;

  // Collective: position, velocity and angular velocity of the particle with global id `id`;
  // found is false on all ranks when no rank has it.
  PetscErrorCode FindParticle(std::int64_t id, PetscReal x[3], PetscReal v[3], PetscBool *found, PetscReal omega[3] = nullptr,
                              PetscReal force[3] = nullptr) const;
  const DemMaterial &Material() const { return material_; }  // the default type's (type 0 when -dem_types is not given)
  // Particle types (-dem_types): names, materials and the mixed pair table.
  PetscInt                        TypeCount() const { return (PetscInt)typeNames_.size(); }
  const std::vector<std::string> &TypeNames() const { return typeNames_; }
  const DemMaterial              &TypeMaterial(PetscInt t) const { return types_[t]; }
  const MaterialTable            &Materials() const { return table_; }
  PetscReal          Radius() const { return radius_; }  // -dem_radius: the single size, and the default one
  PetscReal          MinRadius() const { return rMin_; }
  PetscReal          MaxRadius() const { return rMax_; }
  DM                 Swarm() const { return swarm_.Dm(); }
  const ParticleSwarm &Particles() const { return swarm_; }
  // The fluid coupling (Coupling.hpp) sets the swarm's fluid_* fields; the integrator then applies them.
  void               SetFluidCoupled(bool on) { fluidCoupled_ = on, swarm_.SetFluidFields(on); }
  void               UseFluidFields() { swarm_.SetFluidFields(true); }  // a coupled scene, before SetUp (ParticleSwarm::GetArrays)
  void               UseHeatFields() { swarm_.SetHeatFields(true); }    // particles that exchange heat (P11), before SetUp
  bool               Balancing() const { return balance_; }  // -dem_balance histogram
  // This rank's load as -dem_balance weighs it: its particles plus -dem_balance_contact_weight x their
  // contacts at the last force evaluation (DemBalance.cpp).
  PetscErrorCode BalanceLoad(PetscReal *load) const;
  // A free surface's force on the particles (SurfaceForce.hpp; the coupling's capillary force): every kick adds
  // F_n(R, s) n at the particle's current height s above its fluid_surface_plane.
  void               SetSurfaceForce(const SurfaceForce &force) { surfaceForce_ = force; }
  // -coupling_lubrication: the lubrication (P8) takes the fluid's viscosity instead of -dem_lubrication_viscosity (an
  // input error with both). uniform > 0: the flow's single viscosity; 0: each particle's fluid_viscosity (the mixture it
  // reads with a free surface), the mean of the two for a pair, carried to the ghosts by the halo. Before SetUp.
  PetscErrorCode     SetFluidLubrication(PetscReal uniform);
  PetscReal          Skin() const { return skin_; }  // Verlet skin: particles stray up to half of it outside their rank's box
  const ParticleSources &Sources() const { return sources_; }  // insertion and deletion books
  PetscReal          FillVolumeFraction() const { return fillReached_; }  // reached by the random fill (0: none)
  // Monitor-table columns of the -dem_walls loads (",wall_<name>_fx_N,..."; empty without walls).
  std::string WallLoadColumns() const { return wallSet_.CsvColumns(); }
  // Monitor-table columns of the bonds (P13): made, intact and broken so far, the largest sigma / tensile and
  // tau / shear strength of the intact bonds at the last evaluation (empty without -dem_cohesion bond).
  std::string BondColumns() const { return bonds_.On() ? ",bonds_made,bonds_intact,bonds_broken,bond_sigma_per_strength,bond_tau_per_strength" : ""; }

private:
  PetscErrorCode Fill(std::uint64_t seed);              // DemFill.cpp
  PetscErrorCode FillRandom(std::uint64_t seed);        // DemFill.cpp: -dem_fill_mode random
  PetscErrorCode ReadParticles();                       // DemFill.cpp: -dem_particles_file
  // ContactHistoryFile.cpp: -dem_contact_history_file, for the particles ReadParticles just made (ids start + row);
  // the springs of pairs with a particle on this rank go into springs_ for the first Rebuild().
  PetscErrorCode ReadContactHistory(size_t rows, PetscInt64 start, const std::vector<char> &ownedRow);
  bool           ParticlesFileNamesClumps() const;      // DemFill.cpp: its header has a clump column
  void           StoreFilled(const ParticleArrays &a, PetscInt p, PetscInt64 id, const PetscReal x[3], PetscReal r, std::uint64_t seed) const;
  PetscErrorCode Rebuild();                             // DemContacts.cpp: migrate, halo, list, springs
  void           JkrPairConstants();                    // DemContacts.cpp: jkrPairs_ for the list as it is
  PetscErrorCode ComputeForces(PetscReal dt);           // DemContacts.cpp
  PetscErrorCode UpdateContactStepLimit();              // DemContacts.cpp: contactStepLimit_ from the contacts (collective)
  void           SetUpBonds();                          // DemBonds.cpp: the bonds' reach and step limit (SetUp)
  PetscErrorCode ViewBonds(PetscViewer viewer) const;   // DemBonds.cpp: the banner's line
  void           MakeBonds();                           // DemBonds.cpp: bonds between the list's close pairs (-dem_bond_at_time)
  PetscErrorCode SummarizeBonds(DemSummary *s) const;   // DemBonds.cpp (collective)
  // cohesion: 0 none, 1 JKR, 2 SJKR; near: forces across a gap (van der Waals and/or lubrication)
  template <hertz::Rolling model, int cohesion, bool near, bool linear, bool multi>
  PetscErrorCode ComputeForcesWith(PetscReal dt);
  PetscErrorCode TypesFromOptions(PetscOptionItems *items);  // Dem.cpp: -dem_types, -dem_type_*, -dem_pair_*
  PetscInt       TypeIndex(const std::string &name) const;    // -1 when unknown
  PetscErrorCode ExchangeSprings(const std::vector<PetscInt64> &localIds);
  // DemBalance.cpp: -dem_balance; Balance() repartitions the grid by particle counts at a rebuild
  // when they are uneven and moves the particles, GatherSprings() then hands every rank all springs.
  PetscErrorCode SetBalanceFromOptions(PetscOptionItems *PetscOptionsObject);
  PetscErrorCode Balance(PetscBool *repartitioned);
  PetscErrorCode GatherSprings();
  PetscBool      balance_ = PETSC_FALSE;  // -dem_balance histogram
  PetscReal      balanceThreshold_ = 1.2;
  PetscReal      balanceContactWeight_ = 5;    // -dem_balance_contact_weight
  std::vector<PetscReal> balanceLoads_;        // contact loads per cell layer (x, y, z layers), BalanceContactLoads()
  std::vector<PetscInt>  balanceContacts_;     // scratch: contacts per local particle
  PetscReal              balanceLocalContacts_ = 0;
  void                   BalanceContactLoads(const ParticleArrays &a);
  PetscErrorCode         RestoreOwnership(const std::vector<PetscReal> &savedBox);  // DemSaveLoad.cpp
  void                   CountContacts(PetscInt n, std::vector<PetscInt> *c) const;
  PetscBool      balanceMonitor_ = PETSC_TRUE;
  PetscInt       repartitions_ = 0;
  struct SavedState;  // DemSaveLoad.cpp: what is archived besides members
  PetscErrorCode ArchiveState(RankArchive &ar, SavedState &st);
  PetscErrorCode WriteParticles(PetscReal time);  // DemOutput.cpp
  PetscErrorCode WriteContacts(PetscReal time);

  // Per-evaluation contact statistics of this rank (summed over ranks by Summarize).
  struct LocalStats {
    PetscInt  pairContacts = 0, wallContacts = 0;
    PetscReal maxOverlap = 0, elastic = 0, wallForce[6][3] = {};
    PetscReal bondSigma = 0, bondTau = 0;  // largest load / strength of the intact bonds (P13)
  };

  // The state the pair loop reads, local particles then ghosts, packed so that one particle is one
  // or two cache lines and no branch picks between local and ghost arrays; filled per evaluation.
  struct HotParticle {
    PetscReal x[3], v[3], w[3], r, m, mu;  // mu: the fluid viscosity of -coupling_lubrication (1 otherwise)
  };
  // Rolling parameters of the single-type fast path; the pair table otherwise.
  std::vector<HotParticle> hot_;

  Grid         *grid_ = nullptr;
  ParticleSwarm swarm_;
  Clumps        clumps_;  // rigid multi-sphere bodies (P10) of the particles file's clump ids
  PetscInt      clumpCount_ = 0;
  MortonOrder   sort_;  // -dem_sort_every: Z-order of the local particles at rebuilds (MortonOrder.hpp)
  Halo          halo_;
  NeighbourList list_;
  std::vector<unsigned char> pairImage_;  // periodic image of each list pair (PeriodicImages.hpp)
  std::vector<hertz::JkrPair> jkrPairs_;  // JKR constants of each list pair (with -dem_cohesion jkr), made with the list
  WallList      walls_;
  WallSet       wallSet_;  // -dem_walls: planes, cylinders, STL meshes (Walls.hpp)
  ContactHistory springs_;  // only during Rebuild()
  std::vector<PetscInt64> removeIds_;  // RemoveParticles: the ids the next Rebuild() removes
  Bonds          bonds_;    // -dem_cohesion bond (P13): histories per list pair, carried like the springs
  PetscReal      bondStepLimit_ = PETSC_MAX_REAL;  // s (SetUp)
  LocalStats    stats_;
  DemMaterial   material_;  // -dem_density etc.: the default type, and what -dem_types start from
  std::vector<std::string> typeNames_;  // -dem_types; {"default"} without it
  std::vector<DemMaterial> types_;
  std::vector<PairValues>  pairValues_;  // nt*nt, given pair values (< 0: mixed)
  MaterialTable            table_;
  PetscInt                 fillType_ = 0;  // -dem_fill_type
  PetscReal     wallYoungs_ = -1, wallPoisson_ = -1, wallFriction_ = -1, wallRestitution_ = -1;  // default: the particles'
  PetscBool     limitForce_ = PETSC_FALSE;
  hertz::Rolling       rolling_ = hertz::Rolling::None;
  int                  normalRow_ = 0, cohesionRow_ = 0, rollingRow_ = 0;  // rows of ContactLawTable.hpp (hertz, none, none)
  PetscBool            jkr_ = PETSC_FALSE;                    // -dem_cohesion jkr (P6)
  PetscReal            surfaceEnergy_ = 0, wallSurfaceEnergy_ = -1;  // J/m^2, one surface
  PetscReal            adhesionRange_ = 0;                    // m, JKR break distance or vdW range: widens the cut-offs
  hertz::VanDerWaals   vdw_{};                                // -dem_hamaker > 0 switches it on (P7)
  PetscBool            vdwWalls_ = PETSC_TRUE;                // -dem_vdw_walls: walls attract too
  hertz::VanDerWaals   noVdw_{0, 1, 0};                       // what the walls get with -dem_vdw_walls 0 (A = 0; z0 > 0: no 0/0 in contact)
  PetscBool            sjkr_ = PETSC_FALSE;                   // -dem_cohesion sjkr (P6, LIGGGHTS' definition)
  PetscReal            sjkrDensity_ = 0;                      // J/m^3
  PetscReal            surfaceEnergyModulus_ = 0;             // Pa; > 0: scale surface energies (P9)
  std::vector<PetscReal> measuredSurfaceEnergy_;              // before that scaling, per type
  hertz::Lubrication   lubrication_{};                        // -dem_lubrication_viscosity > 0 switches it on (P8)
  bool                 fluidLubrication_ = false;             // SetFluidLubrication: viscosity 1, times each pair's mu
  PetscReal            lubricationUniform_ = 0;               // Pa s, SetFluidLubrication's uniform value (0: per particle)
  PetscBool            linear_ = PETSC_FALSE;                 // -dem_contact linear (P4) instead of Hertz-Mindlin
  PetscReal            linearKn_ = 1e5, linearKtRatio_ = 1;   // N/m; k_t / k_n
  hertz::RollingParams rollingParams_{};
  hertz::PairMaterial pair_{}, wall_{};
  PetscReal     radius_     = 5e-4;  // m
  PetscReal     rMin_ = 0, rMax_ = 0;  // smallest and largest radius present (set after insertion)
  PetscReal     dtFactor_   = 0.3;   // of the Rayleigh time (seed 001)
  PetscReal     skin_       = 0;     // m, Verlet skin
  PetscReal     gravity_[3] = {0, 0, 0};
  PetscReal     rayleighTime_ = 0;
  PetscReal     jkrStepLimit_ = PETSC_MAX_REAL;   // s, JKR bonds at rest (SetUp)
  static constexpr PetscReal kJkrStepSafety = 0.8;  // of SpinStep's stability bound
  // The contacts' own bound (UpdateContactStepLimit), measured every -dem_contact_step_every steps (0: never)
  PetscReal     contactStepLimit_ = PETSC_MAX_REAL;  // s
  PetscInt      contactStepEvery_ = 10;
  bool          contactStepNoted_ = false;  // the note that the contacts bind the step is printed once
  static constexpr PetscReal kContactStepSafety = 1.0;  // the bound of the stiffest sphere is a Gershgorin bound already (conservative)
  std::vector<PetscReal> spinW2_, spinRate_;  // per local particle, reused
  PetscInt      rebuilds_   = 0;
  PetscInt      steps_      = 0;  // steps begun since SetUp (output schedule)
  DemOutputSettings out_;
  ContactRecord     record_;  // contact forces, on evaluations whose output needs them
  // -log_view events: where a DEM step spends its time.
  PetscLogEvent evRebuild_ = 0, evHalo_ = 0, evForces_ = 0, evIntegrate_ = 0;

  // Lattice fill of a region (-dem_fill_*)
  PetscReal fillLower_[3] = {0, 0, 0}, fillUpper_[3] = {0, 0, 0};
  PetscBool fillLowerSet_ = PETSC_FALSE, fillUpperSet_ = PETSC_FALSE;
  PetscReal fillSpacing_  = 0;  // m; 0 = 2.2 radii
  PetscReal fillJitter_   = 0;  // fraction of the free gap
  PetscInt  fillCount_    = 0;  // 0 = no fill, -1 = as many as fit
  PetscReal fillVelocity_[3] = {0, 0, 0};
  PetscReal fillSpread_   = 0;  // m/s, random velocity components uniform in [-spread, spread]
  SizeDistribution fillSizes_;  // -dem_fill_size_distribution and its parameters
  PetscBool fillRandom_   = PETSC_FALSE;  // -dem_fill_mode random
  PetscReal fillFraction_ = 0;            // -dem_fill_volume_fraction (random fill)
  PetscInt  fillAttempts_ = 1000;         // -dem_fill_attempts (random fill)
  PetscReal fillReached_  = 0;            // volume fraction the random fill reached
  ParticleSources sources_;  // insertion during the run and deletion boxes
  PetscReal time_ = 0;       // s, sum of the steps taken (insertion schedules)
  std::string particlesFile_;  // CSV: x,y,z,vx,vy,vz[,wx,wy,wz] per line, one header line
  std::string savePath_;       // -dem_save_particles: the same CSV at the end of the run
  std::string historyFile_;      // -dem_contact_history_file: the pairs' springs of the particles file
  std::string saveHistoryPath_;  // -dem_save_contact_history: the same at the end of the run
  PetscInt  inserted_     = 0;
  bool      fluidCoupled_ = false;
  SurfaceForce surfaceForce_;  // SetSurfaceForce; no law: no surface force
  MPI_Comm  comm_         = MPI_COMM_NULL;
};

}  // namespace vofdem
