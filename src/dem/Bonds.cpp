// The options and counts of the bonds (Bonds.hpp; docs/physics.md (P13)).
#include "vofdem/dem/Bonds.hpp"

#include "vofdem/base/Runtime.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace vofdem {

PetscErrorCode Bonds::SetFromOptions(OptionReader &opt, MPI_Comm comm, bool on, PetscReal radius) {
  PetscBool tensileSet = PETSC_FALSE, shearSet = PETSC_FALSE, reachSet = PETSC_FALSE;

  PetscFunctionBeginUser;
  on_ = on;
  static const std::vector<std::string> models = {"parallel", "contact"};
  std::vector<std::string>              model  = {models[model_]};
  PetscCall(opt.NameList("-bond_model",
                         "Bond of -dem_cohesion bond (P13): parallel (a cylinder of radius lambda min(r_i, r_j) with force and moments, strengths as stresses) or contact "
                         "(the same springs at the contact point, no moments, strengths as forces)",
                         models, &model));
  if (model.size() != 1) VofdemInputError(comm, "option -dem_bond_model: give one of parallel or contact");
  model_       = model[0] == "contact" ? 1 : 0;
  law_.moments = model_ == 0;
  PetscCall(opt.Real("-bond_radius_ratio", "Bond radius / the smaller sphere's radius, lambda (P13)", "-", &law_.lambda, RealRange::Positive()));
  PetscCall(opt.Real("-bond_normal_stiffness", "Normal stiffness per area of a bond, k_n bar (P13)", "Pa/m", &law_.kn, RealRange::NonNegative()));
  PetscCall(opt.Real("-bond_shear_stiffness", "Shear stiffness per area of a bond, k_s bar (P13)", "Pa/m", &law_.ks, RealRange::NonNegative()));
  PetscCall(opt.Real("-bond_tensile_strength", "Tensile strength of a bond (P13): a stress for -dem_bond_model parallel (Pa), a force for contact (N); required with -dem_cohesion bond",
                     "Pa or N", &law_.tensile, RealRange::Positive(), &tensileSet));
  PetscCall(opt.Real("-bond_shear_strength", "Shear strength of a bond (P13): a stress for -dem_bond_model parallel (Pa), a force for contact (N); required with -dem_cohesion bond",
                     "Pa or N", &law_.shear, RealRange::Positive(), &shearSet));
  PetscCall(opt.Real("-bond_at_time", "Time at which the bonds are made, between the pairs closer than -dem_bond_gap (once)", "s", &atTime_, RealRange::NonNegative()));
  PetscCall(opt.Real("-bond_gap", "Pairs whose gap (centre distance - r_i - r_j) is below this are bonded at -dem_bond_at_time; overlapping pairs always", "m", &gap_,
                     RealRange::NonNegative()));
  PetscCall(opt.Real("-bond_reach", "Gap beyond which an intact bond is given up as broken (the neighbour lists reach this far; default: -dem_bond_gap + 0.1 -dem_radius)",
                     "m", &reach_, RealRange::Positive(), &reachSet));
  if (!reachSet) reach_ = gap_ + 0.1 * radius;
  if (!on_) PetscFunctionReturn(0);
  if (!tensileSet) VofdemInputError(comm, "option -dem_bond_tensile_strength: -dem_cohesion bond needs the bonds' tensile strength (%s)", law_.moments ? "Pa" : "N");
  if (!shearSet) VofdemInputError(comm, "option -dem_bond_shear_strength: -dem_cohesion bond needs the bonds' shear strength (%s)", law_.moments ? "Pa" : "N");
  if (!(law_.kn > 0 || law_.ks > 0)) VofdemInputError(comm, "option -dem_bond_normal_stiffness: -dem_cohesion bond needs a bond stiffness (Pa/m)");
  if (reachSet && !(reach_ > gap_)) VofdemInputError(comm, "option -dem_bond_reach: %g m must exceed -dem_bond_gap %g m", (double)reach_, (double)gap_);
  PetscFunctionReturn(0);
}

PetscReal Bonds::StepLimit(PetscReal rMax, PetscReal mMin) const {
  if (!on_) return PETSC_MAX_REAL;
  // Up to 12 bonds on the lightest sphere, each of the largest section; the shear spring also turns the
  // sphere (lever r, inertia 0.4 m r^2: 2.5 times as stiff), the moments kn I / (0.4 m r^2) <= kn A / 1.6 m.
  const bond::Section s = bond::SectionOf(law_, rMax, rMax);
  const PetscReal     w2 = 12 * 2 * ((law_.kn + 3.5 * law_.ks) * s.A) / mMin;
  return 1 / std::sqrt(w2);  // omega dt = 1, half the Verlet bound
}

PetscReal Bonds::LocalIntact(const NeighbourList &list, PetscInt nLocal) const {
  PetscReal halves = 0;
  for (size_t k = 0; k < state.size() / bond::kWidth; ++k)
    if (state[bond::kWidth * k + bond::kState] != 0) halves += list.first[k] < nLocal && list.second[k] < nLocal ? 2 : 1;
  return halves;
}

}  // namespace vofdem
