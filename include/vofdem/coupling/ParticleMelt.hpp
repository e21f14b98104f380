// A melted particle joins the melt (docs/physics.md P12; -physics dem,flow,vof,energy): before each fluid step
// (Stage::Prepare, before the coupling's projection), every particle whose temperature has reached its material's
// liquidus (with the erf law: f_l >= 1 - 1e-3) leaves the swarm and its metal enters the cells:
//  - its volume m/rho_m (rho_m the interface's heavy phase) shared among the cells by the sphere's own overlap with
//    each (16^3 samples per cell on a lattice of the box, normalised so that the shares sum to the volume exactly;
//    not the kernel, whose tail would leave a metal mist), its enthalpy m h by the same shares;
//  - the fluid fraction gives back the particle's kernel volume at its place now, so the coming projection's change of
//    eps is the other particles' motion and this one's last step (as for any particle); the gas the metal now
//    occupies and the gas that the freed kernel volume holds differ cell by cell (they sum to zero): that gas, with its
//    enthalpy, is moved between those cells at once (physics.md P12's zero-sum divergence source is this step's
//    instant version);
//  - alpha = (eps_before alpha V + volume)/(eps_after V), its excess over 1 (a particle landing on a full pool) to
//    neighbours with room (Vof::BoundAt), the energy following each move;
//  - its momentum m v to the faces whose control volumes the sphere reaches, in proportion to the mass each gained:
//    each face's velocity becomes (M u + dp)/M' with M, M' the face masses (eps rho)_f V before and after
//    (grid/FaceProperties.hpp), a mass average of u and v, so the fluid's momentum grows by m v exactly and no face
//    overshoots (a share by overlap alone put momentum on light faces: 37 % more kinetic energy than the drop had);
//    its spin energy I w^2/2, which the melt cannot carry, is reported;
//  - it leaves the swarm through the DEM's deletion books (Dem::RemoveParticles).
// After each conversion the books are checked: metal volume, energy and momentum to 1e-12 (relative), else an error.
// The melt log (OpenLog: melted_particles.csv in the output folder, one row per melted particle, flushed at once; a
// restart appends, so a row may repeat there: the last row of an id counts) gives where and when each particle melted,
// its velocity, the metal it touched (the sphere's volume-weighted alpha before its own metal came: 0 in flight, > 0
// on or in the melt) and its energy account since it entered: the laser it absorbed, the heat it gave the fluid, the
// heat it took through its contacts, its sensible and latent heat m (h - h_0) split by f_l(T), and the account's
// closure |m (h - h_0) - absorbed + exchanged - conducted| / (m |h|).
#pragma once

#include "vofdem/coupling/Coupling.hpp"
#include "vofdem/energy/Energy.hpp"
#include "vofdem/vof/Vof.hpp"

#include <array>
#include <cstdio>
#include <string>
#include <vector>

namespace vofdem {

struct MeltSummary {
  PetscInt64 melted = 0;        // particles melted into the cells since the start
  PetscReal  mass = 0;          // kg melted since the start
  PetscReal  spin = 0;          // J of spin energy the melt could not carry, since the start
  PetscReal  volumeError = 0, energyError = 0, momentumError = 0;  // of the last conversion (relative)
};

class ParticleMelt {
public:
  PetscErrorCode SetUp(Coupling &coupling, Flow &flow, Vof &vof, Dem &dem, Energy &energy, const std::vector<ThermalMaterial> &particles);  // per DEM type
  // collective; the particles' enthalpy and temperature are the swarm's; T0 is their initial temperature (the account's
  // h_0), time the step's start (the log's)
  PetscErrorCode Melt(PetscReal time, const std::vector<PetscReal> &T0);
  PetscErrorCode OpenLog(const std::string &dir, bool restarting);  // collective
  const MeltSummary &Summary() const { return summary_; }
  MeltSummary       &State() { return summary_; }  // the counters a checkpoint carries
  PetscErrorCode     Destroy();

private:
  struct Melted {  // one particle's data, gathered on every rank
    PetscReal x[3], v[3], w[3], r, m, h, T, id, absorbed, exchanged, conducted, type;
  };
  PetscErrorCode WriteLog(const std::vector<Melted> &all, PetscReal time, const std::vector<PetscReal> &T0);
  bool           MeltsAt(PetscReal T, PetscInt type) const;
  PetscErrorCode FaceMasses(Vec M[3]);  // (eps rho)_f V of the owned faces (0 on walls)
  // The sphere's shares over the lattice of the box: into the owned cells (volume, enthalpy); the owned faces whose
  // control volumes it reaches into faces_ (ShareMomentum).
  PetscErrorCode Share(const std::vector<Melted> &all);
  PetscErrorCode ShareMomentum(const std::vector<Melted> &all);  // m v by the faces' gained mass (after the new alpha)

  Coupling  *coupling_ = nullptr;
  Flow      *flow_     = nullptr;
  Vof       *vof_      = nullptr;
  Dem       *dem_      = nullptr;
  Energy    *energy_   = nullptr;
  std::vector<ThermalMaterial> materials_;  // per DEM type
  PetscInt   samples_ = 16;  // per cell edge
  Vec        volume_ = nullptr, enthalpy_ = nullptr, kernel_ = nullptr, before_ = nullptr, gas_ = nullptr;  // the flow's cells
  Vec        massBefore_[3] = {nullptr, nullptr, nullptr}, massAfter_[3] = {nullptr, nullptr, nullptr}, momentum_[3] = {nullptr, nullptr, nullptr};
  Vec        cellLocal_ = nullptr, rhoLocal_ = nullptr;
  MeltSummary summary_;
  std::vector<PetscReal> around_;  // per melted particle: its volume-weighted alpha before the conversion
  FILE                  *log_ = nullptr;  // rank 0
  std::vector<std::vector<std::array<PetscInt, 4>>> faces_;  // per melted particle: (component, face i, j, k) it reaches, owned
};

}  // namespace vofdem
