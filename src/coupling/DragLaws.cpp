#include "vofdem/coupling/DragLaws.hpp"

#include <cmath>

namespace vofdem {
namespace drag {

namespace {
constexpr double kPi = 3.14159265358979323846;
double Volume(double d) { return kPi * d * d * d / 6; }
}  // namespace

double Reynolds(double d, double eps, double slip, double rho, double mu) { return eps * rho * d * slip / mu; }

double SchillerNaumannCd(double Re) {
  if (Re >= 1000) return 0.44;
  if (Re <= 0) return 0;  // K below multiplies by |u - v|: 24/Re * Re stays finite (see callers)
  return 24 / Re * (1 + 0.15 * std::pow(Re, 0.687));
}

// Cd |u - v| with the Re -> 0 limit kept finite: 24 mu/(eps rho d) (1 + 0.15 Re^0.687).
static double CdSlip(double d, double eps, double slip, double rho, double mu) {
  const double Re = Reynolds(d, eps, slip, rho, mu);
  if (Re >= 1000) return 0.44 * slip;
  return 24 * mu / (eps * rho * d) * (1 + 0.15 * std::pow(Re, 0.687));
}

double WenYu(double d, double eps, double slip, double rho, double mu) {
  const double beta = 0.75 * eps * rho / d * CdSlip(d, eps, slip, rho, mu) * std::pow(eps, -2.65);
  return beta * Volume(d);
}

double Ergun(double d, double eps, double slip, double rho, double mu) {
  const double beta = 150 * (1 - eps) * mu / (eps * d * d) + 1.75 * rho * slip / d;
  return beta * Volume(d);
}

double Gidaspow(double d, double eps, double slip, double rho, double mu, double eSwitch) {
  return eps >= eSwitch ? WenYu(d, eps, slip, rho, mu) : Ergun(d, eps, slip, rho, mu);
}

double SchillerNaumann(double d, double slip, double rho, double mu) { return kPi / 8 * rho * d * d * CdSlip(d, 1, slip, rho, mu); }

double DiFelice(double d, double eps, double slip, double rho, double mu) {
  const double Re  = std::max(Reynolds(d, eps, slip, rho, mu), 1e-12);
  const double a   = 1.5 - std::log10(Re);
  const double chi = 3.7 - 0.65 * std::exp(-0.5 * a * a);
  // Cd |u-v| = (0.63 sqrt(|u-v|) + 4.8 sqrt(mu/(eps rho d)))^2: finite as the slip goes to zero.
  const double c = 0.63 * std::sqrt(slip) + 4.8 * std::sqrt(mu / (eps * rho * d));
  return kPi / 8 * c * c * rho * d * d * eps * eps * std::pow(eps, -chi) * eps;
}

double KochHill(double d, double eps, double slip, double rho, double mu) {
  const double phi = 1 - eps;
  double       F0;
  if (phi < 0.4) {
    const double lnTerm = phi > 0 ? 135.0 / 64.0 * phi * std::log(phi) : 0;
    F0 = (1 + 3 * std::sqrt(phi / 2) + lnTerm + 16.14 * phi) / (1 + 0.681 * phi - 8.48 * phi * phi + 8.16 * phi * phi * phi);
  } else {
    F0 = 10 * phi / std::pow(1 - phi, 3);
  }
  const double F3 = 0.0673 + 0.212 * phi + 0.0232 / std::pow(1 - phi, 5);
  // Koch & Hill define Re on the radius: F0 + F3 Re_a = F0 + F3 Re/2 with Re on the diameter (van Buijtenen
  // et al. 2011, CES 66: 2368; CFDEM's and MFIX's Koch-Hill); the half must not be taken twice.
  const double Re = Reynolds(d, eps, slip, rho, mu);
  return 3 * kPi * mu * d * eps * (F0 + 0.5 * F3 * Re) * eps;
}

double Beetstra(double d, double eps, double slip, double rho, double mu) {
  const double phi = 1 - eps, e2 = eps * eps;
  const double Re  = rho * eps * slip * d / mu;
  double       F   = 10 * phi / e2 + e2 * (1 + 1.5 * std::sqrt(phi));
  if (Re > 0) {
    const double num = 1 / eps + 3 * phi * eps + 8.4 * std::pow(Re, -0.343);
    const double den = 1 + std::pow(10.0, 3 * phi) * std::pow(Re, -(1 + 4 * phi) / 2);
    F += 0.413 * Re / (24 * e2) * num / den;
  }
  // Beetstra's F is the drag part already (its Stokes term 10 phi/eps^2 is Carman-Kozeny's 10 phi/eps^3 times
  // eps): the force on the particle is 3 pi mu d (eps |u - v|) F, without a further eps (MFIX's BVK:
  // 18 mu eps F/d^2 per solid volume, "/= Koch-Hill's by a factor of eps").
  return 3 * kPi * mu * d * eps * F;
}

}  // namespace drag

namespace heat {

double Nusselt(double eps, double Re, double Pr) {
  const double e35 = std::pow(eps, 3.5), pr3 = std::cbrt(Pr);
  if (Re <= 200) return 2 + 0.6 * e35 * std::sqrt(Re) * pr3;
  if (Re <= 1500) return 2 + e35 * (0.5 * std::sqrt(Re) + 0.02 * std::pow(Re, 0.8)) * pr3;
  return 2 + 4.5e-5 * e35 * std::pow(Re, 1.8);
}

double ParticleToFluid(double d, double Nu, double kFluid, double Tp, double Tf, double emissivity) {
  constexpr double sigma = 5.670374419e-8;  // Stefan-Boltzmann, W/(m^2 K^4)
  const double     h     = Nu * kFluid / d;
  return 3.14159265358979323846 * d * d * (h * (Tp - Tf) + emissivity * sigma * (Tp * Tp * Tp * Tp - Tf * Tf * Tf * Tf));
}

}  // namespace heat
}  // namespace vofdem
