// Magnus lift and rotational drag of one particle (RotationLaws.hpp; docs/physics.md P1).
#include "vofdem/coupling/RotationLaws.hpp"

#include <cmath>

namespace vofdem {
namespace rotation {

const std::vector<std::string> &LiftNames() {
  static const std::vector<std::string> names = {"none", "rubinowkeller", "oesterle"};
  return names;
}

bool ParseLift(const std::string &name, Lift *law) {
  const std::vector<std::string> &n = LiftNames();
  for (size_t k = 0; k < n.size(); ++k)
    if (n[k] == name) {
      *law = (Lift)k;
      return true;
    }
  return false;
}

const char *LiftName(Lift law) { return LiftNames()[(size_t)law].c_str(); }

double LiftCoefficient(Lift law, double Rep, double Rer) {
  switch (law) {
  case Lift::None: return 0;
  case Lift::RubinowKeller: return Rer / Rep;
  case Lift::Oesterle: return 0.45 + (Rer / Rep - 0.45) * std::exp(-0.05684 * std::pow(Rer, 0.4) * std::pow(Rep, 0.3));
  }
  return 0;
}

void LiftForce(Lift law, double d, double rho, double mu, const double Omega[3], const double w[3], double F[3]) {
  F[0] = F[1] = F[2] = 0;
  const double om = std::sqrt(Omega[0] * Omega[0] + Omega[1] * Omega[1] + Omega[2] * Omega[2]);
  const double sl = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  if (law == Lift::None || !(om > 0) || !(sl > 0)) return;
  const double Rep = rho * d * sl / mu, Rer = rho * d * d * om / mu;
  // (pi/8) d^2 rho C_L |w| (Omega/|Omega|) x w
  const double c = M_PI / 8 * d * d * rho * LiftCoefficient(law, Rep, Rer) * sl / om;
  F[0] = c * (Omega[1] * w[2] - Omega[2] * w[1]);
  F[1] = c * (Omega[2] * w[0] - Omega[0] * w[2]);
  F[2] = c * (Omega[0] * w[1] - Omega[1] * w[0]);
}

double RotationalDragCoefficient(double d, double rho, double mu, double Omega, bool dennis) {
  const double K = M_PI * mu * d * d * d;
  if (!dennis) return K;
  const double Rer = rho * d * d * Omega / mu;
  return K * (1 + 5 / (64 * M_PI) * std::pow(Rer, 0.6));
}

}  // namespace rotation
}  // namespace vofdem
