#include "vofdem/dem/SizeDistribution.hpp"

#include "vofdem/base/Runtime.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vofdem {

namespace normal {
double Cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }
double Pdf(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2 * M_PI); }

// Newton's method kept inside a shrinking bracket (bisection when a step would leave it): Phi is
// monotone, so this always converges; a sample is drawn once per particle, so cost is no concern.
double InverseCdfIn(double p, double a, double b) {
  double lo = std::max(a, -38.0), hi = std::min(b, 38.0), x = 0.5 * (lo + hi);
  for (int it = 0; it < 200 && hi - lo > 1e-15 * (1 + std::fabs(x)); ++it) {
    const double f = Cdf(x) - p;
    if (f == 0) return x;
    if (f > 0) hi = x;
    else lo = x;
    const double d    = Pdf(x);
    const double next = d > 0 ? x - f / d : 0.5 * (lo + hi);
    x                 = next > lo && next < hi ? next : 0.5 * (lo + hi);
  }
  return x;
}
}  // namespace normal

void SizeDistribution::SetDiscrete(const std::vector<PetscReal> &radii, const std::vector<PetscReal> &massFractions) {
  kind_ = Kind::Discrete;
  radii_ = radii, mass_ = massFractions;
  // Cumulative number fractions n_i ~ w_i / r_i^3: a mass fraction w_i of spheres of volume ~ r_i^3.
  // Summed in this order with the raw fractions: the lattice fill's radii stay bit-identical.
  cdf_.resize(radii_.size());
  for (size_t i = 0; i < cdf_.size(); ++i) cdf_[i] = (i ? cdf_[i - 1] : 0) + mass_[i] / std::pow(radii_[i], 3);
  for (auto &c : cdf_) c /= cdf_.back();
  min_ = *std::min_element(radii_.begin(), radii_.end());
  max_ = *std::max_element(radii_.begin(), radii_.end());
}

void SizeDistribution::SetUniform(PetscReal lo, PetscReal hi) {
  kind_ = Kind::Uniform;
  min_ = lo, max_ = hi;
}

void SizeDistribution::SetNormal(PetscReal mean, PetscReal std, PetscReal lo, PetscReal hi) {
  kind_ = Kind::Normal;
  mu_ = mean, sigma_ = std, min_ = lo, max_ = hi;
  a_ = (lo - mu_) / sigma_, b_ = (hi - mu_) / sigma_;
  pa_ = normal::Cdf(a_), pb_ = normal::Cdf(b_);
}

// The parent lognormal has mean m and standard deviation s of r: ln r is normal with
// sigma^2 = ln(1 + s^2/m^2), mu = ln m - sigma^2/2.
void SizeDistribution::SetLognormal(PetscReal mean, PetscReal std, PetscReal lo, PetscReal hi) {
  kind_  = Kind::Lognormal;
  sigma_ = std::sqrt(std::log1p(std * std / (mean * mean)));
  mu_    = std::log(mean) - 0.5 * sigma_ * sigma_;
  min_ = lo, max_ = hi;
  a_ = (std::log(lo) - mu_) / sigma_, b_ = (std::log(hi) - mu_) / sigma_;
  pa_ = normal::Cdf(a_), pb_ = normal::Cdf(b_);
}

PetscReal SizeDistribution::Radius(double u) const {
  switch (kind_) {
  case Kind::Discrete: {
    size_t i = 0;
    while (i + 1 < cdf_.size() && u >= cdf_[i]) ++i;
    return radii_[i];
  }
  case Kind::Uniform: return min_ + u * (max_ - min_);
  case Kind::Normal: return std::clamp(mu_ + sigma_ * normal::InverseCdfIn(pa_ + u * (pb_ - pa_), a_, b_), min_, max_);
  case Kind::Lognormal: return std::clamp(std::exp(mu_ + sigma_ * normal::InverseCdfIn(pa_ + u * (pb_ - pa_), a_, b_)), min_, max_);
  }
  return 0;
}

PetscReal SizeDistribution::Moment(int k) const {
  switch (kind_) {
  case Kind::Discrete: {
    PetscReal s = 0, prev = 0;
    for (size_t i = 0; i < radii_.size(); ++i) s += (cdf_[i] - prev) * std::pow(radii_[i], k), prev = cdf_[i];
    return s;
  }
  case Kind::Uniform: return (std::pow(max_, k + 1) - std::pow(min_, k + 1)) / ((k + 1) * (max_ - min_));
  case Kind::Normal: {
    // Moments of the standard normal truncated to [a, b]: E[Y] = (phi(a) - phi(b))/Z,
    // E[Y^2] = 1 + (a phi(a) - b phi(b))/Z, E[Y^3] = ((a^2 + 2) phi(a) - (b^2 + 2) phi(b))/Z; then
    // r = mu + sigma Y expanded binomially.
    const double Z = pb_ - pa_, fa = normal::Pdf(a_), fb = normal::Pdf(b_);
    const double ea = std::isfinite(a_) ? a_ * fa : 0, eb = std::isfinite(b_) ? b_ * fb : 0;
    const double m[4] = {1, (fa - fb) / Z, 1 + (ea - eb) / Z, ((a_ * a_ + 2) * fa - (b_ * b_ + 2) * fb) / Z};
    static const int binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    double           s           = 0;
    for (int j = 0; j <= k && k <= 3; ++j) s += binom[k][j] * std::pow(mu_, k - j) * std::pow(sigma_, j) * m[j];
    return s;
  }
  case Kind::Lognormal:
    // E[r^k] = exp(k mu + k^2 sigma^2/2) (Phi(b - k sigma) - Phi(a - k sigma)) / (Phi(b) - Phi(a)).
    return std::exp(k * mu_ + 0.5 * k * k * sigma_ * sigma_) * (normal::Cdf(b_ - k * sigma_) - normal::Cdf(a_ - k * sigma_)) / (pb_ - pa_);
  }
  return 0;
}

PetscReal SizeDistribution::Mean() const { return Moment(1); }
PetscReal SizeDistribution::Variance() const { return Moment(2) - Moment(1) * Moment(1); }
PetscReal SizeDistribution::MeanCube() const { return Moment(3); }

std::string SizeDistribution::Describe() const {
  char buf[256];
  switch (kind_) {
  case Kind::Discrete:
    std::snprintf(buf, sizeof buf, "discrete, %d radii in [%g, %g] m", (int)radii_.size(), (double)min_, (double)max_);
    break;
  case Kind::Uniform: std::snprintf(buf, sizeof buf, "uniform radius in [%g, %g] m", (double)min_, (double)max_); break;
  case Kind::Normal:
    std::snprintf(buf, sizeof buf, "normal radius (parent mean %g m, std %g m) cut to [%g, %g] m", (double)mu_, (double)sigma_, (double)min_, (double)max_);
    break;
  case Kind::Lognormal:
    std::snprintf(buf, sizeof buf, "lognormal radius (ln r: mu %g, sigma %g) cut to [%g, %g] m", (double)mu_, (double)sigma_, (double)min_, (double)max_);
    break;
  }
  std::string s = buf;
  std::snprintf(buf, sizeof buf, "; mean radius %g m, std %g m (by number)", (double)Mean(), (double)std::sqrt(std::max(0.0, (double)Variance())));
  return s + buf;
}

PetscErrorCode SizeDistribution::SetFromOptions(OptionReader &opt, MPI_Comm comm, const std::string &prefix, PetscReal radius) {
  static const std::vector<std::string> kinds = {"discrete", "uniform", "normal", "lognormal"};
  std::vector<std::string>              kind  = {"discrete"};
  std::vector<PetscReal>                radii = {radius}, fractions;
  PetscReal                             mean = 0, std = 0, lo = 0, hi = 0;
  PetscBool                             fractionsSet = PETSC_FALSE, meanSet = PETSC_FALSE, stdSet = PETSC_FALSE, loSet = PETSC_FALSE, hiSet = PETSC_FALSE;
  auto                                  name = [&](const char *s) { return "-" + prefix + s; };
  auto                                  full = [&](const char *s) { return opt.FullName(("-" + prefix + s).c_str()); };

  PetscFunctionBeginUser;
  PetscCall(opt.NameList(name("size_distribution").c_str(),
                         "Size distribution: discrete (the radii of _radii in the MASS fractions of _mass_fractions, drawn by number n_i ~ w_i/r_i^3), or uniform, normal or lognormal (each particle's radius drawn from it BY NUMBER, between the cut-offs)", kinds,
                         &kind));
  if (kind.size() != 1) VofdemInputError(comm, "option %s: give one distribution (discrete, uniform, normal or lognormal)", full("size_distribution").c_str());
  PetscCall(opt.RealList(name("radii").c_str(), "Radii of the discrete size distribution (default: -dem_radius)", "m", &radii, 64, RealRange::Positive()));
  fractions.assign(radii.size(), 1.0 / radii.size());
  PetscCall(opt.RealList(name("mass_fractions").c_str(), "Mass fraction of each discrete radius, normalised to sum 1 (default: equal); by number n_i ~ w_i/r_i^3", "-",
                         &fractions, 64, RealRange::Positive(), &fractionsSet));
  if (fractions.size() != radii.size())
    VofdemInputError(comm, "option %s: %d fractions for %d radii in %s", full("mass_fractions").c_str(), (int)fractions.size(), (int)radii.size(),
                     full("radii").c_str());
  PetscCall(opt.Real(name("radius_mean").c_str(), "Mean radius of the untruncated normal or lognormal law", "m", &mean, RealRange::Positive(), &meanSet));
  PetscCall(opt.Real(name("radius_std").c_str(), "Standard deviation of the radius of the untruncated normal or lognormal law", "m", &std, RealRange::Positive(), &stdSet));
  PetscCall(opt.Real(name("radius_min").c_str(), "Lower cut-off of a continuous size law (default: normal mean - 3 std, lognormal exp(mu - 3 sigma))", "m", &lo,
                     RealRange::Positive(), &loSet));
  PetscCall(opt.Real(name("radius_max").c_str(), "Upper cut-off of a continuous size law (default: normal mean + 3 std, lognormal exp(mu + 3 sigma))", "m", &hi,
                     RealRange::Positive(), &hiSet));
  const std::string &k = kind[0];
  if (k == "discrete") {
    SetDiscrete(radii, fractions);
    PetscFunctionReturn(0);
  }
  if (k == "uniform") {
    if (!loSet || !hiSet) VofdemInputError(comm, "option %s uniform needs %s and %s", full("size_distribution").c_str(), full("radius_min").c_str(), full("radius_max").c_str());
  } else {
    if (!meanSet || !stdSet)
      VofdemInputError(comm, "option %s %s needs %s and %s", full("size_distribution").c_str(), k.c_str(), full("radius_mean").c_str(), full("radius_std").c_str());
    if (k == "normal") {
      if (!loSet) lo = mean - 3 * std;
      if (!hiSet) hi = mean + 3 * std;
      if (!(lo > 0)) VofdemInputError(comm, "option %s: needed, since the default mean - 3 std = %g m is not a positive radius", full("radius_min").c_str(), (double)lo);
    } else {
      const PetscReal s = std::sqrt(std::log1p(std * std / (mean * mean))), m = std::log(mean) - 0.5 * s * s;
      if (!loSet) lo = std::exp(m - 3 * s);
      if (!hiSet) hi = std::exp(m + 3 * s);
    }
  }
  if (!(hi > lo)) VofdemInputError(comm, "options %s/%s: the cut-offs [%g, %g] m are empty", full("radius_min").c_str(), full("radius_max").c_str(), (double)lo, (double)hi);
  if (k == "uniform") SetUniform(lo, hi);
  else if (k == "normal") SetNormal(mean, std, lo, hi);
  else SetLognormal(mean, std, lo, hi);
  if (!(pb_ - pa_ > 1e-12))
    VofdemInputError(comm, "options %s/%s: the cut-offs [%g, %g] m hold no probability of the %s law", full("radius_min").c_str(), full("radius_max").c_str(),
                     (double)lo, (double)hi, k.c_str());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
