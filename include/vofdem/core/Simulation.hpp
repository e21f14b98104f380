// The simulation: clock, time-step control, the coupled step, monitors. It owns the modules the
// scene switched on (-physics) and calls them in the order of ARCHITECTURE.md ("The coupled step"),
// each inside its own PETSc log stage so -log_view breaks the time down per module.
#pragma once

#include "vofdem/core/Checkpoint.hpp"
#include "vofdem/core/Physics.hpp"
#include "vofdem/coupling/Coupling.hpp"
#include "vofdem/dem/Dem.hpp"
#include "vofdem/flow/Flow.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/vof/Vof.hpp"

#include <petsclog.h>

#include <cstdio>
#include <memory>
#include <string>

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
  // "simulation_*"), then every module's Save/Load (groups "dem", "flow", "vof"). LoadState after SetUp()
  // with the saving run's options (Checkpoint::Restore checks them).
  PetscErrorCode SaveState(PetscViewer viewer);
  PetscErrorCode LoadState(PetscViewer viewer);
  // Collective: about how many bytes SaveState writes (all ranks), for the disk-space check.
  PetscErrorCode StateBytes(PetscInt64 *bytes) const;

  PetscReal Time() const { return time_; }
  PetscReal Dt() const { return dt_; }
  PetscInt  StepNumber() const { return step_; }
  const PhysicsSet &Physics() const { return physics_; }
  Dem       *Particles() { return dem_.get(); }
  Flow      *Fluid() { return flow_.get(); }
  Vof       *Interface() { return vof_.get(); }
  Coupling  *Coupled() { return coupling_.get(); }
  const Grid &GetGrid() const { return grid_; }

private:
  // The VOF sweeps move the momentum (mass-consistent transport, not with particles): Step, ChooseTimeStep.
  bool ConsistentVofMomentum() const { return physics_.vof && !coupling_ && vof_->ConsistentMomentum(); }
  PetscErrorCode Monitor();

  MPI_Comm   comm_ = MPI_COMM_NULL;
  PhysicsSet physics_;
  Grid       grid_;
  std::unique_ptr<Dem> dem_;
  std::unique_ptr<Flow> flow_;
  std::unique_ptr<Vof>  vof_;
  PetscReal  vofVolume0_ = 0;  // phase-1 volume at the start (monitor: volume error)
  PetscReal  vofOtherVolume0_ = 0;  // phase-0 volume at the start, with particles (eps (1 - alpha) V)
  std::unique_ptr<Coupling> coupling_;  // -physics dem,flow
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
  PetscLogStage  demStage_  = -1, flowStage_ = -1, vofStage_ = -1, couplingStage_ = -1;
};

}  // namespace vofdem
