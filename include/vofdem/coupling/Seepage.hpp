// The seepage coupling (-physics dem,darcy; options -seepage_*): the particles in the Darcy head equation and
// its seepage force on them (docs/physics.md (F11), docs/modules/darcy.md). One step:
//  1. Project (stage exchange): each particle's volume is deposited with the coupling's kernel (KernelAverager,
//     K3: the total is conserved to round-off, across ranks) into the solid volume of each cell; the head
//     equation's eps = max(1 - solid/V_c, -seepage_min_fluid_fraction);
//  2. the head solve (the darcy module, stage fluid);
//  3. Forces (stage average): cell c's solids receive -grad p_c V_c; particle i gets the share its deposit put
//     in each cell, F_i = V_i sum_c w_ic (-grad p_c V_c)/solid_c (the kernel average of the field
//     -grad p V_c/solid, with the deposit's normalised weights), plus the buoyancy -rho_w V_i g, as the
//     explicit fluid force of the DEM's kicks. The particles' total is then exactly sum_c -grad p_c V_c over the
//     cells that hold solid (the monitor shows both).
// The DEM is not sub-stepped: its stable step is the step, and the head is solved every -darcy_solve_every steps.
#pragma once

#include "vofdem/coupling/KernelAverager.hpp"
#include "vofdem/darcy/Darcy.hpp"
#include "vofdem/dem/Dem.hpp"

#include <string>
#include <vector>

namespace vofdem {

struct SeepageSummary {
  PetscReal particleVolume = 0, projectedVolume = 0;  // m^3, the particles' and the deposit's total
  PetscReal force[3] = {0, 0, 0};                      // N, the seepage force on all particles (buoyancy apart)
  PetscReal gridForce[3] = {0, 0, 0};                  // N, sum_c -grad p_c V_c over the cells that hold solid
  PetscReal minEps = 1;
  PetscInt  clipped = 0;                               // cells whose eps was raised to the floor
};

class Seepage {
public:
  PetscErrorCode SetFromOptions(MPI_Comm comm);
  PetscErrorCode SetUp(const Grid &grid, Darcy &darcy, Dem &dem, const PetscReal gravity[3]);
  PetscErrorCode Project();  // the particles' eps into the head equation
  PetscErrorCode Forces();   // the last head solve's seepage force onto the particles
  PetscErrorCode Summarize(SeepageSummary *s) const {
    *s = last_;
    return 0;
  }
  PetscErrorCode View(PetscViewer viewer) const;
  PetscErrorCode Destroy();
  PetscReal      KernelWidth(PetscReal d) const;

private:
  const Grid      *grid_ = nullptr;
  Darcy           *darcy_ = nullptr;
  Dem             *dem_ = nullptr;
  MPI_Comm         comm_ = MPI_COMM_NULL;
  StaggeredGrid    sg_;  // the kernel's layout (its cells have the grid's ownership, BOX ghosts)
  KernelAverager   avg_;
  KernelAverager::Settings kernel_ = {kernel::Shape::Smooth, 1.5, "seepage"};
  std::string      kernelName_ = "smooth";
  PetscReal        kappa_ = 1.5, minWidthCells_ = 1.0, minEps_ = 0.1;
  PetscBool        buoyancy_ = PETSC_TRUE;
  PetscReal        g_[3] = {0, 0, 0};
  Vec              solid_ = nullptr;                    // m^3 per cell (sg_.Cells())
  Vec              field_[3] = {nullptr, nullptr, nullptr};  // -grad p V_c/solid (sg_.Cells())
  std::vector<PetscReal> H_, volume_, share_;
  SeepageSummary   last_;
};

}  // namespace vofdem
