// Laser.hpp: the beam's path, power and footprint integrals (docs/physics.md F8).
#include "vofdem/energy/Laser.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"

#include <cmath>

namespace vofdem {

PetscReal ErfDifference(PetscReal a, PetscReal b) {
  if (a >= 0) return std::erfc(a) - std::erfc(b);
  if (b <= 0) return std::erfc(-b) - std::erfc(-a);
  return std::erf(b) - std::erf(a);
}

PetscErrorCode Laser::SetFromOptions(const Grid &grid, PetscReal absorptivityDefault) {
  MPI_Comm                 comm = grid.Comm();
  std::vector<std::string> deposition = {"first_interface"};
  PetscBool                pathSet = PETSC_FALSE, etaSet = PETSC_FALSE;

  PetscFunctionBeginUser;
  eta_ = absorptivityDefault;
  PetscOptionsBegin(comm, "laser_", "Laser: a moving Gaussian beam along -z, absorbed at the first metal surface of each column (docs/modules/energy.md)", "Energy");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.Real("-power", "Beam power P (0: no laser)", "W", &power_, RealRange::NonNegative()));
    PetscCall(opt.Real("-radius", "1/e^2 radius R of the Gaussian beam (D4sigma/2)", "m", &radius_, RealRange::NonNegative()));
    PetscCall(opt.Real("-absorptivity", "Fraction eta of the beam absorbed at the metal surface (default: the metal's absorptivity)", "", &eta_, RealRange::Closed(0, 1), &etaSet));
    PetscCall(opt.RealList("-path", "Way points of the beam centre x0,y0,x1,y1,... (one point: a fixed beam)", "m", &points_, 2000, RealRange::Any(), &pathSet));
    PetscCall(opt.Real("-speed", "Speed of the beam along its path", "m/s", &speed_, RealRange::NonNegative()));
    PetscCall(opt.Real("-start_time", "Time the beam switches on", "s", &start_, RealRange::NonNegative()));
    PetscCall(opt.Real("-stop_time", "Time the beam switches off (default: never)", "s", &stop_, RealRange::Positive()));
    PetscCall(opt.Real("-ramp_time", "The power rises linearly from 0 to P over this time after the start", "s", &ramp_, RealRange::NonNegative()));
    PetscCall(opt.NameList("-deposition",
                           "Where the absorbed power goes: first_interface (the first metal of each column takes eta of what reaches it) or gradient (seed 000: eta I |grad alpha| in every cell)",
                           {"first_interface", "gradient"}, &deposition));
    PetscCall(opt.Real("-step_fraction", "Time step: the beam moves at most this fraction of its radius per step", "", &stepFraction_, RealRange::LeftOpen(0, 10)));
  }
  PetscOptionsEnd();
  deposition_ = deposition[0] == "gradient" ? LaserDeposition::Gradient : LaserDeposition::FirstInterface;
  if (power_ == 0) PetscFunctionReturn(0);
  if (!(stop_ > start_)) VofdemInputError(comm, "option -laser_stop_time: %g s is not after -laser_start_time %g s", (double)stop_, (double)start_);
  if (!(radius_ > 0)) VofdemInputError(comm, "option -laser_radius: a laser with -laser_power %g W needs a positive radius", (double)power_);
  if (!(eta_ >= 0 && eta_ <= 1))
    VofdemInputError(comm, "option -laser_absorptivity: not given, and the metal's material file gives no absorptivity (a value in [0, 1])");
  (void)etaSet;
  if (!pathSet || points_.size() % 2 != 0)
    VofdemInputError(comm, "option -laser_path: give the beam centre's way points as x0,y0[,x1,y1,...] (%d numbers given)", (int)points_.size());
  if (points_.size() > 2 && !(speed_ > 0)) VofdemInputError(comm, "option -laser_speed: a path of %d way points needs a positive speed", (int)(points_.size() / 2));
  const PetscReal *lo = grid.Lower(), *up = grid.Upper();
  for (size_t p = 0; p < points_.size(); p += 2)
    for (int d = 0; d < 2; ++d)
      if (points_[p + d] < lo[d] || points_[p + d] > up[d])
        VofdemInputError(comm, "option -laser_path: way point %d (%g, %g) m lies outside the box in %c [%g, %g] m", (int)(p / 2), (double)points_[p], (double)points_[p + 1],
                         "xy"[d], (double)lo[d], (double)up[d]);
  PetscFunctionReturn(0);
}

void Laser::Centre(PetscReal t, PetscReal *x, PetscReal *y) const {
  *x = points_.empty() ? 0 : points_[0], *y = points_.empty() ? 0 : points_[1];
  if (points_.size() <= 2 || t <= start_) return;
  PetscReal left = speed_ * (t - start_);  // distance travelled
  for (size_t p = 2; p < points_.size(); p += 2) {
    const PetscReal dx = points_[p] - points_[p - 2], dy = points_[p + 1] - points_[p - 1], len = std::sqrt(dx * dx + dy * dy);
    if (left <= len && len > 0) {
      *x = points_[p - 2] + dx * left / len, *y = points_[p - 1] + dy * left / len;
      return;
    }
    left -= len;
    *x = points_[p], *y = points_[p + 1];
  }
}

PetscReal Laser::Power(PetscReal t) const {
  if (power_ == 0 || t < start_ || t >= stop_) return 0;
  if (points_.size() > 2) {  // off after the end of the path
    PetscReal length = 0;
    for (size_t p = 2; p < points_.size(); p += 2) length += std::hypot(points_[p] - points_[p - 2], points_[p + 1] - points_[p - 1]);
    if (speed_ * (t - start_) > length * (1 + 1e-12)) return 0;  // the end point itself still has the beam (round-off in t)
  }
  return ramp_ > 0 && t - start_ < ramp_ ? power_ * (t - start_) / ramp_ : power_;
}

PetscReal Laser::FootprintPower(PetscReal t, PetscReal x0, PetscReal x1, PetscReal y0, PetscReal y1) const {
  const PetscReal P = Power(t);
  if (P == 0) return 0;
  PetscReal cx, cy;
  Centre(t, &cx, &cy);
  const PetscReal s = std::sqrt((PetscReal)2) / radius_;  // int of 2/(pi R^2) exp(-2 r^2/R^2) = 1/4 prod_d [erf(s b) - erf(s a)]
  return 0.25 * P * ErfDifference(s * (x0 - cx), s * (x1 - cx)) * ErfDifference(s * (y0 - cy), s * (y1 - cy));
}

PetscErrorCode Laser::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  if (power_ == 0) PetscFunctionReturn(0);
  PetscCall(PetscViewerASCIIPrintf(viewer, "laser: P %g W, R %g m (1/e^2), absorptivity %g, %d way point(s) at %g m/s from t = %g s (ramp %g s)%s; deposition %s; column powers exact (erf)\n",
                                   (double)power_, (double)radius_, (double)eta_, (int)(points_.size() / 2), (double)speed_, (double)start_, (double)ramp_,
                                   stop_ < PETSC_MAX_REAL ? (" until t = " + std::to_string((double)stop_) + " s").c_str() : "",
                                   deposition_ == LaserDeposition::Gradient ? "gradient (seed 000: eta I |grad alpha|)" : "first metal interface of each column"));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
