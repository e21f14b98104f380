// The simulation: clock, time-step control, the coupled step, monitors. It names no module: it creates the
// modules the scene switched on (-physics) from the registry (base/ModuleRegistry.hpp) and runs each in the
// stages it subscribes to, in the one fixed order of Stage (base/Module.hpp; docs/architecture.md, "The
// coupled step"), each module inside its own PETSc log stage so -log_view breaks the time down per module.
// Drivers reach a module's object through sim/ModuleAccess.hpp.
#pragma once

#include "vofdem/base/Module.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/sim/Checkpoint.hpp"

#include <petsclog.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>
namespace vofdem {

class Simulation {
public:
  PetscErrorCode Create(MPI_Comm comm);
  PetscErrorCode SetFromOptions();
  PetscErrorCode SetUp();          // unused-option check, then modules and the time step
  PetscErrorCode Run();            // steps until -max_steps, -final_time or -stop_kinetic_energy
  // True when Run() ended on a signal (Checkpoint.hpp) before its end: the state is not the run's result.
  bool Interrupted() const { return interrupted_; }
  PetscErrorCode Step();           // one coupled step of size Dt()
  // The time step Run() takes next (the modules' stable limits, or -dt): call before Step() to step
  // as Run() does.
  PetscErrorCode ChooseTimeStep();
  PetscErrorCode View(PetscViewer viewer) const;  // the start-up banner
  PetscErrorCode Destroy();
  // Collective, HDF5 viewer: the clock and the time-step controller's state (root attributes
  // "simulation_*"), then every module's Save/Load (its own group, "dem", "flow", "vof"). LoadState after SetUp()
  // with the saving run's options (Checkpoint::Restore checks them).
  PetscErrorCode SaveState(PetscViewer viewer);
  PetscErrorCode LoadState(PetscViewer viewer);
  // Collective: about how many bytes SaveState writes (all ranks), for the disk-space check.
  PetscErrorCode StateBytes(PetscInt64 *bytes) const;

  PetscReal Time() const { return time_; }
  PetscReal Dt() const { return dt_; }
  PetscInt  StepNumber() const { return step_; }
  // The modules on (with the implied ones, e.g. the coupling), in the registry's order, and the -physics
  // words among them ("dem,flow"; the checkpoint's "physics").
  const std::vector<std::string> &ModuleNames() const { return on_; }
  std::string                     PhysicsDescription() const;
  const ModuleSet                &Modules() const { return modules_; }
  const Grid                     &GetGrid() const { return grid_; }

private:
  PetscErrorCode Monitor();
  PetscErrorCode PushStage(std::size_t module) const;  // the module's PETSc log stage
  PetscErrorCode ViewStages(PetscViewer viewer) const;  // the stage table of the banner

  MPI_Comm   comm_ = MPI_COMM_NULL;
  std::vector<std::string> on_;
  Grid       grid_;
  RunContext context_;
  ModuleSet  modules_;
  std::vector<PetscLogStage>        logStages_;           // per module, in modules_' order
  std::vector<std::vector<std::size_t>> stageModules_;  // per Stage: the modules (indices) that run in it
  bool       adaptsEveryStep_ = false;  // a module's limit moves with its state: choose the step every step
  Checkpoint checkpoint_;

  PetscReal time_ = 0, dt_ = 0, dtUser_ = 0, dtInitial_ = 0, dtMax_ = 0, finalTime_ = PETSC_MAX_REAL;
  PetscReal dtTaken_ = 0;  // the last step's length: dt_, or less where it landed on -final_time (the monitor's dt)
  PetscBool dtForce_ = PETSC_FALSE, monitorTiming_ = PETSC_TRUE;
  PetscInt  step_ = 0, maxSteps_ = 100, monitorEvery_ = 10;
  PetscBool maxStepsSet_ = PETSC_FALSE;  // the scene gave -max_steps (the closing line names a default that ended the run)
  PetscReal gravity_[3] = {0, 0, -9.81};
  PetscReal stopKinetic_ = 0, stopKineticAfter_ = 0;  // -stop_kinetic_energy, -stop_kinetic_energy_after
  PetscReal lastKinetic_ = PETSC_MAX_REAL;            // the particles' kinetic energy at the last monitor line
  bool      interrupted_ = false;
  PetscInt  seed_ = 12345;
  std::string outputDir_;
  std::string dtLimitName_;
  FILE     *csv_ = nullptr;
  PetscLogDouble wallStart_ = 0;
  PetscInt       runStartStep_ = 0;  // step and time at Run() (a restart's ETA counts from here)
  PetscReal      runStartTime_ = 0;
};

}  // namespace vofdem
