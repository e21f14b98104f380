// A passive scalar c (a concentration, a dye) carried by the fluid: dc/dt + div(u c) = D lap(c)
// (docs/modules/scalar.md). Finite volumes on the flow's cells: the advective face flux u_f c_f with c_f
// from the upwind cell and a van Leer-limited slope (TVD, so no new extrema), Fickian diffusion
// D (c_R - c_L)/h, no flux through walls, zero gradient at open faces. Heun's method (two TVD Euler
// stages) in time, explicit: stable and bounded for dt (sum_d |u_d|/h_d + 2 D sum_d 1/h_d^2) <= 1/2.
// Every face flux is computed from the same values on the ranks on either side, so the total of c
// changes only through open faces (to round-off), and the field is the same on any rank count.
// This module is the proof of the module interface (base/Module.hpp): its folder and its CMake line are
// all it adds to the program.
#pragma once

#include "vofdem/grid/StaggeredGrid.hpp"

#include <petscviewer.h>

#include <string>

namespace vofdem {

struct ScalarSummary {
  PetscReal total = 0;           // sum c dV, m^3 (units of c)
  PetscReal min = 0, max = 0;    // now
};

class Scalar {
public:
  PetscErrorCode SetFromOptions(const Grid &grid);
  PetscErrorCode SetUp(const StaggeredGrid &sg);  // the field and its initial shape
  // Advances c over dt with the face velocities u[d] (global vectors of sg.Face(d)).
  PetscErrorCode Step(Vec const u[3], PetscReal dt);
  // The largest stable and bounded step for the face velocities u[d].
  PetscErrorCode StableTimeStep(Vec const u[3], PetscReal *dt) const;
  PetscErrorCode Summarize(ScalarSummary *s) const;
  PetscErrorCode View(PetscViewer viewer) const;
  PetscErrorCode Save(PetscViewer viewer) const;  // the field "scalar_c"
  PetscErrorCode Load(PetscViewer viewer);
  PetscErrorCode Destroy();
  Vec            Field() const { return c_; }  // global vector of sg.Cells()
  PetscReal      Diffusivity() const { return D_; }

private:
  PetscErrorCode Rate(Vec c, Vec const u[3], Vec rate);  // -div(u c) + D lap(c), per cell
  PetscErrorCode FillGhosts(LocalField &c) const;       // zero gradient outside a non-periodic box

  const StaggeredGrid *sg_ = nullptr;
  MPI_Comm             comm_ = MPI_COMM_NULL;
  Vec                  c_ = nullptr, stage_ = nullptr, rate_ = nullptr, cLocal_ = nullptr, uLocal_[3] = {nullptr, nullptr, nullptr};
  PetscReal            D_ = 0;                              // -scalar_diffusivity, m^2/s
  PetscReal            cfl_ = 0.5;                          // -scalar_cfl
  std::string          shape_ = "box";                      // -scalar_initial
  PetscReal            value_ = 1, background_ = 0;         // -scalar_value, -scalar_background
  PetscReal            lower_[3] = {0, 0, 0}, upper_[3] = {0, 0, 0};  // -scalar_box_lower/upper, m
  PetscInt             periods_[3] = {1, 0, 0};             // -scalar_sine_periods
};

}  // namespace vofdem
