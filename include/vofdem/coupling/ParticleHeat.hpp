// The particles' heat and its exchange with the fluid's energy equation (-physics dem,flow,vof,energy; options
// -coupling_heat_*): docs/physics.md P11 (the particle's energy), F9 (the fluid's source), F10 (the Nusselt law),
// K1 and K3 (the kernel). Each fluid step, at its start (Stage::Exchange), for every particle:
//  1. the fluid it reads (K1, the coupling's kernel): the temperature Tbar and density (eps-weighted), the fluid
//     fraction (plain), the slip and viscosity the drag read (Coupling.hpp); the metal share of the mixture from the
//     density, and from it the mixture's conductivity k_f, its capacity and Pr;
//  2. h_c = Nu k_f/d with F10's Nu, radiation with the particle's emissivity against Tbar, and one exchange step of
//     P11 over the fluid step (HeatExchange.hpp: exponential relaxation of the particle and the fluid it reads,
//     stable for any step);
//  3. the heat the particle gave, Q/dt (W), shared among the cells by the same kernel (K3), whose weights sum to
//     one: the fluid's source of F9, which the energy module adds to the step's balance (Energy::SetParticleHeat).
//     With -coupling_heat_deposit capacity (the default) each cell's kernel weight is multiplied by its heat capacity
//     (Energy::HeatCapacity), so every cell of the support changes its temperature alike; by volume alone (volume)
//     a gas cell beside water or melt takes a share out of all proportion to what it can hold: a sphere at 300 K
//     entering water at 350 K under air at 300 K cooled the air to 283 K.
//     The fluid's response (-coupling_heat_gas_response) is the mean capacity over the kernel's volume.
// The particles' enthalpy lives in the swarm (ParticleSwarm.hpp field::enthalpy, field::temperature); their total
// joins the energy module's account (energy_total_J, energy_accounted_J).
// With a laser (P11's eta P_beam): before step 2 each particle takes its share of the beam at the step's end time,
// the highest first (ParticleBeam.hpp), absorbing -coupling_heat_absorptivity of it, added to its enthalpy (the
// exchange then relaxes it: a split step); the columns lose what the particles took before the melt sees them
// (Energy::SetBeamTaken), and the account counts what the particles absorbed as input (brought).
// Touching particles exchange heat through their contacts first (ContactConduction.hpp, P11's contact term;
// -coupling_heat_contact_conduction), each particle's share on its own account (heat_conducted). Particles at their
// liquidus join the melt before the next step (ParticleMelt.hpp, P12).
#pragma once

#include "vofdem/coupling/ContactConduction.hpp"
#include "vofdem/coupling/Coupling.hpp"
#include "vofdem/coupling/ParticleBeam.hpp"
#include "vofdem/coupling/ParticleMaterials.hpp"
#include "vofdem/coupling/ParticleMelt.hpp"
#include "vofdem/energy/Energy.hpp"

#include <vector>

namespace vofdem {

struct ParticleHeatSummary {
  PetscReal enthalpy  = 0;  // J: sum m h of all particles now (from the energy module's reference temperature)
  PetscReal toFluid   = 0;  // W: what the particles gave the fluid in the last step, sum over particles of -Q/dt
  PetscReal deposited = 0;  // W: what the cells received of it (the kernel's deposit, summed over the cells)
  PetscReal exchanged = 0;  // J: the particles' heat to the fluid since the start (particle side)
  PetscReal brought   = 0;  // J: the particles' enthalpy at the start plus that of particles added since
  PetscReal Tmax = 0, Tmin = 0;  // K, over all particles (0 without particles)
  PetscReal nusseltMax = 0;      // of the last step
  PetscReal beamAbsorbed = 0, beamIntercepted = 0;  // W of the laser the particles absorbed, and took from the beam, last step
  PetscReal conducted = 0;  // W through the particles' contacts in the last step (sum over pairs of |Q|/dt)
  PetscInt  contacts  = 0;  // the touching pairs that conducted it
};

class ParticleHeat {
public:
  PetscErrorCode SetFromOptions(MPI_Comm comm);
  PetscErrorCode SetTypeOptions(const std::vector<std::string> &typeNames) { return ReadParticleTypeHeat(comm_, typeNames, &types_); }  // the DEM's types
  // After the coupling's and the energy's set-up: the particles take -coupling_heat_initial_temperature.
  PetscErrorCode SetUp(Coupling &coupling, Flow &flow, Vof &vof, Dem &dem, Energy &energy);
  PetscErrorCode Melt(PetscReal time);  // before a step: the particles at their liquidus into the melt (ParticleMelt.hpp; -coupling_heat_melt)
  // The melt log (melted_particles.csv, ParticleMelt.hpp) in the run's output folder; a restart appends to it.
  PetscErrorCode SetOutputDir(const std::string &dir, bool restarting) { return melting_ ? melt_.OpenLog(dir, restarting) : 0; }
  const MeltSummary &MeltBooks() const { return melt_.Summary(); }
  PetscErrorCode Exchange(PetscReal time, PetscReal dt);  // the step from time to time + dt: particles' enthalpy, the cells' source
  PetscErrorCode Summarize(ParticleHeatSummary *s) const;  // collective
  PetscErrorCode Held(PetscReal *now, PetscReal *brought) const;  // collective: sum m h now, and what particles brought
  PetscErrorCode View(PetscViewer viewer) const;
  PetscErrorCode Save(PetscViewer viewer) const;
  PetscErrorCode Load(PetscViewer viewer);
  PetscErrorCode Destroy();
  const ThermalMaterial &Material() const { return material_; }  // the common one; per type: Materials()
  const std::vector<ThermalMaterial> &Materials() const { return materials_; }

private:
  PetscErrorCode StartNew(ParticleArrays &a);
  PetscErrorCode ExcludeHeld();  // the held cells (Energy::HeldMask) out of the coming deposits  // particles at 0 K (new): the initial temperature; brought_ grows

  Coupling *coupling_ = nullptr;
  Flow     *flow_ = nullptr;
  Dem      *dem_ = nullptr;
  Energy   *energy_ = nullptr;
  MPI_Comm  comm_ = MPI_COMM_NULL;

  // options
  PetscReal       T0_ = 300;  // K
  std::string     materialName_ = "energy_metal";  // the energy module's metal (-energy_metal and its options), or a file
  ThermalMaterial material_;                 // the common material (-coupling_heat_material)
  std::vector<ParticleTypeHeat> types_;      // -coupling_heat_type_<name>_*
  std::vector<ThermalMaterial>  materials_;  // per DEM type
  std::vector<PetscReal>        initial_;    // K, the initial temperature per DEM type
  PetscReal       emissivity_ = -1;  // < 0: the material's
  PetscReal       absorptivity_ = -1;  // of the laser at the particles' surface (< 0: the material's, else the laser's)
  PetscInt        raysPerCell_ = 0;  // -coupling_heat_beam_rays (0: automatic)
  PetscBool       radiation_ = PETSC_TRUE, gasResponse_ = PETSC_TRUE;
  PetscBool       conduction_ = PETSC_TRUE;  // -coupling_heat_contact_conduction
  PetscBool       excludeHeld_ = PETSC_TRUE;  // -coupling_heat_exclude_held
  PetscInt        excludedCells_ = 0;
  bool            maskSet_ = false;  // the averager holds held_ as its excluded cells
  ContactConduction contacts_;
  bool            capacityDeposit_ = true;  // -coupling_heat_deposit capacity|volume
  PetscReal       kernelVolume_ = 0;  // V_eff / H^3 of the kernel (0: cell-based, the cell's volume)

  // fields and scratch
  Vec                    T_ = nullptr, source_ = nullptr, sourceEnergy_ = nullptr;  // Tbar's field and the deposit (cells), the energy's copy
  Vec                    capacity_ = nullptr, capacityCells_ = nullptr, solid_ = nullptr;
  Vec                    held_ = nullptr, heldBefore_ = nullptr;  // the cells held at rest at this step's and the last step's deposits  // the cells' heat capacity (sg's cells; the energy's), solid metal
  std::vector<PetscReal> H_, Tbar_, rho_, eps_, power_, Cbar_, solidBar_, beamPower_, taken_;
  ParticleBeam           beam_;
  ParticleMelt           melt_;
  PetscBool              melting_ = PETSC_TRUE;  // -coupling_heat_melt
  bool                   beamOn_ = false;

  // state (saved): global sums, equal on every rank
  PetscReal brought_ = 0, exchanged_ = 0, toFluid_ = 0, deposited_ = 0, nusseltMax_ = 0, conductedPower_ = 0;
  PetscInt  conductingPairs_ = 0;
  PetscLogEvent ev_ = 0, evBeam_ = 0, evMelt_ = 0, evContact_ = 0;  // -log_view: the exchange, and in it the beam and the contacts; the melt
};

}  // namespace vofdem
