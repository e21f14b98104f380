#include "vofdem/dem/ParticleSwarm.hpp"

#include <unordered_map>

namespace vofdem {

PetscErrorCode ParticleSwarm::Create(const Grid &grid) {
  PetscFunctionBeginUser;
  grid_ = &grid;
  PetscCall(DMCreate(grid.Comm(), &swarm_));
  PetscCall(DMSetType(swarm_, DMSWARM));
  PetscCall(PetscObjectSetName((PetscObject)swarm_, "particles"));
  PetscCall(DMSetDimension(swarm_, 3));
  PetscCall(DMSwarmSetType(swarm_, DMSWARM_PIC));
  PetscCall(DMSwarmSetCellDM(swarm_, grid.VertexDM()));
  PetscCall(DMSwarmInitializeFieldRegister(swarm_));
  PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, field::velocity, 3, PETSC_REAL));
  PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, field::force, 3, PETSC_REAL));
  PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, field::radius, 1, PETSC_REAL));
  PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, field::mass, 1, PETSC_REAL));
  PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, field::id, 1, PETSC_INT64));
  PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, field::reference, 3, PETSC_REAL));
  PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, field::omega, 3, PETSC_REAL));
  PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, field::torque, 3, PETSC_REAL));
  PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, field::type, 1, PETSC_INT));
  PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, field::clump, 1, PETSC_INT64));
  // A clump member's rigid-body state only where clumps can exist (11 reals per particle otherwise unused).
  rigidRegistered_ = rigidFields_;
  if (rigidRegistered_) PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, field::rigid, kRigidWidth, PETSC_REAL));
  // The fluid's fields only in a coupled scene (nothing of the coupling is allocated without it).
  fluidRegistered_ = fluidFields_;
  if (fluidRegistered_)
    for (const SwarmFieldWidth &f : kFluidFields) PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, f.name, f.width, PETSC_REAL));
  // The particles' enthalpy and temperature only when they exchange heat (docs/physics.md P11).
  heatRegistered_ = heatFields_;
  if (heatRegistered_)
    for (const SwarmFieldWidth &f : kHeatFields) PetscCall(DMSwarmRegisterPetscDatatypeField(swarm_, f.name, f.width, PETSC_REAL));
  PetscCall(DMSwarmFinalizeFieldRegister(swarm_));
  PetscCall(DMSwarmSetLocalSizes(swarm_, 0, 64));
  PetscCall(FieldsMoved());
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSwarm::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(DMDestroy(&swarm_));
  PetscFunctionReturn(0);
}

namespace {

// One field's address: taken and given back at once (the address stays valid until the swarm is resized).
template <typename T>
PetscErrorCode FieldAddress(DM swarm, const char *name, T **p) {
  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetField(swarm, name, nullptr, nullptr, (void **)p));
  T *q = *p;
  PetscCall(DMSwarmRestoreField(swarm, name, nullptr, nullptr, (void **)&q));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ParticleSwarm::RefreshCache() const {
  ParticleArrays &c = cache_;

  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetLocalSize(swarm_, &c.n));
  PetscCall(FieldAddress(swarm_, field::position, &c.x));
  PetscCall(FieldAddress(swarm_, field::velocity, &c.v));
  PetscCall(FieldAddress(swarm_, field::force, &c.f));
  PetscCall(FieldAddress(swarm_, field::radius, &c.radius));
  PetscCall(FieldAddress(swarm_, field::mass, &c.mass));
  PetscCall(FieldAddress(swarm_, field::id, &c.id));
  PetscCall(FieldAddress(swarm_, field::reference, &c.reference));
  PetscCall(FieldAddress(swarm_, field::omega, &c.omega));
  PetscCall(FieldAddress(swarm_, field::torque, &c.torque));
  PetscCall(FieldAddress(swarm_, field::type, &c.type));
  PetscCall(FieldAddress(swarm_, field::clump, &c.clump));
  c.rigid = nullptr;
  if (rigidRegistered_) PetscCall(FieldAddress(swarm_, field::rigid, &c.rigid));
  if (fluidRegistered_) {
    PetscCall(FieldAddress(swarm_, field::fluidDrag, &c.fluidDrag));
    PetscCall(FieldAddress(swarm_, field::fluidVelocity, &c.fluidVelocity));
    PetscCall(FieldAddress(swarm_, field::fluidForce, &c.fluidForce));
    PetscCall(FieldAddress(swarm_, field::fluidImpulse, &c.fluidImpulse));
    PetscCall(FieldAddress(swarm_, field::fluidAddedMass, &c.fluidAddedMass));
    PetscCall(FieldAddress(swarm_, field::fluidExplicitImpulse, &c.fluidExplicitImpulse));
    PetscCall(FieldAddress(swarm_, field::fluidCapillaryImpulse, &c.fluidCapillaryImpulse));
    PetscCall(FieldAddress(swarm_, field::fluidSurfacePlane, &c.fluidSurfacePlane));
    PetscCall(FieldAddress(swarm_, field::fluidRotationalDrag, &c.fluidRotationalDrag));
    PetscCall(FieldAddress(swarm_, field::fluidRotation, &c.fluidRotation));
    PetscCall(FieldAddress(swarm_, field::fluidViscosity, &c.fluidViscosity));
  }
  c.enthalpy = c.temperature = c.heatAbsorbed = c.heatExchanged = c.heatConducted = nullptr;
  if (heatRegistered_) {
    PetscCall(FieldAddress(swarm_, field::enthalpy, &c.enthalpy));
    PetscCall(FieldAddress(swarm_, field::temperature, &c.temperature));
    PetscCall(FieldAddress(swarm_, field::heatAbsorbed, &c.heatAbsorbed));
    PetscCall(FieldAddress(swarm_, field::heatExchanged, &c.heatExchanged));
    PetscCall(FieldAddress(swarm_, field::heatConducted, &c.heatConducted));
  }
  cacheN_     = c.n;
  cacheValid_ = true;
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSwarm::GetArrays(ParticleArrays *a) const {
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetLocalSize(swarm_, &n));
  PetscCheck(!fluidFields_ || fluidRegistered_, PETSC_COMM_SELF, PETSC_ERR_ORDER,
             "the particle swarm was created without the fluid's fields: a coupled scene calls Dem::UseFluidFields() before Dem::SetUp()");
  if (!cacheValid_ || n != cacheN_) PetscCall(RefreshCache());
  *a = cache_;
  // The fluid's fields only with a coupling (Dem::SetFluidCoupled).
  if (!fluidFields_) {
    a->fluidDrag = a->fluidVelocity = a->fluidForce = a->fluidImpulse = a->fluidAddedMass = a->fluidExplicitImpulse = nullptr;
    a->fluidCapillaryImpulse = a->fluidSurfacePlane = a->fluidRotationalDrag = a->fluidRotation = a->fluidViscosity = nullptr;
  }
  ++held_;
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSwarm::RestoreArrays(ParticleArrays *a) const {
  PetscFunctionBeginUser;
  PetscCheck(held_ > 0, PETSC_COMM_SELF, PETSC_ERR_ORDER, "ParticleSwarm::RestoreArrays without GetArrays");
  --held_;
  *a = ParticleArrays{};
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSwarm::FieldsMoved() const {
  PetscFunctionBeginUser;
  PetscCheck(held_ == 0, PETSC_COMM_SELF, PETSC_ERR_ORDER, "the particle swarm was resized while %d set(s) of its arrays were in use", held_);
  cacheValid_ = false;
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSwarm::GlobalCount(PetscInt *n) const {
  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetSize(swarm_, n));
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSwarm::AddLocal(PetscInt n, PetscInt *first) {
  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetLocalSize(swarm_, first));
  PetscCall(FieldsMoved());  // no arrays in use while the swarm grows
  PetscCall(DMSwarmAddNPoints(swarm_, n));
  PetscCall(FieldsMoved());
  // Not in a clump: identity orientation, zeros (defined bytes for checkpoints).
  if (rigidRegistered_) {
    PetscReal *rigid;
    PetscCall(DMSwarmGetField(swarm_, field::rigid, nullptr, nullptr, (void **)&rigid));
    for (PetscInt p = *first; p < *first + n; ++p)
      for (int k = 0; k < kRigidWidth; ++k) rigid[kRigidWidth * p + k] = k == 0 ? 1 : 0;
    PetscCall(DMSwarmRestoreField(swarm_, field::rigid, nullptr, nullptr, (void **)&rigid));
  }
  // New particles feel no fluid until the coupling's next update (and every byte is defined for checkpoints).
  if (fluidRegistered_)
    for (const SwarmFieldWidth &f : kFluidFields) {
      PetscReal *v;
      PetscCall(DMSwarmGetField(swarm_, f.name, nullptr, nullptr, (void **)&v));
      for (PetscInt k = *first * f.width; k < (*first + n) * f.width; ++k) v[k] = 0;
      PetscCall(DMSwarmRestoreField(swarm_, f.name, nullptr, nullptr, (void **)&v));
    }
  // A new particle's temperature 0 K marks it for the heat coupling, which gives it its initial temperature.
  if (heatRegistered_)
    for (const SwarmFieldWidth &f : kHeatFields) {
      PetscReal *v;
      PetscCall(DMSwarmGetField(swarm_, f.name, nullptr, nullptr, (void **)&v));
      for (PetscInt k = *first * f.width; k < (*first + n) * f.width; ++k) v[k] = 0;
      PetscCall(DMSwarmRestoreField(swarm_, f.name, nullptr, nullptr, (void **)&v));
    }
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSwarm::NeedsRebuild(PetscReal halfSkin, PetscBool *rebuild) const {
  ParticleArrays a;
  PetscReal      moved2 = 0, maxMoved2 = 0;

  PetscFunctionBeginUser;
  PetscCall(GetArrays(&a));
  for (PetscInt p = 0; p < 3 * a.n; p += 3) {
    const PetscReal dx = a.x[p] - a.reference[p], dy = a.x[p + 1] - a.reference[p + 1], dz = a.x[p + 2] - a.reference[p + 2];
    moved2             = PetscMax(moved2, dx * dx + dy * dy + dz * dz);
  }
  PetscCall(RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(&moved2, &maxMoved2, 1, MPIU_REAL, MPIU_MAX, grid_->Comm()));
  *rebuild = (PetscBool)(maxMoved2 > halfSkin * halfSkin);
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleSwarm::Migrate() {
  ParticleArrays a;
  PetscInt       before = 0, after = 0;

  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetSize(swarm_, &before));
  // The spheres of one rigid clump (P10) go to one rank together: each is located by the position of
  // the clump's member with the lowest id (all members are on one rank, so it is known here), and its
  // own position rides in `reference` meanwhile (which is reset below anyway).
  PetscCall(GetArrays(&a));
  {
    std::unordered_map<PetscInt64, PetscInt> lead;  // clump -> local index of its lowest-id member
    for (PetscInt p = 0; p < a.n; ++p) {
      for (int d = 0; d < 3; ++d) a.reference[3 * p + d] = a.x[3 * p + d];
      if (a.clump[p] < 0) continue;
      auto it = lead.find(a.clump[p]);
      if (it == lead.end()) lead.emplace(a.clump[p], p);
      else if (a.id[p] < a.id[it->second]) it->second = p;
    }
    for (PetscInt p = 0; p < a.n && !lead.empty(); ++p)
      if (a.clump[p] >= 0)
        for (int d = 0; d < 3; ++d) a.x[3 * p + d] = a.reference[3 * lead[a.clump[p]] + d];
  }
  PetscCall(RestoreArrays(&a));
  PetscCall(DMSwarmMigrate(swarm_, PETSC_TRUE));
  PetscCall(FieldsMoved());
  PetscCall(DMSwarmGetSize(swarm_, &after));
  PetscCheck(after == before, grid_->Comm(), PETSC_ERR_PLIB,
             "migration lost %" PetscInt_FMT " of %" PetscInt_FMT " particles (a particle left the box or jumped past a neighbouring rank)",
             before - after, before);
  PetscCall(GetArrays(&a));
  for (PetscInt p = 0; p < 3 * a.n; ++p) a.x[p] = a.reference[p];  // each sphere's own position back
  PetscCall(RestoreArrays(&a));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
