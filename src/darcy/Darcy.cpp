// Options, set-up, banner and Save/Load of the Darcy seepage (Darcy.hpp); the solve is DarcySolve.cpp.
#include "vofdem/darcy/Darcy.hpp"

#include "vofdem/base/NamedTable.hpp"
#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/grid/CellMatrix.hpp"

#include <petscviewerhdf5.h>

#include <cmath>
#include <string>

namespace vofdem {

namespace {

// Sets -darcy_<name> <value> unless the user gave it: defaults the user can override.
PetscErrorCode DefaultOption(const char *name, const char *value) {
  PetscBool given;

  PetscFunctionBeginUser;
  const std::string full = std::string("-darcy_") + name;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, full.c_str(), &given));
  if (!given) PetscCall(PetscOptionsSetValue(nullptr, full.c_str(), value));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode Darcy::SetFromOptions(const Grid &grid, const PetscReal gravity[3]) {
  PetscBool headSet = PETSC_FALSE, rampSet = PETSC_FALSE;

  PetscFunctionBeginUser;
  comm_ = grid.Comm();
  grid_ = &grid;
  const PetscReal gm = gravity ? std::sqrt(gravity[0] * gravity[0] + gravity[1] * gravity[1] + gravity[2] * gravity[2]) : 0;
  g_                 = gm > 0 ? gm : 9.81;
  PetscOptionsBegin(comm_, "darcy_", "Darcy: steady seepage div((k(eps)/mu) grad p) = s, p = rho_w g H (docs/modules/darcy.md, docs/physics.md F11)", "Darcy");
  {
    OptionReader             opt(PetscOptionsObject);
    std::vector<std::string> law  = {permeability::kLaws[law_].name};
    const std::string        help = "Permeability law k(eps) (seed 004 table 3): " + table::Help(permeability::kLaws);
    PetscCall(opt.NameList("-permeability_law", help.c_str(), table::Names(permeability::kLaws), &law));
    if (law.size() != 1) VofdemInputError(comm_, "option -darcy_permeability_law: give one law (%s)", table::Choices(permeability::kLaws).c_str());
    law_ = table::Find(permeability::kLaws, law[0]);
    PetscCall(opt.Real("-diameter", "Grain size of the permeability law (D, D10 or d)", "m", &param_.diameter, RealRange::Positive()));
    PetscCall(opt.Real("-reference_permeability", "k0 of the evolving law", "m^2", &param_.k0, RealRange::Positive()));
    PetscCall(opt.Real("-reference_fluid_fraction", "eps0 of the evolving law", "-", &param_.eps0, RealRange::LeftOpen(0, 1)));
    param_.eps0 = std::fmin(param_.eps0, 1 - 1e-12);
    PetscCall(opt.Real("-density", "Density of the pore water rho_w (head to pressure, buoyancy, Ergun's inertial term)", "kg/m^3", &param_.density, RealRange::Positive()));
    PetscCall(opt.Real("-viscosity", "Dynamic viscosity mu of the pore water", "Pa s", &param_.viscosity, RealRange::Positive()));
    std::vector<std::string> axis = {axis_ < 0 ? "none" : std::string(1, "xyz"[axis_])};
    PetscCall(opt.NameList("-axis", "Direction of the seepage: fixed head on the two box faces normal to it (inlet the lower face, outlet the upper), no flux through the others; none: a closed box",
                           {"none", "x", "y", "z"}, &axis));
    if (axis.size() != 1) VofdemInputError(comm_, "option -darcy_axis: give one of none, x, y, z");
    axis_ = axis[0] == "none" ? -1 : axis[0][0] - 'x';
    PetscCall(opt.Real("-head_difference", "Head difference H_inlet - H_outlet (positive: flow from the lower face to the upper); the final value with -darcy_head_ramp", "m", &headDifference_,
                       RealRange::Any(), &headSet));
    PetscCall(opt.Real("-outlet_head", "Head on the outlet face (the excess pressure there is rho_w g times it)", "m", &outletHead_));
    PetscCall(opt.RealVector("-head_ramp", "Raise the head difference in steps: step,period (m,s): the difference is min(final, step (1 + floor(t/period))) (default: none, the final difference at once)", "m,s",
                             ramp_, 2, RealRange::Any(), &rampSet));
    PetscCall(opt.Real("-head_start", "No head difference before this time (a bed settles first); the ramp's steps count from it", "s", &start_, RealRange::NonNegative()));
    PetscCall(opt.RealList("-fluid_fraction", "Fixed fluid fraction eps: one value for the whole box, or n values for n equal layers along -darcy_axis from the inlet (not with particles)", "-", &epsLayers_,
                           1024, RealRange::LeftOpen(0, 1), &epsSet_));
    PetscCall(opt.Real("-max_fluid_fraction", "Cap of eps in the permeability laws (an empty cell would have infinite k)", "-", &maxEps_, RealRange::LeftOpen(0, 1)));
    maxEps_ = std::fmin(maxEps_, 1 - 1e-9);
    PetscCall(opt.Real("-picard_rtol", "Nonlinear laws (ergun): stop the Picard iterations when no cell's k/mu changed by more than this fraction", "-", &picardRtol_, RealRange::Positive()));
    PetscCall(opt.Int("-solve_every", "Solve for the head every this many steps (with particles: they move little in a DEM step)", &every_, 1, 1000000000));
    PetscCall(opt.Int("-picard_max", "Nonlinear laws: at most this many Picard iterations per solve", &picardMax_, 1, 100000));
  }
  PetscOptionsEnd();
  if ((headSet && headDifference_ != 0) || rampSet) {
    if (axis_ < 0)
      VofdemInputError(comm_, "option -darcy_head_difference: a head difference needs open faces, and the box has none (give -darcy_axis x, y or z: fixed head on its two faces)");
  }
  if (axis_ >= 0 && grid.Periodic(axis_))
    VofdemInputError(comm_, "option -darcy_axis: %c is periodic (-grid_periodic); the fixed-head faces need a non-periodic direction", "xyz"[axis_]);
  if (rampSet && !(ramp_[0] != 0 && ramp_[1] > 0)) VofdemInputError(comm_, "option -darcy_head_ramp: give a non-zero step and a positive period (step,period in m,s)");
  if (rampSet && headDifference_ == 0) VofdemInputError(comm_, "option -darcy_head_ramp: give the final head difference too (-darcy_head_difference)");
  if (rampSet && ramp_[0] * headDifference_ < 0) VofdemInputError(comm_, "option -darcy_head_ramp: the step must have the sign of -darcy_head_difference (its final value)");
  if (epsLayers_.size() > 1) {
    if (axis_ < 0) VofdemInputError(comm_, "option -darcy_fluid_fraction: layers lie along -darcy_axis; give one value for a closed box");
    if (grid.Cells()[axis_] % (PetscInt)epsLayers_.size())
      VofdemInputError(comm_, "option -darcy_fluid_fraction: %d layers do not split the %d cells along %c into whole cells", (int)epsLayers_.size(), (int)grid.Cells()[axis_], "xyz"[axis_]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Darcy::TakeFluidFractionFromParticles() {
  PetscFunctionBeginUser;
  if (epsSet_) VofdemInputError(comm_, "option -darcy_fluid_fraction: with particles (dem,darcy) eps comes from them; leave it out");
  fromParticles_ = true;
  PetscFunctionReturn(0);
}

PetscReal Darcy::HeadDifference(PetscReal time) const {
  if (time < start_ * (1 - 1e-12)) return 0;
  if (!(ramp_[1] > 0)) return headDifference_;
  const PetscReal steps = std::floor((time - start_) / ramp_[1] * (1 + 1e-12)) + 1;  // a step's start lands on its own level
  const PetscReal dH    = ramp_[0] * steps;
  return std::fabs(dH) < std::fabs(headDifference_) ? dH : headDifference_;
}

PetscErrorCode Darcy::FixedFluidFraction() {
  PetscScalar ***e;
  PetscInt       s[3], m[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetCorners(dm_, &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  PetscCall(DMDAVecGetArray(dm_, eps_, &e));
  const PetscInt layers = (PetscInt)epsLayers_.size(), per = axis_ >= 0 ? grid_->Cells()[axis_] / layers : 1;
  for (PetscInt k = s[2]; k < s[2] + m[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + m[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + m[0]; ++i) {
        const PetscInt q[3] = {i, j, k};
        e[k][j][i]          = epsLayers_[layers > 1 ? q[axis_] / per : 0];
      }
  PetscCall(DMDAVecRestoreArray(dm_, eps_, &e));
  PetscFunctionReturn(0);
}

PetscErrorCode Darcy::SetUp(const Grid &grid) {
  PC pc;

  PetscFunctionBeginUser;
  grid_ = &grid;
  dm_   = grid.CellDM();
  PetscCall(PetscObjectReference((PetscObject)dm_));
  PetscCall(CreateCellMatrix(dm_, false, &A_));
  PetscCall(PetscObjectSetName((PetscObject)A_, "darcy_operator"));
  PetscCall(DMCreateGlobalVector(dm_, &p_));
  PetscCall(PetscObjectSetName((PetscObject)p_, "darcy_pressure"));
  for (Vec *v : {&b_, &eps_, &beta_, &betaOld_, &speed_}) PetscCall(VecDuplicate(p_, v));
  for (Vec &g : gradient_) PetscCall(VecDuplicate(p_, &g));
  PetscCall(PetscObjectSetName((PetscObject)eps_, "darcy_fluid_fraction"));
  PetscCall(PetscObjectSetName((PetscObject)beta_, "darcy_coefficient"));
  PetscCall(PetscObjectSetName((PetscObject)speed_, "darcy_speed"));
  PetscCall(DMCreateLocalVector(dm_, &pLocal_));
  PetscCall(VecDuplicate(pLocal_, &betaLocal_));
  PetscCall(VecSet(p_, rhoG() * outletHead_));
  PetscCall(VecSet(speed_, 0));
  PetscCall(VecSet(beta_, 0));
  for (Vec g : gradient_) PetscCall(VecSet(g, 0));
  if (!fromParticles_) PetscCall(FixedFluidFraction());
  else PetscCall(VecSet(eps_, 1));

  PetscCall(KSPCreate(comm_, &ksp_));
  PetscCall(KSPSetOptionsPrefix(ksp_, "darcy_"));
  PetscCall(KSPSetOperators(ksp_, A_, A_));
  PetscCall(KSPSetType(ksp_, KSPCG));
  PetscCall(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED));
  // The column's flow rate to 1e-10 (docs/verification.md G4) needs the residual well below that.
  PetscCall(KSPSetTolerances(ksp_, 1e-13, 1e-50, PETSC_DEFAULT, 1000));
  PetscCall(KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE));  // the last pressure
  PetscCall(KSPGetPC(ksp_, &pc));
  PetscCall(PCSetType(pc, PCHYPRE));
  PetscCall(PCHYPRESetType(pc, "boomeramg"));
  // The flow's tuned BoomerAMG settings (docs/petsc-notes.md), where the user chose no other preconditioner.
  char      type[64] = "";
  PetscBool other = PETSC_FALSE, set;
  PetscCall(PetscOptionsGetString(nullptr, "darcy_", "-pc_type", type, sizeof type, &set));
  other = set && std::string(type) != PCHYPRE ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(PetscOptionsGetString(nullptr, "darcy_", "-pc_hypre_type", type, sizeof type, &set));
  if (set && std::string(type) != "boomeramg") other = PETSC_TRUE;
  if (!other) PetscCall(DefaultOption("pc_hypre_boomeramg_coarsen_type", "HMIS"));
  if (!other) PetscCall(DefaultOption("pc_hypre_boomeramg_interp_type", "ext+i"));
  if (!other) PetscCall(DefaultOption("pc_hypre_boomeramg_P_max", "4"));
  if (!other) PetscCall(DefaultOption("pc_hypre_boomeramg_strong_threshold", "0.5"));
  if (!other) PetscCall(DefaultOption("pc_hypre_boomeramg_agg_nl", "1"));
  PetscCall(KSPSetFromOptions(ksp_));
  last_.headDifference = HeadDifference(0);
  PetscFunctionReturn(0);
}

PetscErrorCode Darcy::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  const permeability::Row &row = permeability::kLaws[law_];
  PetscCall(PetscViewerASCIIPrintf(viewer, "darcy: div((k/mu) grad p) = s, p = rho_w g H; permeability law %s (%s), d %g m, rho_w %g kg/m^3, mu %g Pa s, eps capped at %g\n", row.name, row.summary,
                                   (double)param_.diameter, (double)param_.density, (double)param_.viscosity, (double)maxEps_));
  if (axis_ < 0) PetscCall(PetscViewerASCIIPrintf(viewer, "darcy: a closed box (-darcy_axis none): no head difference, no flow\n"));
  else {
    const PetscReal L = grid_->Upper()[axis_] - grid_->Lower()[axis_];
    PetscCall(PetscViewerASCIIPrintf(viewer, "darcy: fixed head on the %clo (inlet) and %chi (outlet) faces, no flux elsewhere; head difference %g m (gradient %g)%s, outlet head %g m, g %g m/s^2\n",
                                     "xyz"[axis_], "xyz"[axis_], (double)headDifference_, (double)(headDifference_ / L),
                                     ((start_ > 0 ? ", from t = " + std::to_string((double)start_) + " s" : std::string()) +
                                      (ramp_[1] > 0 ? ", reached in steps of " + std::to_string((double)ramp_[0]) + " m every " + std::to_string((double)ramp_[1]) + " s" : std::string())).c_str(),
                                     (double)outletHead_, (double)g_));
  }
  if (!fromParticles_) {
    std::string e;
    for (PetscReal v : epsLayers_) e += (e.empty() ? "" : ", ") + std::to_string((double)v);
    PetscCall(PetscViewerASCIIPrintf(viewer, "darcy: fixed fluid fraction %s%s\n", e.c_str(), epsLayers_.size() > 1 ? " (equal layers from the inlet)" : ""));
  }
  PetscFunctionReturn(0);
}

// What the next solve starts from: p (the initial guess), and for a nonlinear law the coefficient and the cell
// speeds of the last iterate (the next step's first Picard iterate), so that a restart repeats the arithmetic.
PetscErrorCode Darcy::Save(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  for (Vec v : {p_, beta_, speed_}) PetscCall(VecView(v, viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode Darcy::Load(PetscViewer viewer) {
  PetscFunctionBeginUser;
  for (Vec v : {p_, beta_, speed_}) PetscCall(VecLoad(v, viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode Darcy::Destroy() {
  PetscFunctionBeginUser;
  for (Vec *v : {&p_, &b_, &eps_, &beta_, &betaOld_, &speed_, &pLocal_, &betaLocal_, &gradient_[0], &gradient_[1], &gradient_[2]}) PetscCall(VecDestroy(v));
  PetscCall(MatDestroy(&A_));
  PetscCall(KSPDestroy(&ksp_));
  PetscCall(DMDestroy(&dm_));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
