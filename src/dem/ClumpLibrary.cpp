// Clump shapes for insertion (ClumpLibrary.hpp, docs/physics.md P10).
#include "vofdem/dem/ClumpLibrary.hpp"

#include "vofdem/base/Runtime.hpp"
#include "vofdem/dem/Clumps.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace vofdem {

PetscErrorCode ClumpLibrary::SetFromOptions(OptionReader &opt, MPI_Comm comm) {
  std::string names;

  PetscFunctionBeginUser;
  comm_ = comm;
  shapes_.clear();
  PetscCall(opt.String("-clump_templates",
                       "Names of clump templates for insertion, comma-separated; each is set by -dem_clump_<name>_spheres (regolith1..regolith4 are built in)", &names));
  for (const auto &n : SplitList(names)) {
    if (n.empty() || !std::all_of(n.begin(), n.end(), [](char c) { return std::isalnum((unsigned char)c); }))
      VofdemInputError(comm, "option -dem_clump_templates: '%s' is not a name (letters and digits only)", n.c_str());
    if (!RegolithTemplate(n).empty()) VofdemInputError(comm, "option -dem_clump_templates: '%s' is a built-in template; choose another name", n.c_str());
    for (const auto &s : shapes_)
      if (s.t.name == n) VofdemInputError(comm, "option -dem_clump_templates: the name '%s' is given twice", n.c_str());
    const std::string      o = "-clump_" + n + "_spheres";
    std::vector<PetscReal> spheres;
    PetscBool              set = PETSC_FALSE;
    PetscCall(opt.RealList(o.c_str(), "Spheres of the template, x,y,z,r each, in units of the base sphere's radius (the base sphere first: 0,0,0,1)", "-",
                           &spheres, 4 * 64, RealRange::Any(), &set));
    if (!set) VofdemInputError(comm, "option -dem_clump_%s_spheres: needed for the template '%s' of -dem_clump_templates", n.c_str(), n.c_str());
    PetscCall(Add(comm, n, spheres, ("option -dem_clump_" + n + "_spheres").c_str()));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ClumpLibrary::Add(MPI_Comm comm, const std::string &name, const std::vector<PetscReal> &s, const char *where) {
  PetscFunctionBeginUser;
  if (s.size() % 4) VofdemInputError(comm, "%s: %d numbers are not whole spheres of 4 (x,y,z,r)", where, (int)s.size());
  if (s.size() < 8) VofdemInputError(comm, "%s: a clump needs at least two spheres (8 numbers)", where);
  if (s[0] != 0 || s[1] != 0 || s[2] != 0 || s[3] != 1)
    VofdemInputError(comm, "%s: the first sphere is the base sphere, 0,0,0,1 (units of its radius), not %g,%g,%g,%g", where, (double)s[0], (double)s[1], (double)s[2],
                     (double)s[3]);
  Shape sh;
  sh.t.name = name;
  sh.rmin = PETSC_MAX_REAL;
  for (size_t k = 0; k < s.size(); k += 4) {
    if (!(s[k + 3] > 0)) VofdemInputError(comm, "%s: sphere %d has radius %g, not > 0", where, (int)(k / 4 + 1), (double)s[k + 3]);
    // A member that does not overlap the base would make a clump that is not one connected body
    // through the base (and far satellites would be missed by the insertion's overlap reach).
    const PetscReal d = std::sqrt(s[k] * s[k] + s[k + 1] * s[k + 1] + s[k + 2] * s[k + 2]);
    if (k && !(d < 1 + s[k + 3]))
      VofdemInputError(comm, "%s: sphere %d (centre %g from the base's) does not overlap the base sphere", where, (int)(k / 4 + 1), (double)d);
    ClumpSphere c;
    for (int q = 0; q < 3; ++q) c.x[q] = s[k + q];
    c.r = s[k + 3];
    sh.t.spheres.push_back(c);
    sh.rmin = std::min(sh.rmin, c.r), sh.rmax = std::max(sh.rmax, c.r);
  }
  sh.t.Compute();  // once per template (P10): every inserted clump scales these values
  sh.req = std::cbrt(3 * sh.t.volume / (4 * PETSC_PI));
  shapes_.push_back(sh);
  PetscFunctionReturn(0);
}

PetscErrorCode ClumpLibrary::Find(const std::string &name, int *index) {
  PetscFunctionBeginUser;
  *index = -1;
  for (size_t k = 0; k < shapes_.size(); ++k)
    if (shapes_[k].t.name == name) *index = (int)k;
  const std::vector<PetscReal> s = RegolithTemplate(name);
  if (*index < 0 && !s.empty()) {
    PetscCall(Add(comm_, name, s, "built-in template"));
    *index = (int)shapes_.size() - 1;
  }
  PetscFunctionReturn(0);
}

void ClumpLibrary::Place(int t, PetscReal rEq, const PetscReal q[4], const PetscReal X[3], PetscReal rho, PlacedClump *out) const {
  const Shape    &sh = shapes_[t];
  const PetscReal s = rEq / sh.req, s3 = s * s * s;
  const size_t    n = sh.t.spheres.size();
  out->x.resize(3 * n), out->r.resize(n), out->body.resize(3 * n);
  for (int c = 0; c < 4; ++c) out->q[c] = q[c];
  out->mass = rho * s3 * sh.t.volume;  // = rho 4/3 pi rEq^3
  for (int d = 0; d < 3; ++d) out->inertia[d] = rho * s3 * s * s * sh.t.principal[d];
  for (size_t k = 0; k < n; ++k) {
    PetscReal rb[3];
    for (int d = 0; d < 3; ++d) out->body[3 * k + d] = s * sh.t.body[3 * k + d];
    rigid::QuatRotate(q, &out->body[3 * k], rb);
    for (int d = 0; d < 3; ++d) out->x[3 * k + d] = X[d] + rb[d];
    out->r[k] = s * sh.t.spheres[k].r;
  }
}

}  // namespace vofdem
