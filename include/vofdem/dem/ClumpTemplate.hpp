// Multi-sphere clumps (docs/physics.md P10): a rigid body made of overlapping spheres. A template is the
// list of its spheres in a body frame; its mass properties are those of the union of the spheres
// (overlaps counted once), computed once per template by ClumpTemplate::Compute:
//   x: Gauss-Legendre on the pieces between the spheres' x extents x_k +- r_k;
//   y: at each x, Gauss-Legendre on the pieces between the circles' y extents y_k +- rho_k(x);
//   z: exact: at each (x, y) the spheres' chords are merged into disjoint intervals and 1, z, z^2
//      integrated in closed form.
// The pieces end where the integrand is not smooth: at the silhouettes (circles' y extents) and over
// the circles where two spheres' surfaces meet (their x extents; their points at each x in y). Each
// piece uses the end-smoothing substitution of analysis/Geometry.hpp (square-root ends become
// smooth), so the rule converges spectrally: 32 nodes per piece give volume and inertia of two
// overlapping spheres within 1e-10 relative of the analytic values (test_clump.cpp), and 32 and 64
// nodes agree to 1e-10 for four spheres.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace vofdem {

struct ClumpSphere {
  PetscReal x[3] = {0, 0, 0};  // centre in the template's frame, m
  PetscReal r    = 0;          // radius, m
};

struct ClumpTemplate {
  std::string              name;
  std::vector<ClumpSphere> spheres;  // as given; Compute() adds the body frame
  // Computed, per unit density: volume of the union (m^3), its centroid in the given frame (m), the
  // inertia tensor about the centroid in the given frame (m^5, row-major), its principal moments
  // (ascending) and axes (columns of `axes`: the body frame, right-handed).
  PetscReal volume = 0, centroid[3] = {0, 0, 0}, inertia[9] = {0}, principal[3] = {0, 0, 0}, axes[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  // Member centres in the body frame (principal axes, origin at the centroid): body[3k..3k+2].
  std::vector<PetscReal> body;
  PetscReal              boundingRadius = 0;  // largest |body_k| + r_k

  void Compute(int nodes = 32);
};

// Symmetric n x n eigen-decomposition (cyclic Jacobi): values ascending, vectors as columns (row-major).
void SymmetricEigen(int n, const PetscReal *A, PetscReal *values, PetscReal *vectors);
// The 3 x 3 case with a right-handed set of vectors.
void SymmetricEigen3(const PetscReal A[9], PetscReal values[3], PetscReal vectors[9]);

}  // namespace vofdem
