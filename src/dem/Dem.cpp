#include "vofdem/dem/Dem.hpp"
#include "vofdem/dem/ContactLawTable.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/io/TextFile.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace vofdem {

PetscErrorCode Dem::SetFromOptions(MPI_Comm comm) {
  PetscFunctionBeginUser;
  comm_ = comm;
  PetscOptionsBegin(comm, "dem_", "Particles (DEM)", "Dem");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.Real("-radius", "Particle radius", "m", &radius_, RealRange::Positive()));
    PetscCall(opt.Real("-density", "Particle density", "kg/m^3", &material_.density, RealRange::Positive()));
    PetscCall(opt.Real("-youngs_modulus", "Particle Young's modulus E", "Pa", &material_.youngs, RealRange::Positive()));
    PetscCall(opt.Real("-poisson_ratio", "Particle Poisson ratio nu", "-", &material_.poisson, RealRange::LeftOpen(-1, 0.5)));
    PetscCall(opt.Real("-restitution", "Coefficient of restitution e (P3)", "-", &material_.restitution, RealRange::LeftOpen(0, 1)));
    PetscCall(opt.Real("-friction", "Sliding friction coefficient mu_s (P3)", "-", &material_.friction, RealRange::NonNegative()));
    {
      std::vector<std::string> chosen = {contact::kRollingLaws[rollingRow_].name};
      const std::string        help   = "Rolling resistance (P5): " + contact::Help(contact::kRollingLaws);
      PetscCall(opt.NameList("-rolling", help.c_str(), contact::Names(contact::kRollingLaws), &chosen));
      if (chosen.size() != 1) VofdemInputError(comm, "option -dem_rolling: give one model (%s)", contact::Choices(contact::kRollingLaws).c_str());
      rollingRow_ = contact::Find(contact::kRollingLaws, chosen[0]);
      rolling_    = contact::kRollingLaws[rollingRow_].model;
      PetscCall(opt.Real("-rolling_friction", "Rolling friction coefficient mu_r (P5)", "-", &material_.rollingFriction, RealRange::NonNegative()));
      PetscCall(opt.Real("-rolling_damping", "EPSD rolling damping as a fraction of critical", "-", &rollingParams_.eta, RealRange::NonNegative()));
      PetscBool twist = rollingParams_.twist ? PETSC_TRUE : PETSC_FALSE;
      PetscCall(opt.Bool("-rolling_twist", "EPSD: the spring-dashpot resists the twist about the contact normal as well as rolling (P5; 0: rolling only)", &twist));
      rollingParams_.twist = twist == PETSC_TRUE;
      static const std::vector<std::string> loads = {"compression", "magnitude", "adhesion"};
      std::vector<std::string>              load  = {"compression"};
      PetscCall(opt.NameList("-rolling_load",
                             "Load N of the rolling cap mu_r R* N (P5): compression (max(F_n,0)), magnitude (|F_n|, P5 as written), adhesion (max(F_n + 2 F_c,0), as the sliding limit with JKR)",
                             loads, &load));
      if (load.size() != 1) VofdemInputError(comm, "option -dem_rolling_load: give one of compression, magnitude or adhesion");
      rollingParams_.load = load[0] == "magnitude" ? hertz::RollingLoad::Magnitude : load[0] == "adhesion" ? hertz::RollingLoad::Adhesion : hertz::RollingLoad::Compression;
    }
    {
      std::vector<std::string> chosen = {contact::kNormalLaws[normalRow_].name};
      const std::string        help   = "Normal contact law: " + contact::Help(contact::kNormalLaws);
      PetscCall(opt.NameList("-contact", help.c_str(), contact::Names(contact::kNormalLaws), &chosen));
      if (chosen.size() != 1) VofdemInputError(comm, "option -dem_contact: give one law (%s)", contact::Choices(contact::kNormalLaws).c_str());
      normalRow_ = contact::Find(contact::kNormalLaws, chosen[0]);
      linear_    = (PetscBool)contact::kNormalLaws[normalRow_].linear;
      PetscCall(opt.Real("-linear_stiffness", "Normal stiffness k_n of the linear law (seed 002: 1e5)", "N/m", &linearKn_, RealRange::Positive()));
      PetscCall(opt.Real("-linear_tangential_ratio", "k_t / k_n of the linear law (seed 002: 1)", "-", &linearKtRatio_, RealRange::Positive()));
    }
    {
      std::vector<std::string> chosen = {contact::kCohesionLaws[cohesionRow_].name};
      const std::string        help   = "Adhesion between touching surfaces: " + contact::Help(contact::kCohesionLaws);
      PetscCall(opt.NameList("-cohesion", help.c_str(), contact::Names(contact::kCohesionLaws), &chosen));
      if (chosen.size() != 1) VofdemInputError(comm, "option -dem_cohesion: give one model (%s)", contact::Choices(contact::kCohesionLaws).c_str());
      cohesionRow_ = contact::Find(contact::kCohesionLaws, chosen[0]);
      jkr_         = (PetscBool)(contact::kCohesionLaws[cohesionRow_].model == kJkr);
      sjkr_        = (PetscBool)(contact::kCohesionLaws[cohesionRow_].model == kSjkr);
      PetscCall(bonds_.SetFromOptions(opt, comm, contact::kCohesionLaws[cohesionRow_].model == kBond, radius_));  // -dem_bond_* (Bonds.cpp, P13)
      PetscCall(opt.Real("-cohesion_energy_density", "SJKR cohesion energy density k: F = k A_overlap (P6; LIGGGHTS' cohesionEnergyDensity)", "J/m^3", &sjkrDensity_,
                         RealRange::NonNegative()));
      if (sjkr_ && sjkrDensity_ == 0) VofdemInputError(comm, "option -dem_cohesion sjkr needs -dem_cohesion_energy_density > 0");
      PetscCall(opt.Real("-surface_energy_modulus", "Young's modulus at which the surface energies were measured: when given, each is scaled to the "
                                                   "modulus in use by (E'/E)^(2/5) (P9, Haervig et al. 2017); 0: they are given for the modulus in use and are never scaled",
                         "Pa", &surfaceEnergyModulus_, RealRange::NonNegative()));
      PetscCall(opt.Real("-surface_energy", "Surface energy gamma of one particle surface; work of adhesion w = 2 gamma (P6)", "J/m^2", &material_.surfaceEnergy,
                         RealRange::NonNegative()));
      PetscCall(opt.Real("-wall_surface_energy", "Surface energy of the walls (default: each particle type's); w = gamma_p + gamma_w", "J/m^2", &wallSurfaceEnergy_,
                         RealRange::NonNegative()));
      vdw_.minGap = 0.165e-9;
      vdw_.range  = 1e-6;
      PetscCall(opt.Real("-hamaker", "Hamaker constant A of van der Waals attraction (P7); 0: none (regolith: 4.3e-20)", "J", &vdw_.hamaker, RealRange::NonNegative()));
      PetscCall(opt.Real("-vdw_min_gap", "Gap z0 below which the van der Waals force is held constant (P7)", "m", &vdw_.minGap, RealRange::Positive()));
      PetscCall(opt.Real("-vdw_range", "Gap beyond which van der Waals attraction is dropped", "m", &vdw_.range, RealRange::Positive()));
      if (vdw_.hamaker > 0 && (jkr_ || sjkr_)) VofdemInputError(comm, "options -dem_hamaker and -dem_cohesion %s: choose one adhesion model", jkr_ ? "jkr" : "sjkr");
      // Seed 002 writes its eq. 8 for pairs of spheres ("between rigid spheres") and does not say whether the walls
      // (rigid shells) attract: both readings are offered, walls attracting by default (R* = R, as a sphere of
      // infinite radius).
      PetscCall(opt.Bool("-vdw_walls", "Van der Waals attraction (P7) between particles and walls as well as between particles", &vdwWalls_));
      PetscCall(opt.Real("-lubrication_viscosity", "Viscosity of the liquid between particles for lubrication (P8); 0: none", "Pa s", &lubrication_.viscosity,
                         RealRange::NonNegative()));
      lubrication_.minGap = 0.01 * radius_;
      lubrication_.maxGap = 0.2 * radius_;
      PetscCall(opt.Real("-lubrication_min_gap", "Gap below which lubrication is held at its value (default 0.01 -dem_radius)", "m", &lubrication_.minGap,
                         RealRange::Positive()));
      PetscCall(opt.Real("-lubrication_max_gap", "Gap beyond which lubrication is dropped (default 0.2 -dem_radius)", "m", &lubrication_.maxGap, RealRange::Positive()));
      if (lubrication_.viscosity > 0 && !(lubrication_.maxGap > lubrication_.minGap))
        VofdemInputError(comm, "option -dem_lubrication_max_gap: %g m must exceed -dem_lubrication_min_gap %g m", (double)lubrication_.maxGap, (double)lubrication_.minGap);
      if (contact::kNormalLaws[normalRow_].linear && contact::kCohesionLaws[cohesionRow_].hertzOnly)
        VofdemInputError(comm, "option -dem_cohesion %s needs -dem_contact hertz (a Hertzian theory)", contact::kCohesionLaws[cohesionRow_].name);
    }
    PetscCall(opt.Bool("-limit_force", "Clip the normal contact force at zero: no tension from damping as a contact ends (LIGGGHTS' limitForce); the restitution then differs from -dem_restitution", &limitForce_));
    PetscCall(opt.Real("-wall_youngs_modulus", "Young's modulus of the walls (default -1: each particle type's)", "Pa", &wallYoungs_));
    PetscCall(opt.Real("-wall_poisson_ratio", "Poisson ratio of the walls (default -1: each particle type's)", "-", &wallPoisson_));
    PetscCall(opt.Real("-wall_friction", "Sliding friction coefficient against the walls (default -1: each particle type's)", "-", &wallFriction_));
    if (wallYoungs_ != -1 && !(wallYoungs_ > 0)) VofdemInputError(comm, "option -dem_wall_youngs_modulus: must be positive (or -1 for the particles')");
    if (wallPoisson_ != -1 && !(wallPoisson_ > -1 && wallPoisson_ <= 0.5)) VofdemInputError(comm, "option -dem_wall_poisson_ratio: must be in (-1, 0.5] (or -1 for the particles')");
    if (wallFriction_ != -1 && !(wallFriction_ >= 0)) VofdemInputError(comm, "option -dem_wall_friction: must be non-negative (or -1 for the particles')");
    PetscCall(opt.Real("-wall_restitution", "Coefficient of restitution against the walls (default -1: each particle type's)", "-", &wallRestitution_));
    if (wallRestitution_ != -1 && !(wallRestitution_ > 0 && wallRestitution_ <= 1)) VofdemInputError(comm, "option -dem_wall_restitution: must be in (0, 1] (or -1 for the particles')");
    skin_ = 0.4 * radius_;
    PetscCall(opt.Real("-skin", "Verlet skin: lists are rebuilt and particles migrate once one has moved half of it (default: 0.2 diameters)", "m", &skin_, RealRange::Positive()));
    PetscCall(sort_.SetFromOptions(opt));  // -dem_sort_every (MortonOrder.cpp)
    PetscCall(opt.Real("-dt_factor", "Time step as a fraction of the Rayleigh time (P9)", "-", &dtFactor_, RealRange::LeftOpen(0, 1)));
    PetscCall(opt.Int("-contact_step_every",
                      "Every this many steps, bound the step by the contacts as they are: the stable step of the sphere whose loaded, damped contacts spin stiffest (HertzMindlin.hpp SpinStep; deep beds of soft spheres); 0: never",
                      &contactStepEvery_, 0));
    PetscCall(opt.RealVector("-fill_lower", "Lower corner of the lattice-fill region (default: the box)", "m", fillLower_, 3, RealRange::Any(), &fillLowerSet_));
    PetscCall(opt.RealVector("-fill_upper", "Upper corner of the lattice-fill region (default: the box)", "m", fillUpper_, 3, RealRange::Any(), &fillUpperSet_));
    PetscCall(opt.Real("-fill_spacing", "Lattice spacing of the fill, at least one diameter (0: 2.2 radii)", "m", &fillSpacing_, RealRange::NonNegative()));
    PetscCall(opt.Real("-fill_jitter", "Random displacement of lattice points, fraction of the free gap", "-", &fillJitter_, RealRange::Closed(0, 1)));
    PetscCall(opt.Int("-fill_count", "Number of particles to place on the fill lattice (0: none, -1: as many as the region holds)", &fillCount_, -1));
    PetscCall(opt.RealVector("-fill_velocity", "Initial velocity of inserted particles", "m/s", fillVelocity_, 3));
    PetscCall(fillSizes_.SetFromOptions(opt, comm, "fill_", radius_));  // SizeDistribution.cpp
    {  // DemFill.cpp (FillRandom)
      static const std::vector<std::string> modes = {"lattice", "random"};
      std::vector<std::string>              mode  = {"lattice"};
      PetscCall(opt.NameList("-fill_mode", "Fill: lattice (with jitter) or random (non-overlapping random sequential addition)", modes, &mode));
      if (mode.size() != 1) VofdemInputError(comm, "option -dem_fill_mode: give one mode (lattice or random)");
      fillRandom_ = (PetscBool)(mode[0] == "random");
      PetscCall(opt.Real("-fill_volume_fraction", "Random fill: solid volume fraction of the region to reach (instead of -dem_fill_count)", "-", &fillFraction_,
                         RealRange::LeftOpen(0, 1)));
      PetscCall(opt.Int("-fill_attempts", "Random fill: candidate centres per particle before the fill gives up", &fillAttempts_, 1));
    }
    PetscCall(opt.Real("-fill_velocity_spread", "Random part of the initial velocity: each component uniform in [-spread, spread]", "m/s", &fillSpread_, RealRange::NonNegative()));
    PetscCall(opt.String("-save_particles", "Write all particles at the end of the run to this CSV (the format -dem_particles_file reads, with radius)", &savePath_));
    PetscCall(opt.String("-save_contact_history",
                         "Write the contact history at the end of the run to this CSV: the springs (tangential, rolling, JKR contact radius and bond) of the touching "
                         "particle pairs and box-face contacts, the particles by their rows in the -dem_save_particles file; read by -dem_contact_history_file",
                         &saveHistoryPath_));
    PetscCall(opt.String("-contact_history_file",
                         "CSV of the contact history of the particles of -dem_particles_file (as -dem_save_contact_history writes it): the run keeps their friction, "
                         "rolling and JKR bonds instead of starting every contact afresh",
                         &historyFile_));
    PetscCall(opt.String("-particles_file", "CSV of particles to insert after the fill; the header names the columns: x,y,z required, vx,vy,vz,wx,wy,wz,radius,type,clump optional (m, m/s, rad/s, index into -dem_types, clump id or -1)", &particlesFile_));
    PetscCall(TypesFromOptions(PetscOptionsObject));
    PetscCall(SetBalanceFromOptions(PetscOptionsObject));
    {
      std::vector<PetscReal> densities;
      for (const auto &m : types_) densities.push_back(m.density);
      PetscCall(sources_.SetFromOptions(opt, comm, radius_, typeNames_, densities));  // ParticleSources.cpp
    }
  }
  PetscOptionsEnd();
  if (surfaceEnergyModulus_ > 0) {  // P9: measured gamma -> gamma' = gamma (E'/E)^(2/5) for each type's E'
    measuredSurfaceEnergy_.resize(types_.size());
    for (size_t t = 0; t < types_.size(); ++t) {
      measuredSurfaceEnergy_[t] = types_[t].surfaceEnergy;
      types_[t].surfaceEnergy *= std::pow(types_[t].youngs / surfaceEnergyModulus_, 0.4);
    }
    material_.surfaceEnergy = types_[0].surfaceEnergy;
    if (wallSurfaceEnergy_ >= 0) {
      PetscReal Ewall = wallYoungs_ > 0 ? wallYoungs_ : types_[0].youngs;
      wallSurfaceEnergy_ *= std::pow(Ewall / surfaceEnergyModulus_, 0.4);
    }
  }
  if (jkr_)
    for (size_t t = 0; t < types_.size(); ++t)
      if (types_[t].surfaceEnergy == 0) {
        if (types_.size() == 1 && typeNames_[0] == "default") VofdemInputError(comm, "option -dem_cohesion jkr needs a surface energy > 0 for every type (-dem_surface_energy)");
        VofdemInputError(comm, "option -dem_cohesion jkr needs a surface energy > 0 for every type: type %s has none (-dem_type_%s_surface_energy; a material file's value is not overridden by -dem_surface_energy)",
                         typeNames_[t].c_str(), typeNames_[t].c_str());
      }
  if (!saveHistoryPath_.empty() && savePath_.empty())
    VofdemInputError(comm, "option -dem_save_contact_history: give -dem_save_particles too (the contacts name the particles by their rows in that file)");
  if (!historyFile_.empty() && particlesFile_.empty())
    VofdemInputError(comm, "option -dem_contact_history_file: give -dem_particles_file too (the contacts name the particles by their rows in that file)");
  const PetscReal rFillMax = fillSizes_.MaxRadius();
  PetscCall(wallSet_.SetFromOptions(comm));
  PetscCall(out_.SetFromOptions(comm));
  if (fillSpacing_ == 0) fillSpacing_ = 2.2 * rFillMax;
  if (fillSpacing_ < 2 * rFillMax)
    VofdemInputError(comm, "option -dem_fill_spacing: %g m is less than the largest particle diameter (%g m): particles would overlap", (double)fillSpacing_,
                     (double)(2 * rFillMax));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::SetUp(Grid &grid, const PetscReal gravity[3], std::uint64_t seed) {
  PetscFunctionBeginUser;
  grid_ = &grid;
  std::copy(gravity, gravity + 3, gravity_);
  WallMaterial wall;
  wall.youngs = wallYoungs_, wall.poisson = wallPoisson_, wall.friction = wallFriction_, wall.surfaceEnergy = wallSurfaceEnergy_, wall.restitution = wallRestitution_;
  table_.Build(types_, pairValues_, wall, linear_, linearKtRatio_, limitForce_, jkr_, rollingParams_);
  // The single-type fast path of the contact loop binds these.
  pair_          = table_.Pair(0);
  wall_          = table_.Wall(0);
  rollingParams_ = table_.Rolling(0);
  PetscClassId classId;
  PetscCall(PetscClassIdRegister("DEM", &classId));
  PetscCall(PetscLogEventRegister("DEMRebuild", classId, &evRebuild_));
  PetscCall(PetscLogEventRegister("DEMHaloRefresh", classId, &evHalo_));
  PetscCall(PetscLogEventRegister("DEMForces", classId, &evForces_));
  PetscCall(PetscLogEventRegister("DEMIntegrate", classId, &evIntegrate_));
  if (!savePath_.empty()) PetscCall(CheckWritable(comm_, savePath_, "option -dem_save_particles"));
  if (!saveHistoryPath_.empty()) PetscCall(CheckWritable(comm_, saveHistoryPath_, "option -dem_save_contact_history"));
  // The clumps' rigid state (11 reals per particle) only where clumps can come: inserted, or from the file.
  swarm_.SetRigidFields(sources_.InsertsClumps() || ParticlesFileNamesClumps());
  PetscCall(swarm_.Create(grid));
  PetscCall(halo_.SetUp(grid));
  PetscCall(halo_.Images().CheckRanks(grid));
  PetscCall(wallSet_.SetUp(grid.Lower(), grid.Upper()));
  PetscCall(Fill(seed));
  PetscCall(ReadParticles());
  {  // Clumps (P10) of the particles file: templates, rigid state, rigid velocities (Clumps.hpp).
    ParticleArrays         a;
    std::vector<PetscReal> density;
    PetscInt               local;
    for (const DemMaterial &m : types_) density.push_back(m.density);
    PetscCall(swarm_.GetArrays(&a));
    PetscCall(clumps_.SetUp(a, density, gravity_, &local));
    PetscCall(swarm_.RestoreArrays(&a));
    PetscCallMPI(MPI_Allreduce(&local, &clumpCount_, 1, MPIU_INT, MPI_SUM, comm_));
    clumps_.SetAny(clumpCount_ > 0 || sources_.InsertsClumps());  // inserted clumps move as rigid bodies too
  }
  PetscCall(swarm_.GlobalCount(&inserted_));
  {  // The sizes present: R_min sets the Rayleigh time (P9), R_max the neighbour cut-off.
    ParticleArrays a;
    PetscReal      range[2] = {-PETSC_MAX_REAL, -PETSC_MAX_REAL}, global[2];  // -min, max
    PetscCall(swarm_.GetArrays(&a));
    for (PetscInt p = 0; p < a.n; ++p) range[0] = std::max(range[0], -a.radius[p]), range[1] = std::max(range[1], a.radius[p]);
    PetscCall(swarm_.RestoreArrays(&a));
    PetscCallMPI(MPI_Allreduce(range, global, 2, MPIU_REAL, MPIU_MAX, comm_));
    rMin_ = inserted_ ? -global[0] : radius_;
    rMax_ = inserted_ ? global[1] : radius_;
    if (!inserted_ && sources_.Sources().size()) rMin_ = PETSC_MAX_REAL, rMax_ = 0;
    sources_.RadiusRange(&rMin_, &rMax_);  // what insertion will bring
  }
  PetscCall(sources_.SetUp(grid, swarm_, seed));
  // The smallest time scale over the types present in the scene's definition (P9, P4).
  rayleighTime_ = PETSC_MAX_REAL;
  adhesionRange_ = 0;
  for (const DemMaterial &m : types_) {
    // With the linear law the time scale is the contact duration of two equal smallest spheres,
    // pi sqrt(m*/k_n) with m* = m_min/2: a tenth of it takes the Rayleigh time's place, so the default
    // -dem_dt_factor 0.3 gives about 33 steps per contact.
    const PetscReal tr = linear_ ? 0.1 * PETSC_PI * std::sqrt(m.density * 4.0 / 3.0 * PETSC_PI * rMin_ * rMin_ * rMin_ / (2 * linearKn_))
                                 : hertz::RayleighTime(rMin_, m.density, m.youngs, m.poisson);
    rayleighTime_ = std::min(rayleighTime_, tr);
  }
  // JKR bonds at rest may be stiffer than the Rayleigh time allows for (HertzMindlin.hpp SpinStep): the
  // smallest, lightest sphere held by 12 bonds of the stiffest pair material, or by 11 and a wall.
  jkrStepLimit_ = PETSC_MAX_REAL;
  if (jkr_) {
    PetscReal rhoMin = PETSC_MAX_REAL;
    for (const DemMaterial &m : types_) rhoMin = std::min(rhoMin, m.density);
    const PetscReal m = rhoMin * 4.0 / 3.0 * PETSC_PI * rMin_ * rMin_ * rMin_;
    for (const auto &c : table_.Pairs()) {
      PetscReal w2 = 0, rate = 0;
      hertz::JkrSpinBond(c, rMin_ / 2, m / 2, m, false, &w2, &rate);
      jkrStepLimit_ = std::min(jkrStepLimit_, kJkrStepSafety * hertz::SpinStep(12 * w2, 12 * rate));
      for (PetscInt t = 0; t < table_.Count(); ++t) {
        PetscReal ww2 = 11 * w2, wrate = 11 * rate;
        hertz::JkrSpinBond(table_.Wall(t), rMin_, m, m, true, &ww2, &wrate);
        jkrStepLimit_ = std::min(jkrStepLimit_, kJkrStepSafety * hertz::SpinStep(ww2, wrate));
      }
    }
  }
  // A JKR bond holds until the overlap falls to its break value, largest for the largest R* (a wall).
  if (jkr_) {
    for (const auto &c : table_.Pairs()) adhesionRange_ = std::max(adhesionRange_, -hertz::JkrBreakOverlap(c, rMax_ / 2));
    for (PetscInt t = 0; t < table_.Count(); ++t) adhesionRange_ = std::max(adhesionRange_, -hertz::JkrBreakOverlap(table_.Wall(t), rMax_));
  }
  if (vdw_.hamaker > 0) adhesionRange_ = vdw_.range;
  if (lubrication_.viscosity > 0) adhesionRange_ = std::max(adhesionRange_, lubrication_.maxGap);
  SetUpBonds();  // DemBonds.cpp: their reach and step (P13)
  PetscCall(Rebuild());
  record_.on = out_.NeedsContacts(steps_);
  PetscCall(ComputeForces(0));
  if (contactStepEvery_ > 0) PetscCall(UpdateContactStepLimit());  // a start among loaded contacts (a particle file) steps safely at once
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::SetFluidLubrication(PetscReal uniform) {
  PetscFunctionBeginUser;
  if (lubrication_.viscosity > 0)
    VofdemInputError(comm_, "options -coupling_lubrication and -dem_lubrication_viscosity: the lubrication takes either the fluid's viscosity or a fixed one; give one of them");
  if (!(lubrication_.maxGap > lubrication_.minGap))
    VofdemInputError(comm_, "option -dem_lubrication_max_gap: %g m must exceed -dem_lubrication_min_gap %g m", (double)lubrication_.maxGap, (double)lubrication_.minGap);
  fluidLubrication_   = true;
  lubricationUniform_ = uniform;
  lubrication_.viscosity = 1;  // the coefficient per unit viscosity: each pair multiplies it by its mu (DemContacts.cpp)
  halo_.SetCarryViscosity(uniform <= 0);
  PetscFunctionReturn(0);
}

// Half a velocity-Verlet kick: v += dt/2 F/m, w += dt/2 T/I with I = 2/5 m R^2 (spheres; clump
// members move with their clump, Clumps::Kick). Coupled to
// a fluid (Coupling.hpp), the other fluid forces join F and the drag K (u - v) is taken implicitly,
// v' = (v + (h K/m) u)/(1 + h K/m) (stable for any response time m/K); its impulse is summed for the
// fluid's reaction (docs/physics.md F5), so the fluid gets exactly what the particles got.
// The added mass m_a = C_vm rho_f V (P1, f_vm = m_a (Du/Dt - dv/dt)) is taken implicitly: its -m_a dv/dt
// part moves to the left, (m + m_a) dv/dt = F + ..., and the coupling puts m_a Du/Dt into the fluid
// force; the fluid gets -f_vm as well (F5). Without it (m_a = 0) the kick is the one above.
// With a surface force set (SurfaceForce.hpp: the coupling's capillary force, Princen's F_n n) it joins the explicit
// fluid force, evaluated at the particle's current height s = n.x + c above the surface plane the coupling
// read once per fluid step: the force is stiff (dF/ds = 2 pi sigma at a floating equilibrium, a 1 mm sphere
// oscillates with a period of about 10 ms), and held over a fluid step at any one height it feeds that
// oscillation (held at the start of the step: growth 1 + (omega dt)^2/2 per step; at the mid-step: no damping
// at all, so that any other lag wins). Taken per kick it is part of the symplectic DEM integration.
// Its impulse is summed for the fluid's reaction (F5).
template <bool fluid>
static void HalfKick(const ParticleArrays &a, PetscReal dt, const SurfaceForce &surface) {
  for (PetscInt p = 0; p < a.n; ++p) {
    if (a.clump[p] >= 0) continue;
    const PetscReal ma = fluid ? a.fluidAddedMass[p] : 0, m = a.mass[p] + ma;
    const PetscReal h = 0.5 * dt / m, hI = 0.5 * dt / a.mass[p] / (0.4 * a.radius[p] * a.radius[p]);
    PetscReal       v0[3];
    for (int d = 0; d < 3; ++d) {
      v0[d] = a.v[3 * p + d];
      a.v[3 * p + d] += h * a.f[3 * p + d];
      a.omega[3 * p + d] += hI * a.torque[3 * p + d];
    }
    if (fluid) {
      // The rotational drag torque -K_r (omega - Omega_f) (-coupling_rotational_drag, RotationLaws.hpp), implicit like
      // the drag: its time I/K_r = rho_p d^2/60 mu is a third of the translational response time.
      const PetscReal cr = hI * a.fluidRotationalDrag[p];
      if (cr > 0)
        for (int d = 0; d < 3; ++d) a.omega[3 * p + d] = (a.omega[3 * p + d] + cr * a.fluidRotation[3 * p + d]) / (1 + cr);
      PetscReal Fn = 0;
      const PetscReal *plane = &a.fluidSurfacePlane[4 * p];
      if (surface.law && (plane[0] != 0 || plane[1] != 0 || plane[2] != 0)) {
        const PetscReal s = plane[0] * a.x[3 * p] + plane[1] * a.x[3 * p + 1] + plane[2] * a.x[3 * p + 2] + plane[3];
        Fn                = surface.law(a.radius[p], s, surface.params);
      }
      const PetscReal c = h * a.fluidDrag[p];
      for (int d = 0; d < 3; ++d) {
        const PetscReal fc = Fn * plane[d];
        const PetscReal v  = a.v[3 * p + d] + h * (a.fluidForce[3 * p + d] + fc);
        const PetscReal u  = a.fluidVelocity[3 * p + d];
        const PetscReal w  = (v + c * u) / (1 + c);
        a.fluidImpulse[3 * p + d] += m * (w - v);
        // The implicit part of the f_vm impulse, -m_a (w - v0); its explicit part m_a Du/Dt dt the
        // coupling adds once per fluid step (Coupling::Average).
        if (ma > 0) a.fluidImpulse[3 * p + d] -= ma * (w - v0[d]);
        if (Fn != 0) a.fluidCapillaryImpulse[3 * p + d] += 0.5 * dt * fc;
        a.v[3 * p + d] = w;
      }
    }
  }
}

static void HalfKick(const ParticleArrays &a, PetscReal dt, bool fluid, const SurfaceForce &surface) {
  if (fluid) HalfKick<true>(a, dt, surface);
  else HalfKick<false>(a, dt, surface);
}

// Velocity Verlet for translation and rotation. Forces are evaluated with the half-step
// velocities, as in LIGGGHTS.
PetscErrorCode Dem::Step(PetscReal dt) {
  ParticleArrays a;
  PetscBool      rebuild;

  PetscFunctionBeginUser;
  record_.on = out_.NeedsContacts(++steps_);
  PetscCall(PetscLogEventBegin(evIntegrate_, 0, 0, 0, 0));
  PetscCall(swarm_.GetArrays(&a));
  HalfKick(a, dt, fluidCoupled_, surfaceForce_);
  for (PetscInt p = 0; p < a.n; ++p)
    if (a.clump[p] < 0)
      for (int d = 0; d < 3; ++d) a.x[3 * p + d] += dt * a.v[3 * p + d];
  clumps_.Kick(a, dt, true);
  PetscCall(swarm_.RestoreArrays(&a));
  time_ += dt;
  PetscCall(swarm_.NeedsRebuild(0.5 * skin_, &rebuild));
  if (!rebuild && sources_.Active()) PetscCall(sources_.NeedsChange(time_, swarm_, &rebuild));  // Rebuild() inserts and deletes
  wallSet_.Advance(dt);  // moving walls count in the rebuild rule too (Walls.hpp)
  if (wallSet_.MovedBeyond(0.5 * skin_)) rebuild = PETSC_TRUE;
  PetscCall(PetscLogEventEnd(evIntegrate_, 0, 0, 0, 0));
  if (rebuild) {
    PetscCall(PetscLogEventBegin(evRebuild_, 0, 0, 0, 0));
    PetscCall(Rebuild());
    PetscCall(PetscLogEventEnd(evRebuild_, 0, 0, 0, 0));
  } else {
    PetscCall(PetscLogEventBegin(evHalo_, 0, 0, 0, 0));
    PetscCall(swarm_.GetArrays(&a));
    PetscCall(halo_.Refresh(a, a.omega));
    PetscCall(swarm_.RestoreArrays(&a));
    PetscCall(PetscLogEventEnd(evHalo_, 0, 0, 0, 0));
  }
  PetscCall(PetscLogEventBegin(evForces_, 0, 0, 0, 0));
  PetscCall(ComputeForces(dt));
  if (contactStepEvery_ > 0 && steps_ % contactStepEvery_ == 0) PetscCall(UpdateContactStepLimit());
  PetscCall(PetscLogEventEnd(evForces_, 0, 0, 0, 0));
  PetscCall(PetscLogEventBegin(evIntegrate_, 0, 0, 0, 0));
  PetscCall(swarm_.GetArrays(&a));
  HalfKick(a, dt, fluidCoupled_, surfaceForce_);
  clumps_.Kick(a, dt, false);
  PetscCall(swarm_.RestoreArrays(&a));
  PetscCall(PetscLogEventEnd(evIntegrate_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::Summarize(DemSummary *s) const {
  ParticleArrays a;
  PetscReal      sums[3 + 18 + 1] = {0}, global[3 + 18 + 1];
  PetscInt       counts[2] = {stats_.pairContacts, stats_.wallContacts}, gcounts[2];

  PetscFunctionBeginUser;
  PetscCall(swarm_.GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p) {
    const PetscReal *v = &a.v[3 * p], *w = &a.omega[3 * p];
    sums[3 + 18] += a.mass[p];
    if (a.clump[p] >= 0) continue;  // clumps: the rigid body's energy below
    sums[0] += 0.5 * a.mass[p] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    sums[1] += 0.2 * a.mass[p] * a.radius[p] * a.radius[p] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  }
  PetscReal clumpKinetic, clumpRotational;
  clumps_.Energy(a, &clumpKinetic, &clumpRotational);
  sums[0] += clumpKinetic, sums[1] += clumpRotational;
  PetscCall(swarm_.RestoreArrays(&a));
  sums[2] = stats_.elastic;
  for (int f = 0; f < 6; ++f)
    for (int d = 0; d < 3; ++d) sums[3 + 3 * f + d] = stats_.wallForce[f][d];
  PetscCallMPI(MPI_Allreduce(sums, global, 22, MPIU_REAL, MPIU_SUM, comm_));
  PetscCallMPI(MPI_Allreduce(counts, gcounts, 2, MPIU_INT, MPI_SUM, comm_));
  PetscCallMPI(MPI_Allreduce(&stats_.maxOverlap, &s->maxOverlap, 1, MPIU_REAL, MPIU_MAX, comm_));
  PetscCall(swarm_.GlobalCount(&s->particles));
  s->kinetic      = global[0];
  s->rotational   = global[1];
  s->elastic      = global[2];
  s->mass         = global[3 + 18];
  s->pairContacts = gcounts[0] / 2;  // each pair was counted twice (see ComputeForces)
  s->wallContacts = gcounts[1];
  s->coordination = s->particles ? (PetscReal)gcounts[0] / s->particles : 0;
  for (int f = 0; f < 6; ++f)
    for (int d = 0; d < 3; ++d) s->wallForce[f][d] = global[3 + 3 * f + d];
  s->sources = (PetscBool)sources_.Active();
  s->inserted = sources_.Inserted(), s->deleted = sources_.Deleted();
  s->massInserted = sources_.MassInserted(), s->massDeleted = sources_.MassDeleted();
  PetscCall(wallSet_.Summarize(comm_, &s->walls));
  PetscCall(SummarizeBonds(s));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::FindParticle(std::int64_t id, PetscReal x[3], PetscReal v[3], PetscBool *found, PetscReal omega[3], PetscReal force[3]) const {
  ParticleArrays a;
  PetscReal      local[13] = {0}, global[13];

  PetscFunctionBeginUser;
  PetscCall(swarm_.GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p) {
    if (a.id[p] != id) continue;
    local[0] = 1;
    for (int d = 0; d < 3; ++d)
      local[1 + d] = a.x[3 * p + d], local[4 + d] = a.v[3 * p + d], local[7 + d] = a.omega[3 * p + d], local[10 + d] = a.f[3 * p + d];
  }
  PetscCall(swarm_.RestoreArrays(&a));
  // Exactly one rank holds the particle, so the sum is the value itself, bit for bit.
  PetscCallMPI(MPI_Allreduce(local, global, 13, MPIU_REAL, MPIU_SUM, comm_));
  *found = (PetscBool)(global[0] == 1);
  for (int d = 0; d < 3; ++d) {
    x[d] = global[1 + d];
    v[d] = global[4 + d];
    if (omega) omega[d] = global[7 + d];
    if (force) force[d] = global[10 + d];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  // One type: its own material (with -dem_types it is not material_, which is what the types start from);
  // several: each type's line below.
  const bool         oneType = types_.size() == 1;
  const DemMaterial &shown   = types_[0];
  if (oneType)
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: %" PetscInt_FMT " spheres of radius %g to %g m, density %g kg/m^3, E %g Pa, nu %g, e %g, mu %g; Rayleigh time %g s; skin %g m\n",
                                     inserted_, (double)rMin_, (double)rMax_, (double)shown.density, (double)shown.youngs, (double)shown.poisson, (double)shown.restitution,
                                     (double)shown.friction, (double)rayleighTime_, (double)skin_));
  else
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: %" PetscInt_FMT " spheres of radius %g to %g m, %" PetscInt_FMT " types (materials below); Rayleigh time %g s; skin %g m\n", inserted_,
                                     (double)rMin_, (double)rMax_, (PetscInt)types_.size(), (double)rayleighTime_, (double)skin_));
  if (clumpCount_ > 0)
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: %" PetscInt_FMT " rigid clumps of overlapping spheres (P10): mass and inertia of each shape's union, quaternion rotation\n", clumpCount_));
  if (types_.size() > 1) {
    const PetscInt nt = (PetscInt)types_.size();
    for (PetscInt t = 0; t < nt; ++t) {
      const DemMaterial &m = types_[t];
      PetscCall(PetscViewerASCIIPrintf(viewer, "dem: type %" PetscInt_FMT " '%s': density %g kg/m^3, E %g Pa, nu %g, e %g, mu %g, mu_r %g, gamma %g J/m^2\n", t,
                                       typeNames_[t].c_str(), (double)m.density, (double)m.youngs, (double)m.poisson, (double)m.restitution, (double)m.friction,
                                       (double)m.rollingFriction, (double)m.surfaceEnergy));
    }
    for (PetscInt i = 0; i < nt; ++i)
      for (PetscInt j = i + 1; j < nt; ++j) {
        const PetscInt k = table_.PairIndex(i, j);
        PetscCall(PetscViewerASCIIPrintf(viewer, "dem: pair %s-%s: E* %g Pa, e %g, mu %g, mu_r %g%s\n", typeNames_[i].c_str(), typeNames_[j].c_str(),
                                         (double)table_.Pair(k).Estar, (double)table_.Restitution(k), (double)table_.Pair(k).mu, (double)table_.Rolling(k).mu,
                                         pairValues_[k].restitution < 0 || pairValues_[k].friction < 0 ? " (unset values: mean of the two types)" : ""));
      }
  }
  char                     law[128];
  if (linear_) std::snprintf(law, sizeof law, "linear spring-dashpot, k_n %g N/m, k_t/k_n %g (P4)", (double)linearKn_, (double)linearKtRatio_);
  else std::snprintf(law, sizeof law, "Hertz-Mindlin (P3)");
  char muR[48] = "mu_r per type";
  if (oneType) std::snprintf(muR, sizeof muR, "mu_r %g", (double)shown.rollingFriction);
  static const char *const loads[] = {"", ", cap mu_r R* |F_n|", ", cap mu_r R* (F_n + 2 F_c)"};
  PetscCall(PetscViewerASCIIPrintf(viewer, "dem: contacts: %s with damping, tangential springs and Coulomb friction between spheres and with the box faces%s; rolling resistance: %s, %s%s%s (P5)\n",
                                   law, limitForce_ ? ", normal force clipped at zero" : "", contact::kRollingLaws[rollingRow_].shown, muR,
                                   rolling_ == hertz::Rolling::None ? "" : loads[(int)rollingParams_.load], rolling_ == hertz::Rolling::Epsd && !rollingParams_.twist ? ", twist free" : ""));
  if (jkr_ && oneType)
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: adhesion: JKR (P6), surface energy %g J/m^2 (work of adhesion %g J/m^2), walls %g J/m^2; bonds break up to %g m apart; bonds at rest allow steps up to %g s (HertzMindlin.hpp SpinStep)\n",
                                     (double)shown.surfaceEnergy, (double)pair_.w, (double)wall_.w, (double)adhesionRange_, (double)jkrStepLimit_));
  else if (jkr_)
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: adhesion: JKR (P6), surface energies per type (work of adhesion %g J/m^2 between type 0's spheres), walls %g J/m^2; bonds break up to %g m apart; bonds at rest allow steps up to %g s (HertzMindlin.hpp SpinStep)\n",
                                     (double)pair_.w, (double)wall_.w, (double)adhesionRange_, (double)jkrStepLimit_));
  if (sjkr_) PetscCall(PetscViewerASCIIPrintf(viewer, "dem: adhesion: SJKR (LIGGGHTS' cohesion sjkr, P6), cohesion energy density %g J/m^3\n", (double)sjkrDensity_));
  PetscCall(ViewBonds(viewer));  // DemBonds.cpp (P13)
  if (surfaceEnergyModulus_ > 0)
    for (size_t t = 0; t < types_.size(); ++t)
      PetscCall(PetscViewerASCIIPrintf(viewer, "dem: surface energy of type '%s': %g J/m^2 measured at E = %g Pa, scaled to %g J/m^2 for E' = %g Pa (P9: (E'/E)^(2/5), keeps the energy of separation, not the pull-off force)\n",
                                       typeNames_[t].c_str(), (double)measuredSurfaceEnergy_[t], (double)surfaceEnergyModulus_, (double)types_[t].surfaceEnergy,
                                       (double)types_[t].youngs));
  if (fluidLubrication_)
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: lubrication (P8): the fluid's viscosity (%s) across gaps from %g m (held below) to %g m\n",
                                     lubricationUniform_ > 0 ? ("uniform, " + std::to_string((double)lubricationUniform_) + " Pa s").c_str() : "each pair's mean of the viscosities its particles read",
                                     (double)lubrication_.minGap, (double)lubrication_.maxGap));
  else if (lubrication_.viscosity > 0)
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: lubrication (P8): viscosity %g Pa s across gaps from %g m (held below) to %g m\n", (double)lubrication_.viscosity,
                                     (double)lubrication_.minGap, (double)lubrication_.maxGap));
  if (vdw_.hamaker > 0)
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: van der Waals (P7): Hamaker constant %g J, held below a gap of %g m, dropped beyond %g m; %s\n", (double)vdw_.hamaker,
                                     (double)vdw_.minGap, (double)vdw_.range, vdwWalls_ ? "walls attract too" : "between particles only (-dem_vdw_walls 0)"));
  const PetscReal g = std::sqrt(gravity_[0] * gravity_[0] + gravity_[1] * gravity_[1] + gravity_[2] * gravity_[2]);
  if ((jkr_ || vdw_.hamaker > 0) && g > 0 && rMax_ > 0) {
    // Bond number K = pull-off force of two equal spheres / weight of one (P7): 1.5 pi w R* for JKR,
    // A R* / (6 z0^2) for van der Waals, with R* = R/2; with type 0's density (its own w for JKR).
    auto bond = [&](PetscReal r) {
      const PetscReal pull = jkr_ ? 1.5 * PETSC_PI * pair_.w * r / 2 : vdw_.hamaker * (r / 2) / (6 * vdw_.minGap * vdw_.minGap);
      return pull / (types_[0].density * 4.0 / 3.0 * PETSC_PI * r * r * r * g);
    };
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: bond number (pull-off of two equal spheres / weight of one%s): %g for radius %g m, %g for radius %g m\n", oneType ? "" : ", type 0",
                                     (double)bond(rMin_), (double)rMin_, (double)bond(rMax_), (double)rMax_));
  }
  PetscCall(sources_.View(viewer));
  PetscCall(wallSet_.View(viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(swarm_.Destroy());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
