#include "vofdem/dem/Dem.hpp"

#include "vofdem/core/Options.hpp"
#include "vofdem/core/Runtime.hpp"
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
      static const std::vector<std::string> models = {"none", "cdt", "epsd", "epsd2"};
      std::vector<std::string>              chosen = {"none"};
      PetscCall(opt.NameList("-rolling", "Rolling resistance (P5): none, cdt (constant torque), epsd (elastic-plastic spring-dashpot, Ai et al.), epsd2 (LIGGGHTS' undamped epsd2)",
                             models, &chosen));
      if (chosen.size() != 1) VofdemInputError(comm, "option -dem_rolling: give one model (none, cdt, epsd or epsd2)");
      rolling_ = chosen[0] == "cdt" ? hertz::Rolling::ConstantTorque
               : chosen[0] == "epsd" ? hertz::Rolling::Epsd
               : chosen[0] == "epsd2" ? hertz::Rolling::Epsd2 : hertz::Rolling::None;
      PetscCall(opt.Real("-rolling_friction", "Rolling friction coefficient mu_r (P5)", "-", &rollingParams_.mu, RealRange::NonNegative()));
      PetscCall(opt.Real("-rolling_damping", "EPSD rolling damping as a fraction of critical", "-", &rollingParams_.eta, RealRange::NonNegative()));
    }
    {
      static const std::vector<std::string> contacts = {"hertz", "linear"};
      std::vector<std::string>              chosen   = {"hertz"};
      PetscCall(opt.NameList("-contact", "Normal contact law: hertz (Hertz-Mindlin, P3) or linear (spring-dashpot, P4)", contacts, &chosen));
      if (chosen.size() != 1) VofdemInputError(comm, "option -dem_contact: give one law (hertz or linear)");
      linear_ = (PetscBool)(chosen[0] == "linear");
      PetscCall(opt.Real("-linear_stiffness", "Normal stiffness k_n of the linear law (seed 002: 1e5)", "N/m", &linearKn_, RealRange::Positive()));
      PetscCall(opt.Real("-linear_tangential_ratio", "k_t / k_n of the linear law (seed 002: 1)", "-", &linearKtRatio_, RealRange::Positive()));
    }
    {
      static const std::vector<std::string> models = {"none", "jkr"};
      std::vector<std::string>              chosen = {"none"};
      PetscCall(opt.NameList("-cohesion", "Adhesion between touching surfaces: none, jkr (JKR with hysteresis, P6)", models, &chosen));
      if (chosen.size() != 1) VofdemInputError(comm, "option -dem_cohesion: give one model (none or jkr)");
      jkr_ = (PetscBool)(chosen[0] == "jkr");
      PetscCall(opt.Real("-surface_energy", "Surface energy gamma of one particle surface; work of adhesion w = 2 gamma (P6)", "J/m^2", &surfaceEnergy_,
                         RealRange::NonNegative()));
      wallSurfaceEnergy_ = surfaceEnergy_;
      PetscCall(opt.Real("-wall_surface_energy", "Surface energy of the walls (default: the particles'); w = gamma_p + gamma_w", "J/m^2", &wallSurfaceEnergy_,
                         RealRange::NonNegative()));
      if (jkr_ && surfaceEnergy_ == 0) VofdemInputError(comm, "option -dem_cohesion jkr needs -dem_surface_energy > 0");
      vdw_.minGap = 0.165e-9;
      vdw_.range  = 1e-6;
      PetscCall(opt.Real("-hamaker", "Hamaker constant A of van der Waals attraction (P7); 0: none (regolith: 4.3e-20)", "J", &vdw_.hamaker, RealRange::NonNegative()));
      PetscCall(opt.Real("-vdw_min_gap", "Gap z0 below which the van der Waals force is held constant (P7)", "m", &vdw_.minGap, RealRange::Positive()));
      PetscCall(opt.Real("-vdw_range", "Gap beyond which van der Waals attraction is dropped", "m", &vdw_.range, RealRange::Positive()));
      if (vdw_.hamaker > 0 && jkr_) VofdemInputError(comm, "options -dem_hamaker and -dem_cohesion jkr: choose one adhesion model");
      if (linear_ && jkr_) VofdemInputError(comm, "option -dem_cohesion jkr needs -dem_contact hertz (JKR is a Hertzian theory)");
    }
    PetscCall(opt.Bool("-limit_force", "Clip the normal contact force at zero: no tension from damping as a contact ends (LIGGGHTS' limitForce); the restitution then differs from -dem_restitution", &limitForce_));
    wallYoungs_   = material_.youngs;
    wallPoisson_  = material_.poisson;
    wallFriction_ = material_.friction;
    PetscCall(opt.Real("-wall_youngs_modulus", "Young's modulus of the walls (default: the particles')", "Pa", &wallYoungs_, RealRange::Positive()));
    PetscCall(opt.Real("-wall_poisson_ratio", "Poisson ratio of the walls (default: the particles')", "-", &wallPoisson_, RealRange::LeftOpen(-1, 0.5)));
    PetscCall(opt.Real("-wall_friction", "Sliding friction coefficient against the walls (default: the particles')", "-", &wallFriction_, RealRange::NonNegative()));
    skin_ = 0.4 * radius_;
    PetscCall(opt.Real("-skin", "Verlet skin: lists are rebuilt and particles migrate once one has moved half of it (default: 0.2 diameters)", "m", &skin_, RealRange::Positive()));
    PetscCall(opt.Real("-dt_factor", "Time step as a fraction of the Rayleigh time (P9)", "-", &dtFactor_, RealRange::LeftOpen(0, 1)));
    PetscCall(opt.RealVector("-fill_lower", "Lower corner of the lattice-fill region (default: the box)", "m", fillLower_, 3, RealRange::Any(), &fillLowerSet_));
    PetscCall(opt.RealVector("-fill_upper", "Upper corner of the lattice-fill region (default: the box)", "m", fillUpper_, 3, RealRange::Any(), &fillUpperSet_));
    PetscCall(opt.Real("-fill_spacing", "Lattice spacing of the fill, at least one diameter (0: 2.2 radii)", "m", &fillSpacing_, RealRange::NonNegative()));
    PetscCall(opt.Real("-fill_jitter", "Random displacement of lattice points, fraction of the free gap", "-", &fillJitter_, RealRange::Closed(0, 1)));
    PetscCall(opt.Int("-fill_count", "Number of particles to place on the fill lattice (0: none, -1: as many as the region holds)", &fillCount_, -1));
    PetscCall(opt.RealVector("-fill_velocity", "Initial velocity of inserted particles", "m/s", fillVelocity_, 3));
    fillRadii_ = {radius_};
    PetscCall(opt.RealList("-fill_radii", "Radii of the fill's discrete size distribution (default: -dem_radius)", "m", &fillRadii_, 64, RealRange::Positive()));
    fillMassFractions_.assign(fillRadii_.size(), 1.0 / fillRadii_.size());
    PetscBool fractionsSet = PETSC_FALSE;
    PetscCall(opt.RealList("-fill_mass_fractions", "Mass fraction of each fill radius, normalised to sum 1 (default: equal)", "-", &fillMassFractions_, 64,
                           RealRange::Positive(), &fractionsSet));
    if (fillMassFractions_.size() != fillRadii_.size())
      VofdemInputError(comm, "option -dem_fill_mass_fractions: %d fractions for %d radii in -dem_fill_radii", (int)fillMassFractions_.size(), (int)fillRadii_.size());
    PetscCall(opt.Real("-fill_velocity_spread", "Random part of the initial velocity: each component uniform in [-spread, spread]", "m/s", &fillSpread_, RealRange::NonNegative()));
    PetscCall(opt.String("-save_particles", "Write all particles at the end of the run to this CSV (the format -dem_particles_file reads, with radius)", &savePath_));
    PetscCall(opt.String("-particles_file", "CSV of particles to insert after the fill; the header names the columns: x,y,z required, vx,vy,vz,wx,wy,wz,radius optional (m, m/s, rad/s)", &particlesFile_));
  }
  PetscOptionsEnd();
  PetscCall(out_.SetFromOptions(comm));
  const PetscReal rFillMax = *std::max_element(fillRadii_.begin(), fillRadii_.end());
  if (fillSpacing_ == 0) fillSpacing_ = 2.2 * rFillMax;
  if (fillSpacing_ < 2 * rFillMax)
    VofdemInputError(comm, "option -dem_fill_spacing: %g m is less than the largest particle diameter (%g m): particles would overlap", (double)fillSpacing_,
                     (double)(2 * rFillMax));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::SetUp(const Grid &grid, const PetscReal gravity[3], std::uint64_t seed) {
  PetscFunctionBeginUser;
  grid_ = &grid;
  std::copy(gravity, gravity + 3, gravity_);
  const DemMaterial &m = material_;
  pair_ = hertz::MakePairMaterial(m.youngs, m.poisson, m.youngs, m.poisson, m.restitution, m.friction, limitForce_, jkr_ ? 2 * surfaceEnergy_ : 0);
  wall_ = hertz::MakePairMaterial(m.youngs, m.poisson, wallYoungs_, wallPoisson_, m.restitution, wallFriction_, limitForce_,
                                  jkr_ ? surfaceEnergy_ + wallSurfaceEnergy_ : 0);
  if (linear_) {
    pair_ = hertz::MakeLinearMaterial(m.restitution, m.friction, linearKtRatio_, limitForce_);
    wall_ = hertz::MakeLinearMaterial(m.restitution, wallFriction_, linearKtRatio_, limitForce_);
  }
  PetscClassId classId;
  PetscCall(PetscClassIdRegister("DEM", &classId));
  PetscCall(PetscLogEventRegister("DEMRebuild", classId, &evRebuild_));
  PetscCall(PetscLogEventRegister("DEMHaloRefresh", classId, &evHalo_));
  PetscCall(PetscLogEventRegister("DEMForces", classId, &evForces_));
  PetscCall(PetscLogEventRegister("DEMIntegrate", classId, &evIntegrate_));
  if (!savePath_.empty()) PetscCall(CheckWritable(comm_, savePath_, "option -dem_save_particles"));
  PetscCall(swarm_.Create(grid));
  PetscCall(halo_.SetUp(grid));
  PetscCall(Fill(seed));
  PetscCall(ReadParticles());
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
  }
  rayleighTime_ = hertz::RayleighTime(rMin_, m.density, m.youngs, m.poisson);
  // With the linear law the time scale is the contact duration of two equal smallest spheres,
  // pi sqrt(m*/k_n) with m* = m_min/2: a tenth of it takes the Rayleigh time's place, so the default
  // -dem_dt_factor 0.3 gives about 33 steps per contact.
  if (linear_) rayleighTime_ = 0.1 * PETSC_PI * std::sqrt(m.density * 4.0 / 3.0 * PETSC_PI * rMin_ * rMin_ * rMin_ / (2 * linearKn_));
  // A JKR bond holds until the overlap falls to its break value, largest for the largest R* (a wall).
  if (jkr_) adhesionRange_ = -std::min(hertz::JkrBreakOverlap(pair_, rMax_ / 2), hertz::JkrBreakOverlap(wall_, rMax_));
  if (vdw_.hamaker > 0) adhesionRange_ = vdw_.range;
  PetscCall(Rebuild());
  record_.on = out_.NeedsContacts(steps_);
  PetscCall(ComputeForces(0));
  PetscFunctionReturn(0);
}

// Half a velocity-Verlet kick: v += dt/2 F/m, w += dt/2 T/I with I = 2/5 m R^2 (spheres).
static void HalfKick(const ParticleArrays &a, PetscReal dt) {
  for (PetscInt p = 0; p < a.n; ++p) {
    const PetscReal h = 0.5 * dt / a.mass[p], hI = h / (0.4 * a.radius[p] * a.radius[p]);
    for (int d = 0; d < 3; ++d) {
      a.v[3 * p + d] += h * a.f[3 * p + d];
      a.omega[3 * p + d] += hI * a.torque[3 * p + d];
    }
  }
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
  HalfKick(a, dt);
  for (PetscInt k = 0; k < 3 * a.n; ++k) a.x[k] += dt * a.v[k];
  PetscCall(swarm_.RestoreArrays(&a));
  PetscCall(swarm_.NeedsRebuild(0.5 * skin_, &rebuild));
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
  PetscCall(PetscLogEventEnd(evForces_, 0, 0, 0, 0));
  PetscCall(PetscLogEventBegin(evIntegrate_, 0, 0, 0, 0));
  PetscCall(swarm_.GetArrays(&a));
  HalfKick(a, dt);
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
    sums[0] += 0.5 * a.mass[p] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    sums[1] += 0.2 * a.mass[p] * a.radius[p] * a.radius[p] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    sums[3 + 18] += a.mass[p];
  }
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
  PetscCall(PetscViewerASCIIPrintf(viewer, "dem: %" PetscInt_FMT " spheres of radius %g to %g m, density %g kg/m^3, E %g Pa, nu %g, e %g, mu %g; Rayleigh time %g s; skin %g m\n",
                                   inserted_, (double)rMin_, (double)rMax_, (double)material_.density, (double)material_.youngs, (double)material_.poisson,
                                   (double)material_.restitution, (double)material_.friction, (double)rayleighTime_, (double)skin_));
  static const char *const rolling[] = {"none", "constant torque", "EPSD", "EPSD2 (LIGGGHTS)"};
  char                     law[128];
  if (linear_) std::snprintf(law, sizeof law, "linear spring-dashpot, k_n %g N/m, k_t/k_n %g (P4)", (double)linearKn_, (double)linearKtRatio_);
  else std::snprintf(law, sizeof law, "Hertz-Mindlin (P3)");
  PetscCall(PetscViewerASCIIPrintf(viewer, "dem: contacts: %s with damping, tangential springs and Coulomb friction between spheres and with the box faces%s; rolling resistance: %s, mu_r %g (P5)\n",
                                   law, limitForce_ ? ", normal force clipped at zero" : "", rolling[(int)rolling_], (double)rollingParams_.mu));
  if (jkr_)
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: adhesion: JKR (P6), surface energy %g J/m^2 (work of adhesion %g J/m^2), walls %g J/m^2; bonds break up to %g m apart\n",
                                     (double)surfaceEnergy_, (double)pair_.w, (double)wall_.w, (double)adhesionRange_));
  if (vdw_.hamaker > 0)
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: van der Waals (P7): Hamaker constant %g J, held below a gap of %g m, dropped beyond %g m\n", (double)vdw_.hamaker,
                                     (double)vdw_.minGap, (double)vdw_.range));
  const PetscReal g = std::sqrt(gravity_[0] * gravity_[0] + gravity_[1] * gravity_[1] + gravity_[2] * gravity_[2]);
  if ((jkr_ || vdw_.hamaker > 0) && g > 0 && rMax_ > 0) {
    // Bond number K = pull-off force of two equal spheres / weight of one (P7): 1.5 pi w R* for JKR,
    // A R* / (6 z0^2) for van der Waals, with R* = R/2.
    auto bond = [&](PetscReal r) {
      const PetscReal pull = jkr_ ? 1.5 * PETSC_PI * pair_.w * r / 2 : vdw_.hamaker * (r / 2) / (6 * vdw_.minGap * vdw_.minGap);
      return pull / (material_.density * 4.0 / 3.0 * PETSC_PI * r * r * r * g);
    };
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: bond number (pull-off of two equal spheres / weight of one): %g for radius %g m, %g for radius %g m\n",
                                     (double)bond(rMin_), (double)rMin_, (double)bond(rMax_), (double)rMax_));
  }
  PetscCall(PetscViewerASCIIPrintf(viewer, "dem: this build has no SJKR adhesion, STL or moving walls, periodic boundaries, several particle types (DEM engine issue)\n"));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(swarm_.Destroy());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
