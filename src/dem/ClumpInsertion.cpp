// Insertion of rigid clumps (P10) by a source with -dem_insert_<name>_clumps (ParticleSources.hpp):
// each clump draws, from the counter-based generator keyed by its insertion index (so the same clumps
// on any rank count), its template (by the number fractions), its volume-equivalent radius (the
// source's size distribution), a uniformly random orientation and candidate centroids in the region;
// a candidate is taken when none of its member spheres overlaps a particle present or inserted before.
// Its members get consecutive ids (the base sphere first, so it is the clump's lowest-id member, which
// Migrate follows) and the rigid state that Clumps::SetUp would give them: the template's mass
// properties computed once and scaled (ClumpLibrary::Place), mass shares M/n, the velocity of the
// source, no spin.
#include "vofdem/base/Random.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/dem/Clumps.hpp"
#include "vofdem/dem/ParticleSources.hpp"
#include "vofdem/dem/SphereHash.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

PetscErrorCode ParticleSources::ClumpsFromOptions(OptionReader &opt, InsertionSource &s) {
  const std::string      p = "-insert_" + s.name + "_";
  std::string            names;
  std::vector<PetscReal> fractions;
  PetscBool              fractionsSet = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(opt.String((p + "clumps").c_str(),
                       "Clump templates this source inserts instead of spheres (names of -dem_clump_templates or built-in regolith1..regolith4); its size distribution is then of the volume-equivalent radius",
                       &names));
  for (const auto &n : SplitList(names)) {
    int t;
    PetscCall(library_.Find(n, &t));
    if (t < 0) VofdemInputError(comm_, "option -dem_insert_%s_clumps: no clump template '%s' (declare it in -dem_clump_templates, or use regolith1..regolith4)", s.name.c_str(), n.c_str());
    s.clumps.push_back(t);
  }
  PetscCall(opt.RealList((p + "clump_fractions").c_str(), "Number fractions of the templates of -dem_insert_<name>_clumps (default: equal), summing to 1", "-", &fractions,
                         64, RealRange::NonNegative(), &fractionsSet));
  if (fractionsSet && s.clumps.empty()) VofdemInputError(comm_, "option -dem_insert_%s_clump_fractions: given without -dem_insert_%s_clumps", s.name.c_str(), s.name.c_str());
  if (s.clumps.empty()) PetscFunctionReturn(0);
  if (!fractionsSet) fractions.assign(s.clumps.size(), 1.0 / s.clumps.size());
  if (fractions.size() != s.clumps.size())
    VofdemInputError(comm_, "option -dem_insert_%s_clump_fractions: %d fractions for %d templates", s.name.c_str(), (int)fractions.size(), (int)s.clumps.size());
  PetscReal sum = 0;
  for (PetscReal f : fractions) sum += f;
  if (std::fabs(sum - 1) > 1e-6) VofdemInputError(comm_, "option -dem_insert_%s_clump_fractions: the fractions sum to %g, not 1", s.name.c_str(), (double)sum);
  s.clumpCdf.clear();
  for (size_t k = 0; k < fractions.size(); ++k) s.clumpCdf.push_back((k ? s.clumpCdf.back() : 0) + fractions[k] / sum);
  s.clumpCdf.back() = 1;
  PetscFunctionReturn(0);
}

PetscReal ParticleSources::Reach(const InsertionSource &s) const {
  PetscReal reach = s.clumps.empty() ? s.sizes.MaxRadius() : 0;
  for (int t : s.clumps) reach = std::max(reach, library_.Bounding(t) / library_.EquivalentRadius(t) * s.sizes.MaxRadius());
  return reach;
}

void ParticleSources::MemberRadii(const InsertionSource &s, PetscReal *rmin, PetscReal *rmax) const {
  *rmin = s.sizes.MinRadius(), *rmax = s.sizes.MaxRadius();
  if (s.clumps.empty()) return;
  *rmin = PETSC_MAX_REAL, *rmax = 0;
  for (int t : s.clumps) {
    *rmin = std::min(*rmin, library_.MinMember(t) / library_.EquivalentRadius(t) * s.sizes.MinRadius());
    *rmax = std::max(*rmax, library_.MaxMember(t) / library_.EquivalentRadius(t) * s.sizes.MaxRadius());
  }
}

bool ParticleSources::TryClump(InsertionSource &s, std::uint64_t key, PetscReal rEq, SphereHash &hash) {
  // Streams 3-5 (velocity), 6 (size) and 16+ (centres) as for spheres; 7 template, 8-10 orientation.
  const double u = random::Uniform(s.seed, key, 7);
  size_t       c = 0;
  while (c + 1 < s.clumpCdf.size() && !(u < s.clumpCdf[c])) ++c;
  const int t = s.clumps[c];
  // A uniformly random rotation (Shoemake 1992): q from three uniform numbers.
  const double    u1 = random::Uniform(s.seed, key, 8), a2 = 2 * PETSC_PI * random::Uniform(s.seed, key, 9), a3 = 2 * PETSC_PI * random::Uniform(s.seed, key, 10);
  const PetscReal q[4] = {std::sqrt(u1) * std::cos(a3), std::sqrt(1 - u1) * std::sin(a2), std::sqrt(1 - u1) * std::cos(a2), std::sqrt(u1) * std::sin(a3)};
  PetscReal       X[3], v[3];
  bool            placed = false;
  for (PetscInt k = 0; k < s.attempts && !placed; ++k, ++s.tries) {
    for (int d = 0; d < 3; ++d) X[d] = s.now[d] + (s.now[3 + d] - s.now[d]) * random::Uniform(s.seed, key, 16 + 3 * (std::uint64_t)s.tries + d);
    library_.Place(t, rEq, q, X, s.density, &placed_);
    placed = true;
    for (size_t m = 0; m < placed_.r.size() && placed; ++m) placed = !hash.Overlaps(&placed_.x[3 * m], placed_.r[m]);
  }
  if (!placed) return false;
  for (int d = 0; d < 3; ++d) v[d] = s.velocity[d] + s.spread * (2 * random::Uniform(s.seed, key, 3 + d) - 1);
  const size_t     n     = placed_.r.size();
  const PetscInt64 clump = clumpBase_ + nextId_;  // nextId_: the base sphere's id
  PetscReal        state[kRigidWidth];
  for (int k = 0; k < 4; ++k) state[rigid::kQ + k] = placed_.q[k];
  state[rigid::kMass] = placed_.mass;
  for (int d = 0; d < 3; ++d) state[rigid::kInertia + d] = placed_.inertia[d];
  const PetscReal lead[3] = {placed_.x[0], placed_.x[1], placed_.x[2]};
  for (size_t m = 0; m < n; ++m) {
    for (int d = 0; d < 3; ++d) state[rigid::kBody + d] = placed_.body[3 * m + d];
    hash.Add(&placed_.x[3 * m], placed_.r[m]);
    AppendRow(&placed_.x[3 * m], v, placed_.r[m], placed_.mass / n, clump, lead, state);
  }
  return true;
}

}  // namespace vofdem
