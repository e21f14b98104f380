// Clump shapes for insertion (docs/physics.md P10): templates given in units of the base sphere's radius
// (the base sphere first, at the origin, radius 1), their mass properties computed ONCE per template
// by ClumpTemplate::Compute at unit size, and scaled for each inserted clump: a clump of
// volume-equivalent radius r_eq (the radius of the sphere of equal volume) is the template scaled by
// s = r_eq / r_eq,unit, so its volume is s^3 V_unit = 4/3 pi r_eq^3 and its principal moments
// s^5 I_unit (per unit density); member centres and radii scale by s.
//
// Templates: -dem_clump_templates a,b with -dem_clump_<name>_spheres x,y,z,r,... (base-radius units),
// and the four built-in lunar-regolith shapes regolith1..regolith4 (RegolithTemplates.cpp), usable by
// name without being declared.
#pragma once

#include "vofdem/base/Options.hpp"
#include "vofdem/dem/ClumpTemplate.hpp"

#include <string>
#include <vector>

namespace vofdem {

// One inserted clump: member centres (world), radii, and the rigid state Clumps keeps per member
// (orientation q body -> world, body-frame centres, mass M, principal moments I).
struct PlacedClump {
  std::vector<PetscReal> x, r, body;  // 3n, n, 3n
  PetscReal              q[4] = {1, 0, 0, 0}, mass = 0, inertia[3] = {0, 0, 0};
};

class ClumpLibrary {
public:
  // Reads -dem_clump_templates and -dem_clump_<name>_spheres (inside the Dem's options block).
  PetscErrorCode SetFromOptions(OptionReader &opt, MPI_Comm comm);
  // Index of a template by name (declared, or built in: computed on first use); -1 when unknown.
  PetscErrorCode Find(const std::string &name, int *index);
  const ClumpTemplate &Template(int t) const { return shapes_[t].t; }
  const std::string   &Name(int t) const { return shapes_[t].t.name; }
  size_t               Size() const { return shapes_.size(); }
  // At unit base radius: the volume-equivalent radius, smallest and largest member radius, and the
  // bounding radius about the centroid. Multiply by s = r_eq / EquivalentRadius(t).
  PetscReal EquivalentRadius(int t) const { return shapes_[t].req; }
  PetscReal MinMember(int t) const { return shapes_[t].rmin; }
  PetscReal MaxMember(int t) const { return shapes_[t].rmax; }
  PetscReal Bounding(int t) const { return shapes_[t].t.boundingRadius; }
  // Template t at volume-equivalent radius rEq, centroid X, orientation q (unit quaternion, body ->
  // world), density rho: the members' world centres X + R(q) s b_k, radii s r_k, and the rigid state.
  // Adds a template (spheres x,y,z,r in base-radius units, base first) and computes it; `where`
  // names the option in error messages.
  PetscErrorCode Add(MPI_Comm comm, const std::string &name, const std::vector<PetscReal> &spheres, const char *where);
  void Place(int t, PetscReal rEq, const PetscReal q[4], const PetscReal X[3], PetscReal rho, PlacedClump *out) const;

private:
  struct Shape {
    ClumpTemplate t;
    PetscReal     req = 0, rmin = 0, rmax = 0;
  };
  std::vector<Shape> shapes_;
  MPI_Comm           comm_ = PETSC_COMM_SELF;
};

// The built-in lunar-regolith shapes (RegolithTemplates.cpp): x,y,z,r per sphere in base-radius units;
// empty when `name` is not one of them.
std::vector<PetscReal> RegolithTemplate(const std::string &name);

}  // namespace vofdem
