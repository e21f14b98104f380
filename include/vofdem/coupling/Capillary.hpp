// The capillary force of a wetted sphere at a free surface (issue 9; docs/physics.md P1, the particle's
// wettability, -coupling_contact_angle): pure functions, unit-tested on their own (test_capillary.cpp);
// the coupling applies them at each particle (CouplingCapillary.cpp).
//
// Princen's flat-interface model. A sphere of radius R whose centre lies a height s above a flat
// liquid-gas interface (along the normal n from the liquid into the gas) meets it on the circle at
// the polar angle beta from the sphere's liquid-side pole, cos(beta) = s/R (radius R sin(beta)); none
// if |s| >= R. The liquid wets the sphere with the contact angle theta (measured through the
// liquid). In the meridional plane (r outward, z along n) the contact point is R (sin b, -cos b), the
// sphere's surface there points down into the wetted part along (-cos b, -sin b), at the angle b - pi;
// the liquid-gas interface leaves the contact line at theta from it, through the liquid, i.e. along
// the angle b - pi + theta. Surface tension pulls the contact line along the interface, sigma per unit
// length; its component along n, integrated over the circle:
//   F_n = 2 pi R sin(b) sigma sin(b - pi + theta) = -2 pi R sigma sin(b) sin(b + theta).
// Checks: theta = 90 deg and b = 90 deg: 0 (a neutral sphere floats centred); theta = 120 deg: zero at
// b = 60 deg (centre R/2 above the interface), F_n < 0 above it and > 0 below (restoring, stiffness
// dF_n/ds = -2 pi sigma cos(b + theta) at the zero); the largest force toward the gas over b is
// 2 pi R sigma sin^2(theta/2) (at b = 180 deg - theta/2), the classical detachment force of a sphere
// from a flat interface (Scheludko; Nutt 1960); theta = 0 pulls the sphere into the liquid at every b.
// The interface's deformation by the particle (the meniscus) and the line tension are not modelled.
//
// Where the interface is (the coupling's kernel view of it): for a planar interface at the signed
// height s below the particle, the kernel average of the liquid fraction alpha at the particle is
// alpha_avg = F(-s/H), F the cumulative 1-D marginal of the 3-D kernel of width H (Kernel.hpp):
//   m(t) = 2 pi int_|t|^rc w(r) r dr,  F(t) = int_-rc^t m / int_-rc^rc m,
// so s = -H F^-1(alpha_avg). F is tabulated once per kernel shape (Marginal) and inverted per
// particle by bisection of the table. On the grid the kernel samples cell averages of alpha: that
// convolves F with the cell's box, F + (h^2/24) F'' + ..., which moves s by about (h^2/24) |F''/F'| =
// (h^2/24) |t|/var, under 1 % of s for cells of 0.4 H or less (var ~ 0.3-0.8 H^2 for these kernels).
#pragma once

#include "vofdem/coupling/Kernel.hpp"

#include <vector>

namespace vofdem {
namespace capillary {

// F of a kernel shape, at H = 1 (for width H: F(t/H)). Unresolved has no kernel: not supported.
class Marginal {
public:
  void   Build(kernel::Shape shape, double truncation);
  double Cutoff() const { return rc_; }  // F = 0 below -rc, 1 above rc
  double Fraction(double t) const;       // F(t), t in widths H
  double Coordinate(double alpha) const; // F^-1(alpha), clamped to [-rc, rc]

private:
  double              rc_ = 0, dt_ = 0;
  std::vector<double> F_;  // at t_k = -rc + k dt, k = 0..N
};

// Princen's F_n (N, along n from the liquid into the gas) on a sphere of radius R (m) whose centre is s
// (m) above the interface, contact angle theta (rad), surface tension sigma (N/m); 0 for |s| >= R.
double PrincenForce(double R, double sigma, double theta, double s);

}  // namespace capillary
}  // namespace vofdem
