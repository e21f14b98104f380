// Delaunay tetrahedra of the sphere centres in a window (PowderMetrics.hpp), by CGAL's 3-D Delaunay
// triangulation with exact predicates (degenerate inputs such as a lattice, with four or more
// co-spherical points, are resolved by symbolic perturbation). Only this file includes CGAL.
#include "vofdem/analysis/PowderMetrics.hpp"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

namespace vofdem::analysis {

namespace {
constexpr double kPi = 3.14159265358979323846;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point  = Kernel::Point_3;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel>;

double TriangleArea(const Point &a, const Point &b, const Point &c) {
  return 0.5 * std::sqrt(CGAL::to_double(CGAL::cross_product(b - a, c - a).squared_length()));
}
}  // namespace

// Surface of the sphere of the same volume over the tetrahedron's surface.
double TetrahedronSphericity(double volume, double area) { return std::cbrt(kPi) * std::pow(6 * volume, 2.0 / 3.0) / area; }

PoreStats DelaunayPores(const Spheres &s, const Window &w) {
  PoreStats          out;
  std::vector<Point> pts;
  for (std::size_t i : CentresIn(s, w)) pts.emplace_back(s.x[3 * i], s.x[3 * i + 1], s.x[3 * i + 2]);
  if (pts.size() < 4) return out;
  const Delaunay dt(pts.begin(), pts.end());
  if (dt.dimension() < 3) return out;  // all centres coplanar: no tetrahedron
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    const Point &a = c->vertex(0)->point(), &b = c->vertex(1)->point(), &p = c->vertex(2)->point(), &q = c->vertex(3)->point();
    const double V = std::fabs(CGAL::to_double(CGAL::volume(a, b, p, q)));
    const double A = TriangleArea(a, b, p) + TriangleArea(a, b, q) + TriangleArea(a, p, q) + TriangleArea(b, p, q);
    out.volume.push_back(V);
    out.equivalentRadius.push_back(std::cbrt(3 * V / (4 * kPi)));
    out.sphericity.push_back(A > 0 ? TetrahedronSphericity(V, A) : 0);
    out.hullVolume += V;
  }
  return out;
}

}  // namespace vofdem::analysis
