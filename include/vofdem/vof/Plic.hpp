// PLIC geometry of one cell (docs/physics.md F1b, F4): the fluid in a cell is the part of the unit cube
// [0,1]^3 (the cell in cell units) where n.x <= alpha, n pointing out of the fluid. These functions
// relate the plane constant alpha to the volume fraction the plane cuts off, exactly (piecewise cubic,
// written in a form without cancellation when components of n are tiny or zero), and give the fluid
// fraction of a sub-box (the volume a face flux carries in a split sweep).
#pragma once

namespace vofdem {
namespace plic {

// Fluid fraction of the unit cube below the plane n.x = alpha (any signs of n; n = 0 gives 0 or 1).
double Volume(const double n[3], double alpha);
// The plane constant alpha with Volume(n, alpha) = v, v in [0, 1] (n != 0); Newton with bisection
// safeguard, converged to round-off.
double Alpha(const double n[3], double v);
// Fluid fraction of the box [lo, hi] (inside the unit cube) under the plane n.x = alpha, relative to
// the box's own volume.
double BoxFraction(const double n[3], double alpha, const double lo[3], const double hi[3]);

// A normal reduced once (components' absolute values over their sum, sorted) for many queries with
// it, e.g. the same plane cut against a block of cells (ELVIRA): the same numbers as the functions above.
struct ReducedNormal {
  double m[3], sum, shift;
};
ReducedNormal Reduce(const double n[3]);
double        Volume(const ReducedNormal &r, double alpha);
double        Alpha(const ReducedNormal &r, double v);

// ELVIRA normal (Pilliod & Puckett 2004, in three dimensions) of the centre cell of a 3 x 3 x 3 block of
// fractions, block[9 (z+1) + 3 (y+1) + (x+1)] for offsets x, y, z in {-1, 0, 1}. young: Youngs' normal
// of the block (pointing out of the fluid), which gives the fluid's side and is a candidate itself.
// Writes the candidate whose plane through the centre cell best reproduces the 27 fractions (least
// squares) to n; exact for a plane whose 3-cell columns along its steepest direction each hold the whole
// transition.
void Elvira(const double block[27], const double young[3], double n[3]);

}  // namespace plic
}  // namespace vofdem
