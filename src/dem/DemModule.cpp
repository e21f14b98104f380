// DemModule.hpp: the particles in the simulation's stages, monitor and banner.
#include "vofdem/dem/DemModule.hpp"

#include "vofdem/base/ModuleRegistry.hpp"

#include <cstdio>

namespace vofdem {

PetscErrorCode DemModule::Run(Stage stage, StepState &step) {
  PetscFunctionBeginUser;
  if (stage == Stage::Particles)
    for (PetscInt k = 0; k < step.substeps; ++k) PetscCall(dem_.Step(step.dt / step.substeps));
  PetscFunctionReturn(0);
}

PetscErrorCode DemModule::LowerTimeStep(TimeStepLimit *limit) {
  PetscFunctionBeginUser;
  if (!substepped_) limit->Lower(dem_.StableTimeStep(), dem_.TimeStepBasis());  // sub-stepped: inside the fluid's step
  PetscFunctionReturn(0);
}

std::string DemModule::MonitorColumnsLead() const {
  return ",particles,kinetic_energy_J,rotational_energy_J,pair_contacts,coordination,wall_contacts,max_overlap_per_diameter,floor_force_z_N,inserted,deleted";
}

PetscErrorCode DemModule::Monitor(MonitorPart *part) {
  DemSummary  s;
  std::string extraCsv, extraScreen;
  char        buf[512];

  PetscFunctionBeginUser;
  PetscCall(dem_.Summarize(&s));
  part->restEnergy = s.kinetic + s.rotational;
  PetscCall(dem_.MonitorValues(&extraCsv, &extraScreen));
  std::snprintf(buf, sizeof buf, "  | particles %d  KE %.6e J  rot %.3e J  contacts %d  Z %.3f  wall %d  overlap %.3e d  floor %.6e N", (int)s.particles, (double)s.kinetic,
                (double)s.rotational, (int)s.pairContacts, (double)s.coordination, (int)s.wallContacts, (double)s.maxOverlap, (double)s.wallForce[4][2]);
  part->screen = buf;
  if (s.sources) {  // insertion sources or deletion boxes (ParticleSources)
    std::snprintf(buf, sizeof buf, "  inserted %lld deleted %lld", (long long)s.inserted, (long long)s.deleted);
    part->screen += buf;
  }
  part->screen += extraScreen;
  for (const WallLoad &L : s.walls) {  // -dem_walls: the force of the particles on each wall
    std::snprintf(buf, sizeof buf, "  %s F (%.6e, %.6e, %.6e) N", L.name.c_str(), (double)L.force[0], (double)L.force[1], (double)L.force[2]);
    part->screen += buf;
  }
  std::snprintf(buf, sizeof buf, ",%d,%.10e,%.10e,%d,%.6f,%d,%.6e,%.10e,%lld,%lld", (int)s.particles, (double)s.kinetic, (double)s.rotational, (int)s.pairContacts,
                (double)s.coordination, (int)s.wallContacts, (double)s.maxOverlap, (double)s.wallForce[4][2], (long long)s.inserted, (long long)s.deleted);
  part->csvLead = buf;
  part->csv.clear();
  for (const WallLoad &L : s.walls)
    for (const PetscReal *q : {L.force, L.torque}) {
      std::snprintf(buf, sizeof buf, ",%.10e,%.10e,%.10e", (double)q[0], (double)q[1], (double)q[2]);
      part->csv += buf;
    }
  if (s.bonds) {  // -dem_cohesion bond (P13)
    std::snprintf(buf, sizeof buf, ",%lld,%lld,%lld,%.15e,%.15e", (long long)s.bondsMade, (long long)s.bondsIntact, (long long)s.bondsBroken, (double)s.bondSigma, (double)s.bondTau);
    part->csv += buf;
    std::snprintf(buf, sizeof buf, "  bonds %lld intact %lld broken", (long long)s.bondsIntact, (long long)s.bondsBroken);
    part->screen += buf;
  }
  part->csv += extraCsv;
  PetscFunctionReturn(0);
}

PetscErrorCode DemModule::ViewTimeStep(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "time step limits: dem %g s%s\n", (double)dem_.StableTimeStep(), substepped_ ? " (sub-steps inside the fluid step)" : ""));
  PetscFunctionReturn(0);
}

PetscErrorCode DemModule::Finish() {
  PetscFunctionBeginUser;
  if (!dem_.SaveParticlesPath().empty()) PetscCall(dem_.SaveParticles(dem_.SaveParticlesPath()));
  if (!dem_.SaveContactHistoryPath().empty()) PetscCall(dem_.SaveContactHistory(dem_.SaveContactHistoryPath()));
  PetscFunctionReturn(0);
}

void RegisterModule_dem(ModuleRegistry &registry) {
  ModuleEntry e;
  e.name    = "dem";
  e.summary = "particles: Hertz-Mindlin DEM with rolling resistance, cohesion, walls, clumps, insertion (src/dem)";
  e.create  = [] { return std::unique_ptr<Module>(new DemModule); };
  registry.Add(std::move(e));
}

}  // namespace vofdem
