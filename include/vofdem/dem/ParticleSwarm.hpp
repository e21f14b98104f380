// The particles' DMSwarm (PIC type) on the grid's vertex DMDA, with its structure-of-arrays fields,
// and migration that never loses a particle silently: DMSwarmMigrate deletes particles that jump
// more than one subdomain or leave the box (docs/petsc-notes.md), so the global count is checked.
#pragma once

#include "vofdem/grid/Grid.hpp"

#include <petscdmswarm.h>

namespace vofdem {

// Names of the swarm fields (each one contiguous array; vectors are 3 values per particle).
namespace field {
inline constexpr const char *position = DMSwarmPICField_coor;  // m
inline constexpr const char *velocity = "velocity";            // m/s
inline constexpr const char *force    = "force";               // N, total force of the last evaluation
inline constexpr const char *radius   = "radius";              // m
inline constexpr const char *mass     = "mass";                // kg
inline constexpr const char *id       = "id";                  // global id, PetscInt64
inline constexpr const char *reference = "reference";          // m, position at the last migration
inline constexpr const char *omega    = "omega";               // rad/s, angular velocity
inline constexpr const char *torque   = "torque";              // N m, total torque of the last evaluation
inline constexpr const char *type     = "type";                // particle type (index into -dem_types), PetscInt
inline constexpr const char *clump    = "clump";               // id of the rigid clump the sphere belongs to, -1: none (P10), PetscInt64
inline constexpr const char *rigid    = "rigid";               // a clump member's body state (Clumps.hpp), kRigidWidth reals; clump scenes only
// Set by the fluid coupling (Coupling.hpp) once per fluid step, read by every DEM sub-step. Registered only in a
// coupled scene (ParticleSwarm::SetFluidFields before Create): a DEM-only swarm neither holds, migrates nor saves them.
inline constexpr const char *fluidDrag     = "fluid_drag";      // kg/s, drag coefficient K: drag = K (u - v), applied implicitly
inline constexpr const char *fluidVelocity = "fluid_velocity";  // m/s, the fluid velocity u the drag relaxes to
inline constexpr const char *fluidForce    = "fluid_force";     // N, the other fluid forces (pressure gradient), explicit
inline constexpr const char *fluidImpulse  = "fluid_impulse";   // N s, drag impulse received since the coupling last read it
inline constexpr const char *fluidAddedMass = "fluid_added_mass";  // kg, C_vm rho_f V: the added mass taken implicitly (P1 f_vm)
// N s, the explicit fluid forces' impulse over the coming sub-steps (f_vm's m_a Du/Dt, the capillary force),
// kept apart from the drag impulse so the fluid receives it with either -coupling_fluid_drag (F5)
inline constexpr const char *fluidExplicitImpulse = "fluid_explicit_impulse";
inline constexpr const char *fluidCapillaryImpulse = "fluid_capillary_impulse";  // N s, the capillary force's, likewise (its own deposit)
// The local free surface seen by the particle's kernel, as a plane: unit normal n (liquid to gas) and offset c,
// so that the centre's height above it is s = n.x + c (4 reals; n = 0: no interface). The DEM sub-steps
// evaluate the capillary force at the current s (Dem::SetSurfaceForce).
inline constexpr const char *fluidSurfacePlane = "fluid_surface_plane";
// Rotation (-coupling_rotational_drag): the torque -K_r (omega - Omega_f), taken implicitly by every kick like the
// drag, with K_r (N m s) and half the fluid's vorticity Omega_f = curl(u)/2 at the particle (rad/s, 3 reals).
inline constexpr const char *fluidRotationalDrag = "fluid_rotational_drag";
inline constexpr const char *fluidRotation       = "fluid_rotation";
// Pa s, the fluid viscosity the particle reads (K1): the lubrication of -coupling_lubrication (P8) between two particles
// takes the mean of theirs.
inline constexpr const char *fluidViscosity = "fluid_viscosity";
// The particle's energy (docs/physics.md P11), registered only when the particles exchange heat with the energy
// equation (ParticleSwarm::SetHeatFields before Create): the enthalpy per mass h = int cp dT + f_l(T) L from the
// reference temperature of the energy module, and the temperature T(h) it gives (0 K: not set yet, a new particle).
// The particles know no fluid: the coupling (coupling/ParticleHeat.hpp) fills and moves both.
inline constexpr const char *enthalpy    = "enthalpy";     // J/kg
inline constexpr const char *temperature = "temperature";  // K
// The particle's own energy account since it entered (J): the laser it absorbed and the heat it gave the fluid
// (convection and radiation) and the heat it took through its contacts with other particles;
// m (h - h_0) = absorbed - exchanged + conducted closes it (the melt log, ParticleMelt.hpp).
inline constexpr const char *heatAbsorbed  = "heat_absorbed";   // J
inline constexpr const char *heatExchanged = "heat_exchanged";  // J
inline constexpr const char *heatConducted = "heat_conducted";  // J
}  // namespace field
// q (4), centre in the body frame (3), clump mass, principal moments (3): see Clumps.hpp.
inline constexpr int kRigidWidth = 11;
// The fluid coupling's fields with their reals per particle: registered together (a coupled scene only), zeroed
// together for new particles, and saved in this order (DemSaveLoad.cpp).
struct SwarmFieldWidth {
  const char *name;
  PetscInt    width;
};
inline constexpr SwarmFieldWidth kFluidFields[] = {{field::fluidDrag, 1},         {field::fluidVelocity, 3},         {field::fluidForce, 3},
                                                   {field::fluidImpulse, 3},      {field::fluidAddedMass, 1},        {field::fluidExplicitImpulse, 3},
                                                   {field::fluidCapillaryImpulse, 3}, {field::fluidSurfacePlane, 4}, {field::fluidRotationalDrag, 1},
                                                   {field::fluidRotation, 3},     {field::fluidViscosity, 1}};
inline constexpr int kNumFluidFields = sizeof(kFluidFields) / sizeof(kFluidFields[0]);
// The heat fields, likewise (zeroed for new particles; saved after the bonds, DemSaveLoad.cpp).
inline constexpr SwarmFieldWidth kHeatFields[] = {{field::enthalpy, 1}, {field::temperature, 1}, {field::heatAbsorbed, 1}, {field::heatExchanged, 1}, {field::heatConducted, 1}};
inline constexpr int             kNumHeatFields = sizeof(kHeatFields) / sizeof(kHeatFields[0]);
inline constexpr int             kNumHeatState  = 2;  // enthalpy and temperature; the rest is the account (0 when a file lacks it)

// Every field of the local particles at once, for loops over particles (structure of arrays;
// vectors hold x,y,z per particle). Valid between GetArrays and RestoreArrays.
struct ParticleArrays {
  PetscInt    n = 0;
  PetscReal  *x = nullptr, *v = nullptr, *f = nullptr, *radius = nullptr, *mass = nullptr, *reference = nullptr;
  PetscReal  *omega = nullptr, *torque = nullptr, *rigid = nullptr;
  PetscInt64 *id = nullptr, *clump = nullptr;
  PetscInt   *type = nullptr;
  PetscReal  *fluidDrag = nullptr, *fluidVelocity = nullptr, *fluidForce = nullptr, *fluidImpulse = nullptr, *fluidAddedMass = nullptr;
  PetscReal  *fluidExplicitImpulse = nullptr, *fluidCapillaryImpulse = nullptr, *fluidSurfacePlane = nullptr;
  PetscReal  *fluidRotationalDrag = nullptr, *fluidRotation = nullptr, *fluidViscosity = nullptr;
  PetscReal  *enthalpy = nullptr, *temperature = nullptr;  // null unless SetHeatFields(true) before Create
  PetscReal  *heatAbsorbed = nullptr, *heatExchanged = nullptr, *heatConducted = nullptr;  // likewise
};

class ParticleSwarm {
public:
  PetscErrorCode Create(const Grid &grid);
  PetscErrorCode Destroy();

  DM       Dm() const { return swarm_; }
  PetscErrorCode GlobalCount(PetscInt *n) const;
  // The bytes one particle's registered fields take (DMSwarm's own coordinates, pid, cell and rank included):
  // the least a particle costs, for refusing requests that cannot fit (CheckMemoryRequest). Valid after Create.
  double BytesPerParticle() const {
    PetscInt reals = 3 * 6 + 2 + (rigidRegistered_ ? kRigidWidth : 0) + 3;  // velocity ... torque, radius, mass; rigid; coordinates
    if (fluidRegistered_)
      for (const SwarmFieldWidth &f : kFluidFields) reals += f.width;
    if (heatRegistered_) reals += kNumHeatFields;
    return 8.0 * reals + 8 + 4 + 8 + 8 + 4 + 4;  // id, type, clump; DMSwarm_pid, _cellid, _rank
  }

  // The arrays come from a cache of the fields' addresses: DMSwarmGetField finds a field by comparing its
  // name with every registered one (twice), and the 23 lookups of one GetArrays took ~10 us, which a DEM
  // step with few particles pays several times (70 % of a single settling sphere's run). The addresses
  // change only when the swarm is resized, so the cache is refreshed when the local count differs and
  // after FieldsMoved(), which whatever resizes the swarm must call (migration, insertion, deletion, load,
  // sorting). Between GetArrays and RestoreArrays the swarm must not be resized (as DMSwarm's own access
  // rule); FieldsMoved() checks it.
  PetscErrorCode GetArrays(ParticleArrays *a) const;  // the fluid_* arrays are null unless SetFluidFields(true)
  // A coupled scene: before Create, so that the fluid_* fields are registered (26 reals per particle that a
  // DEM-only scene does without); after Create only to switch them off or on again.
  void           SetFluidFields(bool on) { fluidFields_ = on; }
  bool           HasFluidFields() const { return fluidRegistered_; }  // the fluid_* fields exist in the swarm
  // A scene that can hold clumps (P10: a particles file with a clump column, clump insertion): before Create, so
  // that the `rigid` field is registered (11 reals per particle a scene of single spheres does without; a.rigid
  // is null otherwise).
  void           SetRigidFields(bool on) { rigidFields_ = on; }
  bool           HasRigidFields() const { return rigidRegistered_; }
  // Particles that exchange heat (the energy module with a coupling): before Create, so that the enthalpy and
  // temperature fields are registered (a.enthalpy and a.temperature are null otherwise).
  void           SetHeatFields(bool on) { heatFields_ = on; }
  bool           HasHeatFields() const { return heatRegistered_; }
  PetscErrorCode RestoreArrays(ParticleArrays *a) const;
  PetscErrorCode FieldsMoved() const;  // after any DMSwarm call that may reallocate (resize) the fields

  // Appends n particles locally (fields left for the caller to fill); returns the first new index.
  PetscErrorCode AddLocal(PetscInt n, PetscInt *first);

  // Collective: whether any particle has moved more than `halfSkin` since the last migration, the
  // Verlet-list rebuild rule. Migrating only then keeps every particle within halfSkin of its
  // rank's box; DMSwarmMigrate is costly (point location and collectives): calling it on every
  // step that some particle crossed a boundary took 61 % of a 2-rank run.
  PetscErrorCode NeedsRebuild(PetscReal halfSkin, PetscBool *rebuild) const;
  // Sends particles to the ranks that own their positions and resets the reference positions.
  // The global count before and after must agree: a lost particle is an error.
  PetscErrorCode Migrate();

private:
  PetscErrorCode RefreshCache() const;

  bool fluidFields_ = false;      // GetArrays takes the fluid_* fields too (a coupled scene)
  bool fluidRegistered_ = false;  // Create registered them (fluidFields_ was set before it)
  bool rigidFields_ = false, rigidRegistered_ = false;  // the same for the clumps' `rigid` field
  bool heatFields_ = false, heatRegistered_ = false;    // and for the heat fields
  mutable ParticleArrays cache_;         // every field's address (fluid ones included) for cacheN_ local particles
  mutable bool           cacheValid_ = false;
  mutable PetscInt       cacheN_     = -1;
  mutable int            held_       = 0;  // GetArrays without RestoreArrays yet
  const Grid *grid_  = nullptr;
  DM          swarm_ = nullptr;
};

}  // namespace vofdem
