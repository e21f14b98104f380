// The fluid forces that come from rotation (docs/physics.md P1 f_Magnus; -coupling_lift, -coupling_rotational_drag), as plain
// functions of one particle. Omega = omega_p - curl(u)/2 is the particle's rotation relative to the local fluid's
// (u the kernel-averaged velocity, K1; its curl the kernel average of the grid's velocity gradient, K2), and
// w = v - u its velocity relative to the fluid. Reynolds numbers (Loth & Dorgan 2009, Environ. Fluid Mech. 9:187):
// Re_p = rho d |w|/mu, Re_r = rho d^2 |Omega|/mu.
//  - Magnus (rotation-induced) lift: F = (pi/8) d^2 rho C_L |w| (Omega/|Omega|) x w. Rubinow & Keller (1961, J. Fluid
//    Mech. 11:447), Re_p << 1: C_L = Re_r/Re_p, i.e. F = (pi/8) d^3 rho Omega x w (= pi a^3 rho Omega x w). Oesterle &
//    Bui Dinh (1998, Exp. Fluids 25:16), Re_p up to 140: C_L = 0.45 + (Re_r/Re_p - 0.45) exp(-0.05684 Re_r^0.4 Re_p^0.3),
//    which tends to Rubinow-Keller's as Re_r, Re_p -> 0. The sign: a sphere moving along +x with Omega along +z (its
//    top surface moving backwards, with the stream it sees: backspin) is lifted along +y = Omega x w.
//    (Written with the fluid's slip u - v = -w the force is (pi/8) d^3 rho (u - v) x Omega.)
//  - Rotational drag: the torque T = -K_r Omega, K_r = pi mu d^3 (Stokes; Rubinow & Keller 1961: 8 pi mu a^3),
//    optionally times Dennis, Singh & Ingham's (1980, J. Fluid Mech. 101:257) finite-Re_r factor in Loth's (2008,
//    AIAA J. 46:801) fit, 1 + (5/(64 pi)) Re_r^0.6 (Re_r < about 2000).
#pragma once

#include <string>
#include <vector>

namespace vofdem {
namespace rotation {

enum class Lift { None, RubinowKeller, Oesterle };

const std::vector<std::string> &LiftNames();  // in the order of Lift
bool        ParseLift(const std::string &name, Lift *law);
const char *LiftName(Lift law);

// The lift coefficient C_L(Re_p, Re_r) of the law (both Reynolds numbers positive).
double LiftCoefficient(Lift law, double Rep, double Rer);
// The lift force on a sphere of diameter d in fluid of density rho and viscosity mu, relative rotation Omega and
// relative velocity w = v - u (both 3-vectors). Zero when Omega or w is zero, or for Lift::None.
void LiftForce(Lift law, double d, double rho, double mu, const double Omega[3], const double w[3], double F[3]);
// K_r of T = -K_r Omega; dennis: with the finite-Re_r factor (Re_r from |Omega|).
double RotationalDragCoefficient(double d, double rho, double mu, double Omega, bool dennis);

}  // namespace rotation
}  // namespace vofdem
