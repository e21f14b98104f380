// Particle size distributions for insertion, by number (each particle draws its radius
// independently): discrete radii with mass fractions, or a continuous law of the radius (uniform,
// normal, lognormal) truncated at lower and upper cut-offs. A radius is a function of one uniform
// number u in [0, 1) (inverse of the truncated cumulative distribution), so with the counter-based
// generator it depends only on (seed, particle id), never on the rank count.
#pragma once

#include "vofdem/base/Options.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace vofdem {

class SizeDistribution {
public:
  enum class Kind { Discrete, Uniform, Normal, Lognormal };

  // Reads -<prefix>size_distribution, -<prefix>radii, -<prefix>mass_fractions, -<prefix>radius_mean,
  // -<prefix>radius_std, -<prefix>radius_min, -<prefix>radius_max inside an open PetscOptionsBegin
  // block (prefix e.g. "fill_" or "insert_a_"); `radius` is the default single size.
  PetscErrorCode SetFromOptions(OptionReader &opt, MPI_Comm comm, const std::string &prefix, PetscReal radius);

  // Discrete: radii r_i with mass fractions w_i (normalised); by number n_i ~ w_i / r_i^3.
  void SetDiscrete(const std::vector<PetscReal> &radii, const std::vector<PetscReal> &massFractions);
  // Uniform on [lo, hi].
  void SetUniform(PetscReal lo, PetscReal hi);
  // Normal (lognormal) law of the radius whose untruncated parent has this mean and standard
  // deviation (m), truncated to [lo, hi].
  void SetNormal(PetscReal mean, PetscReal std, PetscReal lo, PetscReal hi);
  void SetLognormal(PetscReal mean, PetscReal std, PetscReal lo, PetscReal hi);

  // The radius for a uniform number u in [0, 1).
  PetscReal Radius(double u) const;
  PetscReal MinRadius() const { return min_; }
  PetscReal MaxRadius() const { return max_; }
  Kind      Type() const { return kind_; }
  // Mean and variance of the radius of the truncated distribution (by number), analytic.
  PetscReal Mean() const;
  PetscReal Variance() const;
  // Mean of r^3 (for the mean particle volume 4/3 pi <r^3>).
  PetscReal MeanCube() const;
  std::string Describe() const;

private:
  PetscReal Moment(int k) const;  // E[r^k] of the truncated distribution

  Kind                   kind_ = Kind::Discrete;
  std::vector<PetscReal> radii_, mass_, cdf_;  // discrete: radii, mass fractions, cumulative number fractions
  PetscReal              mu_ = 0, sigma_ = 0;  // normal: of r; lognormal: of ln r
  PetscReal              min_ = 0, max_ = 0;   // cut-offs (discrete: smallest and largest radius)
  PetscReal              a_ = 0, b_ = 0;       // standardised cut-offs (normal, lognormal)
  PetscReal              pa_ = 0, pb_ = 1;     // Phi(a), Phi(b)
};

namespace normal {
double Cdf(double x);                              // standard normal Phi(x)
double Pdf(double x);                              // standard normal phi(x)
double InverseCdfIn(double p, double a, double b);  // x in [a, b] with Phi(x) = p, Phi(a) <= p <= Phi(b)
}  // namespace normal

}  // namespace vofdem
