#include "vofdem/core/Simulation.hpp"

#include "vofdem/core/Options.hpp"
#include "vofdem/core/Runtime.hpp"

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

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  PetscOptionsBegin(comm_, nullptr, "Simulation: physics, clock and monitors", "Simulation");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.NameList("-physics", "Modules to switch on, comma-separated", KnownPhysics(), &names, &physicsSet));
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
  if (physicsSet) PetscCall(MakePhysicsSet(comm_, names, &physics_));
  if (stopKinetic_ > 0 && !physics_.dem && !help) VofdemInputError(comm_, "option -stop_kinetic_energy: it is the particles' energy; -physics has no dem");
  if (stopKineticAfter_ > 0 && stopKinetic_ == 0) VofdemInputError(comm_, "option -stop_kinetic_energy_after: no -stop_kinetic_energy to check");
  PetscCall(grid_.SetFromOptions(comm_));
  // With -help, every available module registers its options so that -help lists them all.
  if (physics_.dem || help) {
    dem_ = std::make_unique<Dem>();
    PetscCall(dem_->SetFromOptions(comm_));
    if (!physics_.dem) dem_.reset();
  }
  if (physics_.flow || help) {
    flow_ = std::make_unique<Flow>();
    PetscCall(flow_->SetFromOptions(grid_));
    if (!physics_.flow) flow_.reset();
  }
  if (physics_.vof || help) {
    vof_ = std::make_unique<Vof>();
    PetscCall(vof_->SetFromOptions(grid_));
    if (!physics_.vof) vof_.reset();
    else if (flow_) PetscCall(vof_->CheckFlowOptions(*flow_));
  }
  if ((physics_.dem && physics_.flow) || help) {
    coupling_ = std::make_unique<Coupling>();
    PetscCall(coupling_->SetFromOptions(comm_));
    if (!(physics_.dem && physics_.flow)) coupling_.reset();
    else PetscCall(coupling_->CheckParticleSize(grid_, 2 * dem_->Radius()));
    // The particles' fluid_* arrays are taken from the start (the DEM's set-up already reads some).
    if (coupling_) dem_->UseFluidFields();
    // The kernels and deposits live on the flow's decomposition: a DEM repartition would leave particles
    // outside their rank's fluid cells (DemBalance.cpp).
    if (coupling_ && dem_->Balancing())
      VofdemInputError(comm_, "option -dem_balance: coupled scenes keep the fluid's decomposition (the particles' kernels live on its cells); use none (the default) and choose the split with -grid_ranks");
    // F1b: with moving particles, the interface's transport conserves both phases only with d(eps)/dt.
    if (coupling_ && physics_.vof && !coupling_->EpsRate())
      VofdemInputError(comm_, "option -coupling_eps_rate: particles with a free surface (dem,flow,vof) need it on: without d(eps)/dt the volumes of both phases drift as particles move");
    if (coupling_ && !physics_.vof && coupling_->ContactAngleSet())
      VofdemInputError(comm_, "option -coupling_contact_angle: the capillary force acts at a free surface; it needs -physics dem,flow,vof");
    // P8 with the fluid's viscosity: the flow's single one, or with a free surface each particle's mixture (Coupling.hpp).
    if (coupling_ && coupling_->Lubrication()) PetscCall(dem_->SetFluidLubrication(physics_.vof ? 0 : flow_->ReferenceViscosity()));
  }
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
  PetscCall(grid_.SetUp(physics_.dem ? PETSC_TRUE : PETSC_FALSE));
  if (physics_.flow) {
    PetscCall(PetscLogStageGetId("Flow", &flowStage_));
    if (flowStage_ < 0) PetscCall(PetscLogStageRegister("Flow", &flowStage_));
    PetscCall(PetscLogStagePush(flowStage_));
    PetscCall(flow_->SetUp(gravity_));
    PetscCall(PetscLogStagePop());
  }
  if (physics_.vof) {  // after the flow: alpha lives on the flow's cells and sets its density and viscosity
    PetscCall(PetscLogStageGetId("VOF", &vofStage_));
    if (vofStage_ < 0) PetscCall(PetscLogStageRegister("VOF", &vofStage_));
    PetscCall(PetscLogStagePush(vofStage_));
    PetscCall(vof_->SetUp(flow_->Staggered()));
    PetscCall(vof_->SetInitialShapes());
    PetscCall(vof_->UpdateProperties(*flow_));
    flow_->AddOutputField(vof_->Fraction());  // alpha in flow_<step>.h5 / flow.xmf (-flow_output_every)
    VofSummary vs;
    PetscCall(vof_->Summarize(&vs));
    vofVolume0_ = vs.volume;
    PetscCall(PetscLogStagePop());
  }
  // Every option has been read by now (the flow solvers read their KSP options, -flow_pressure_ksp_*
  // and -flow_viscous_*, in the cheap set-up above): a typo fails here, before the DEM fill.
  PetscCall(CheckUnusedOptions(comm_));
  if (physics_.dem) {
    PetscCall(PetscLogStageGetId("DEM", &demStage_));  // a program may run several simulations
    if (demStage_ < 0) PetscCall(PetscLogStageRegister("DEM", &demStage_));
    PetscCall(PetscLogStagePush(demStage_));
    PetscCall(dem_->SetUp(grid_, gravity_, (std::uint64_t)seed_));
    PetscCall(PetscLogStagePop());
  }
  if (coupling_) {
    PetscCall(PetscLogStageGetId("Coupling", &couplingStage_));
    if (couplingStage_ < 0) PetscCall(PetscLogStageRegister("Coupling", &couplingStage_));
    PetscCall(PetscLogStagePush(couplingStage_));
    PetscCall(coupling_->SetUp(*flow_, *dem_));
    flow_->AddOutputField(flow_->FluidFraction());  // eps in flow_<step>.h5 / flow.xmf: where the bed is, its bubbles
    if (physics_.vof) {  // particles with a free surface: eps in the interface's transport (F1b), its forces on them (P1)
      vof_->SetFluidFraction(flow_->FluidFraction(), coupling_->FluidFractionChange());
      coupling_->SetInterfaceForces(vof_->SurfaceTensionCoefficient() > 0);
      PetscCall(coupling_->SetFreeSurface(vof_->Fraction(), vof_->SurfaceTensionCoefficient()));
      PetscCall(coupling_->Average());  // again, with the interface's force field
      VofSummary vs;
      PetscCall(vof_->Summarize(&vs));  // the particles displace their volume of either phase from the start
      vofVolume0_ = vs.volume;
      vofOtherVolume0_ = vs.otherVolume;
    }
    // A fluid set moving at the start (an inflow's velocity everywhere, divergence-free for eps = 1), or an inflow
    // into fluid at rest (the first step's projection would set it moving): with the particles' eps the pores carry
    // U/eps (F1). Projected now, so that the first step's limit sees that speed (a packed bed's first step ran at
    // CFL 1.16 with the limit of U alone) and the particles read it. A fluid at rest with closed boundaries needs
    // nothing; a restart loads its own velocity.
    if (!checkpoint_.Restarting()) {
      PetscReal umax = 0;
      for (int d = 0; d < 3; ++d) {
        PetscReal m;
        PetscCall(VecNorm(flow_->Velocity(d), NORM_INFINITY, &m));
        umax = std::fmax(umax, m);
        for (int f = 0; f < 6; ++f) umax = std::fmax(umax, std::fabs(flow_->Boundary().Face(f).velocity[d]));
      }
      if (umax > 0) {
        PetscCall(flow_->ProjectInitialVelocity());
        PetscCall(coupling_->Average());
      }
    }
    PetscCall(PetscLogStagePop());
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
      if (csv_ && !append)
        std::fprintf(csv_, "step,time_s,dt_s,particles,kinetic_energy_J,rotational_energy_J,pair_contacts,coordination,wall_contacts,max_overlap_per_diameter,floor_force_z_N,inserted,deleted,wall_time_s%s%s%s%s%s%s\n",
                     physics_.dem ? dem_->WallLoadColumns().c_str() : "", physics_.dem ? dem_->MonitorHeader().c_str() : "",
                     physics_.flow ? ",flow_kinetic_energy_J,flow_max_velocity_m_s,flow_max_divergence_1_s,flow_cfl,pressure_iterations,pressure_residual,pressure_pc_reused,viscous_iterations" : "",
                     physics_.vof ? (coupling_ ? ",vof_volume_m3,vof_volume_relative_change,vof_bound_violation,vof_interface_cells,vof_phase0_volume_m3,vof_phase0_volume_relative_change"
                                               : ",vof_volume_m3,vof_volume_relative_change,vof_bound_violation,vof_interface_cells") : "",
                     physics_.vof && vof_->HasOpenFaces() ? ",vof_inflow_volume_m3,vof_outflow_volume_m3,vof_balance_error" : "",
                     coupling_ ? ",coupling_min_eps,coupling_eps_clipped_cells,coupling_drag_x_N,coupling_drag_y_N,coupling_drag_z_N,coupling_exchange_error,coupling_volume_error" : "");
    }
    PetscCallMPI(MPI_Allreduce(&ok, &allOk, 1, MPI_INT, MPI_MIN, comm_));
    if (!allOk) VofdemInputError(comm_, "option -output_dir: cannot create '%s' or write monitor.csv in it", outputDir_.c_str());
  }
  if (physics_.dem) PetscCall(dem_->SetOutputDir(outputDir_));
  if (physics_.flow) PetscCall(flow_->SetOutputDir(outputDir_));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::ChooseTimeStep() {
  PetscReal limit = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  if (physics_.dem && !coupling_) {  // coupled, the DEM sub-steps inside the fluid step (Coupling.hpp)
    limit        = dem_->StableTimeStep();
    dtLimitName_ = dem_->TimeStepBasis();
  }
  // With mass-consistent momentum (Step) the VOF sweeps move the momentum: the flow's AB2 limit over the
  // sum of directions becomes -flow_cfl per direction (Flow::StableTimeStep).
  const bool ownAdvection = !ConsistentVofMomentum();
  if (physics_.flow) {
    PetscReal   f;
    std::string basis;
    PetscCall(flow_->StableTimeStep(&f, &basis, ownAdvection));
    if (f < limit) {
      limit        = f;
      dtLimitName_ = basis;
    }
  }
  if (physics_.vof) {
    PetscReal   f;
    std::string basis;
    Vec         u[3] = {flow_->Velocity(0), flow_->Velocity(1), flow_->Velocity(2)};
    PetscCall(vof_->StableTimeStep(u, &f, &basis));
    if (f < limit) {
      limit        = f;
      dtLimitName_ = basis;
    }
    const PetscReal cap = vof_->CapillaryTimeStep(flow_->ReferenceDensity());
    if (cap < limit) {
      limit        = cap;
      dtLimitName_ = "capillary sqrt(rho_mean h^3/(2 pi sigma))";
    }
  }
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
  // The DEM's limit moves with its contacts (Dem::UpdateContactStepLimit): a DEM-only step follows it here,
  // so that drivers calling Step() alone (the examples) step stably too; a step the contacts allow is kept.
  if (physics_.dem && !physics_.flow && dtUser_ == 0 && step_ > 0 && dem_->StableTimeStep() != dt_) PetscCall(ChooseTimeStep());
  const PetscReal dt = finalTime_ < PETSC_MAX_REAL ? std::min(dt_, finalTime_ - time_) : dt_;
  dtTaken_           = dt;
  // The coupled step (ARCHITECTURE.md, Coupling.hpp): projection, flow step, averaging, DEM sub-steps.
  // With a free surface the interface's force joins the flow step and the interface moves with the
  // projected velocity before the particles read the fluid (its new density and viscosity, P1).
  if (coupling_) {
    PetscCall(PetscLogStagePush(couplingStage_));
    PetscCall(coupling_->Project(dt));
    PetscCall(PetscLogStagePop());
    if (physics_.vof) {
      PetscCall(PetscLogStagePush(vofStage_));
      PetscCall(vof_->SurfaceTension(*flow_));
      PetscCall(PetscLogStagePop());
    }
    PetscCall(PetscLogStagePush(flowStage_));
    PetscCall(flow_->Step(time_, dt));
    PetscCall(PetscLogStagePop());
    if (physics_.vof) {
      PetscCall(PetscLogStagePush(vofStage_));
      Vec u[3] = {flow_->Velocity(0), flow_->Velocity(1), flow_->Velocity(2)};
      PetscCall(vof_->Advect(u, dt));
      PetscCall(vof_->UpdateProperties(*flow_));
      PetscCall(PetscLogStagePop());
    }
    PetscCall(PetscLogStagePush(couplingStage_));
    PetscCall(coupling_->Average(dt));
    PetscCall(PetscLogStagePop());
    PetscCall(PetscLogStagePush(demStage_));
    const PetscInt n = coupling_->Substeps(dt);
    for (PetscInt k = 0; k < n; ++k) PetscCall(dem_->Step(dt / n));
    PetscCall(PetscLogStagePop());
    coupling_->Finish(dt);
  }
  // With particles only, steps 2 and 6 are one DEM step.
  if (physics_.dem && !coupling_) {
    PetscCall(PetscLogStagePush(demStage_));
    PetscCall(dem_->Step(dt));
    PetscCall(PetscLogStagePop());
  }
  // With particles the coupled step above moves the interface after the flow step, with the
  // flow's own (advective) momentum transport: the mass-consistent sweeps do not carry eps yet.
  const bool consistent = ConsistentVofMomentum();
  if (consistent) {
    // Mass-consistent momentum (PHYSICS.md F2, VofMomentum.cpp): alpha and rho u move together with
    // u^n and the same geometric fluxes; the flow's step then works with rho^{n+1} and the surface
    // tension of the moved interface.
    PetscCall(PetscLogStagePush(vofStage_));
    PetscCall(vof_->AdvectWithMomentum(*flow_, dt));
    PetscCall(vof_->UpdateProperties(*flow_));
    PetscCall(PetscLogStagePop());
  }
  if (physics_.vof && !coupling_) {  // surface tension of the current interface, for the flow's predictor (F2)
    PetscCall(PetscLogStagePush(vofStage_));
    PetscCall(vof_->SurfaceTension(*flow_));
    PetscCall(PetscLogStagePop());
  }
  if (physics_.flow && !coupling_) {
    PetscCall(PetscLogStagePush(flowStage_));
    PetscCall(flow_->Step(time_, dt));
    PetscCall(PetscLogStagePop());
  }
  if (physics_.vof && !coupling_ && !consistent) {
    // The interface moves with the projected (divergence-free) velocity of the step just taken, then
    // sets the density and viscosity of the next one (ARCHITECTURE.md, the coupled step, 4-5).
    PetscCall(PetscLogStagePush(vofStage_));
    Vec u[3] = {flow_->Velocity(0), flow_->Velocity(1), flow_->Velocity(2)};
    PetscCall(vof_->Advect(u, dt));
    PetscCall(vof_->UpdateProperties(*flow_));
    PetscCall(PetscLogStagePop());
  }
  time_ += dt;
  ++step_;
  if (physics_.dem) PetscCall(dem_->WriteOutput(time_));
  if (physics_.flow) PetscCall(flow_->WriteOutput(step_, time_));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::Run() {
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&wallStart_));
  runStartStep_ = step_;
  runStartTime_ = time_;
  if (!checkpoint_.Restarting()) {  // a restart's first state was output by the run it continues
    if (physics_.dem) PetscCall(dem_->WriteOutput(time_));
    if (physics_.flow) PetscCall(flow_->WriteOutput(step_, time_));
    PetscCall(Monitor());
  }
  while (step_ < maxSteps_ && time_ < finalTime_ * (1 - 1e-12)) {
    if (physics_.flow && dtUser_ == 0) PetscCall(ChooseTimeStep());  // the flow's limit moves with the flow
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
  if (physics_.dem && !dem_->SaveParticlesPath().empty()) PetscCall(dem_->SaveParticles(dem_->SaveParticlesPath()));
  if (physics_.dem && !dem_->SaveContactHistoryPath().empty()) PetscCall(dem_->SaveContactHistory(dem_->SaveContactHistoryPath()));
  if (physics_.flow && !flow_->ProfilePath().empty()) PetscCall(flow_->WriteProfile(flow_->ProfilePath()));
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
  DemSummary     s;

  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  const double wall = now - wallStart_;
  std::string extraCsv, extraScreen;
  if (physics_.dem) PetscCall(dem_->Summarize(&s));
  if (physics_.dem) lastKinetic_ = s.kinetic + s.rotational;
  if (physics_.dem) PetscCall(dem_->MonitorValues(&extraCsv, &extraScreen));
  FlowSummary fs;
  std::string flowScreen;
  if (physics_.flow) {
    PetscCall(flow_->Summarize(&fs));
    char fb[400];
    std::snprintf(fb, sizeof fb, "  | flow KE %.6e J  max|u_i| %.4e m/s  div %.2e 1/s  CFL %.3f  p its %d%s  visc its %d", (double)fs.kinetic, (double)fs.maxSpeed,
                  (double)fs.maxDivergence, (double)fs.cfl, (int)fs.pressureIterations, fs.preconditionerReused ? " (pc reused)" : "", (int)fs.viscousIterations);
    flowScreen = fb;
    std::snprintf(fb, sizeof fb, ",%.10e,%.10e,%.6e,%.6f,%d,%.6e,%d,%d", (double)fs.kinetic, (double)fs.maxSpeed, (double)fs.maxDivergence, (double)fs.cfl,
                  (int)fs.pressureIterations, (double)fs.pressureResidual, (int)fs.preconditionerReused, (int)fs.viscousIterations);
    extraCsv += fb;
  }
  if (physics_.vof) {
    VofSummary vs;
    PetscCall(vof_->Summarize(&vs));
    char vb[300];
    const PetscReal volErr = vofVolume0_ > 0 ? (vs.volume - vofVolume0_) / vofVolume0_ : 0;
    std::snprintf(vb, sizeof vb, "  | vof volume %.10e m^3  rel. change %.2e  bounds %.1e  interface cells %d", (double)vs.volume, (double)volErr, (double)vs.boundViolation,
                  (int)vs.interfaceCells);
    flowScreen += vb;
    std::snprintf(vb, sizeof vb, ",%.16e,%.6e,%.6e,%d", (double)vs.volume, (double)volErr, (double)vs.boundViolation, (int)vs.interfaceCells);
    extraCsv += vb;
    if (coupling_) {  // F1b with particles: the other phase's volume too (eps (1 - alpha) V)
      const PetscReal otherErr = vofOtherVolume0_ > 0 ? (vs.otherVolume - vofOtherVolume0_) / vofOtherVolume0_ : 0;
      std::snprintf(vb, sizeof vb, "  phase-0 volume %.10e m^3  rel. change %.2e", (double)vs.otherVolume, (double)otherErr);
      flowScreen += vb;
      std::snprintf(vb, sizeof vb, ",%.16e,%.6e", (double)vs.otherVolume, (double)otherErr);
      extraCsv += vb;
    }
    if (vs.openFaces) {  // inflow/outflow (VofOpenFaces.cpp): V - V0 = in - out, the error relative to the largest of the four
      const PetscReal scale = std::max({vofVolume0_, vs.volume, vs.inflowVolume, vs.outflowVolume, (PetscReal)PETSC_SMALL});
      const PetscReal balance = (vs.volume - vofVolume0_ - (vs.inflowVolume - vs.outflowVolume)) / scale;
      std::snprintf(vb, sizeof vb, "  in %.6e out %.6e m^3  balance %.1e", (double)vs.inflowVolume, (double)vs.outflowVolume, (double)balance);
      flowScreen += vb;
      std::snprintf(vb, sizeof vb, ",%.16e,%.16e,%.6e", (double)vs.inflowVolume, (double)vs.outflowVolume, (double)balance);
      extraCsv += vb;
    }
  }
  if (coupling_) {  // C3 in every run: the fluid's source is minus the particles' drag, projected volume = particle volume
    CouplingSummary c;
    PetscCall(coupling_->Summarize(&c));
    const PetscReal drag = std::sqrt(c.dragSum[0] * c.dragSum[0] + c.dragSum[1] * c.dragSum[1] + c.dragSum[2] * c.dragSum[2]);
    PetscReal       miss = 0;
    for (int d = 0; d < 3; ++d) miss += (c.sourceSum[d] + c.dragSum[d]) * (c.sourceSum[d] + c.dragSum[d]);
    const PetscReal exch = drag > 0 ? std::sqrt(miss) / drag : 0, verr = c.particleVolume > 0 ? std::fabs(c.projectedVolume / c.particleVolume - 1) : 0;
    char cb[400];
    std::snprintf(cb, sizeof cb, "  | coupling eps_min %.4f%s  drag (%.4e, %.4e, %.4e) N  exchange error %.1e  volume error %.1e", (double)c.minEps,
                  c.clipped ? (" (" + std::to_string((long long)c.clipped) + " cells clipped)").c_str() : "", (double)c.dragSum[0], (double)c.dragSum[1],
                  (double)c.dragSum[2], (double)exch, (double)verr);
    flowScreen += cb;
    std::snprintf(cb, sizeof cb, ",%.6f,%d,%.10e,%.10e,%.10e,%.3e,%.3e", (double)c.minEps, (int)c.clipped, (double)c.dragSum[0], (double)c.dragSum[1], (double)c.dragSum[2],
                  (double)exch, (double)verr);
    extraCsv += cb;
  }
  std::string line;
  char        buf[512];
  const PetscReal dtShown = step_ > runStartStep_ ? dtTaken_ : dt_;  // the step just taken (a last step shortened to -final_time too)
  std::snprintf(buf, sizeof buf, "step %6d  t %.6e s  dt %.3e s", (int)step_, (double)time_, (double)dtShown);
  line += buf;
  if (physics_.dem) {
    std::snprintf(buf, sizeof buf, "  | particles %d  KE %.6e J  rot %.3e J  contacts %d  Z %.3f  wall %d  overlap %.3e d  floor %.6e N", (int)s.particles,
                  (double)s.kinetic, (double)s.rotational, (int)s.pairContacts, (double)s.coordination, (int)s.wallContacts, (double)s.maxOverlap,
                  (double)s.wallForce[4][2]);
    line += buf;
    if (s.sources) {  // insertion sources or deletion boxes (ParticleSources)
      std::snprintf(buf, sizeof buf, "  inserted %lld deleted %lld", (long long)s.inserted, (long long)s.deleted);
      line += buf;
    }
    line += extraScreen;
    for (const WallLoad &L : s.walls) {  // -dem_walls: the force of the particles on each wall
      std::snprintf(buf, sizeof buf, "  %s F (%.6e, %.6e, %.6e) N", L.name.c_str(), (double)L.force[0], (double)L.force[1], (double)L.force[2]);
      line += buf;
    }
  }
  line += flowScreen;
  if (monitorTiming_) {
    // the fraction of this run's own span done (from the step and time it started at, so a restart's ETA is right)
    double fraction = maxSteps_ > runStartStep_ ? (double)(step_ - runStartStep_) / (maxSteps_ - runStartStep_) : 0;
    if (finalTime_ < PETSC_MAX_REAL && finalTime_ > runStartTime_) fraction = std::max(fraction, (double)((time_ - runStartTime_) / (finalTime_ - runStartTime_)));
    std::snprintf(buf, sizeof buf, "  | wall %.2f s  ETA %.1f s", wall, fraction > 0 ? wall * (1 - fraction) / fraction : 0.0);
    line += buf;
  }
  PetscCall(PetscPrintf(comm_, "%s\n", line.c_str()));
  if (csv_) {
    std::fprintf(csv_, "%d,%.10e,%.6e,%d,%.10e,%.10e,%d,%.6f,%d,%.6e,%.10e,%lld,%lld,%.3f", (int)step_, (double)time_, (double)dtShown, (int)s.particles, (double)s.kinetic,
                 (double)s.rotational, (int)s.pairContacts, (double)s.coordination, (int)s.wallContacts, (double)s.maxOverlap, (double)s.wallForce[4][2],
                 (long long)s.inserted, (long long)s.deleted, wall);
    for (const WallLoad &L : s.walls)
      for (const PetscReal *q : {L.force, L.torque}) std::fprintf(csv_, ",%.10e,%.10e,%.10e", (double)q[0], (double)q[1], (double)q[2]);
    std::fprintf(csv_, "%s\n", extraCsv.c_str());
    std::fflush(csv_);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::View(PetscViewer viewer) const {
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  PetscCall(PetscViewerASCIIPrintf(viewer, "vofdem %s: physics %s on %d rank%s\n", VOFDEM_VERSION, physics_.Describe().c_str(), (int)size, size > 1 ? "s" : ""));
  PetscCall(grid_.View(viewer));
  if (dem_) PetscCall(dem_->View(viewer));
  if (flow_) PetscCall(flow_->View(viewer));
  if (vof_) PetscCall(vof_->View(viewer));
  if (coupling_) PetscCall(coupling_->View(viewer, dt_));
  if (physics_.dem) PetscCall(PetscViewerASCIIPrintf(viewer, "time step limits: dem %g s%s\n", (double)dem_->StableTimeStep(), coupling_ ? " (sub-steps inside the fluid step)" : ""));
  if (physics_.flow) {
    PetscReal   f;
    std::string basis;
    PetscCall(flow_->StableTimeStep(&f, &basis, !ConsistentVofMomentum()));
    PetscCall(PetscViewerASCIIPrintf(viewer, "time step limits: flow %g s (%s)%s\n", (double)f, basis.c_str(), dtUser_ > 0 ? "" : "; adapted every step"));
  }
  if (physics_.vof) {  // the interface's fixed limit (PETSC_MAX_REAL: none)
    const PetscReal cap = vof_->CapillaryTimeStep(flow_->ReferenceDensity());
    if (cap < PETSC_MAX_REAL) PetscCall(PetscViewerASCIIPrintf(viewer, "time step limits: vof capillary %g s\n", (double)cap));
  }
  PetscCall(PetscViewerASCIIPrintf(viewer, "time step: %g s (set by %s); gravity (%g, %g, %g) m/s^2; seed %" PetscInt_FMT "\n", (double)dt_,
                                   dtLimitName_.c_str(), (double)gravity_[0], (double)gravity_[1], (double)gravity_[2], seed_));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::SaveState(PetscViewer viewer) {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "simulation_step", PETSC_INT, &step_));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "simulation_time", PETSC_REAL, &time_));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "simulation_dt", PETSC_REAL, &dt_));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "simulation_dt_basis", PETSC_STRING, dtLimitName_.c_str()));
  if (physics_.dem) PetscCall(dem_->Save(viewer));  // its own group "dem"
  if (physics_.flow) {
    PetscCall(PetscViewerHDF5PushGroup(viewer, "flow"));
    PetscCall(flow_->Save(viewer));
    PetscCall(PetscViewerHDF5PopGroup(viewer));
  }
  if (physics_.vof) {
    PetscCall(PetscViewerHDF5PushGroup(viewer, "vof"));
    PetscCall(vof_->Save(viewer));
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/vof", "vof_initial_volume", PETSC_REAL, &vofVolume0_));
    if (coupling_) PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/vof", "vof_initial_phase0_volume", PETSC_REAL, &vofOtherVolume0_));
    PetscCall(PetscViewerHDF5PopGroup(viewer));
  }
  if (coupling_) PetscCall(coupling_->Save(viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::StateBytes(PetscInt64 *bytes) const {
  PetscInt64 part = 0;

  PetscFunctionBeginUser;
  *bytes = 4096;  // the header attributes
  if (physics_.dem) {
    PetscCall(dem_->SavedBytes(&part));
    *bytes += part;
  }
  if (physics_.flow) {
    PetscCall(flow_->SavedBytes(&part));
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
  if (physics_.dem) PetscCall(dem_->Load(viewer));
  if (physics_.flow) {
    PetscCall(PetscViewerHDF5PushGroup(viewer, "flow"));
    PetscCall(flow_->Load(viewer));
    PetscCall(PetscViewerHDF5PopGroup(viewer));
  }
  if (physics_.vof) {  // after the flow: the flow's loaded density and viscosity already match alpha
    PetscCall(PetscViewerHDF5PushGroup(viewer, "vof"));
    PetscCall(vof_->Load(viewer));
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/vof", "vof_initial_volume", PETSC_REAL, nullptr, &vofVolume0_));
    if (coupling_) PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/vof", "vof_initial_phase0_volume", PETSC_REAL, nullptr, &vofOtherVolume0_));
    PetscCall(PetscViewerHDF5PopGroup(viewer));
  }
  if (coupling_) PetscCall(coupling_->Load(viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(checkpoint_.Destroy());
  if (csv_) std::fclose(csv_);
  csv_ = nullptr;
  if (coupling_) PetscCall(coupling_->Destroy());
  coupling_.reset();
  if (dem_) PetscCall(dem_->Destroy());
  dem_.reset();
  if (vof_) PetscCall(vof_->Destroy());
  vof_.reset();
  if (flow_) PetscCall(flow_->Destroy());
  flow_.reset();
  PetscCall(grid_.Destroy());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
