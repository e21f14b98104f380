// ParticleHeat.hpp: the particles' enthalpy and its exchange with the fluid's energy (docs/physics.md P11, F9, F10, K1, K3).
#include "vofdem/coupling/ParticleHeat.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/coupling/HeatExchange.hpp"

#include <petscviewerhdf5.h>

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace {

// V_eff/H^3 = (int k dV)^2 / int k^2 dV of a kernel of width 1 (radial midpoint rule): the volume whose fluid
// answers a deposit, as the fluid the particle then reads sees it (a uniform field: the deposit's weights w_J are the
// kernel's, the average's weights too, and sum_J w_J^2 = V_cell/V_eff). 0 for the cell-based shapes.
PetscReal KernelVolume(const KernelAverager::Settings &k) {
  if (kernel::CellBased(k.shape) || k.shape == kernel::Shape::Linear) return 0;
  const double rc = kernel::Cutoff(k.shape, 1.0, k.truncation);
  const int    n  = 4000;
  double       i1 = 0, i2 = 0;
  for (int q = 0; q < n; ++q) {
    const double r = (q + 0.5) * rc / n, w = kernel::Weight(k.shape, r * r, 1.0, rc), dv = 4 * PETSC_PI * r * r * rc / n;
    i1 += w * dv, i2 += w * w * dv;
  }
  return i2 > 0 ? i1 * i1 / i2 : 0;
}

}  // namespace

PetscErrorCode ParticleHeat::SetFromOptions(MPI_Comm comm) {
  PetscFunctionBeginUser;
  comm_ = comm;
  PetscOptionsBegin(comm, "coupling_heat_", "Particle heat: the particles' enthalpy and its exchange with the fluid (docs/physics.md P11, F9, F10)", "Coupling");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.Real("-initial_temperature", "Initial temperature of the particles (and of particles added later)", "K", &T0_, RealRange::Positive()));
    PetscCall(opt.String("-material", "Material file of the particles' h(T) and emissivity (config/materials/NAME.yaml or a path); energy_metal: the energy's -energy_metal with its -energy_metal_* options", &materialName_));
    PetscCall(opt.Real("-emissivity", "Emissivity of the particles' surface (default: the material's)", "", &emissivity_, RealRange::Any()));
    if (emissivity_ != -1 && (emissivity_ < 0 || emissivity_ > 1)) VofdemInputError(comm, "option -coupling_heat_emissivity: %g is out of range [0, 1]", (double)emissivity_);
    PetscCall(opt.Real("-absorptivity", "Absorptivity of the laser at the particles' surface (default: the material's, else -laser_absorptivity)", "", &absorptivity_, RealRange::Any()));
    if (absorptivity_ != -1 && (absorptivity_ < 0 || absorptivity_ > 1)) VofdemInputError(comm, "option -coupling_heat_absorptivity: %g is out of range [0, 1]", (double)absorptivity_);
    PetscCall(opt.Int("-beam_rays", "Rays of the laser per cell edge for the particles' share (0: a ray at most a sixteenth of the smallest particle radius and of the beam radius; at most ~4e6 rays)", &raysPerCell_, 0));
    PetscCall(opt.Bool("-melt", "Particles that reach their liquidus join the melt (docs/physics.md P12: their volume, momentum and enthalpy into the cells, out of the swarm)", &melting_));
    PetscCall(opt.Bool("-contact_conduction", "Heat through the contacts of touching particles, 4 k_i k_j/(k_i + k_j) sqrt(pi a^2) (T_j - T_i) with the contact radius a (P11; ContactConduction.hpp)", &conduction_));
    PetscCall(opt.Bool("-exclude_held", "The particles' volume and forces go only to cells (and faces) that the energy does not hold at rest as solid metal, so that particles may rest on a solid substrate (KernelAverager::SetExcludedCells); their heat goes to the solid too", &excludeHeld_));
    PetscCall(opt.Bool("-radiation", "Radiation between each particle and the fluid temperature it reads, e sigma (Tbar^4 - T^4) (P11)", &radiation_));
    std::vector<std::string> deposit = {capacityDeposit_ ? "capacity" : "volume"};
    PetscCall(opt.NameList("-deposit", "How a particle's heat is shared among the cells of its kernel: capacity (the kernel weight times the cell's heat capacity: the cells change their temperature alike) or volume (the kernel weight alone, K3)",
                           {"capacity", "volume"}, &deposit));
    if (deposit.size() != 1) VofdemInputError(comm, "option -coupling_heat_deposit: give capacity or volume");
    capacityDeposit_ = deposit[0] == "capacity";
    PetscCall(opt.Bool("-gas_response", "Each particle's step relaxes it together with the fluid it reads (the mixture's capacity over the kernel's volume), so that neither passes their common temperature (HeatExchange.hpp); off: against a fixed Tbar", &gasResponse_));
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleHeat::SetUp(Coupling &coupling, Flow &flow, Vof &vof, Dem &dem, Energy &energy) {
  PetscFunctionBeginUser;
  coupling_ = &coupling, flow_ = &flow, dem_ = &dem, energy_ = &energy;
  PetscCheck(dem.Particles().HasHeatFields(), comm_, PETSC_ERR_ORDER, "particle heat: the swarm was created without the heat fields (Dem::UseHeatFields before Dem::SetUp)");
  // Latent heat needs the backward Euler of the moving energy (Energy::Step): there the cells gain exactly dt times the source.
  PetscCheck(energy.Moving(), comm_, PETSC_ERR_ORDER, "particle heat: the energy must move with the interface (-physics dem,flow,vof,energy)");
  if (materialName_ == "energy_metal") material_ = energy.Metal();
  else PetscCall(ReadParticleMaterial(comm_, "-coupling_heat_material", materialName_, &material_));  // checked per type below
  material_.referenceTemperature = energy.Metal().referenceTemperature;  // one zero of enthalpy for the whole account
  if (emissivity_ >= 0) material_.emissivity = emissivity_;
  if (!radiation_) material_.emissivity = 0;
  initial_.assign(std::max((size_t)1, types_.size()), T0_);
  for (size_t t = 0; t < types_.size(); ++t)
    if (types_[t].initialTemperature > 0) initial_[t] = types_[t].initialTemperature;
  PetscCall(BuildParticleMaterials(comm_, material_, types_, melting_, conduction_, radiation_ ? emissivity_ : 0, &materials_));
  kernelVolume_ = KernelVolume(coupling.KernelSettings());
  const StaggeredGrid &sg = flow.Staggered();
  PetscCall(DMCreateGlobalVector(sg.Cells(), &T_));
  PetscCall(VecDuplicate(T_, &source_));
  PetscCall(VecDuplicate(T_, &capacity_));
  PetscCall(VecDuplicate(T_, &solid_));
  PetscCall(VecDuplicate(T_, &held_));
  PetscCall(VecDuplicate(T_, &heldBefore_));
  PetscCall(VecSet(held_, 0));
  PetscCall(DMCreateGlobalVector(sg.Base().CellDM(), &capacityCells_));
  PetscCall(VecSet(source_, 0));
  PetscCall(DMCreateGlobalVector(sg.Base().CellDM(), &sourceEnergy_));
  PetscCall(VecSet(sourceEnergy_, 0));
  PetscCall(PetscLogEventRegister("CouplingHeat", DM_CLASSID, &ev_));
  PetscCall(PetscLogEventRegister("CouplingBeam", DM_CLASSID, &evBeam_));
  PetscCall(PetscLogEventRegister("CouplingMelt", DM_CLASSID, &evMelt_));
  PetscCall(PetscLogEventRegister("CouplingContact", DM_CLASSID, &evContact_));
  // The particles there now take the initial temperature (a restart then loads theirs).
  ParticleArrays a;
  PetscCall(dem.Particles().GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p) a.temperature[p] = 0;
  PetscCall(StartNew(a));
  PetscCall(dem.Particles().RestoreArrays(&a));
  beamOn_ = energy.Beam().On();
  if (beamOn_) {  // P11: the particles take their share of the beam before the melt sees it
    const PetscReal eta = absorptivity_ >= 0 ? absorptivity_ : material_.absorptivity >= 0 ? material_.absorptivity : energy.Beam().Absorptivity();
    beam_.SetUp(sg.Base(), energy.Beam(), eta, raysPerCell_);
    energy.SetBeamTaken([this]() { return &taken_; });
  }
  if (melting_) PetscCall(melt_.SetUp(coupling, flow, vof, dem, energy, materials_));
  energy.SetParticleHeat(sourceEnergy_, [this](PetscReal *now, PetscReal *brought) { return Held(now, brought); });
  // The cells' energy counts the fluid's share eps of their volume, moved with d(eps)/dt as alpha is (F7 with eps).
  PetscCall(energy.SetFluidFraction(flow.FluidFraction(), coupling.FluidFractionChange()));
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleHeat::Melt(PetscReal time) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evMelt_, 0, 0, 0, 0));
  if (melting_) PetscCall(melt_.Melt(time, initial_));  // with the mask of the last deposits (it gives back their kernel volume)
  PetscCall(PetscLogEventEnd(evMelt_, 0, 0, 0, 0));
  PetscCall(ExcludeHeld());
  PetscFunctionReturn(0);
}

// The cells of solid metal held at rest now (Energy::HeldMask) take no share of the particles' volume and forces
// from this step's deposits on (KernelAverager::SetExcludedCells).
PetscErrorCode ParticleHeat::ExcludeHeld() {
  PetscFunctionBeginUser;
  if (!excludeHeld_) PetscFunctionReturn(0);
  if (!coupling_->Averager().CanExclude()) {  // the smoothers deposit everywhere: the check below watches the solid metal as without
    excludeHeld_ = PETSC_FALSE;
    PetscFunctionReturn(0);
  }
  PetscCall(VecCopy(held_, heldBefore_));
  PetscCall(energy_->HeldMask(held_));
  PetscBool same = PETSC_FALSE;
  if (maskSet_) PetscCall(VecEqual(held_, heldBefore_, &same));  // most steps: the averager's masks stand
  if (!same) PetscCall(coupling_->Averager().SetExcludedCells(held_, &excludedCells_));
  maskSet_ = true;
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleHeat::StartNew(ParticleArrays &a) {
  PetscReal mine = 0, all = 0;

  PetscFunctionBeginUser;
  for (PetscInt p = 0; p < a.n; ++p)
    if (a.temperature[p] == 0) {
      const PetscReal T0 = initial_[a.type[p]], h0 = materials_[a.type[p]].Enthalpy(T0);
      a.temperature[p] = T0, a.enthalpy[p] = h0;
      mine += a.mass[p] * h0;
    }
  PetscCallMPI(MPI_Allreduce(&mine, &all, 1, MPIU_REAL, MPIU_SUM, comm_));
  brought_ += all;
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleHeat::Exchange(PetscReal time, PetscReal dt) {
  ParticleArrays a;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(ev_, 0, 0, 0, 0));
  const ParticleSwarm &sw = dem_->Particles();
  PetscCall(sw.GetArrays(&a));
  PetscCall(StartNew(a));
  const PetscInt n = a.n;
  if (conduction_) {  // P11's contact term first, a split step (exact in energy: what one particle gains its partner loses)
    PetscCall(PetscLogEventBegin(evContact_, 0, 0, 0, 0));
    PetscCall(contacts_.Step(comm_, *dem_, materials_, a, dt, a.heatConducted));
    PetscCall(PetscLogEventEnd(evContact_, 0, 0, 0, 0));
    conductedPower_ = contacts_.Last().power, conductingPairs_ = contacts_.Last().contacts;
  }
  beamPower_.assign(n, 0);
  if (beamOn_) {  // the beam at the step's end, as the energy's deposit takes it (Energy::LaserSource)
    PetscCall(PetscLogEventBegin(evBeam_, 0, 0, 0, 0));
    PetscCall(beam_.Trace(time + dt, n, a.x, a.radius, beamPower_.data(), &taken_));
    PetscCall(PetscLogEventEnd(evBeam_, 0, 0, 0, 0));
    brought_ += beam_.Absorbed() * dt;  // the account's input
  }
  H_.resize(n), Tbar_.resize(n), rho_.resize(n), eps_.resize(n), power_.resize(n), Cbar_.resize(n);
  for (PetscInt p = 0; p < n; ++p) H_[p] = coupling_->KernelWidth(2 * a.radius[p]);
  // K1: the fluid at each particle; T and rho eps-weighted, eps plain (as the drag reads it, CouplingStep.cpp).
  PetscCall(VecCopy(energy_->Temperature(), T_));  // the energy's cells, the same layout on the staggered grid's cells
  PetscCall(energy_->HeatCapacity(capacityCells_));  // and the cells' capacity per cell volume, plain (the deposit's share)
  PetscCall(VecCopy(capacityCells_, capacity_));
  PetscCall(energy_->SolidFraction(capacityCells_));  // and the solid metal the particles sit in (the check below)
  PetscCall(VecCopy(capacityCells_, solid_));
  solidBar_.resize(n);
  {
    const Vec  fields[5]  = {T_, flow_->Density(), flow_->FluidFraction(), capacity_, excludeHeld_ ? held_ : solid_};
    const Vec  weights[5] = {flow_->FluidFraction(), flow_->FluidFraction(), nullptr, nullptr, nullptr};
    const bool walls[5]   = {true, true, true, true, true};
    PetscReal *outs[5]    = {Tbar_.data(), rho_.data(), eps_.data(), Cbar_.data(), solidBar_.data()};
    PetscCall(coupling_->Averager().Average(3, 5, fields, weights, walls, n, a.x, H_.data(), outs, 1));
  }
  {  // Particles whose motion changes eps in solid metal: the flow holds those cells at rest and cannot make room there
     // (in checkpoint/bitwise_coupled_heat's scene run on, the divergence left grew from 1e-10 to 20 1/s and the metal
     // reached 2e4 K): once eps changes by more than 1e-6 in a step in a cell of solid metal (the volume book then
     // drifts by about that much of a cell per step), stop, naming the particle whose kernel reads the most solid
     // metal, not run on to nonsense. The kernel's tail (1.5 widths) reaches solid metal a few diameters away.
     // With -coupling_heat_exclude_held (the default) the deposits leave the held cells out, and what is checked is
     // the cells held at this step's and the last step's deposits, where eps can fall only for a particle whose
     // whole support is held (inside the solid); a cell that froze under a particle's kernel returns to eps = 1 once
     // (over a few steps when the step shrinks: Coupling::Project moves eps by dt/dt_last of the way), which is not
     // counted.
    PetscReal          change = 0;
    const PetscScalar *dc, *sc, *hb = nullptr;
    PetscInt           m;
    if (Vec dEps = coupling_->FluidFractionChange()) {
      PetscCall(VecGetLocalSize(dEps, &m));
      PetscCall(VecGetArrayRead(dEps, &dc));
      PetscCall(VecGetArrayRead(excludeHeld_ ? held_ : solid_, &sc));
      if (excludeHeld_) PetscCall(VecGetArrayRead(heldBefore_, &hb));
      for (PetscInt c = 0; c < m; ++c)
        if (PetscRealPart(sc[c]) > 0.5 && (!hb || PetscRealPart(hb[c]) > 0.5)) change = std::max(change, (PetscReal)(hb ? -PetscRealPart(dc[c]) : std::fabs(PetscRealPart(dc[c]))));
      if (hb) PetscCall(VecRestoreArrayRead(heldBefore_, &hb));
      PetscCall(VecRestoreArrayRead(excludeHeld_ ? held_ : solid_, &sc));
      PetscCall(VecRestoreArrayRead(dEps, &dc));
    }
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &change, 1, MPIU_REAL, MPIU_MAX, comm_));
    // Excluding held cells, a particle whose kernel lies for more than three quarters in them has passed into the solid
    // (its centre is in it; one resting on a solid surface, or in a corner of the solid, reads up to about a half).
    PetscReal inside = 0;
    if (excludeHeld_)
      for (PetscInt p = 0; p < n; ++p) inside = std::max(inside, solidBar_[p]);
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &inside, 1, MPIU_REAL, MPIU_MAX, comm_));
    if (change > 1e-6 || inside > 0.75) {  // the particle whose kernel reads the most solid metal
      struct {
        double s;
        int    rank;
      } mine = {-1, 0}, worst;
      PetscMPIInt rank;
      PetscCallMPI(MPI_Comm_rank(comm_, &rank));
      PetscInt where = -1;
      for (PetscInt p = 0; p < n; ++p)
        if (solidBar_[p] > mine.s) mine.s = solidBar_[p], where = p;
      mine.rank = rank;
      PetscCallMPI(MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm_));
      PetscReal at[4] = {0, 0, 0, 0};
      if (rank == worst.rank) at[0] = a.x[3 * where], at[1] = a.x[3 * where + 1], at[2] = a.x[3 * where + 2], at[3] = (PetscReal)a.id[where];
      PetscCallMPI(MPI_Bcast(at, 4, MPIU_REAL, worst.rank, comm_));
      if (change > 1e-6)
        VofdemInputError(comm_, "coupling: particle %lld at (%g, %g, %g) m moves its volume into solid metal (eps changes there by %.1e in a step; %.1e of the fluid its kernel reads is solid), which the flow holds at rest and particles do not collide with; give the solid's surface as a DEM wall (-dem_walls) so that particles stop above it, or keep them away from it",
                         (long long)at[3], (double)at[0], (double)at[1], (double)at[2], (double)change, (double)worst.s);
      VofdemInputError(comm_, "coupling: particle %lld at (%g, %g, %g) m has passed into solid metal (%.2f of its kernel lies in cells held at rest), which particles do not collide with; give the solid's surface as a DEM wall (-dem_walls) so that particles stop above it, or keep them away from it",
                       (long long)at[3], (double)at[0], (double)at[1], (double)at[2], (double)worst.s);
    }
  }
  const ThermalMaterial &metal = energy_->Metal(), &gas = energy_->Gas();
  const PetscReal       *h = flow_->Staggered().Base().Spacing();
  const PetscReal        Vc = h[0] * h[1] * h[2], drho = metal.density - gas.density;
  PetscReal              sums[2] = {0, 0}, nuMax = 0;  // heat to the fluid (W): particle side; deposited
  for (PetscInt p = 0; p < n; ++p) {
    const PetscReal d = 2 * a.radius[p], Tb = Tbar_[p], rho = rho_[p], eps = eps_[p];
    // The mixture the particle reads (docs/physics.md F): the metal share from the averaged density.
    const PetscReal al = drho != 0 ? std::min((PetscReal)1, std::max((PetscReal)0, (rho - gas.density) / drho)) : 0;
    const PetscReal kf = al * metal.k.At(Tb) + (1 - al) * gas.k.At(Tb);
    const PetscReal cv = al * metal.density * metal.cp.At(Tb) + (1 - al) * gas.density * gas.cp.At(Tb);  // J/(m^3 K)
    PetscReal       slip2 = 0;
    for (int c = 0; c < 3; ++c) slip2 += (a.fluidVelocity[3 * p + c] - a.v[3 * p + c]) * (a.fluidVelocity[3 * p + c] - a.v[3 * p + c]);
    const PetscReal mu = a.fluidViscosity[p];
    const PetscReal Re = eps * rho * d * std::sqrt(slip2) / mu, Pr = mu * (cv / rho) / kf;
    const PetscReal Nu = heat::Nusselt(eps, Re, Pr);  // docs/physics.md (F10)
    nuMax = std::max(nuMax, Nu);
    // The fluid that answers the deposit: the kernel's mean capacity per cell volume (eps and the latent share in it)
    // over its effective volume; by volume, the mixture's capacity there.
    const PetscReal Cg = gasResponse_ ? (capacityDeposit_ ? Cbar_[p] : cv) * std::max(kernelVolume_ * H_[p] * H_[p] * H_[p], Vc) : 0;
    // docs/physics.md (P11): the particle's step; (F9): what it loses the fluid gains.
    if (beamPower_[p] > 0) {  // the beam's share first (a split step: exact in energy)
      a.enthalpy[p] += beamPower_[p] * dt / a.mass[p];
      a.heatAbsorbed[p] += beamPower_[p] * dt;
      a.temperature[p] = heat::TemperatureOf(materials_[a.type[p]], a.enthalpy[p], a.temperature[p]);
    }
    const ThermalMaterial &mp = materials_[a.type[p]];
    const heat::StepResult r  = heat::Step(mp, a.mass[p], PETSC_PI * d * d, Nu * kf / d, mp.emissivity, Tb, Cg, a.enthalpy[p], a.temperature[p], dt);
    a.enthalpy[p] = r.h, a.temperature[p] = r.T;
    power_[p] = dt > 0 ? -r.heat / dt : 0;
    a.heatExchanged[p] -= r.heat;
    sums[0] += power_[p];
  }
  // K3: the same kernel, normalised over the cells that take part: the cells' total is the particles' to round-off.
  PetscCall(VecSet(source_, 0));
  if (capacityDeposit_) {  // cell J takes Q w_J C_J / sum_K w_K C_K: the kernel's share of Q/Cbar, times C_J
    for (PetscInt p = 0; p < n; ++p) power_[p] /= Cbar_[p];
    PetscCall(coupling_->Averager().Deposit(3, n, a.x, H_.data(), power_.data(), 1, source_, false, true));  // solid metal takes heat too
    PetscCall(VecPointwiseMult(source_, source_, capacity_));
  } else PetscCall(coupling_->Averager().Deposit(3, n, a.x, H_.data(), power_.data(), 1, source_, false, true));
  PetscCall(sw.RestoreArrays(&a));
  PetscCall(VecSum(source_, &sums[1]));
  PetscCall(VecScale(source_, 1 / Vc));  // W/m^3
  PetscCall(VecCopy(source_, sourceEnergy_));
  {
    const PetscReal mine = sums[0];
    PetscCallMPI(MPI_Allreduce(&mine, &sums[0], 1, MPIU_REAL, MPIU_SUM, comm_));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &nuMax, 1, MPIU_REAL, MPIU_MAX, comm_));
  toFluid_ = sums[0], deposited_ = sums[1], nusseltMax_ = nuMax;
  exchanged_ += toFluid_ * dt;
  PetscCall(PetscLogEventEnd(ev_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleHeat::Held(PetscReal *now, PetscReal *brought) const {
  ParticleArrays a;
  PetscReal      mine = 0;

  PetscFunctionBeginUser;
  PetscCall(dem_->Particles().GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p) mine += a.mass[p] * a.enthalpy[p];
  PetscCall(dem_->Particles().RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(&mine, now, 1, MPIU_REAL, MPIU_SUM, comm_));
  *brought = brought_;
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleHeat::Summarize(ParticleHeatSummary *s) const {
  ParticleArrays a;
  PetscReal      range[2] = {-PETSC_MAX_REAL, -PETSC_MAX_REAL};  // max T, -min T

  PetscFunctionBeginUser;
  PetscCall(Held(&s->enthalpy, &s->brought));
  PetscCall(dem_->Particles().GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p)  // a particle added in this step's sub-steps (0 K) takes its temperature at the next exchange
    if (a.temperature[p] > 0) range[0] = std::max(range[0], a.temperature[p]), range[1] = std::max(range[1], -a.temperature[p]);
  PetscCall(dem_->Particles().RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, range, 2, MPIU_REAL, MPIU_MAX, comm_));
  const bool any = range[0] > -PETSC_MAX_REAL;
  s->Tmax = any ? range[0] : 0, s->Tmin = any ? -range[1] : 0;
  s->toFluid = toFluid_, s->deposited = deposited_, s->exchanged = exchanged_, s->nusseltMax = nusseltMax_;
  s->beamAbsorbed = beamOn_ ? beam_.Absorbed() : 0, s->beamIntercepted = beamOn_ ? beam_.Intercepted() : 0;
  s->conducted = conductedPower_, s->contacts = conductingPairs_;
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleHeat::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "particle heat (P11, F9, F10): material %s (cp %g J/(kg K) at %g K, latent heat %g J/kg, solidus %g K, liquidus %g K), emissivity %g, "
                                           "initial %g K; Nusselt of F10; kernel volume %.4g H^3%s; deposit by %s\n",
                                   material_.path.empty() ? material_.name.c_str() : material_.path.c_str(), (double)material_.cp.At(T0_), (double)T0_, (double)material_.latentHeat,
                                   (double)material_.solidus, (double)material_.liquidus, (double)material_.emissivity, (double)T0_, (double)kernelVolume_,
                                   gasResponse_ ? " (the fluid's response in each step)" : " (fixed fluid temperature over a step)", capacityDeposit_ ? "kernel weight x heat capacity" : "kernel weight (volume)"));
  for (size_t t = 0; t < types_.size(); ++t)
    if (!types_[t].material.empty() || types_[t].specificHeat > 0 || types_[t].initialTemperature > 0) {
      const ThermalMaterial &m = materials_[t];
      PetscCall(PetscViewerASCIIPrintf(viewer, "particle heat: type %s: material %s, cp %g J/(kg K) at %g K, latent heat %g J/kg, solidus %g K, liquidus %g K, initial %g K\n", types_[t].name.c_str(),
                                       m.path.empty() ? m.name.c_str() : m.path.c_str(), (double)m.cp.At(initial_[t]), (double)initial_[t], (double)m.latentHeat, (double)m.solidus, (double)m.liquidus,
                                       (double)initial_[t]));
    }
  PetscCall(PetscViewerASCIIPrintf(viewer, "particle heat: contact conduction %s\n", conduction_ ? "through the Hertz (or JKR) contact radius (P11)" : "off"));
  if (beamOn_)
    PetscCall(PetscViewerASCIIPrintf(viewer, "particle heat: the beam's share first (P11; rays within 3 R_l, %s per cell edge, the highest disc takes each; absorptivity %g)\n",
                                     raysPerCell_ > 0 ? std::to_string((long long)raysPerCell_).c_str() : "automatic", (double)beam_.Absorptivity()));
  PetscFunctionReturn(0);
}

// The particles' enthalpy and temperature travel in the swarm (DemSaveLoad.cpp); here the account's sums.
PetscErrorCode ParticleHeat::Save(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  const MeltSummary &m = melt_.Summary();
  const PetscReal state[8] = {brought_, exchanged_, toFluid_, deposited_, nusseltMax_, (PetscReal)m.melted, m.mass, m.spin};
  const char     *names[8] = {"particle_heat_brought", "particle_heat_exchanged", "particle_heat_to_fluid", "particle_heat_deposited", "particle_heat_nusselt_max", "particle_melted", "particle_melted_mass", "particle_melt_spin"};
  for (int k = 0; k < 8; ++k) PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", names[k], PETSC_REAL, &state[k]));
  const PetscReal conduction[2] = {conductedPower_, (PetscReal)conductingPairs_};  // the monitor's last values
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "particle_heat_conducted_W", PETSC_REAL, &conduction[0]));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer, "/", "particle_heat_conducting_pairs", PETSC_REAL, &conduction[1]));
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleHeat::Load(PetscViewer viewer) {
  PetscFunctionBeginUser;
  MeltSummary &m = melt_.State();
  PetscReal    melted = 0;
  PetscReal   *state[8] = {&brought_, &exchanged_, &toFluid_, &deposited_, &nusseltMax_, &melted, &m.mass, &m.spin};
  const char  *names[8] = {"particle_heat_brought", "particle_heat_exchanged", "particle_heat_to_fluid", "particle_heat_deposited", "particle_heat_nusselt_max", "particle_melted", "particle_melted_mass", "particle_melt_spin"};
  for (int k = 0; k < 8; ++k) PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", names[k], PETSC_REAL, nullptr, state[k]));
  m.melted = (PetscInt64)melted;
  PetscBool has;  // checkpoints from before contact conduction (2026-12-08) lack these
  PetscCall(PetscViewerHDF5HasAttribute(viewer, "/", "particle_heat_conducted_W", &has));
  if (has) {
    PetscReal pairs = 0;
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "particle_heat_conducted_W", PETSC_REAL, nullptr, &conductedPower_));
    PetscCall(PetscViewerHDF5ReadAttribute(viewer, "/", "particle_heat_conducting_pairs", PETSC_REAL, nullptr, &pairs));
    conductingPairs_ = (PetscInt)pairs;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleHeat::Destroy() {
  PetscFunctionBeginUser;
  if (energy_) energy_->SetParticleHeat(nullptr, nullptr);
  PetscCall(melt_.Destroy());
  for (Vec *v : {&T_, &source_, &sourceEnergy_, &capacity_, &capacityCells_, &solid_, &held_, &heldBefore_}) PetscCall(VecDestroy(v));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
