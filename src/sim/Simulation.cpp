#include "vofdem/sim/Simulation.hpp"

#include "vofdem/base/MemoryBudget.hpp"

#include "vofdem/base/ModuleRegistry.hpp"
#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"

#include <petsctime.h>
#include <petscviewerhdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

namespace vofdem {

PetscErrorCode Simulation::Create(MPI_Comm comm) {
  PetscFunctionBeginUser;
  comm_ = comm;
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::SetFromOptions() {
  std::vector<std::string> names;
  PetscBool                help = PETSC_FALSE, physicsSet = PETSC_FALSE, finalSet = PETSC_FALSE;
  const ModuleRegistry    &registry = ModuleRegistry::Built();

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  PetscOptionsBegin(comm_, nullptr, "Simulation: physics, clock and monitors", "Simulation");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.NameList("-physics", "Modules to switch on, comma-separated", registry.PhysicsWords(), &names, &physicsSet));
    PetscCall(opt.Int("-max_steps", "Number of time steps to run at most", &maxSteps_, 0, PETSC_MAX_INT, &maxStepsSet_));
    PetscCall(opt.Real("-final_time", "Simulated time to stop at (default: none)", "s", &finalTime_, RealRange::Positive(), &finalSet));
    PetscCall(opt.Real("-dt", "Time step (0: the smallest stable limit of the modules)", "s", &dtUser_, RealRange::NonNegative()));
    PetscCall(opt.Bool("-dt_force", "Accept a -dt above a module's stable limit", &dtForce_));
    PetscCall(opt.Real("-dt_initial", "First step of an adaptive run (0: the stable limit); it grows by at most 20 percent per step from there, so an impulsive start (an inflow switched on through a packed bed) is resolved", "s", &dtInitial_, RealRange::NonNegative()));
    PetscCall(opt.Real("-dt_max", "Largest step of an adaptive run (0: no bound but the modules' limits), e.g. a fraction of the particles' drag response time m/K in a dense bed: fluid and particles exchange momentum once per step", "s", &dtMax_, RealRange::NonNegative()));
    if (dtInitial_ > 0 && dtUser_ > 0) VofdemInputError(comm_, "option -dt_initial: a fixed -dt is given; -dt_initial is the first step of an adaptive run (leave one out)");
    if (dtMax_ > 0 && dtUser_ > 0) VofdemInputError(comm_, "option -dt_max: a fixed -dt is given; -dt_max bounds an adaptive run (leave one out)");
    PetscCall(opt.Real("-stop_kinetic_energy", "End the run once the particles' kinetic energy (translational and rotational) is below this at a monitor line (a pile at rest; 0: never)", "J", &stopKinetic_, RealRange::NonNegative()));
    PetscCall(opt.Real("-stop_kinetic_energy_after", "Check -stop_kinetic_energy only from this simulated time on (particles at rest before they fall)", "s", &stopKineticAfter_, RealRange::NonNegative()));
    PetscCall(opt.Int("-monitor_every", "Print a monitor line every this many steps", &monitorEvery_, 1));
    PetscCall(opt.Bool("-monitor_timing", "Show wall time and ETA in monitor lines (off for reproducible output)", &monitorTiming_));
    PetscCall(opt.RealVector("-gravity", "Gravitational acceleration x,y,z", "m/s^2", gravity_, 3));
    PetscCall(opt.Int("-seed", "Seed of every random choice of the run", &seed_, 0));
    PetscCall(opt.String("-output_dir", "Folder for the monitor table (monitor.csv) and output files (default: none)", &outputDir_));
  }
  PetscOptionsEnd();
  PetscCall(checkpoint_.SetFromOptions(comm_, outputDir_));
  if (!physicsSet && !help) VofdemInputError(comm_, "option -physics is missing: name the modules to run, e.g. -physics dem");
  if (!finalSet) finalTime_ = PETSC_MAX_REAL;
  if (physicsSet) PetscCall(SelectModules(comm_, names, &on_));
  PetscCall(grid_.SetFromOptions(comm_));
  context_.comm       = comm_;
  context_.grid       = &grid_;
  context_.gravity    = gravity_;
  context_.seed       = (std::uint64_t)seed_;
  context_.help       = help == PETSC_TRUE;
  context_.restarting = checkpoint_.Restarting();
  context_.fixedDt    = dtUser_ > 0;
  // Each module in the registry's order: its options, then (the modules below it configured) its checks
  // and wiring across modules. With -help every module of the build registers its options, so that -help
  // lists them all, and only those on stay.
  for (const ModuleEntry &e : registry.Entries()) {
    const bool isOn = std::find(on_.begin(), on_.end(), e.name) != on_.end();
    if (!isOn && !help) continue;
    std::unique_ptr<Module> m = e.create();
    PetscCall(m->SetFromOptions(context_));
    if (!isOn) continue;
    PetscCall(m->Configure(modules_, context_));
    modules_.Add(std::move(m));
  }
  bool restEnergy = false;
  for (const auto &m : modules_.All()) restEnergy = restEnergy || m->HasRestEnergy();
  if (stopKinetic_ > 0 && !restEnergy && !help) VofdemInputError(comm_, "option -stop_kinetic_energy: it is the particles' energy; -physics has no dem");
  if (stopKineticAfter_ > 0 && stopKinetic_ == 0) VofdemInputError(comm_, "option -stop_kinetic_energy_after: no -stop_kinetic_energy to check");
  // The stage table: which module runs in which stage, in the registry's order within a stage.
  stageModules_.assign(kStageCount, {});
  for (std::size_t i = 0; i < modules_.All().size(); ++i) {
    const Module &m = *modules_.All()[i];
    for (Stage st : m.Stages()) stageModules_[(int)st].push_back(i);
    adaptsEveryStep_ = adaptsEveryStep_ || m.AdaptsEveryStep();
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::PushStage(std::size_t module) const {
  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(logStages_[module]));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::SetUp() {
  PetscFunctionBeginUser;
  // The output folder first: the modules check at their set-up that their own files (-dem_save_particles
  // out/p.csv) can be written, and a fresh run's folder must not fail that. Its errors are reported below.
  if (!outputDir_.empty()) {
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(comm_, &rank));
    std::error_code ec;
    if (rank == 0) std::filesystem::create_directories(outputDir_, ec);
  }
  bool vertexGrid = false;
  for (const auto &m : modules_.All()) vertexGrid = vertexGrid || m->NeedsVertexGrid();
  {  // a grid too large for the memory is refused before it is made (the full nozzle scene's 13 million cells took
     // 24 GB and were killed); the largest rank holds at least the mean share of the cells
    double      perCell = 0;
    PetscMPIInt size;
    for (const auto &m : modules_.All()) perCell += m->BytesPerCell();
    PetscCallMPI(MPI_Comm_size(comm_, &size));
    const PetscInt *n    = grid_.Cells();
    const double    mean = (double)n[0] * (double)n[1] * (double)n[2] / size;
    if (perCell > 0) PetscCall(CheckMemoryRequest(comm_, "-grid_cells", (PetscInt64)std::ceil(mean), perCell, "cells per rank (the fields and solvers of -physics, measured)"));
  }
  PetscCall(grid_.SetUp(vertexGrid ? PETSC_TRUE : PETSC_FALSE));
  // The cheap set-ups first (fields, solvers); every option has been read by then (the flow solvers read
  // their KSP options, -flow_pressure_ksp_* and -flow_viscous_*, there): a typo fails at the unused-option
  // check, before the costly set-ups (a particle fill). A program may run several simulations: a log stage
  // is registered once.
  logStages_.assign(modules_.All().size(), -1);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) PetscCall(CheckUnusedOptions(comm_));
    for (std::size_t i = 0; i < modules_.All().size(); ++i) {
      Module &m = *modules_.All()[i];
      if (m.CheapSetUp() != (pass == 0)) continue;
      PetscCall(PetscLogStageGetId(m.LogStage(), &logStages_[i]));
      if (logStages_[i] < 0) PetscCall(PetscLogStageRegister(m.LogStage(), &logStages_[i]));
      PetscCall(PushStage(i));
      PetscCall(m.SetUp(modules_, context_));
      PetscCall(PetscLogStagePop());
    }
  }
  PetscCall(ChooseTimeStep());
  PetscCall(checkpoint_.SetUp());
  PetscCall(checkpoint_.Restore(*this));
  if (!outputDir_.empty()) {
    PetscMPIInt rank;
    int         ok = 1, allOk;
    PetscCallMPI(MPI_Comm_rank(comm_, &rank));
    if (rank == 0) {
      std::error_code ec;
      std::filesystem::create_directories(outputDir_, ec);
      const std::string path = outputDir_ + "/monitor.csv";
      // A restart continues the table of the run it continues.
      const bool append = checkpoint_.Restarting() && std::filesystem::exists(path, ec);
      if (!ec) csv_ = std::fopen(path.c_str(), append ? "a" : "w");
      ok = csv_ != nullptr;
      if (csv_ && !append) {
        std::string lead, columns;
        for (const auto &m : modules_.All()) lead += m->MonitorColumnsLead(), columns += m->MonitorColumns();
        std::fprintf(csv_, "step,time_s,dt_s%s,wall_time_s%s\n", lead.c_str(), columns.c_str());
      }
    }
    PetscCallMPI(MPI_Allreduce(&ok, &allOk, 1, MPI_INT, MPI_MIN, comm_));
    if (!allOk) VofdemInputError(comm_, "option -output_dir: cannot create '%s' or write monitor.csv in it", outputDir_.c_str());
  }
  for (const auto &m : modules_.All()) PetscCall(m->SetOutputDir(outputDir_));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::ChooseTimeStep() {
  TimeStepLimit lowest;

  PetscFunctionBeginUser;
  // Each module lowers the limit to its own (a sub-stepped DEM has none: it steps inside the fluid's step;
  // a flow whose momentum the interface's sweeps move limits per direction, FlowModule).
  for (const auto &m : modules_.All()) PetscCall(m->LowerTimeStep(&lowest));
  PetscReal limit = lowest.dt;
  if (limit < PETSC_MAX_REAL) dtLimitName_ = lowest.basis;
  if (dtMax_ > 0 && dtMax_ < limit) {
    limit        = dtMax_;
    dtLimitName_ = "-dt_max";
  }
  if (!(limit < PETSC_MAX_REAL) && step_ > 0) PetscFunctionReturn(0);  // came to rest: keep the step
  if (!(limit < PETSC_MAX_REAL) && !(dtUser_ > 0))
    VofdemInputError(comm_, "option -dt: nothing moves at the start (no velocity, no gravity): give a time step");
  // An adaptive step (the flow's) shrinks at once to 95 percent of the limit when the limit falls below
  // it, and grows (at most 20 percent per step, so the variable-step AB2 of the flow stays close to
  // constant-step accuracy) only once it is 15 percent under the limit: in between it is kept, so that
  // what depends on dt (the implicit viscous matrix) is not rebuilt every step. A constant limit (DEM)
  // is used as it is.
  if (step_ == 0 || !(dt_ > 0)) dt_ = dtInitial_ > 0 ? std::min(dtInitial_, limit) : limit;
  else if (dt_ > limit) dt_ = 0.95 * limit;
  else if (dt_ < 0.85 * limit) dt_ = std::min((PetscReal)0.95 * limit, (PetscReal)1.2 * dt_);
  if (dtUser_ > 0 && step_ == 0) {
    if (dtUser_ > limit && !dtForce_)
      VofdemInputError(comm_, "option -dt: %g s exceeds the stable limit %g s of %s; lower it or add -dt_force", (double)dtUser_, (double)limit,
                       dtLimitName_.c_str());
    if (dtUser_ > limit) PetscCall(PetscPrintf(comm_, "vofdem: warning: -dt %g s exceeds the stable limit %g s of %s (forced)\n", (double)dtUser_, (double)limit, dtLimitName_.c_str()));
    dt_          = dtUser_;
    dtLimitName_ = "-dt";
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::Step() {
  PetscFunctionBeginUser;
  // A module's limit that moves with its state (the DEM's contacts, Dem::UpdateContactStepLimit) where no
  // module adapts the step every step: followed here, so that drivers calling Step() alone (the examples)
  // step stably too; a step the limit allows is kept.
  if (!adaptsEveryStep_ && dtUser_ == 0 && step_ > 0) {
    bool moved = false;
    for (const auto &m : modules_.All()) moved = moved || m->LimitMoved(dt_);
    if (moved) PetscCall(ChooseTimeStep());
  }
  StepState state;
  state.time = time_;
  state.dt   = finalTime_ < PETSC_MAX_REAL ? std::min(dt_, finalTime_ - time_) : dt_;
  state.step = step_;
  dtTaken_   = state.dt;
  // The coupled step: every stage in the fixed order of Stage (base/Stage.cpp gives each one's reason; the
  // banner prints the table), and in each stage the modules that subscribe to it, in the registry's order.
  for (int st = 0; st < kStageCount; ++st)
    for (std::size_t i : stageModules_[st]) {
      PetscCall(PushStage(i));
      PetscCall(modules_.All()[i]->Run((Stage)st, state));
      PetscCall(PetscLogStagePop());
    }
  time_ += state.dt;
  ++step_;
  for (const auto &m : modules_.All()) PetscCall(m->WriteOutput(step_, time_));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::Run() {
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&wallStart_));
  runStartStep_ = step_;
  runStartTime_ = time_;
  if (!checkpoint_.Restarting()) {  // a restart's first state was output by the run it continues
    for (const auto &m : modules_.All()) PetscCall(m->WriteOutput(step_, time_));
    PetscCall(Monitor());
  }
  while (step_ < maxSteps_ && time_ < finalTime_ * (1 - 1e-12)) {
    if (adaptsEveryStep_ && dtUser_ == 0) PetscCall(ChooseTimeStep());  // a limit that moves with the state (the flow's)
    PetscCall(Step());
    const bool end     = step_ == maxSteps_ || time_ >= finalTime_ * (1 - 1e-12);
    const bool monitor = step_ % monitorEvery_ == 0 || end;
    if (monitor) PetscCall(Monitor());
    // At rest: the monitor's energy (the same on every rank) below the bound, once the particles had time to move.
    const bool settled = monitor && stopKinetic_ > 0 && time_ >= stopKineticAfter_ && lastKinetic_ < stopKinetic_;
    bool       stop;
    PetscCall(checkpoint_.AfterStep(*this, end || settled, &stop));
    if (stop) {  // a signal: checkpoint written, the run ends cleanly
      interrupted_ = true;
      PetscFunctionReturn(0);
    }
    if (settled) {
      PetscCall(PetscPrintf(comm_, "vofdem: the particles' kinetic energy %g J is below -stop_kinetic_energy %g J at t = %g s: at rest\n", (double)lastKinetic_, (double)stopKinetic_, (double)time_));
      break;
    }
  }
  for (const auto &m : modules_.All()) PetscCall(m->Finish());  // the end-of-run files (-dem_save_particles, -flow_profile)
  // A run that a limit the scene did not set ended (the default -max_steps before its -final_time) says so.
  std::string why;
  if (step_ == maxSteps_ && !maxStepsSet_ && finalTime_ < PETSC_MAX_REAL && time_ < finalTime_ * (1 - 1e-12)) {
    char b[200];
    std::snprintf(b, sizeof b, " (the default -max_steps %d ended it before -final_time %g s: raise -max_steps)", (int)maxSteps_, (double)finalTime_);
    why = b;
  }
  PetscCall(PetscPrintf(comm_, "vofdem: finished after %" PetscInt_FMT " steps at t = %g s%s%s%s\n", step_, (double)time_, why.c_str(),
                        csv_ ? "; monitor table in " : "", csv_ ? (outputDir_ + "/monitor.csv").c_str() : ""));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::Monitor() {
  PetscLogDouble now;
  std::string    screen, lead, csv;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  const double wall = now - wallStart_;
  for (const auto &m : modules_.All()) {  // collective: every module summarises, in order
    MonitorPart part;
    PetscCall(m->Monitor(&part));
    screen += part.screen;
    lead += part.csvLead;
    csv += part.csv;
    if (part.restEnergy >= 0) lastKinetic_ = part.restEnergy;
  }
  std::string line;
  char        buf[512];
  const PetscReal dtShown = step_ > runStartStep_ ? dtTaken_ : dt_;  // the step just taken (a last step shortened to -final_time too)
  std::snprintf(buf, sizeof buf, "step %6d  t %.6e s  dt %.3e s", (int)step_, (double)time_, (double)dtShown);
  line += buf;
  line += screen;
  if (monitorTiming_) {
    // the fraction of this run's own span done (from the step and time it started at, so a restart's ETA is right)
    double fraction = maxSteps_ > runStartStep_ ? (double)(step_ - runStartStep_) / (maxSteps_ - runStartStep_) : 0;
    if (finalTime_ < PETSC_MAX_REAL && finalTime_ > runStartTime_) fraction = std::max(fraction, (double)((time_ - runStartTime_) / (finalTime_ - runStartTime_)));
    std::snprintf(buf, sizeof buf, "  | wall %.2f s  ETA %.1f s", wall, fraction > 0 ? wall * (1 - fraction) / fraction : 0.0);
    line += buf;
  }
  PetscCall(PetscPrintf(comm_, "%s\n", line.c_str()));
  if (csv_) {
    std::fprintf(csv_, "%d,%.10e,%.6e%s,%.3f%s\n", (int)step_, (double)time_, (double)dtShown, lead.c_str(), wall, csv.c_str());
    std::fflush(csv_);
  }
  PetscFunctionReturn(0);
}

std::string Simulation::PhysicsDescription() const { return DescribePhysics(on_); }

PetscErrorCode Simulation::ViewStages(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "step stages (in this order; docs/architecture.md):\n"));
  for (int st = 0; st < kStageCount; ++st) {
    if (stageModules_[st].empty()) continue;
    std::string who;
    for (std::size_t i : stageModules_[st]) who += (who.empty() ? "" : ",") + std::string(modules_.All()[i]->Name());
    PetscCall(PetscViewerASCIIPrintf(viewer, "  %-10s %-9s %s\n", StageName((Stage)st), who.c_str(), StageReason((Stage)st)));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::View(PetscViewer viewer) const {
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  PetscCall(PetscViewerASCIIPrintf(viewer, "vofdem %s: physics %s on %d rank%s\n", VOFDEM_VERSION, PhysicsDescription().c_str(), (int)size, size > 1 ? "s" : ""));
  PetscCall(grid_.View(viewer));
  for (const auto &m : modules_.All()) PetscCall(m->View(viewer, dt_));
  for (const auto &m : modules_.All()) PetscCall(m->ViewTimeStep(viewer));
  PetscCall(PetscViewerASCIIPrintf(viewer, "time step: %g s (set by %s); gravity (%g, %g, %g) m/s^2; seed %" PetscInt_FMT "\n", (double)dt_,
                                   dtLimitName_.c_str(), (double)gravity_[0], (double)gravity_[1], (double)gravity_[2], seed_));
  PetscCall(ViewStages(viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::SaveState(PetscViewer viewer) {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "simulation_step", PETSC_INT, &step_));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "simulation_time", PETSC_REAL, &time_));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "simulation_dt", PETSC_REAL, &dt_));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "simulation_dt_basis", PETSC_STRING, dtLimitName_.c_str()));
  for (const auto &m : modules_.All()) PetscCall(m->Save(viewer));  // each in its own group
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::StateBytes(PetscInt64 *bytes) const {
  PetscInt64 part = 0;

  PetscFunctionBeginUser;
  *bytes = 4096;  // the header attributes
  for (const auto &m : modules_.All()) {
    PetscCall(m->SavedBytes(&part));
    *bytes += part;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::LoadState(PetscViewer viewer) {
  char *basis = nullptr;

  PetscFunctionBeginUser;
  // ChooseTimeStep depends on step_ and dt_ (and the modules' state): restoring them continues the
  // adaptive step exactly where the saving run was.
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "simulation_step", PETSC_INT, nullptr, &step_));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "simulation_time", PETSC_REAL, nullptr, &time_));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "simulation_dt", PETSC_REAL, nullptr, &dt_));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "simulation_dt_basis", PETSC_STRING, nullptr, &basis));
  dtLimitName_ = basis;
  PetscCall(PetscFree(basis));
  for (const auto &m : modules_.All()) PetscCall(m->Load(viewer));  // in order: the interface after the flow it sets
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(checkpoint_.Destroy());
  if (csv_) std::fclose(csv_);
  csv_ = nullptr;
  const auto &all = modules_.All();
  for (auto m = all.rbegin(); m != all.rend(); ++m) PetscCall((*m)->Destroy());  // the top floor first
  modules_.Clear();
  PetscCall(grid_.Destroy());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
