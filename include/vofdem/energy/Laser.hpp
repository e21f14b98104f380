// The laser of the energy module (docs/physics.md F8; docs/modules/energy.md): a Gaussian beam along -z
// with 1/e^2 radius R, I(x, y) = 2 P/(pi R^2) exp(-2 r^2/R^2), moving along a polyline of way points at a
// set speed, its power ramped up linearly from the start. The power entering a column of cells is the
// exact integral of I over the column's footprint (a product of differences of erf), so the columns of a
// box that holds the beam sum to P to round-off whatever R/h and wherever the centre lies.
// Options, prefix laser_: -laser_power, -laser_radius, -laser_absorptivity, -laser_path, -laser_speed,
// -laser_start_time, -laser_stop_time, -laser_ramp_time, -laser_deposition, -laser_step_fraction.
#pragma once

#include "vofdem/grid/Grid.hpp"

#include <petscviewer.h>

#include <string>
#include <vector>

namespace vofdem {

enum class LaserDeposition { FirstInterface, Gradient };

class Laser {
public:
  // absorptivityDefault: the metal's (< 0: none, then -laser_absorptivity is needed).
  PetscErrorCode SetFromOptions(const Grid &grid, PetscReal absorptivityDefault);
  bool           On() const { return power_ > 0; }
  // The beam centre at time t (the last way point after the path's end) and whether it is still moving.
  void      Centre(PetscReal t, PetscReal *x, PetscReal *y) const;
  PetscReal Power(PetscReal t) const;  // W at time t: 0 before the start and after the path's end
  // The power through the rectangle [x0, x1] x [y0, y1] at time t, W (exact integral of I).
  PetscReal FootprintPower(PetscReal t, PetscReal x0, PetscReal x1, PetscReal y0, PetscReal y1) const;
  PetscReal Absorptivity() const { return eta_; }
  PetscReal Radius() const { return radius_; }
  LaserDeposition Deposition() const { return deposition_; }
  // The largest step in which the beam moves by at most -laser_step_fraction of its radius (0: no limit).
  PetscReal StepLimit() const { return speed_ > 0 && points_.size() > 2 ? stepFraction_ * radius_ / speed_ : 0; }
  PetscErrorCode View(PetscViewer viewer) const;

private:
  PetscReal              power_ = 0, radius_ = 0, eta_ = -1, speed_ = 0, start_ = 0, stop_ = PETSC_MAX_REAL, ramp_ = 0, stepFraction_ = 0.25;
  std::vector<PetscReal> points_;  // x0, y0, x1, y1, ... (m)
  LaserDeposition        deposition_ = LaserDeposition::FirstInterface;
};

// erf(b) - erf(a) without the cancellation of two values near +-1 (a <= b).
PetscReal ErfDifference(PetscReal a, PetscReal b);

}  // namespace vofdem
