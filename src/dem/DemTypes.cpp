// Particle types (-dem_types) and their materials: each type starts from the -dem_* material
// (density, youngs_modulus, ...), takes a material file if -dem_type_<t>_material names one
// (config/materials/<name>.yaml), then its own -dem_type_<t>_<property> options. Pairs of types mix
// as MaterialTable says, unless -dem_pair_<a>_<b>_<property> gives the pair's value.
#include "vofdem/dem/Dem.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"

#include <cctype>

namespace vofdem {

PetscInt Dem::TypeIndex(const std::string &name) const {
  for (size_t t = 0; t < typeNames_.size(); ++t)
    if (typeNames_[t] == name) return (PetscInt)t;
  return -1;
}

PetscErrorCode Dem::TypesFromOptions(PetscOptionItems *items) {
  OptionReader opt(items);
  std::string  list;

  PetscFunctionBeginUser;
  PetscCall(opt.String("-types", "Names of the particle types, comma-separated (default: one type, 'default', with the -dem_* material); each may take "
                                 "-dem_type_<name>_material FILE|NAME and -dem_type_<name>_<property>",
                       &list));
  typeNames_ = list.empty() ? std::vector<std::string>{"default"} : SplitList(list);
  if (typeNames_.size() > 64) VofdemInputError(comm_, "option -dem_types: at most 64 types");
  for (size_t t = 0; t < typeNames_.size(); ++t) {
    const std::string &n = typeNames_[t];
    bool               ok = !n.empty();
    for (char c : n) ok = ok && (std::isalnum((unsigned char)c) || c == '_');
    if (!ok) VofdemInputError(comm_, "option -dem_types: '%s' is not a type name (letters, digits and _ only)", n.c_str());
    for (size_t u = 0; u < t; ++u)
      if (typeNames_[u] == n) VofdemInputError(comm_, "option -dem_types: type '%s' is named twice", n.c_str());
  }
  const size_t nt = typeNames_.size();
  types_.assign(nt, material_);
  for (size_t t = 0; t < nt && !list.empty(); ++t) {
    const std::string pre = "-type_" + typeNames_[t] + "_";
    DemMaterial      &m   = types_[t];
    std::string       file;
    PetscCall(opt.String((pre + "material").c_str(), "Material file of the type: a path, or a name in config/materials (e.g. glass)", &file));
    if (!file.empty()) {
      const std::string path = FindMaterialFile(file);
      std::string       message;
      if (path.empty()) VofdemInputError(comm_, "option %s: no material file '%s' (nor %s.yaml in config/materials)", opt.FullName((pre + "material").c_str()).c_str(), file.c_str(), file.c_str());
      if (!ReadMaterialFile(path, &m, &message)) VofdemInputError(comm_, "option %s: %s", opt.FullName((pre + "material").c_str()).c_str(), message.c_str());
    }
    PetscBool given[7] = {PETSC_FALSE};
    int       k        = 0;
    PetscCall(opt.Real((pre + "density").c_str(), "Density of the type", "kg/m^3", &m.density, RealRange::Positive(), &given[k++]));
    PetscCall(opt.Real((pre + "youngs_modulus").c_str(), "Young's modulus of the type", "Pa", &m.youngs, RealRange::Positive(), &given[k++]));
    PetscCall(opt.Real((pre + "poisson_ratio").c_str(), "Poisson ratio of the type", "-", &m.poisson, RealRange::LeftOpen(-1, 0.5), &given[k++]));
    PetscCall(opt.Real((pre + "restitution").c_str(), "Restitution of two particles of the type (P3)", "-", &m.restitution, RealRange::LeftOpen(0, 1), &given[k++]));
    PetscCall(opt.Real((pre + "friction").c_str(), "Sliding friction of the type (P3)", "-", &m.friction, RealRange::NonNegative(), &given[k++]));
    PetscCall(opt.Real((pre + "rolling_friction").c_str(), "Rolling friction of the type (P5)", "-", &m.rollingFriction, RealRange::NonNegative(), &given[k++]));
    PetscCall(opt.Real((pre + "surface_energy").c_str(), "Surface energy gamma of the type (P6)", "J/m^2", &m.surfaceEnergy, RealRange::NonNegative(), &given[k++]));
    bool any = !file.empty();
    for (PetscBool g : given) any = any || g;
    // A type without any material of its own would silently be the -dem_* default: almost always a
    // forgotten line in the scene.
    if (!any)
      VofdemInputError(comm_, "option -dem_types: type '%s' has no material (give -dem_type_%s_material NAME, or its properties -dem_type_%s_density etc.)",
                       typeNames_[t].c_str(), typeNames_[t].c_str(), typeNames_[t].c_str());
  }
  pairValues_.assign(nt * nt, {});
  for (size_t i = 0; i < nt && nt > 1; ++i)
    for (size_t j = i; j < nt; ++j) {
      PairValues       &v   = pairValues_[i * nt + j];
      const std::string pre = "-pair_" + typeNames_[i] + "_" + typeNames_[j] + "_";
      PetscCall(opt.Real((pre + "restitution").c_str(), "Restitution of the pair (default -1: mean of the two types)", "-", &v.restitution));
      PetscCall(opt.Real((pre + "friction").c_str(), "Sliding friction of the pair (default -1: mean)", "-", &v.friction));
      PetscCall(opt.Real((pre + "rolling_friction").c_str(), "Rolling friction of the pair (default -1: mean)", "-", &v.rollingFriction));
      PetscCall(opt.Real((pre + "work_of_adhesion").c_str(), "Work of adhesion w of the pair, JKR (default -1: gamma_i + gamma_j)", "J/m^2", &v.workOfAdhesion));
      if (v.restitution != -1 && !(v.restitution > 0 && v.restitution <= 1)) VofdemInputError(comm_, "option %srestitution: must be in (0, 1]", opt.FullName(pre.c_str()).c_str());
      const PetscReal rest[3] = {v.friction, v.rollingFriction, v.workOfAdhesion};
      for (PetscReal r : rest)
        if (r != -1 && !(r >= 0)) VofdemInputError(comm_, "option %s*: pair values must be non-negative (or -1 to mix)", opt.FullName(pre.c_str()).c_str());
      pairValues_[j * nt + i] = v;
    }
  std::string fillType = typeNames_[0];
  PetscCall(opt.String("-fill_type", "Type of the particles of the fill (default: the first of -dem_types)", &fillType));
  fillType_ = TypeIndex(fillType);
  if (fillType_ < 0) VofdemInputError(comm_, "option -dem_fill_type: no type '%s' in -dem_types", fillType.c_str());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
