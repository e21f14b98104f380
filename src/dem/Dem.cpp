#include "vofdem/dem/Dem.hpp"

#include "vofdem/core/Options.hpp"
#include "vofdem/core/Random.hpp"
#include "vofdem/core/Runtime.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace {

// Calls f(face, axis, overlap, force) for each face of the box [lo, hi] that the sphere at x with
// radius r and velocity v overlaps; face = 2*axis for the lower face, 2*axis+1 for the upper one,
// and force is the Hertz normal force of the face on the sphere along the axis (P3). The only
// place wall contacts are detected, so forces and the reported wall loads cannot disagree.
template <class F>
inline void ForEachWallContact(const PetscReal x[3], PetscReal r, const PetscReal v[3], const PetscReal lo[3], const PetscReal hi[3],
                               const hertz::NormalContact &c, F &&f) {
  for (int d = 0; d < 3; ++d) {
    const PetscReal dLo = r - (x[d] - lo[d]);  // overlap with the lower face, inward normal +e_d
    const PetscReal dHi = r - (hi[d] - x[d]);  // overlap with the upper face, inward normal -e_d
    if (dLo > 0) f(2 * d, d, dLo, hertz::NormalForce(c, dLo, v[d]));
    if (dHi > 0) f(2 * d + 1, d, dHi, -hertz::NormalForce(c, dHi, -v[d]));
  }
}

}  // namespace

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
    wallYoungs_  = material_.youngs;
    wallPoisson_ = material_.poisson;
    PetscCall(opt.Real("-wall_youngs_modulus", "Young's modulus of the walls (default: the particles')", "Pa", &wallYoungs_, RealRange::Positive()));
    PetscCall(opt.Real("-wall_poisson_ratio", "Poisson ratio of the walls (default: the particles')", "-", &wallPoisson_, RealRange::LeftOpen(-1, 0.5)));
    skin_ = 0.4 * radius_;
    PetscCall(opt.Real("-skin", "Verlet skin: particles migrate once one has moved half of it (default: 0.2 diameters)", "m", &skin_, RealRange::NonNegative()));
    PetscCall(opt.Real("-dt_factor", "Time step as a fraction of the Rayleigh time (P9)", "-", &dtFactor_, RealRange::LeftOpen(0, 1)));
    PetscCall(opt.RealVector("-fill_lower", "Lower corner of the lattice-fill region (default: the box)", "m", fillLower_, 3, RealRange::Any(), &fillLowerSet_));
    PetscCall(opt.RealVector("-fill_upper", "Upper corner of the lattice-fill region (default: the box)", "m", fillUpper_, 3, RealRange::Any(), &fillUpperSet_));
    PetscCall(opt.Real("-fill_spacing", "Lattice spacing of the fill, at least one diameter (0: 2.2 radii)", "m", &fillSpacing_, RealRange::NonNegative()));
    PetscCall(opt.Real("-fill_jitter", "Random displacement of lattice points, fraction of the free gap", "-", &fillJitter_, RealRange::Closed(0, 1)));
    PetscCall(opt.Int("-fill_count", "Number of particles to place on the fill lattice (0: none, -1: as many as the region holds)", &fillCount_, -1));
    PetscCall(opt.RealVector("-fill_velocity", "Initial velocity of inserted particles", "m/s", fillVelocity_, 3));
  }
  PetscOptionsEnd();
  if (fillSpacing_ == 0) fillSpacing_ = 2.2 * radius_;
  if (fillSpacing_ < 2 * radius_)
    VofdemInputError(comm, "option -dem_fill_spacing: %g m is less than a particle diameter (%g m): particles would overlap", (double)fillSpacing_,
                     (double)(2 * radius_));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::SetUp(const Grid &grid, const PetscReal gravity[3], std::uint64_t seed) {
  PetscFunctionBeginUser;
  grid_ = &grid;
  std::copy(gravity, gravity + 3, gravity_);
  const PetscReal mass  = material_.density * 4.0 / 3.0 * PETSC_PI * radius_ * radius_ * radius_;
  const PetscReal Estar = hertz::EffectiveModulus(material_.youngs, material_.poisson, wallYoungs_, wallPoisson_);
  // A wall is a particle of infinite radius and mass (P3): R* = R, m* = m.
  wallContact_  = hertz::MakeNormalContact(Estar, radius_, mass, material_.restitution);
  rayleighTime_ = hertz::RayleighTime(radius_, material_.density, material_.youngs, material_.poisson);
  PetscCall(swarm_.Create(grid));
  PetscCall(Fill(seed));
  PetscCall(ComputeForces());
  PetscFunctionReturn(0);
}

// Lattice fill: centres at lower + R + j + i*s, j the jitter amplitude, so that jittered particles
// neither overlap each other nor leave the region. Every rank walks the same lattice and keeps
// the points it owns; ids and jitter depend only on the lattice index and the seed, so the same
// particles result on any rank count.
PetscErrorCode Dem::Fill(std::uint64_t seed) {
  PetscReal lo[3], hi[3];
  PetscInt  n[3];

  PetscFunctionBeginUser;
  if (fillCount_ == 0) PetscFunctionReturn(0);
  for (int d = 0; d < 3; ++d) {
    lo[d] = fillLowerSet_ ? fillLower_[d] : grid_->Lower()[d];
    hi[d] = fillUpperSet_ ? fillUpper_[d] : grid_->Upper()[d];
    if (lo[d] < grid_->Lower()[d] || hi[d] > grid_->Upper()[d] || !(hi[d] > lo[d]))
      VofdemInputError(comm_, "options -dem_fill_lower/-dem_fill_upper: the region [%g, %g] in %c must be non-empty and inside the box [%g, %g]",
                       (double)lo[d], (double)hi[d], "xyz"[d], (double)grid_->Lower()[d], (double)grid_->Upper()[d]);
  }
  const PetscReal jitter = fillJitter_ * (fillSpacing_ - 2 * radius_) / 2;
  PetscInt64      total  = 1;
  for (int d = 0; d < 3; ++d) {
    const PetscReal room = hi[d] - lo[d] - 2 * (radius_ + jitter);
    n[d]                 = room < 0 ? 0 : (PetscInt)std::floor(room / fillSpacing_ * (1 + 1e-12)) + 1;
    total *= n[d];
  }
  if (fillCount_ < 0 && total > PETSC_MAX_INT)
    VofdemInputError(comm_, "option -dem_fill_count -1: the fill region holds %" PetscInt64_FMT " particles, more than this build's 32-bit indices allow; give a count or a smaller region",
                     total);
  if (fillCount_ > total)
    VofdemInputError(comm_, "option -dem_fill_count: cannot fit %" PetscInt_FMT " particles, the fill region holds %" PetscInt64_FMT " at spacing %g m",
                     fillCount_, total, (double)fillSpacing_);
  const PetscInt64 want = fillCount_ < 0 ? total : fillCount_;
  if (want == 0) VofdemInputError(comm_, "options -dem_fill_*: the fill region is too small for a single particle of radius %g m", (double)radius_);

  auto centre = [&](PetscInt64 id, PetscReal x[3]) {
    const PetscInt64 idx[3] = {id % n[0], (id / n[0]) % n[1], id / ((PetscInt64)n[0] * n[1])};
    for (int d = 0; d < 3; ++d) x[d] = lo[d] + radius_ + jitter + idx[d] * fillSpacing_ + jitter * (2 * random::Uniform(seed, (std::uint64_t)id, d) - 1);
  };
  PetscInt local = 0;
  for (PetscInt64 id = 0; id < want; ++id) {
    PetscReal x[3];
    centre(id, x);
    if (grid_->OwnsPoint(x)) ++local;
  }
  PetscInt       first;
  ParticleArrays a;
  PetscCall(swarm_.AddLocal(local, &first));
  PetscCall(swarm_.GetArrays(&a));
  const PetscReal m = material_.density * 4.0 / 3.0 * PETSC_PI * radius_ * radius_ * radius_;
  PetscInt        p = first;
  for (PetscInt64 id = 0; id < want; ++id) {
    PetscReal x[3];
    centre(id, x);
    if (!grid_->OwnsPoint(x)) continue;
    for (int d = 0; d < 3; ++d) {
      a.x[3 * p + d] = x[d];
      a.v[3 * p + d] = fillVelocity_[d];
      a.f[3 * p + d] = 0;
    }
    a.radius[p] = radius_;
    a.mass[p]   = m;
    a.id[p]     = id;
    ++p;
  }
  PetscCall(swarm_.RestoreArrays(&a));
  PetscCall(swarm_.GlobalCount(&inserted_));
  PetscCheck(inserted_ == want, comm_, PETSC_ERR_PLIB, "lattice fill placed %" PetscInt_FMT " particles instead of %" PetscInt64_FMT, inserted_, want);
  PetscCall(swarm_.MigrateIfNeeded(0, PETSC_TRUE));  // agree with the swarm's own point location; set references
  PetscFunctionReturn(0);
}

// Gravity plus the Hertz normal force of each box face on each particle (P3). The velocity used for
// the damping is the one at hand (half step inside velocity Verlet).
PetscErrorCode Dem::ComputeForces() {
  ParticleArrays a;

  PetscFunctionBeginUser;
  PetscCall(swarm_.GetArrays(&a));
  const PetscReal *lo = grid_->Lower(), *hi = grid_->Upper();
  for (PetscInt p = 0; p < a.n; ++p) {
    PetscReal *f = &a.f[3 * p];
    for (int d = 0; d < 3; ++d) f[d] = a.mass[p] * gravity_[d];
    ForEachWallContact(&a.x[3 * p], a.radius[p], &a.v[3 * p], lo, hi, wallContact_, [f](int, int d, PetscReal, PetscReal fn) { f[d] += fn; });
  }
  PetscCall(swarm_.RestoreArrays(&a));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::Step(PetscReal dt) {
  ParticleArrays a;

  PetscFunctionBeginUser;
  PetscCall(swarm_.GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p) {
    const PetscReal h = 0.5 * dt / a.mass[p];
    for (int d = 0; d < 3; ++d) {
      a.v[3 * p + d] += h * a.f[3 * p + d];
      a.x[3 * p + d] += dt * a.v[3 * p + d];
    }
  }
  PetscCall(swarm_.RestoreArrays(&a));
  PetscCall(swarm_.MigrateIfNeeded(0.5 * skin_, PETSC_FALSE));
  PetscCall(ComputeForces());
  PetscCall(swarm_.GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p) {
    const PetscReal h = 0.5 * dt / a.mass[p];
    for (int d = 0; d < 3; ++d) a.v[3 * p + d] += h * a.f[3 * p + d];
  }
  PetscCall(swarm_.RestoreArrays(&a));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::Summarize(DemSummary *s) const {
  ParticleArrays a;
  PetscReal      sums[1 + 18] = {0}, global[1 + 18], maxOverlap = 0;
  PetscInt       contacts = 0;

  PetscFunctionBeginUser;
  PetscCall(swarm_.GetArrays(&a));
  const PetscReal *lo = grid_->Lower(), *hi = grid_->Upper();
  for (PetscInt p = 0; p < a.n; ++p) {
    const PetscReal *v = &a.v[3 * p], diameter = 2 * a.radius[p];
    sums[0] += 0.5 * a.mass[p] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    // The particles push on a face with minus the force the face exerts on them.
    ForEachWallContact(&a.x[3 * p], a.radius[p], v, lo, hi, wallContact_, [&](int face, int d, PetscReal overlap, PetscReal fn) {
      ++contacts;
      maxOverlap = std::max(maxOverlap, overlap / diameter);
      sums[1 + 3 * face + d] -= fn;
    });
  }
  PetscCall(swarm_.RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(sums, global, 19, MPIU_REAL, MPIU_SUM, comm_));
  PetscCallMPI(MPI_Allreduce(&maxOverlap, &s->maxOverlap, 1, MPIU_REAL, MPIU_MAX, comm_));
  PetscCallMPI(MPI_Allreduce(&contacts, &s->wallContacts, 1, MPIU_INT, MPI_SUM, comm_));
  PetscCall(swarm_.GlobalCount(&s->particles));
  s->kinetic = global[0];
  for (int f = 0; f < 6; ++f)
    for (int d = 0; d < 3; ++d) s->wallForce[f][d] = global[1 + 3 * f + d];
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::FindParticle(std::int64_t id, PetscReal x[3], PetscReal v[3], PetscBool *found) const {
  ParticleArrays a;
  PetscReal      local[7] = {0}, global[7];

  PetscFunctionBeginUser;
  PetscCall(swarm_.GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p) {
    if (a.id[p] != id) continue;
    local[0] = 1;
    for (int d = 0; d < 3; ++d) {
      local[1 + d] = a.x[3 * p + d];
      local[4 + d] = a.v[3 * p + d];
    }
  }
  PetscCall(swarm_.RestoreArrays(&a));
  // Exactly one rank holds the particle, so the sum is the value itself, bit for bit.
  PetscCallMPI(MPI_Allreduce(local, global, 7, MPIU_REAL, MPIU_SUM, comm_));
  *found = (PetscBool)(global[0] == 1);
  for (int d = 0; d < 3; ++d) {
    x[d] = global[1 + d];
    v[d] = global[4 + d];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "dem: %" PetscInt_FMT " spheres of radius %g m, density %g kg/m^3, E %g Pa, nu %g, e %g; Rayleigh time %g s\n",
                                   inserted_, (double)radius_, (double)material_.density, (double)material_.youngs, (double)material_.poisson,
                                   (double)material_.restitution, (double)rayleighTime_));
  PetscCall(PetscViewerASCIIPrintf(viewer, "dem: contacts: Hertz normal with damping against the box faces (P3); particle-particle contacts, friction and adhesion are not implemented yet\n"));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(swarm_.Destroy());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
