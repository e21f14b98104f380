// Energy.hpp: options, materials, fields, solver, banner and checkpoints of the energy equation.
#include "vofdem/energy/Energy.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/grid/CellMatrix.hpp"
#include "vofdem/io/MaterialFile.hpp"
#include "vofdem/io/XdmfCheckpoint.hpp"

#include <petscdmda.h>
#include <petscviewerhdf5.h>

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace {
const char *kFaces[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
}

PetscErrorCode Energy::FaceOptions(PetscOptionItems *items) {
  OptionReader opt(items);

  PetscFunctionBeginUser;
  for (int f = 0; f < 6; ++f) {
    if (grid_->Periodic(f / 2)) continue;
    const std::string        base = std::string("-bc_") + kFaces[f];
    std::vector<std::string> type = {"adiabatic"};
    PetscBool                valueSet = PETSC_FALSE;
    PetscCall(opt.NameList(base.c_str(), "Box face: adiabatic, temperature (-..._value K), flux (-..._value W/m^2 into the box) or convective (-..._value h W/(m^2 K) to -..._ambient, with -..._emissivity)",
                           {"adiabatic", "temperature", "flux", "convective"}, &type));
    PetscCall(opt.Real((base + "_value").c_str(), "The face's temperature (K), flux into the box (W/m^2) or heat transfer coefficient (W/(m^2 K))", "", &face_[f].value, RealRange::Any(), &valueSet));
    PetscCall(opt.Real((base + "_ambient").c_str(), "Ambient temperature of a convective face", "K", &face_[f].ambient, RealRange::Positive()));
    PetscCall(opt.Real((base + "_emissivity").c_str(), "Emissivity of a convective face (radiation to the ambient)", "", &face_[f].emissivity, RealRange::Closed(0, 1)));
    const std::string &t = type[0];
    face_[f].type = t == "temperature" ? EnergyBoundary::Temperature : t == "flux" ? EnergyBoundary::Flux : t == "convective" ? EnergyBoundary::Convective : EnergyBoundary::Adiabatic;
    if (face_[f].type != EnergyBoundary::Adiabatic && !valueSet) VofdemInputError(comm_, "option -energy%s_value: a %s face needs its value", base.c_str(), t.c_str());
    if (face_[f].type == EnergyBoundary::Temperature && !(face_[f].value > 0)) VofdemInputError(comm_, "option -energy%s_value: a temperature must be positive (K)", base.c_str());
    if (face_[f].type == EnergyBoundary::Convective && face_[f].value < 0) VofdemInputError(comm_, "option -energy%s_value: a heat transfer coefficient cannot be negative", base.c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::ReadMaterials() {
  PetscFunctionBeginUser;
  for (int phase = 0; phase < 2; ++phase) {
    const std::string &name = phase == 0 ? metalName_ : gasName_;
    ThermalMaterial   &m    = phase == 0 ? metal_ : gas_;
    const std::string  path = FindMaterialFile(name);
    if (path.empty()) VofdemInputError(comm_, "option -energy_%s: no material file '%s' (config/materials/%s.yaml or a path)", phase == 0 ? "metal" : "gas", name.c_str(), name.c_str());
    std::string message;
    m.name = name;
    if (!ReadThermalMaterial(path, phase == 0, &m, &message)) VofdemInputError(comm_, "option -energy_%s: %s", phase == 0 ? "metal" : "gas", message.c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::SetFromOptions(const Grid &grid) {
  std::vector<std::string> scheme = {"bdf2"}, pc, law;
  PetscBool                boxLo = PETSC_FALSE, boxHi = PETSC_FALSE;

  PetscFunctionBeginUser;
  grid_ = &grid, comm_ = grid.Comm();
  for (int d = 0; d < 3; ++d) boxLower_[d] = boxUpper_[d] = grid.Lower()[d];
  metalTop_ = grid.Upper()[2];
  pc        = {"auto"};
  // The materials first (their values are the defaults of the options below).
  PetscOptionsBegin(comm_, "energy_", "Energy: temperature, latent heat and the laser (docs/modules/energy.md)", "Energy");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.String("-metal", "Material file of the metal (config/materials/NAME.yaml or a path)", &metalName_));
    PetscCall(opt.String("-gas", "Material file of the gas", &gasName_));
  }
  PetscOptionsEnd();
  PetscCall(ReadMaterials());
  PetscOptionsBegin(comm_, "energy_", "Energy: temperature, latent heat and the laser (docs/modules/energy.md)", "Energy");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.String("-metal", "Material file of the metal (config/materials/NAME.yaml or a path)", &metalName_));
    PetscCall(opt.String("-gas", "Material file of the gas", &gasName_));
    for (int phase = 0; phase < 2; ++phase) {
      ThermalMaterial  &m = phase == 0 ? metal_ : gas_;
      const std::string p = phase == 0 ? "-metal_" : "-gas_";
      PetscReal         cp = m.cp.Valid() ? m.cp.v[0] : 0, k = m.k.Valid() ? m.k.v[0] : 0;
      PetscBool         cpSet = PETSC_FALSE, kSet = PETSC_FALSE;
      PetscCall(opt.Real((p + "density").c_str(), "Density (default: the material file's)", "kg/m^3", &m.density, RealRange::Any()));
      PetscCall(opt.Real((p + "specific_heat").c_str(), "Specific heat, constant (replaces the material file's value or table)", "J/(kg K)", &cp, RealRange::Any(), &cpSet));
      PetscCall(opt.Real((p + "conductivity").c_str(), "Thermal conductivity, constant (replaces the material file's value or table)", "W/(m K)", &k, RealRange::Any(), &kSet));
      PetscCall(opt.Real((p + "emissivity").c_str(), "Emissivity of the surface", "", &m.emissivity, RealRange::Closed(0, 1)));
      if (cpSet) m.cp = PropertyTable{{}, {cp}};
      if (kSet) m.k = PropertyTable{{}, {k}};
      if (phase == 0) {
        PetscCall(opt.Real("-metal_solidus", "Solidus temperature T_s", "K", &m.solidus, RealRange::Any()));
        PetscCall(opt.Real("-metal_liquidus", "Liquidus temperature T_l", "K", &m.liquidus, RealRange::Any()));
        PetscCall(opt.Real("-metal_latent_heat", "Latent heat of melting L", "J/kg", &m.latentHeat, RealRange::NonNegative()));
        PetscCall(opt.Real("-metal_boiling_point", "Boiling point: a surface past it by -energy_boiling_margin stops the run (no evaporation model)", "K", &m.boilingPoint, RealRange::Any()));
      }
      const char *what = phase == 0 ? "metal" : "gas";
      if (!(m.density > 0)) VofdemInputError(comm_, "option -energy_%s_density: the %s (%s) needs a positive density", what, what, m.path.c_str());
      if (!m.cp.Valid() || !(m.cp.Min() > 0)) VofdemInputError(comm_, "option -energy_%s_specific_heat: the %s (%s) needs a positive specific heat", what, what, m.path.c_str());
      if (!m.k.Valid() || !(m.k.Min() > 0)) VofdemInputError(comm_, "option -energy_%s_conductivity: the %s (%s) needs a positive conductivity", what, what, m.path.c_str());
    }
    law = {metal_.melt == MeltLaw::Erf ? "erf" : "linear"};
    PetscCall(opt.NameList("-melt_law", "Melt fraction f_l(T): linear (clamp((T - T_s)/(T_l - T_s), 0, 1)) or erf (seed 000; never exactly 0 or 1)", {"linear", "erf"}, &law));
    metal_.melt = law[0] == "erf" ? MeltLaw::Erf : MeltLaw::Linear;
    PetscCall(opt.Real("-initial_temperature", "Initial temperature everywhere (then the box and the substrate)", "K", &T0_, RealRange::Positive()));
    PetscCall(opt.RealVector("-substrate_velocity",
                             "Without a flow: the box's contents move at this velocity (x, y) under a fixed beam (give -laser_path one point); what enters is at the initial temperature",
                             "m/s", substrateVelocity_, 2, RealRange::Any()));
    PetscCall(opt.Real("-substrate_cfl",
                       "Time step: the moving substrate travels at most this fraction of a cell per step (its explicit shift is stable to 1; 0.5 puts E4's peak 2.3 % high at R_l/h 2, 0.25 0.8 %)",
                       "-", &substrateCfl_, RealRange::LeftOpen(0, 1)));
    PetscCall(opt.RealVector("-initial_gradient", "A uniform initial temperature gradient G: T = T0 + G.(x - lower corner) (before the box and the substrate)", "K/m", gradient0_, 3));
    PetscCall(opt.RealVector("-box_lower", "Lower corner of a box at -energy_box_temperature", "m", boxLower_, 3, RealRange::Any(), &boxLo));
    PetscCall(opt.RealVector("-box_upper", "Upper corner of that box", "m", boxUpper_, 3, RealRange::Any(), &boxHi));
    boxT_ = T0_, substrateT_ = T0_;
    PetscCall(opt.Real("-box_temperature", "Initial temperature inside the box (cells whose centre is inside)", "K", &boxT_, RealRange::Positive()));
    PetscCall(opt.Real("-substrate_top", "Top of a preheated substrate (cells whose centre is below it; default: none)", "m", &substrateTop_, RealRange::Any()));
    PetscCall(opt.Real("-substrate_temperature", "Initial temperature of the substrate", "K", &substrateT_, RealRange::Positive()));
    PetscCall(opt.Real("-metal_top", "Without an interface module: metal below this height, gas above (default: the box top, all metal)", "m", &metalTop_, RealRange::Any()));
    metal_.referenceTemperature = 300;
    PetscCall(opt.Real("-reference_temperature", "Where the enthalpy is zero (energy_total_J counts from it)", "K", &metal_.referenceTemperature, RealRange::NonNegative()));
    gas_.referenceTemperature = metal_.referenceTemperature;
    PetscCall(opt.Real("-ambient_temperature", "Ambient temperature of the interface's losses", "K", &ambient_, RealRange::Positive()));
    PetscCall(opt.Real("-interface_convection", "Heat transfer coefficient of the metal surface to the ambient", "W/(m^2 K)", &interfaceConvection_, RealRange::NonNegative()));
    PetscCall(opt.Bool("-interface_radiation", "Radiation of the metal surface (its emissivity) to the ambient", &interfaceRadiation_));
    PetscCall(FaceOptions(PetscOptionsObject));
    PetscCall(opt.NameList("-time_scheme", "Time scheme: bdf2 (backward Euler on the first step) or euler (backward)", {"bdf2", "euler"}, &scheme));
    PetscCall(opt.Real("-tolerance", "Enthalpy iteration: every cell's balance residual below this, relative to rho_m (cp_m (T_l - T_s) + L)", "", &tolerance_, RealRange::Positive()));
    PetscCall(opt.Int("-max_iterations", "Enthalpy iteration: at most this many linear solves per step", &maxIterations_, 1, 10000));
    std::vector<std::string> rebuild = {pcRebuild_ == PcRebuild::Step ? "step" : "iteration"};
    PetscCall(opt.NameList("-pc_rebuild", "Enthalpy iteration: build the preconditioner once per step (step) or for every iteration's Jacobian (iteration)", {"step", "iteration"}, &rebuild));
    pcRebuild_ = rebuild[0] == "step" ? PcRebuild::Step : PcRebuild::Iteration;
    PetscCall(opt.NameList("-pc",
                           "Preconditioner: auto (jacobi while the longest step the module expects is below 20 explicit diffusion limits, else pfmg, or boomeramg with one cell across x or y), "
                           "pfmg (hypre structured), boomeramg or jacobi",
                           {"auto", "pfmg", "boomeramg", "jacobi"}, &pc));
    PetscCall(opt.Real("-boiling_margin", "Stop the run when the metal passes its boiling point by more than this", "K", &boilingMargin_, RealRange::NonNegative()));
    poolIsotherm_ = metal_.liquidus;
    PetscCall(opt.Int("-output_every", "ParaView files of T, the melt fraction and alpha every N steps (0: none; needs -output_dir)", &outputEvery_, 0));
    PetscCall(opt.Real("-mushy_constant", "With a flow: Carman-Kozeny constant D_c of the Darcy term D_c s^2/((1 - s)^3 + D_cs) U, s the solid metal fraction (docs/physics.md F2)",
                       "kg/(m^3 s)", &mushyConstant_, RealRange::NonNegative()));
    PetscCall(opt.Real("-mushy_epsilon", "With a flow: the small D_cs of the Darcy term (bounds it where s = 1)", "", &mushyEpsilon_, RealRange::Positive()));
    PetscCall(opt.Bool("-hold_solid", "With a flow: hold cells of solid metal at rest (see -energy_freeze_alpha; 0: only the Darcy term)", &holdSolid_));
    PetscCall(opt.Real("-freeze_alpha", "With a flow: a cell with at least this metal fraction whose metal is all solid (f_l = 0) is held at rest", "", &freezeAlpha_,
                       RealRange::Closed(0, 1)));
    PetscCall(opt.Real("-pool_isotherm", "The isotherm whose extent is the pool's length, width and depth (default: the liquidus)", "K", &poolIsotherm_, RealRange::Positive()));
  }
  PetscOptionsEnd();
  bdf2_ = scheme[0] == "bdf2";
  PetscCall(laser_.SetFromOptions(grid, metal_.absorptivity));
  // The explicit diffusion limit (printed; the scheme is implicit): min rho cp / (2 k sum 1/h^2) over both phases.
  const PetscReal *h = grid.Spacing();
  const PetscReal  sh = 1 / (h[0] * h[0]) + 1 / (h[1] * h[1]) + 1 / (h[2] * h[2]);
  explicitLimit_      = PETSC_MAX_REAL;
  for (const ThermalMaterial *m : {&metal_, &gas_}) {
    PetscReal kmax = *std::max_element(m->k.v.begin(), m->k.v.end()), cmin = m->cp.Min();
    explicitLimit_ = std::min(explicitLimit_, m->density * cmin / (2 * kmax * sh));
  }
  // auto: the correction's system is I + (dt/C) div k grad, within about 1 + 2 dt/dt_explicit of the identity
  // after Jacobi scaling; CG with Jacobi then needs a few iterations and no set-up, which beats multigrid's
  // set-up each step up to about 20 explicit limits (docs/modules/energy.md). Chosen step by step from the step.
  const bool oneAcross = grid.Cells()[0] == 1 || grid.Cells()[1] == 1;  // docs/petsc-notes.md: hyprestruct with one cell across x or y
  autoPc_   = pc[0] == "auto";
  jacobiPc_ = pc[0] == "jacobi";
  pfmg_     = pc[0] == "pfmg" || (autoPc_ && !oneAcross);
  if (pfmg_ && (grid.Cells()[0] == 1 || grid.Cells()[1] == 1))
    VofdemInputError(comm_, "option -energy_pc: pfmg cannot take one cell across x or y (docs/petsc-notes.md); use boomeramg");
  box_ = boxLo || boxHi;
  if (boxLo != boxHi) VofdemInputError(comm_, "option -energy_box_%s: give both corners of the box", boxLo ? "upper" : "lower");
  if (!(metal_.solidus > 0) || !(metal_.liquidus > 0)) VofdemInputError(comm_, "option -energy_metal_solidus: the metal (%s) needs a solidus and a liquidus", metal_.path.c_str());
  if (!(metal_.liquidus > metal_.solidus))
    VofdemInputError(comm_, "option -energy_metal_liquidus: the liquidus %g K must exceed the solidus %g K", (double)metal_.liquidus, (double)metal_.solidus);
  energyScale_ = metal_.density * (metal_.cp.At(metal_.liquidus) * (metal_.liquidus - metal_.solidus) + metal_.latentHeat);
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::SetUp() {
  PetscInt px, py, pz;

  PetscFunctionBeginUser;
  dm_ = grid_->CellDM();
  PetscCall(PetscLogEventRegister("EnergyLaser", DM_CLASSID, &evLaser_));
  PetscCall(PetscLogEventRegister("EnergyProperties", DM_CLASSID, &evProperties_));
  PetscCall(PetscLogEventRegister("EnergyResidual", DM_CLASSID, &evResidual_));
  PetscCall(PetscLogEventRegister("EnergyAssemble", DM_CLASSID, &evAssemble_));
  PetscCall(PetscLogEventRegister("EnergyClose", DM_CLASSID, &evClose_));
  PetscCall(PetscLogEventRegister("EnergyTransport", DM_CLASSID, &evTransport_));
  PetscCall(PetscLogEventRegister("EnergyMushyDrag", DM_CLASSID, &evMushy_));
  for (Vec *v : {&T_, &E_, &Eold_, &H_, &C_, &Ecur_, &k_, &q_, &alpha_, &r_, &rhs_, &Tstar_, &fl_, &F_, &slope_, &TF_, &Tbase_, &Fbase_, &Xstart_}) PetscCall(DMCreateGlobalVector(dm_, v));
  for (Vec *v : {&TLocal_, &kLocal_, &alphaLocal_}) PetscCall(DMCreateLocalVector(dm_, v));
  PetscCall(DMCreateGlobalVector(dm_, &epsCells_));
  PetscCall(DMCreateLocalVector(dm_, &epsLocal_));
  PetscCall(RefreshFluidFraction());
  PetscCall(PetscObjectSetName((PetscObject)T_, "energy_temperature"));
  PetscCall(PetscObjectSetName((PetscObject)Eold_, "energy_previous_energy"));
  PetscCall(PetscObjectSetName((PetscObject)E_, "energy_energy"));
  PetscCall(PetscObjectSetName((PetscObject)F_, "energy_metal_melt_fraction"));
  PetscCall(PetscObjectSetName((PetscObject)fl_, "energy_melt_fraction"));
  PetscCall(PetscObjectSetName((PetscObject)alpha_, "energy_metal_fraction"));
  PetscCall(SetInitial());
  PetscCall(SetUpSubstrate());  // after SetInitial: its inflow is the initial field
  // The process column of this rank in z (DMDA ranks run x fastest), top first: the laser's scan.
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  PetscCall(DMDAGetInfo(dm_, nullptr, nullptr, nullptr, nullptr, &px, &py, &pz, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  const int xy = rank % (px * py), zr = rank / (px * py);
  PetscCallMPI(MPI_Comm_split(comm_, xy, (int)pz - 1 - zr, &column_));
  // The solvers: multigrid (hypre PFMG on its structured matrix, grid/CellMatrix.hpp, or BoomerAMG) and CG with
  // Jacobi on an AIJ matrix; -energy_pc auto keeps both and takes one per step (SolverFor).
  if (!jacobiPc_) PetscCall(CreateSolver(kMultigrid, pfmg_ ? "pfmg" : "boomeramg"));
  if (jacobiPc_ || autoPc_) PetscCall(CreateSolver(kJacobi, "jacobi"));
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::CreateSolver(int slot, const std::string &pc) {
  Mat &A   = A_[slot];
  KSP &ksp = ksp_[slot];
  PC   pcx;

  PetscFunctionBeginUser;
  PetscCall(CreateCellMatrix(dm_, pc == "pfmg", &A));
  PetscCall(MatSetOption(A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(KSPCreate(comm_, &ksp));
  PetscCall(KSPSetOptionsPrefix(ksp, "energy_"));
  PetscCall(KSPSetOperators(ksp, A, A));
  PetscCall(KSPSetType(ksp, KSPCG));
  // Of a correction, in the unpreconditioned norm: rtol 1e-10, and an absolute tolerance each solve sets from
  // -energy_tolerance (Step), so that a solve goes as far as the enthalpy iteration needs and no further.
  PetscCall(KSPSetTolerances(ksp, 1e-10, 0, PETSC_DEFAULT, 500));
  PetscCall(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED));
  PetscCall(KSPGetPC(ksp, &pcx));
  if (pc == "pfmg") PetscCall(PCSetType(pcx, PCPFMG));
  else if (pc == "jacobi") PetscCall(PCSetType(pcx, PCJACOBI));
  else {
    PetscCall(PCSetType(pcx, PCHYPRE));
    PetscCall(PCHYPRESetType(pcx, "boomeramg"));
  }
  PetscCall(KSPSetFromOptions(ksp));
  if (pc == "pfmg") {  // hypre's structured matrix serves hypre's structured preconditioners alone (no diagonal, no rows)
    PCType type;
    PetscCall(PCGetType(pcx, &type));
    const std::string t = type ? type : "";
    if (t != PCPFMG && t != PCSMG && t != PCSYSPFMG && t != PCNONE)
      VofdemInputError(comm_, "option -energy_pc_type: %s cannot take the hypre structured matrix that -energy_pc pfmg (or auto) builds; give -energy_pc jacobi or boomeramg instead", t.c_str());
  }
  PetscCall(KSPGetTolerances(ksp, nullptr, &kspAtol_, nullptr, nullptr));  // the user's -energy_ksp_atol, a floor
  PetscFunctionReturn(0);
}

// The step's solver: Jacobi for short steps (-energy_pc auto, SetFromOptions), multigrid for long ones.
PetscReal Energy::StepLimit() const {
  const PetscReal a = laser_.StepLimit(), b = SubstrateStepLimit();
  return a > 0 && b > 0 ? std::min(a, b) : std::max(a, b);
}

int Energy::SolverFor(PetscReal dt) const {
  if (jacobiPc_) return kJacobi;
  return autoPc_ && dt < 20 * explicitLimit_ ? kJacobi : kMultigrid;
}

PetscErrorCode Energy::SetInitial() {
  const PetscReal *h = grid_->Spacing(), *lo = grid_->Lower();
  PetscScalar   ***T, ***al, ***F;
  PetscInt         s[3], m[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetCorners(dm_, &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  PetscCall(DMDAVecGetArray(dm_, T_, &T));
  PetscCall(DMDAVecGetArray(dm_, F_, &F));
  PetscCall(DMDAVecGetArray(dm_, alpha_, &al));
  for (PetscInt z = s[2]; z < s[2] + m[2]; ++z)
    for (PetscInt y = s[1]; y < s[1] + m[1]; ++y)
      for (PetscInt x = s[0]; x < s[0] + m[0]; ++x) {
        const PetscReal c[3] = {lo[0] + (x + 0.5) * h[0], lo[1] + (y + 0.5) * h[1], lo[2] + (z + 0.5) * h[2]};
        PetscReal       t    = T0_ + gradient0_[0] * (c[0] - lo[0]) + gradient0_[1] * (c[1] - lo[1]) + gradient0_[2] * (c[2] - lo[2]);
        if (c[2] < substrateTop_) t = substrateT_;
        bool inside = box_;
        for (int d = 0; d < 3 && inside; ++d) inside = c[d] > boxLower_[d] && c[d] < boxUpper_[d];
        if (inside) t = boxT_;
        T[z][y][x]  = t;
        F[z][y][x]  = metal_.MeltFraction(t);
        if (!interfaceAlpha_) al[z][y][x] = std::min((PetscReal)1, std::max((PetscReal)0, (metalTop_ - (lo[2] + z * h[2])) / h[2]));  // the cell's metal below metalTop_
      }
  PetscCall(DMDAVecRestoreArray(dm_, alpha_, &al));
  PetscCall(DMDAVecRestoreArray(dm_, F_, &F));
  if (interfaceAlpha_) PetscCall(VecCopy(interfaceAlpha_(), alpha_));  // the interface's metal
  PetscCall(DMDAVecRestoreArray(dm_, T_, &T));
  PetscCall(DMGlobalToLocal(dm_, alpha_, INSERT_VALUES, alphaLocal_));
  PetscCall(InitialEnergy());
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::InitialEnergy() {
  const PetscReal *h = grid_->Spacing();
  PetscReal        total;

  PetscFunctionBeginUser;
  PetscCall(Properties());
  PetscCall(VecCopy(Ecur_, E_));
  PetscCall(VecCopy(Ecur_, Eold_));
  PetscCall(VecSum(E_, &total));
  total *= h[0] * h[1] * h[2];
  W_ = Wold_ = totalOld_ = totalOlder_ = total;
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::SetFluidFraction(Vec eps, Vec change) {
  PetscFunctionBeginUser;
  PetscCheck(steps_ == 0, comm_, PETSC_ERR_ORDER, "energy: the fluid fraction is set before the first step");
  epsFluid_ = eps, epsChange_ = change;
  if (dm_) {  // set up already: the initial energy counts the fluid's share (a restart then loads its own)
    PetscCall(RefreshFluidFraction());
    PetscCall(InitialEnergy());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::RefreshFluidFraction() {
  PetscFunctionBeginUser;
  // Without particles eps = 1 is set once: the unchanged epsLocal_ keeps Residual's face conductances (its key).
  if (!epsFluid_ && epsUnit_) PetscFunctionReturn(0);
  if (epsFluid_) PetscCall(VecCopy(epsFluid_, epsCells_));  // the flow's cells: the same layout as dm_'s
  else PetscCall(VecSet(epsCells_, 1));
  PetscCall(DMGlobalToLocal(dm_, epsCells_, INSERT_VALUES, epsLocal_));
  epsUnit_ = !epsFluid_;
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::View(PetscViewer viewer) const {
  static const char *types[] = {"adiabatic", "temperature", "flux", "convective"};
  std::string        faces;

  const std::string multigrid = pfmg_ ? "hypre PFMG" : "hypre BoomerAMG";
  const std::string solver    = jacobiPc_ ? "Jacobi" : autoPc_ ? "Jacobi while dt < 20 explicit diffusion limits, else " + multigrid : multigrid;

  PetscFunctionBeginUser;
  for (int f = 0; f < 6; ++f)
    if (!grid_->Periodic(f / 2)) faces += std::string(f ? ", " : "") + kFaces[f] + " " + types[(int)face_[f].type];
  PetscCall(PetscViewerASCIIPrintf(viewer, "energy: metal %s (rho %g kg/m^3, T_s %g K, T_l %g K, L %g J/kg, melt law %s), gas %s (rho %g kg/m^3); %s, implicit, enthalpy iteration to %g; CG + %s (prefix energy_)\n",
                                   metal_.path.c_str(), (double)metal_.density, (double)metal_.solidus, (double)metal_.liquidus, (double)metal_.latentHeat,
                                   metal_.melt == MeltLaw::Erf ? "erf" : "linear", gas_.path.c_str(), (double)gas_.density, bdf2_ ? "BDF2" : "backward Euler",
                                   (double)tolerance_, solver.c_str()));
  PetscCall(PetscViewerASCIIPrintf(viewer, "energy: box faces %s; explicit diffusion limit %g s (not binding: the scheme is implicit)\n", faces.c_str(), (double)explicitLimit_));
  PetscCall(laser_.View(viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::Save(PetscViewer viewer) const {
  PetscReal scalars[6] = {(PetscReal)steps_, dtOld_, W_, Wold_, totalOld_, totalOlder_};

  PetscFunctionBeginUser;
  PetscCall(VecView(T_, viewer));
  PetscCall(VecView(F_, viewer));
  PetscCall(VecView(E_, viewer));
  PetscCall(VecView(Eold_, viewer));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/energy", "energy_account", PETSC_REAL, scalars));  // first of six, see Load
  for (int i = 1; i < 6; ++i) {
    const std::string name = "energy_account_" + std::to_string(i);
    PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/energy", name.c_str(), PETSC_REAL, &scalars[i]));
  }
  PetscCall(SaveXdmfIndex(viewer, comm_, "energy_output_entries", outputEntries_));
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::Load(PetscViewer viewer) {
  PetscReal scalars[6];

  PetscFunctionBeginUser;
  PetscCall(VecLoad(T_, viewer));
  PetscCall(VecLoad(F_, viewer));
  PetscCall(VecLoad(E_, viewer));
  PetscCall(VecLoad(Eold_, viewer));
  PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/energy", "energy_account", PETSC_REAL, nullptr, &scalars[0]));
  for (int i = 1; i < 6; ++i) {
    const std::string name = "energy_account_" + std::to_string(i);
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/energy", name.c_str(), PETSC_REAL, nullptr, &scalars[i]));
  }
  std::vector<std::pair<PetscInt, PetscReal>> saved;
  PetscCall(LoadXdmfIndex(viewer, comm_, "energy_output_entries", &saved));
  outputEntries_.clear();
  for (const auto &st : saved) outputEntries_.push_back(OutputEntry(st.first, st.second));
  steps_ = (PetscInt)scalars[0], dtOld_ = scalars[1], W_ = scalars[2], Wold_ = scalars[3], totalOld_ = scalars[4], totalOlder_ = scalars[5];
  if (interfaceAlpha_) {  // the interface's alpha as its own Load restored it (the vof module loads first)
    PetscCall(VecCopy(interfaceAlpha_(), alpha_));
    PetscCall(DMGlobalToLocal(dm_, alpha_, INSERT_VALUES, alphaLocal_));
  }
  PetscCall(VecCopy(E_, Ecur_));
  PetscFunctionReturn(0);
}

PetscErrorCode Energy::Destroy() {
  PetscFunctionBeginUser;
  for (Vec *v : {&T_, &E_, &Eold_, &H_, &C_, &Ecur_, &k_, &q_, &alpha_, &r_, &rhs_, &Tstar_, &fl_, &F_, &slope_, &TF_, &Tbase_, &Fbase_, &Xstart_, &TLocal_, &kLocal_, &alphaLocal_, &Tsg_, &Fsg_, &sLocal_, &rhoLocal_, &sGlobal_, &rhoGlobal_, &TsgLocal_, &FsgLocal_, &AsgLocal_, &uLocal_[0], &uLocal_[1], &uLocal_[2], &fluxLocal_[0], &fluxLocal_[1], &fluxLocal_[2], &epsCells_, &epsLocal_, &EpsSgLocal_}) PetscCall(VecDestroy(v));
  PetscCall(VecDestroy(&wideGlobal_));
  PetscCall(VecDestroy(&wideT_));
  PetscCall(VecDestroy(&wideF_));
  PetscCall(VecDestroy(&Tinflow_));
  PetscCall(VecDestroy(&Told_));
  PetscCall(VecDestroy(&Fold_));
  PetscCall(DMDestroy(&wide_));
  for (int slot = 0; slot < 2; ++slot) {
    PetscCall(MatDestroy(&A_[slot]));
    PetscCall(KSPDestroy(&ksp_[slot]));
  }
  if (column_ != MPI_COMM_NULL) PetscCallMPI(MPI_Comm_free(&column_));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
