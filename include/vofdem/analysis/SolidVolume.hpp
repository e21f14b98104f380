// The solid volume of a set of spheres inside a sample region (a box window or a cutting ring), with
// the overlapping members of a rigid clump (P10) counted once: the volume of the union of the
// members inside the region, periodic images included.
//
// For the members of one clump (indices i), with k(x) the number of members that hold the point x:
//   V(union inside region) = sum_i V(sphere_i inside region) - C,   C = integral over the region of (k - 1)+.
// The first sum is exact (Geometry.hpp). C lives in the lenses where members overlap, so it is
//  - 0 when the box around the lenses misses the region (and for members that overlap no other),
//  - the clump's whole overlap sum_i V_i - V_union when that box is inside the region,
//  - else a quadrature over columns: at each lattice point (x, y) the members' chords are clipped to
//    the region's z range and (sum of lengths - length of their union) is exact; the lattice over
//    the region's footprint is a midpoint rule, Cartesian for a box (aligned to the clipped
//    rectangle) and polar about the axis for a ring (aligned to its circles), so the region's
//    boundary never cuts a lattice cell; the integrand is continuous, with square-root edges at the
//    lenses' silhouettes. The whole overlap of every clump is the same quadrature over the lenses' box.
// Resolution: lattice spacing at most the largest member diameter of the clump / `resolution`, and at
// least `resolution` points along each side of the integrated footprint (a small window or ring is
// resolved as finely as a whole clump). Error of C (test_clump_packing.cpp, two spheres with centres
// 1.2 apart, the lens in closed form): up to ~4e-3 of the lens's volume at 16, 2e-3 at 32, 4e-4 at 64
// (the default), 8e-5 at 128, i.e. ~4e-5 of the clump's volume at 64; a region inside a clump reads
// a packing of 1 within ~3e-4. The square-root edges at the lenses' rims limit the midpoint rule to
// O(h^1.5)-O(h^2). Cost: ~resolution^2 columns per clump whose lenses the region cuts (and once per
// clump for its whole overlap), each a loop over the clump's members, without allocation.
#pragma once

#include "vofdem/analysis/Geometry.hpp"

#include <cstdint>
#include <vector>

namespace vofdem::analysis {

struct Spheres;
struct Window;

constexpr int kClumpResolution = 64;

// The clumps of a Spheres grouped once for many regions: members with their centres unwrapped to
// the minimum image of the first member (a clump may straddle a periodic face), the box around the
// lenses where members overlap, and the clump's whole overlap C.
class ClumpUnions {
public:
  ClumpUnions(const Spheres &s, int resolution = kClumpResolution);
  std::size_t Count() const { return start_.empty() ? 0 : start_.size() - 1; }
  // Volume of the union of clump c's members (for tests and messages).
  double UnionVolume(std::size_t c) const;
  // Solid volume of every sphere and clump inside the region.
  double Inside(const Spheres &s, const Window &w) const;
  double Inside(const Spheres &s, const Ring &g) const;

private:
  template <class Region>
  double InsideOf(const Spheres &s, const Region &g) const;
  // C of clump c moved by `shift` inside the region: 0, the whole, or Quadrature().
  template <class Region>
  double Overlap(std::size_t c, const double shift[3], const Region &g, std::vector<double> *scratch) const;
  template <class Region>
  double Quadrature(std::size_t c, const double shift[3], const Region &g, std::vector<double> *scratch) const;
  bool   HasLens(std::size_t c) const { return lensBox_[6 * c + 3] > lensBox_[6 * c]; }

  int                      resolution_;
  std::vector<std::size_t> start_;   // clump c's members are member_[start_[c] .. start_[c + 1])
  std::vector<std::size_t> member_;  // sphere indices
  std::vector<double>      centre_;  // 3 per member, unwrapped
  std::vector<double>      radius_;  // per member
  std::vector<char>        lens_;    // per member: overlaps another member of its clump
  std::vector<double>      box_;     // 6 per clump: lo, hi of all members
  std::vector<double>      lensBox_; // 6 per clump: lo, hi of the lenses (empty box: none)
  std::vector<double>      step_;    // per clump: lattice spacing, largest member diameter / resolution
  std::vector<double>      overlap_; // per clump: C over all space
  std::vector<char>        loose_;   // per sphere: not in a clump of two or more members
  std::size_t              maxMembers_ = 0;
};

}  // namespace vofdem::analysis
