// Options, set-up, banner and Save/Load of the coupling (Coupling.hpp); the step is CouplingStep.cpp.
#include "vofdem/coupling/Coupling.hpp"

#include "vofdem/base/NamedTable.hpp"
#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"

#include <petscviewerhdf5.h>

#include <algorithm>
#include <utility>
#include <cmath>
#include <cstdio>

namespace vofdem {

PetscErrorCode Coupling::SetFromOptions(MPI_Comm comm) {
  PetscFunctionBeginUser;
  comm_ = comm;
  PetscOptionsBegin(comm, "coupling_", "Coupling: semi-resolved CFD-DEM (docs/physics.md K1-K3, F5, F6, P1)", "Coupling");
  {
    OptionReader             opt(PetscOptionsObject);
    std::vector<std::string> k    = {kernelName_};
    const std::string        help = "Kernel of averaging and projection: " + table::Help(kernel::kKernels);
    PetscCall(opt.NameList("-kernel", help.c_str(), table::Names(kernel::kKernels), &k));
    if (k.size() != 1) VofdemInputError(comm, "option -coupling_kernel: give one kernel");
    kernelName_   = k[0];
    kernel_.shape = kernel::kKernels[table::Find(kernel::kKernels, kernelName_)].shape;
    PetscCall(opt.Real("-kernel_width", "Kernel width H in particle diameters (kappa of K1: H = kappa d)", "-", &kappa_, RealRange::Positive()));
    PetscCall(opt.Real("-kernel_min_width", "Smallest kernel width in cells: H = max(kappa d, this x the largest cell spacing), so that coarse cells still see a smooth kernel", "cells",
                       &minWidthCells_, RealRange::Positive()));
    if (minWidthCells_ < 0.5)
      VofdemInputError(comm, "option -coupling_kernel_min_width: %g cells is below the cell size; a kernel narrower than half a cell cannot be sampled by the grid (use 0.5 or more, or -coupling_kernel unresolved)",
                       (double)minWidthCells_);
    std::vector<std::string> sm = {Smoothing::Name(smoothing_.method)};
    PetscCall(opt.NameList("-smoothing", "How the kernel is applied (docs/physics.md K1, K3): kernel (sums over each particle's support), diffusion (tent deposit, then backward-Euler diffusion in pseudo-time to the kernel's variance, Sun & Xiao 2015; KSP options -coupling_smoothing_ksp_*), gaussian (tent deposit, then a separable discrete Gaussian of the same variance, GaussianFilter.hpp) or auto (kernel or gaussian, the one measured faster for the grid and particle count, Smoothing.cpp)",
                           {"kernel", "diffusion", "gaussian", "auto"}, &sm));
    if (sm.size() != 1) VofdemInputError(comm, "option -coupling_smoothing: give one of kernel, diffusion, gaussian, auto");
    smoothing_.method = sm[0] == "kernel" ? Smoothing::Method::Kernel : sm[0] == "diffusion" ? Smoothing::Method::Diffusion : sm[0] == "gaussian" ? Smoothing::Method::Gaussian : Smoothing::Method::Auto;
    PetscCall(opt.Int("-smoothing_steps", "Backward-Euler pseudo-steps of the diffusion smoothing (the variance added is the same for any number; more steps: closer to a Gaussian)", &smoothing_.steps, 1));
    PetscCall(opt.Real("-smoothing_crossover", "auto: gaussian when the kernel's points summed over all particles exceed this many times the grid's cells times the Gaussian filter's taps (sum over directions of 2R + 1; break-even measured near 0.3-0.5 in the bubbling bed, Smoothing.cpp), else kernel", "-", &smoothing_.crossover,
                       RealRange::Positive()));
    PetscCall(opt.Real("-kernel_truncation", "Cut-off of the truncated Gaussian kernel, in widths H (seed 000: 1.2-1.5)", "-", &kernel_.truncation, RealRange::LeftOpen(0, 10)));
    std::vector<std::string> d = {drag::Name(law_)};
    const std::string dragHelp = "Drag law (docs/physics.md F6): " + drag::Help();
    PetscCall(opt.NameList("-drag", dragHelp.c_str(), drag::Names(), &d));
    if (d.size() != 1) VofdemInputError(comm, "option -coupling_drag: give one drag law");
    drag::Parse(d[0], &law_);
    PetscCall(opt.Real("-drag_switch", "Fluid fraction at which Gidaspow's law switches from Ergun (below) to Wen-Yu (F6; seed 000: 0.74)", "-", &dragSwitch_, RealRange::LeftOpen(0, 1)));
    PetscCall(opt.Bool("-pressure_force", "Pressure-gradient force -V grad p on the particles (with the hydrostatic pressure it is the buoyancy, P1)", &pressureForce_));
    PetscCall(opt.Bool("-self_correction", "Remove the particle's own disturbance from the velocity it reads (K1b)", &selfCorrection_));
    std::vector<std::string> fd = {implicitFluid_ ? "implicit" : "explicit"};
    PetscCall(opt.NameList("-fluid_drag", "The fluid side of the drag: explicit (the particles last drag impulse, exact exchange; needs dt below the fluid relaxation time eps rho/beta) or implicit (relaxation toward the particles velocity, seen by the projection too: stable in dense beds)",
                           {"explicit", "implicit"}, &fd));
    if (fd.size() != 1) VofdemInputError(comm, "option -coupling_fluid_drag: give implicit or explicit");
    implicitFluid_ = fd[0] == "implicit" ? PETSC_TRUE : PETSC_FALSE;
    PetscCall(opt.Real("-self_correction_min_eps", "Apply the self-disturbance correction only to particles whose averaged eps is at least this (it models an isolated particle)", "-",
                       &selfMinEps_, RealRange::Closed(0, 1)));
    std::vector<std::string> fa = {weightedFraction_ ? "weighted" : "plain"};
    PetscCall(opt.NameList("-fraction_average", "The fluid fraction a particle reads: plain (sum eps k/sum k, consistent with the eps-weighted velocity: their product is the averaged superficial velocity) or weighted (sum eps^2 k/sum eps k, K1 as written)",
                           {"plain", "weighted"}, &fa));
    if (fa.size() != 1) VofdemInputError(comm, "option -coupling_fraction_average: give plain or weighted");
    weightedFraction_ = fa[0] == "weighted" ? PETSC_TRUE : PETSC_FALSE;
    PetscCall(opt.Real("-added_mass", "Added-mass coefficient C_vm of f_vm = C_vm rho_f V (Du/Dt - dv/dt) (P1; 0.5 for a sphere), rho_f the kernel-averaged local density", "-",
                       &addedMass_, RealRange::NonNegative()));
    const char *const        amNames[] = {"velocity", "pressure", "none"};
    std::vector<std::string> am        = {amNames[(int)addedMassAccel_]};
    PetscCall(opt.NameList("-added_mass_acceleration",
                           "The fluid's acceleration Du/Dt in f_vm: velocity (the change over the step of the fluid velocity the particle reads; it includes the fluid the particle pushes itself), "
                           "pressure ((-grad p + f_st)/rho_f + g from the kernel averages: exact for inviscid fluid with no particle forces in it, e.g. waves on a pool; wrong in a bed, where grad p balances the drag) "
                           "or none (Du/Dt = 0: fluid at rest)",
                           {"velocity", "pressure", "none"}, &am));
    if (am.size() != 1) VofdemInputError(comm, "option -coupling_added_mass_acceleration: give one of velocity, pressure, none");
    addedMassAccel_ = am[0] == "pressure" ? FluidAcceleration::Pressure : am[0] == "none" ? FluidAcceleration::None : FluidAcceleration::Velocity;
    PetscCall(opt.Real("-contact_angle", "Contact angle of the liquid (the VOF's phase 1) on every particle, measured through the liquid: the particles feel Princen's capillary force at the free surface (Capillary.hpp, P1; needs -physics dem,flow,vof and a kernel). Not given (the default): no capillary force",
                       "deg", &contactAngle_, RealRange::Closed(0, 180), &contactAngleSet_));
    if (contactAngleSet_ && (smoothing_.method == Smoothing::Method::Diffusion || smoothing_.method == Smoothing::Method::Gaussian))
      VofdemInputError(comm, "option -coupling_contact_angle: the capillary force finds the interface through the kernel's marginal; use -coupling_smoothing kernel or auto");
    if (contactAngleSet_) smoothing_.method = Smoothing::Method::Kernel;  // auto: the capillary force needs the kernel
    if (contactAngleSet_ && kernel::CellBased(kernel_.shape))
      VofdemInputError(comm, "option -coupling_contact_angle: the capillary force finds the interface through the kernel's marginal; -coupling_kernel %s has no kernel (use smooth or truncated)",
                       kernelName_.c_str());
    std::vector<std::string> lf = {rotation::LiftName(lift_)};
    PetscCall(opt.NameList("-lift", "Magnus (rotation-induced) lift on the particles (RotationLaws.hpp, P1): none, rubinowkeller ((pi/8) d^3 rho Omega x (v - u), Re_p << 1) or oesterle (Oesterle & Bui Dinh 1998, Re_p < 140); "
                                    "Omega = omega_p - curl(u)/2. Its reaction joins the fluid's source (F5)",
                           rotation::LiftNames(), &lf));
    if (lf.size() != 1) VofdemInputError(comm, "option -coupling_lift: give one of none, rubinowkeller, oesterle");
    rotation::ParseLift(lf[0], &lift_);
    PetscCall(opt.Bool("-rotational_drag", "Rotational drag torque -pi mu d^3 (omega_p - curl(u)/2) on the particles (Rubinow & Keller 1961), implicit; its reaction torque on the fluid is neglected", &rotationalDrag_));
    PetscCall(opt.Bool("-rotational_drag_correction", "With -coupling_rotational_drag: Dennis et al.'s (1980) finite-Re_r factor 1 + (5/(64 pi)) Re_r^0.6 (Loth 2008), Re_r = rho d^2 |Omega|/mu", &rotationalDragDennis_));
    if (rotationalDragDennis_ && !rotationalDrag_) VofdemInputError(comm, "option -coupling_rotational_drag_correction: needs -coupling_rotational_drag");
    PetscCall(opt.Bool("-lubrication", "The DEM's lubrication (P8, f = 6 pi mu R_eff^2 v_n/h, gaps of -dem_lubrication_min_gap to -dem_lubrication_max_gap) with the fluid's viscosity mu: "
                                       "the flow's, or with a free surface the mixture viscosity the particles read (instead of -dem_lubrication_viscosity)",
                       &lubrication_));
    PetscCall(opt.Bool("-eps_rate", "The fluid the particles displace: the projection makes div(eps u) = -d(eps)/dt (F1) and the VOF transport carries eps (F1b)", &epsRate_));
    PetscCall(opt.Real("-min_fluid_fraction", "Floor of the fluid fraction eps (cells below it are counted in the monitor)", "-", &minEps_, RealRange::LeftOpen(0, 1)));
  }
  PetscOptionsEnd();
  PetscCall(Smoothing::ReadSolverOptions(comm));
  PetscFunctionReturn(0);
}

PetscReal Coupling::SelfCoefficient(PetscReal H, PetscReal ReH) const {
  const PetscReal x = (std::log10(std::max(ReH, (PetscReal)1e-3)) + 3) * 20;
  const PetscInt  k = std::min((PetscInt)x, (PetscInt)139);
  const PetscReal f = std::min(x - k, (PetscReal)1);  // beyond Re_H = 1e4: the last value
  return ((1 - f) * selfTable_[k] + f * selfTable_[k + 1]) / H;
}

PetscReal Coupling::KernelWidth(PetscReal d) const {
  if (kernel_.shape == kernel::Shape::Divided) return d / 2;  // the divided volume reaches the sphere's radius (Kernel.hpp)
  const PetscReal *h = flow_->Staggered().Base().Spacing();
  return std::max(kappa_ * d, minWidthCells_ * std::max(h[0], std::max(h[1], h[2])));
}

PetscErrorCode Coupling::CheckParticleSize(const Grid &g, PetscReal d) const {
  PetscFunctionBeginUser;
  for (int e = 0; e < 3; ++e)
    if (d > g.Upper()[e] - g.Lower()[e])
      VofdemInputError(comm_, "coupling: particles of diameter %g m are larger than the box (%g m in %c)", (double)d, (double)(g.Upper()[e] - g.Lower()[e]), "xyz"[e]);
  PetscFunctionReturn(0);
}

PetscErrorCode Coupling::SetUp(Flow &flow, Dem &dem) {
  PetscFunctionBeginUser;
  flow_ = &flow;
  dem_  = &dem;
  const StaggeredGrid &sg = flow.Staggered();
  const Grid          &g  = sg.Base();
  PetscCall(CheckParticleSize(g, 2 * dem.MaxRadius()));  // the sizes the fill and the sources made
  const PetscReal Hmax = KernelWidth(2 * dem.MaxRadius());
  // A particle strays up to half the Verlet skin outside its rank's box between migrations.
  PetscInt particles;
  PetscCall(dem.Particles().GlobalCount(&particles));
  PetscCall(avg_.SetUp(sg, kernel_, smoothing_, Hmax, 0.5 * dem.Skin() + 1e-12, particles));
  {
    std::vector<double> re(141);
    // Diffusion: about a Gaussian of the kernel's standard deviation sigma = r H (K1b's coefficient of a
    // Gaussian of width sigma, as a function of Re_H: sigma C(r Re_H)/r, with the table at width 1).
    const double r = avg_.Diffusion() ? std::sqrt(Smoothing::KernelVariance(kernel_.shape, 1.0, kernel_.truncation)) : 1.0;
    for (int k = 0; k <= 140; ++k) re[k] = r * std::pow(10.0, -3 + k / 20.0);
    std::vector<double> t = avg_.Diffusion() ? kernel::SelfDisturbanceTable(kernel::Shape::Truncated, 6.0, re) : kernel::SelfDisturbanceTable(kernel_.shape, kernel_.truncation, re);
    for (double &v : t) v /= r;
    selfTable_.assign(t.begin(), t.end());
  }
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMCreateGlobalVector(sg.Face(d), &faceEps_[d]));
    PetscCall(VecDuplicate(faceEps_[d], &gradP_[d]));
    PetscCall(VecDuplicate(faceEps_[d], &accel_[d]));
    PetscCall(VecSet(accel_[d], 0));
    PetscCall(VecDuplicate(faceEps_[d], &wallForce_[d]));
    PetscCall(VecSet(wallForce_[d], 0));
    if (Rotation()) {
      for (Vec &g : gradU_[d]) PetscCall(VecDuplicate(faceEps_[d], &g));
      PetscCall(DMCreateLocalVector(sg.Face(d), &faceLocal_[d]));
    }
    if (implicitFluid_) {
      PetscCall(VecDuplicate(faceEps_[d], &rate_[d]));
      PetscCall(VecDuplicate(faceEps_[d], &target_[d]));
      PetscCall(VecSet(rate_[d], 0));
      PetscCall(VecSet(target_[d], 0));
    }
  }
  PetscCall(DMCreateLocalVector(sg.Cells(), &cellLocal_));
  PetscCall(DMCreateLocalVector(sg.Cells(), &rhoLocal_));
  PetscCall(DMCreateGlobalVector(sg.Cells(), &volume_));
  if (epsRate_) {
    PetscCall(VecDuplicate(volume_, &epsChange_));
    PetscCall(VecSet(epsChange_, 0));
    flow.SetFluidFractionChange(epsChange_);
  }
  flow.SetFaceAcceleration(accel_);
  if (implicitFluid_) flow.SetFaceRelaxation(rate_, target_);
  dem.SetFluidCoupled(true);
  PetscCall(PetscLogEventRegister("CouplingProject", DM_CLASSID, &evProject_));
  PetscCall(PetscLogEventRegister("CouplingAverage", DM_CLASSID, &evAverage_));
  // The particles displace the fluid from the start; the flow's first step sees them.
  PetscCall(Project());
  if (epsChange_) PetscCall(VecSet(epsChange_, 0));  // the particles were there from the start: nothing displaced
  PetscCall(Average());
  PetscFunctionReturn(0);
}

// Settings, and the CFD-DEM diagnostics users check first (for the smallest and largest particle):
// the particle response time m/K against the fluid step (drag taken implicitly below it), the cell
// to particle volume ratio and the kernel width in cells, a Stokes number tau_p U/d with the
// particles' Stokes settling speed as U.
PetscErrorCode Coupling::View(PetscViewer viewer, PetscReal dt) const {
  PetscFunctionBeginUser;
  const PetscReal *h = flow_->Staggered().Base().Spacing();
  const PetscReal  Vc = h[0] * h[1] * h[2], hmax = std::max(h[0], std::max(h[1], h[2]));
  const PetscReal  rho = flow_->ReferenceDensity(), mu = flow_->ReferenceViscosity();
  char width[96];
  if (kernel_.shape == kernel::Shape::Unresolved) std::snprintf(width, sizeof width, "the cell of the centre");
  else if (kernel_.shape == kernel::Shape::Divided) std::snprintf(width, sizeof width, "the cells the sphere overlaps (32 cubes of side R/2, split by overlap)");
  else std::snprintf(width, sizeof width, "H = max(%g d, %g cells)", (double)kappa_, (double)minWidthCells_);
  // K1b's table is zero where the kernel has no self-disturbance model (cell-based deposits, the linear hat).
  const bool  modelled = std::any_of(selfTable_.begin(), selfTable_.end(), [](PetscReal c) { return c != 0; });
  const char *k1b      = !selfCorrection_ ? "off" : modelled ? "on" : "off (none for this kernel)";
  PetscCall(PetscViewerASCIIPrintf(viewer, "coupling: kernel %s, %s%s, drag %s%s (fluid side %s), pressure-gradient force %s, self-disturbance correction (K1b) %s, added mass C_vm %g (Du/Dt: %s), d(eps)/dt in continuity %s, ghost width %d cells\n",
                                   kernelName_.c_str(), width,
                                   kernel_.shape == kernel::Shape::Truncated ? (", cut at " + std::to_string((double)kernel_.truncation) + " H").c_str() : "",
                                   drag::Name(law_), std::string(drag::Name(law_)) == "gidaspow" ? (" (switch at eps " + std::to_string((double)dragSwitch_) + ")").c_str() : "", implicitFluid_ ? "implicit" : "explicit",
                                   pressureForce_ ? "on" : "off", k1b, (double)addedMass_, addedMassAccel_ == FluidAcceleration::Pressure ? "pressure balance" : addedMassAccel_ == FluidAcceleration::None ? "none: fluid at rest" : "velocity read", epsRate_ ? "on" : "off", (int)avg_.GhostWidth()));
  PetscCall(PetscViewerASCIIPrintf(viewer, "coupling: Magnus lift %s, rotational drag torque %s, lubrication (P8) with the fluid's viscosity %s\n", rotation::LiftName(lift_),
                                   !rotationalDrag_ ? "off" : rotationalDragDennis_ ? "on (pi mu d^3, Dennis et al. Re_r factor; no reaction torque on the fluid)" : "on (pi mu d^3; no reaction torque on the fluid)",
                                   lubrication_ ? "on" : "off"));
  if (avg_.Diffusion() && avg_.Smoother().GetOperator() == DiffusionSmoother::Operator::Gaussian)
    PetscCall(PetscViewerASCIIPrintf(viewer, "coupling: gaussian smoothing (-coupling_smoothing %s): tent deposit, separable discrete Gaussian to the kernel's variance (spread b = %.3g cells in x, %d taps per side)\n",
                                     Smoothing::Name(smoothing_.method), (double)(std::sqrt(avg_.Spread(0)) / h[0]), (int)avg_.Smoother().FilterRadius(0)));
  else if (avg_.Diffusion())
    PetscCall(PetscViewerASCIIPrintf(viewer, "coupling: diffusion smoothing (-coupling_smoothing %s): tent deposit, %d backward-Euler pseudo-steps to the kernel's variance (spread b = %.3g cells in x)\n",
                                     Smoothing::Name(smoothing_.method), (int)smoothing_.steps, (double)(std::sqrt(avg_.Spread(0)) / h[0])));
  if (contactAngleSet_)
    PetscCall(PetscViewerASCIIPrintf(viewer, "coupling: capillary force (Princen, flat interface) with contact angle %g deg for all particles, surface tension %g N/m%s\n", (double)contactAngle_, (double)sigma_,
                                     !freeSurface_ ? ": no free surface, no force" : sigma_ > 0 ? "" : ": the force is zero (-vof_surface_tension 0)"));
  // The extremes of the response time: the smallest sphere of the lightest type, the largest of the heaviest.
  PetscReal rhoLo = PETSC_MAX_REAL, rhoHi = 0;
  for (PetscInt t = 0; t < dem_->TypeCount(); ++t) rhoLo = std::min(rhoLo, dem_->TypeMaterial(t).density), rhoHi = std::max(rhoHi, dem_->TypeMaterial(t).density);
  std::vector<std::pair<PetscReal, PetscReal>> sizes = {{dem_->MinRadius(), rhoLo}};
  if (dem_->MaxRadius() > dem_->MinRadius() || rhoHi > rhoLo) sizes.push_back({dem_->MaxRadius(), rhoHi});
  for (const auto &[r, rhoP] : sizes) {
    const PetscReal d = 2 * r, V = PETSC_PI * d * d * d / 6, m = rhoP * V;
    const PetscReal K = 3 * PETSC_PI * mu * d, tau = m / K;  // Stokes response time rho_p d^2/(18 mu)
    const PetscReal g = 9.81, uSettle = std::fabs(rhoP - rho) * g * d * d / (18 * mu);
    PetscCall(PetscViewerASCIIPrintf(viewer, "coupling: d = %g m, rho_p %g kg/m^3: response time %.3g s (fluid step %.3g s: %s), cell/particle volume %.3g, cell/d %.3g, H = %.3g cells, Stokes number (Stokes settling speed) %.3g\n",
                                     (double)d, (double)rhoP, (double)tau, (double)dt, tau < dt ? "drag implicit" : "resolved by the step", (double)(Vc / V), (double)(hmax / d),
                                     (double)(KernelWidth(d) / hmax), (double)(tau * uSettle / d)));
    if (kernel::CellBased(kernel_.shape) && Vc < 3 * V)
      PetscCall(PetscViewerASCIIPrintf(viewer, "vofdem: warning: coupling: cells of %.3g particle volumes with -coupling_kernel %s: a particle fills most of its cell (use a kernel)\n", (double)(Vc / V),
                                       kernelName_.c_str()));
  }
  // The centred rule moves a whole particle's volume when its centre crosses a face: with d(eps)/dt in the continuity a
  // particle rattling across a face gets a pressure impulse back each time (results/c2-packed-bed.md, 2026-11-27).
  if (kernel_.shape == kernel::Shape::Unresolved && epsRate_)
    PetscCall(PetscViewerASCIIPrintf(viewer, "coupling: note: with -coupling_kernel unresolved eps jumps by a particle's volume when its centre crosses a face; in a dense bed of a few "
                                             "particles per cell the drop can chatter (-coupling_kernel divided is continuous)\n"));
  if (dem_->StableTimeStep() > dt)
    PetscCall(PetscViewerASCIIPrintf(viewer, "coupling: the DEM step %.3g s exceeds the fluid step: one DEM step per fluid step\n", (double)dem_->StableTimeStep()));
  else
    PetscCall(PetscViewerASCIIPrintf(viewer, "coupling: %d DEM sub-steps of at most %.3g s per fluid step\n", (int)Substeps(dt), (double)dem_->StableTimeStep()));
  PetscFunctionReturn(0);
}

PetscErrorCode Coupling::Save(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "coupling_dt_last", PETSC_REAL, &dtLast_));
  PetscFunctionReturn(0);
}

// The drag impulses travel with the particles (swarm fields, DemSaveLoad.cpp); eps, the face sources and
// the particles' fluid fields are rebuilt from them exactly as the saving run had them.
PetscErrorCode Coupling::Load(PetscViewer viewer) {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "coupling_dt_last", PETSC_REAL, nullptr, &dtLast_));
  PetscFunctionReturn(0);
}

PetscErrorCode Coupling::Destroy() {
  PetscFunctionBeginUser;
  if (flow_) flow_->SetFaceAcceleration(nullptr);
  if (flow_) flow_->SetFaceRelaxation(nullptr, nullptr);
  if (flow_) flow_->SetFluidFractionChange(nullptr);
  for (int d = 0; d < 3; ++d)
    for (Vec *v : {&faceEps_[d], &gradP_[d], &accel_[d], &rate_[d], &target_[d], &gradAlpha_[d], &massWork_[d], &wallForce_[d]}) PetscCall(VecDestroy(v));
  for (int d = 0; d < 3; ++d)
    for (Vec *v : {&gradU_[d][0], &gradU_[d][1], &faceLocal_[d]}) PetscCall(VecDestroy(v));
  for (Vec *v : {&cellLocal_, &rhoLocal_, &volume_, &epsChange_, &bornCells_}) PetscCall(VecDestroy(v));
  PetscCall(avg_.Destroy());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
