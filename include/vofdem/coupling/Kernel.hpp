// The kernels of the semi-resolved coupling (docs/physics.md K1-K3): the weight a grid point at distance
// r from a particle gets, for averaging the fluid at the particle (K1, K2) and for projecting the
// particle's volume, force and heat to the grid (K3). Pure functions, unit-tested on their own.
//  - Smooth (default): k(r) = (1 - r^2/rc^2)^4 for r < rc, rc = sqrt(8) H. It reaches zero at rc with
//    three vanishing derivatives, so weights, eps and forces change smoothly as cells enter the
//    support, and it matches the Gaussian exp(-r^2/(2 H^2)) of K1 near the centre
//    ((1 - x/n)^n -> exp(-x) with n = 4, x = r^2/(2 H^2)).
//  - Truncated (seed 000): the Gaussian exp(-r^2/(2 H^2)) cut off at rc = c H (c = 1.2-1.5 in the
//    seed): weights jump as cells cross rc.
//  - Unresolved: no kernel; the cell that contains the particle (Kernel.hpp users handle it).
//  - Divided: no kernel; the particle's volume divided among the cells it overlaps: 32 cubes of side R/2 and
//    equal volume (centres inside the sphere), each split among the cells by its overlap with them, so eps is
//    continuous in the particle's position (KernelAverager handles it; CFDEM's "divided" void fraction, whose
//    sample points go whole to a cell, docs/physics.md K3).
//    Its width H is the particle's radius: the farthest the volume reaches.
//  - Linear: no kernel; the tent (cloud-in-cell) weight prod_e (1 - |x_e - x_J,e|/h_e) to the 2x2x2
//    nearest points (KernelAverager handles it): the compact weight of the diffusion smoothing
//    (DiffusionSmoother.hpp, docs/physics.md K1).
#pragma once

#include <cmath>
#include <vector>

namespace vofdem {
namespace kernel {

enum class Shape { Smooth, Truncated, Unresolved, Linear, Divided };

// The kernels a scene chooses by name (-coupling_kernel; base/NamedTable.hpp): the option's names and help
// come from these rows. A new kernel function is a Shape, its branches in Cutoff and Weight below, and a row.
struct Row {
  const char *name, *summary;
  Shape       shape;
};
inline constexpr Row kKernels[] = {
    {"smooth", "(1 - r^2/rc^2)^4, rc = sqrt(8) H", Shape::Smooth},
    {"truncated", "Gaussian cut at -coupling_kernel_truncation H, seed 000", Shape::Truncated},
    {"unresolved", "the cell that contains the particle: unresolved CFD-DEM, cells of 3 d or more", Shape::Unresolved},
    {"divided", "the cells the particle's volume overlaps: 32 cubes of side R/2 split among cells by overlap, CFDEM's divided void fraction made "
                "continuous in the particle's position; for cells that hold few particles",
     Shape::Divided},
};

// Shapes without a kernel function: the particle's own cell (Unresolved) or the cells its volume overlaps (Divided).
inline bool CellBased(Shape s) { return s == Shape::Unresolved || s == Shape::Divided; }

// Support radius of a kernel of width H; `truncation` is the truncated Gaussian's c.
inline double Cutoff(Shape s, double H, double truncation) {
  switch (s) {
  case Shape::Smooth: return std::sqrt(8.0) * H;
  case Shape::Truncated: return truncation * H;
  case Shape::Divided: return H;  // H is the radius
  case Shape::Unresolved:
  case Shape::Linear: return 0;
  }
  return 0;
}

// Unnormalised weight at distance^2 r2 (users normalise by the sum over the grid points they use).
inline double Weight(Shape s, double r2, double H, double rc) {
  if (r2 >= rc * rc) return 0;
  switch (s) {
  case Shape::Smooth: {
    const double q = 1 - r2 / (rc * rc);
    return q * q * q * q;
  }
  case Shape::Truncated: return std::exp(-r2 / (2 * H * H));
  case Shape::Divided:
  case Shape::Unresolved:
  case Shape::Linear: return 0;
  }
  return 0;
}

// The velocity a particle reads from its own force, per unit force and viscosity (m^-1), when the
// force is projected with a kernel and the fluid averaged with the same kernel (docs/physics.md K1b):
// u_self = C F / mu along F. From the steady Oseen equations for a fluid streaming past at the slip
// speed W (the Stokes limit at W = 0), with g^ the kernel's Fourier transform (normalised to 1):
//   C = 1/(4 pi^2) int_0^inf |g^(k)|^2 J(W/(nu k)) dk,  J(a) = int_-1^1 (1 - c^2)/(1 + a^2 c^2) dc,
// J(0) = 4/3. In Stokes flow and for a Gaussian of width H, C = 1/(6 pi^(3/2) H): with Stokes drag
// 3 pi mu d W, u_self/W = 0.282 d/H (docs/physics.md's 0.28 d/H). The Oseen factor J matters as soon as
// Re_H = W H/nu is of order one: at Re_H = 8 (a 1 mm sphere settling at Re 5.5 with H = 1.5 d) the
// Stokes value overestimates the disturbance several times over.
// C scales as 1/H at fixed Re_H: the table holds H C at the given Re_H values (quadrature).
std::vector<double> SelfDisturbanceTable(Shape s, double truncation, const std::vector<double> &ReH);
inline double SelfDisturbanceCoefficient(Shape s, double H, double truncation, double ReH = 0) {
  return SelfDisturbanceTable(s, truncation, {ReH})[0] / H;
}

}  // namespace kernel
}  // namespace vofdem
