// Powder-bed metrics of a set of spheres (seeds 001 and 002, docs/physics.md section S), serial and free
// of PETSc objects so that unit tests can build packings with known answers:
//  - packing density of a box window and of vertical sample rings (seed 002's "cutting rings"), with
//    the part of every sphere inside the region (Geometry.hpp), periodic images included, and the
//    union of a clump's members inside it (SolidVolume.hpp);
//  - coordination numbers: contacts with overlap > 0 (or a gap below a tolerance) to any sphere,
//    counted for the spheres whose centre is in the window;
//  - Delaunay tetrahedra of the centres in the window (CGAL, Pores.cpp): equivalent radius
//    (3V/4pi)^(1/3) and sphericity pi^(1/3) (6V)^(2/3) / A (0.671 for a regular tetrahedron);
//  - the surface by rays cast down (-z) on a grid: height of the first sphere hit, or the substrate;
//    Sa as seed 001 defines it (standard deviation of the heights), the ISO mean absolute deviation,
//    and Ra along the window's centre line (seed 002 eq. 17, mean absolute deviation);
//  - segregation index per cell: mean radius of the centres in the cell / a reference mean radius;
//  - angle of repose: a straight line fitted to height against distance from the pile's axis.
// Spheres "in the window" are those whose centre is inside it (closed box).
#pragma once

#include "vofdem/analysis/Geometry.hpp"
#include "vofdem/analysis/SolidVolume.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace vofdem::analysis {

struct Spheres {
  std::vector<double>       x;  // 3 per sphere
  std::vector<double>       r;
  std::vector<std::int64_t> type;
  // Rigid clumps (P10), optional (empty: every sphere is a particle): each sphere's clump id (-1:
  // none). A clump is one particle for coordination and rings; its members' overlaps are counted
  // once in packing densities (SolidVolume.hpp).
  std::vector<std::int64_t> clump;
  std::int64_t Clump(std::size_t i) const { return clump.empty() ? -1 : clump[i]; }
  // Periodic directions wrap at the box [lower, upper] (minimum image; the box must be wider than
  // three largest diameters in a periodic direction).
  bool   periodic[3] = {false, false, false};
  double lower[3] = {0, 0, 0}, upper[3] = {0, 0, 0};
  std::size_t Size() const { return r.size(); }
  void   Add(double px, double py, double pz, double radius, std::int64_t t = 0) {
    x.push_back(px), x.push_back(py), x.push_back(pz), r.push_back(radius), type.push_back(t);
  }
  double MaxRadius() const;
  double MeanRadius() const;
};

struct Window {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  double Volume() const { return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]); }
  bool   Empty() const { return !(hi[0] > lo[0] && hi[1] > lo[1] && hi[2] > lo[2]); }
  bool   Contains(const double p[3]) const {
    return p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1] && p[2] >= lo[2] && p[2] <= hi[2];
  }
};

// Indices of the spheres whose centre is in the window.
std::vector<std::size_t> CentresIn(const Spheres &s, const Window &w);

// Solid volume inside the window (periodic images included, clump overlaps once) / window volume;
// `resolution`: of the clump overlaps cut by the window (SolidVolume.hpp).
double PackingDensity(const Spheres &s, const Window &w, int resolution = kClumpResolution);

// Contacts of every sphere: neighbours j with |x_i - x_j| < r_i + r_j + gap (minimum image).
std::vector<int> CoordinationNumbers(const Spheres &s, double gap = 0);

struct RingResult {
  Ring   ring;
  long   centres      = 0;  // spheres whose centre is in the ring
  double packing      = 0;  // solid volume in the ring / ring volume
  double coordination = 0;  // mean contacts of the spheres whose centre is in the ring
};
std::vector<RingResult> SampleRings(const Spheres &s, const std::vector<Ring> &rings, const std::vector<int> &contacts, int resolution = kClumpResolution);
// n rings of radius `radius` along x through the window's middle in y, evenly spaced, its full height.
std::vector<Ring> RingsAlongX(const Window &w, int n, double radius);

struct PoreStats {
  std::vector<double> volume, equivalentRadius, sphericity;  // one per finite Delaunay tetrahedron
  double              hullVolume = 0;                        // sum of the volumes
};
// Delaunay tetrahedra of the centres in the window (Pores.cpp, CGAL); needs 4 centres not coplanar.
PoreStats DelaunayPores(const Spheres &s, const Window &w);
double    TetrahedronSphericity(double volume, double area);

struct Surface {
  int                 nx = 0, ny = 0;
  double              x0 = 0, y0 = 0, spacing = 0;  // ray (i, j) is at (x0 + (i + 1/2) spacing, y0 + (j + 1/2) spacing)
  std::vector<double> z;                            // ny rows of nx heights
  long                hits = 0;                     // rays that met a sphere
  double              mean = 0, saStd = 0, saMeanAbs = 0;
};
// Rays on the grid over the window's x-y extent (spacing s; the count per direction rounds the
// extent / s) meet the spheres whose centre is in the window's z range (periodic images in x, y);
// a ray that meets none reads `substrate`.
Surface CastRays(const Spheres &s, const Window &w, double spacing, double substrate);
struct LineProfile {
  std::vector<double> x, z;
  double              mean = 0, ra = 0, rq = 0;
};
// n rays along x at the window's middle y (seed 002: 500 rays on the centre line).
LineProfile CastLine(const Spheres &s, const Window &w, int n, double substrate);

struct SegregationCell {
  int    i = 0, j = 0, k = 0;
  Window box;
  long   centres = 0;
  double meanRadius = 0, index = 0;  // index: meanRadius / reference (0 when the cell is empty)
};
std::vector<SegregationCell> Segregation(const Spheres &s, const Window &w, const int cells[3], double referenceRadius);

struct ReposeFit {
  double angleDeg = 0, slope = 0, intercept = 0, axis[2] = {0, 0}, height = 0;
  long   points = 0;
  std::vector<double> distance, z;  // the fitted points
};
// Height against horizontal distance from the axis (given, or the centroid of the heights above the
// substrate when axis is null), least squares over the points between fitLo and fitHi of the pile's
// height above the substrate. angleDeg = atan(-slope).
ReposeFit FitRepose(const Surface &surface, double substrate, const double *axis, double fitLo, double fitHi);
// Seed 001's funnel-test angle (its fig. 6): alpha = atan(2 H/D) of the pile's height H above the cup's top and the
// diameter D of its base (the cup), in degrees; the measured 32.81 deg of D7 is this angle, not a fitted slope.
double HeightReposeAngleDeg(double height, double base);

struct Histogram {
  std::vector<double> lo, hi;
  std::vector<long>   count;
};
Histogram MakeHistogram(const std::vector<double> &values, double lo, double hi, int bins);

}  // namespace vofdem::analysis
