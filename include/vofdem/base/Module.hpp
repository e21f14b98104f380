// The module interface (docs/architecture.md, "Modules"): what a physics module (dem, flow, vof, the
// coupling, ...) offers the simulation, in PETSc's life cycle. The simulation (src/sim) names no module: it
// creates the ones the scene switched on from the registry (ModuleRegistry.hpp), in the registry's order
// (the floors: a module comes after the ones it builds on), and runs each in the stages it subscribes to
// (Stage.hpp) in the one fixed order of the coupled step.
//
// Life cycle, per run:
//   SetFromOptions(context)   own options (also with -help, so that -help lists every module's options)
//   Configure(modules)        the modules below are configured: checks across modules, wiring
//   SetUp(modules)            fields, solvers, the initial state ("cheap" modules before the unused-option
//                             check, the others, e.g. a particle fill, after it)
//   per step: Run(stage) for each subscribed stage; WriteOutput after the clock moved
//   Monitor, View (the banner), Save/Load (checkpoints), Finish (end-of-run files), Destroy
#pragma once

#include <petscsys.h>
#include <petscviewer.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace vofdem {

class Grid;  // the grid floor (src/grid): the modules' cells; the simulation owns it

// The one fixed list of stages of a step, in the order they run (Stage.cpp gives each its reason).
enum class Stage : int { Prepare, Exchange, Forces, Fluid, Transport, Properties, Average, Particles, Finish };
constexpr int kStageCount = 9;
const char *StageName(Stage s);    // "prepare"
const char *StageReason(Stage s);  // why it sits where it does, one line

// The run-wide settings every module may read (the simulation's options).
struct RunContext {
  MPI_Comm        comm       = MPI_COMM_NULL;
  Grid           *grid       = nullptr;
  const PetscReal *gravity   = nullptr;  // m/s^2, 3 components
  std::uint64_t   seed       = 0;
  bool            help       = false;  // -help: read options only
  bool            restarting = false;  // -restart: the state comes from a checkpoint after SetUp
  bool            fixedDt    = false;  // -dt given
};

// One step, as the stages see it.
struct StepState {
  PetscReal time     = 0;  // at the start of the step, s
  PetscReal dt       = 0;  // the step taken, s
  PetscInt  step     = 0;  // steps done before this one
  PetscInt  substeps = 1;  // sub-steps of the particles in this step (set at Stage::Average by a coupling)
};

// The smallest stable step so far and what sets it; a module lowers it where its own limit is smaller.
struct TimeStepLimit {
  PetscReal   dt = PETSC_MAX_REAL;
  std::string basis;
  void Lower(PetscReal limit, const std::string &why) {
    if (limit < dt) dt = limit, basis = why;
  }
};

// A module's part of a monitor line: the screen text, its columns of monitor.csv (lead: before the wall
// time, the particles' summary as the table has always had it), and the particles' kinetic energy for
// -stop_kinetic_energy (negative: none).
struct MonitorPart {
  std::string screen, csvLead, csv;
  PetscReal   restEnergy = -1;
};

class ModuleSet;

class Module {
public:
  virtual ~Module() = default;
  virtual const char *Name() const     = 0;  // the -physics word (or the module's own name if it is implied)
  virtual const char *LogStage() const = 0;  // its PETSc log stage in -log_view ("DEM")

  virtual PetscErrorCode SetFromOptions(const RunContext &run) = 0;
  virtual PetscErrorCode Configure(ModuleSet &modules, const RunContext &run) = 0;
  virtual bool           NeedsVertexGrid() const { return false; }  // the grid's vertex DM (DMSwarm cell location)
  virtual bool           CheapSetUp() const { return true; }        // set up before the unused-option check
  // A lower bound of the bytes it holds per grid cell (its fields and solvers), measured (Simulation::SetUp refuses
  // a grid that cannot fit with one line naming -grid_cells, not an out-of-memory kill).
  virtual double         BytesPerCell() const { return 0; }
  virtual PetscErrorCode SetUp(ModuleSet &modules, const RunContext &run) = 0;
  virtual bool           OwnsOutputDir() const { return false; }     // takes -output_dir (SetOutputDir)
  virtual PetscErrorCode SetOutputDir(const std::string &) { return 0; }

  // The stages it runs in (after Configure) and each one's action.
  virtual std::vector<Stage> Stages() const = 0;
  virtual PetscErrorCode     Run(Stage stage, StepState &step) = 0;

  // Its stable time step, lowering limit; AdaptsEveryStep: its limit moves with its state (choose every step);
  // LimitMoved: otherwise, whether the step dt is no longer its limit (its contacts changed it).
  virtual PetscErrorCode LowerTimeStep(TimeStepLimit *) { return 0; }
  virtual bool           AdaptsEveryStep() const { return false; }
  virtual bool           LimitMoved(PetscReal) const { return false; }
  virtual bool           HasRestEnergy() const { return false; }  // reports MonitorPart::restEnergy

  virtual std::string    MonitorColumnsLead() const { return ""; }  // ",name,..." before wall_time_s
  virtual std::string    MonitorColumns() const { return ""; }      // ",name,..." after it
  virtual PetscErrorCode Monitor(MonitorPart *part) = 0;

  virtual PetscErrorCode View(PetscViewer viewer, PetscReal dt) const = 0;  // settings (banner)
  virtual PetscErrorCode ViewTimeStep(PetscViewer) const { return 0; }      // "time step limits: ..." line
  virtual PetscErrorCode Save(PetscViewer viewer) = 0;                      // its own group of the checkpoint
  virtual PetscErrorCode Load(PetscViewer viewer) = 0;
  virtual PetscErrorCode SavedBytes(PetscInt64 *bytes) const {
    *bytes = 0;
    return 0;
  }
  virtual PetscErrorCode WriteOutput(PetscInt, PetscReal) { return 0; }  // after SetUp and after each step
  virtual PetscErrorCode Finish() { return 0; }                          // end of the run's files
  virtual PetscErrorCode Destroy() = 0;
};

// The modules of a run, in the registry's order.
class ModuleSet {
public:
  void    Add(std::unique_ptr<Module> m) { modules_.push_back(std::move(m)); }
  Module *Find(const std::string &name) const;
  bool    Has(const std::string &name) const { return Find(name) != nullptr; }
  // The module of that name as its concrete type (nullptr if absent).
  template <class M>
  M *Get(const std::string &name) const {
    return dynamic_cast<M *>(Find(name));
  }
  const std::vector<std::unique_ptr<Module>> &All() const { return modules_; }
  void Clear() { modules_.clear(); }

private:
  std::vector<std::unique_ptr<Module>> modules_;
};

}  // namespace vofdem
