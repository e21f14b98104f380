// Darcy seepage through a packing (docs/physics.md (F11), docs/modules/darcy.md; seed 004 section 3.1, eq. 20):
// for slow flow the pore water's excess (piezometric) pressure p = rho_w g H, H the head above the outlet's,
// solves the steady head equation
//     div((k(eps)/mu) grad p) = s,      q = -(k/mu) grad p   (the Darcy, i.e. superficial, velocity),
// s a source (1/s) a caller may pass to Solve (no module does yet: docs/modules/darcy.md, limits), with k from the cell's
// fluid fraction eps through a law of Permeability.hpp. Finite volumes on the grid's cell DMDA: the face
// coefficient is the harmonic mean of its two cells' k/mu (the flux is continuous through a change of
// packing, and a layered column is exact), fixed head on the two box faces normal to -darcy_axis
// (half a cell from the boundary cell's centre), no flux through the other faces. The head difference
// H_inlet - H_outlet (inlet: the lower face) may start late (-darcy_head_start) and rise in steps (-darcy_head_ramp). CG + hypre BoomerAMG
// with its own prefix, -darcy_ksp_*, -darcy_pc_* (as the flow's pressure solve). Ergun's law depends on
// |q|: Picard iterations, k from the last iterate's speed, until k changes less than -darcy_picard_rtol.
#pragma once

#include "vofdem/darcy/Permeability.hpp"
#include "vofdem/grid/Grid.hpp"

#include <petscksp.h>
#include <petscviewer.h>

#include <vector>

namespace vofdem {

struct DarcySummary {
  PetscReal headDifference = 0;  // m, H_inlet - H_outlet now
  PetscReal gradient       = 0;  // the mean hydraulic gradient (H_inlet - H_outlet)/L, -
  PetscReal inflow = 0, outflow = 0;  // m^3/s, into the box through the inlet, out of it through the outlet
  PetscReal permeability = 0;    // m^2, the column's effective k = mu L Q_out/(A dp) (0 without a difference)
  PetscReal minEps = 1, maxEps = 1;
  PetscInt  iterations = 0, picard = 0;  // KSP iterations of the last solve, Picard iterations of the last step
  PetscReal residual = 0;
};

class Darcy {
public:
  // gravity: the run's (m/s^2); its magnitude turns heads into pressures (9.81 when the run has none).
  PetscErrorCode SetFromOptions(const Grid &grid, const PetscReal gravity[3]);
  // The particles give eps (a coupling, after SetFromOptions, before SetUp): -darcy_fluid_fraction must not be given.
  PetscErrorCode TakeFluidFractionFromParticles();
  PetscErrorCode SetUp(const Grid &grid);
  // Solves for p at time t (the head difference of the ramp at t), with the source s (a cell vector, 1/s) or none.
  PetscErrorCode Solve(PetscReal time, Vec source = nullptr);
  // -grad p at the cells (Pa/m, 3 global cell vectors): q_C/beta_C, q_C the mean of the cell's two face fluxes,
  // i.e. the drop of the flux-continuous pressure across the cell's own two halves over h, so that
  // sum_cells (-grad p) V along a column is exactly A (p_inlet - p_outlet), and a packed stretch of it holds its
  // own drop (docs/physics.md (F11)). From the last Solve.
  const Vec     *PressureGradient() const { return gradient_; }
  Vec            FluidFraction() const { return eps_; }  // global cell vector; a coupling writes it before Solve
  Vec            Pressure() const { return p_; }
  PetscReal      Density() const { return param_.density; }
  PetscReal      Viscosity() const { return param_.viscosity; }
  PetscReal      MaxFluidFraction() const { return maxEps_; }
  PetscReal      rhoG() const { return param_.density * g_; }  // Pa per m of head
  PetscReal      HeadDifference(PetscReal time) const;  // m, with the ramp
  PetscInt       SolveEvery() const { return every_; }
  PetscErrorCode Summarize(DarcySummary *s) const;
  PetscErrorCode View(PetscViewer viewer) const;
  PetscErrorCode Save(PetscViewer viewer) const;  // p, k/mu and |q| (where the next solve starts)
  PetscErrorCode Load(PetscViewer viewer);
  PetscErrorCode Destroy();

private:
  PetscErrorCode Assemble(PetscReal pIn, PetscReal pOut, Vec source);  // A and b from beta_
  PetscErrorCode Fluxes(PetscReal pIn, PetscReal pOut);  // speed_, gradient_, the boundary flows
  PetscErrorCode FixedFluidFraction();          // -darcy_fluid_fraction into eps_
  bool           Open(int face) const { return axis_ >= 0 && face / 2 == axis_; }

  const Grid *grid_ = nullptr;
  MPI_Comm    comm_ = MPI_COMM_NULL;
  DM          dm_   = nullptr;  // the grid's cell DMDA (STAR, width 1), referenced
  Mat         A_    = nullptr;
  KSP         ksp_  = nullptr;
  Vec         p_ = nullptr, b_ = nullptr, eps_ = nullptr, beta_ = nullptr, betaOld_ = nullptr, speed_ = nullptr;
  Vec         pLocal_ = nullptr, betaLocal_ = nullptr;
  Vec         gradient_[3] = {nullptr, nullptr, nullptr};

  // options
  permeability::Parameters param_;
  int                      law_ = 0;      // row of permeability::kLaws
  int                      axis_ = -1;    // -darcy_axis: the open faces' normal; -1 none (a closed box)
  PetscReal                headDifference_ = 0, outletHead_ = 0;  // m
  PetscReal                ramp_[2] = {0, 0};  // -darcy_head_ramp: the step (m) and its period (s); 0: none
  PetscReal                start_ = 0;         // -darcy_head_start, s
  std::vector<PetscReal>   epsLayers_ = {0.4};  // -darcy_fluid_fraction
  PetscReal                maxEps_ = 0.99;      // -darcy_max_fluid_fraction
  PetscReal                picardRtol_ = 1e-12;
  PetscInt                 picardMax_ = 200;
  PetscReal                g_ = 9.81;           // |gravity| (m/s^2)
  bool                     fromParticles_ = false;
  PetscBool                epsSet_ = PETSC_FALSE;  // -darcy_fluid_fraction given
  PetscInt                 every_ = 1;             // -darcy_solve_every

  DarcySummary last_;
};

}  // namespace vofdem
