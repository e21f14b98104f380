// Exact-or-quadrature volumes of a sphere inside a sample region, for packing densities that count
// the part of each sphere inside the region (a window cuts spheres; counting centres would make the
// density jump by whole spheres). Slices z = const: the area of the disc of the slice inside the
// region is closed-form (disc-rectangle by quadrant inclusion-exclusion, disc-annulus by lens areas);
// the integral over z is Gauss-Legendre on the pieces between the heights where the slice's disc
// touches an edge, a corner or a ring circle. Inside a piece the area is smooth but for
// (z - z_k)^(1/2) and ^(3/2) terms at the piece's ends; the substitution z = a + (b-a)(3s^2 - 2s^3)
// makes those smooth in s, so 24 nodes per piece give ~1e-13 relative error (test_analysis_geometry:
// exact caps, octants and the simple-cubic pi/6 to 1e-12, and 24 vs 64 nodes).
#pragma once

namespace vofdem::analysis {

// Area of the disc of radius rho centred at the origin inside [x0,x1] x [y0,y1].
double DiscRectangleArea(double rho, double x0, double x1, double y0, double y1);
// Area of the intersection of two discs of radii a and b whose centres are d apart.
double DiscDiscArea(double a, double b, double d);

// Volume of the sphere (centre c, radius r) inside the box [lo, hi].
double SphereBoxVolume(const double c[3], double r, const double lo[3], const double hi[3], int nodes = 24);

// A vertical sample cylinder or ring ("cutting ring", seed 002): axis (x, y), radii inner < outer
// (inner 0: a full cylinder), heights [z0, z1].
struct Ring {
  double x = 0, y = 0, inner = 0, outer = 0, z0 = 0, z1 = 0;
  double Volume() const;
  bool   Contains(const double p[3]) const;
};
// Volume of the sphere (centre c, radius r) inside the ring.
double SphereRingVolume(const double c[3], double r, const Ring &ring, int nodes = 24);

}  // namespace vofdem::analysis
