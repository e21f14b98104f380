// The particle module (-physics dem), first part: one particle type of spheres, lattice insertion,
// gravity, Hertz normal contact with damping against the six faces of the box (PHYSICS.md P3),
// velocity Verlet, a Rayleigh-time step (P9), migration across ranks with a count check.
// Particle-particle contacts, friction, rolling, adhesion and the rest of P3-P10 are the DEM
// engine's issue and are not here yet: the start-up banner says so.
#pragma once

#include "vofdem/dem/HertzMindlin.hpp"
#include "vofdem/dem/ParticleSwarm.hpp"
#include "vofdem/grid/Grid.hpp"

#include <array>
#include <cstdint>

namespace vofdem {

struct DemMaterial {
  PetscReal density     = 2500;  // kg/m^3
  PetscReal youngs      = 1e8;   // Pa
  PetscReal poisson     = 0.28;  // -
  PetscReal restitution = 0.5;   // -
};

// Global totals over all ranks, for monitors and tests.
struct DemSummary {
  PetscInt  particles      = 0;
  PetscReal kinetic        = 0;  // translational kinetic energy, J
  PetscReal maxOverlap     = 0;  // largest wall overlap / diameter
  PetscInt  wallContacts   = 0;
  PetscReal wallForce[6][3] = {};  // force of the particles on each face (x-, x+, y-, y+, z-, z+), N
};

class Dem {
public:
  PetscErrorCode SetFromOptions(MPI_Comm comm);
  // Creates the swarm on the grid's vertex DMDA, fills the insertion region, evaluates forces.
  PetscErrorCode SetUp(const Grid &grid, const PetscReal gravity[3], std::uint64_t seed);
  // Largest stable step: -dem_dt_factor times the Rayleigh time (P9).
  PetscReal StableTimeStep() const { return dtFactor_ * rayleighTime_; }
  PetscReal RayleighTime() const { return rayleighTime_; }
  PetscErrorCode Step(PetscReal dt);  // one velocity-Verlet step
  PetscErrorCode Summarize(DemSummary *s) const;
  PetscErrorCode View(PetscViewer viewer) const;
  PetscErrorCode Destroy();

  // Collective: position and velocity of the particle with global id `id`; found is false on all
  // ranks when no rank has it.
  PetscErrorCode FindParticle(std::int64_t id, PetscReal x[3], PetscReal v[3], PetscBool *found) const;
  const DemMaterial &Material() const { return material_; }
  PetscReal          Radius() const { return radius_; }
  DM                 Swarm() const { return swarm_.Dm(); }

private:
  PetscErrorCode Fill(std::uint64_t seed);
  PetscErrorCode ComputeForces();

  const Grid   *grid_ = nullptr;
  ParticleSwarm swarm_;
  DemMaterial   material_;
  PetscReal     wallYoungs_ = -1, wallPoisson_ = -1;  // default: the particles' own
  PetscReal     radius_     = 5e-4;                     // m
  PetscReal     dtFactor_   = 0.3;                      // of the Rayleigh time (seed 001)
  PetscReal     skin_       = 0;                        // m, migration margin
  PetscReal     gravity_[3] = {0, 0, 0};
  PetscReal     rayleighTime_ = 0;
  hertz::NormalContact wallContact_{};

  // Lattice fill of a region (-dem_fill_*)
  PetscReal fillLower_[3] = {0, 0, 0}, fillUpper_[3] = {0, 0, 0};
  PetscBool fillLowerSet_ = PETSC_FALSE, fillUpperSet_ = PETSC_FALSE;
  PetscReal fillSpacing_  = 0;  // m; 0 = 2.2 radii
  PetscReal fillJitter_   = 0;  // fraction of the free gap
  PetscInt  fillCount_    = 0;  // 0 = no fill, -1 = as many as fit
  PetscReal fillVelocity_[3] = {0, 0, 0};
  PetscInt  inserted_     = 0;
  MPI_Comm  comm_         = MPI_COMM_NULL;
};

}  // namespace vofdem
