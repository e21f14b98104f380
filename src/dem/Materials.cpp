#include "vofdem/dem/Materials.hpp"

#include "vofdem/base/Options.hpp"

#include <yaml.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>

namespace vofdem {

namespace {

struct Key {
  const char *name;
  PetscReal DemMaterial::*field;
  PetscReal lo, hi;
  bool      loOpen;
};

// Allowed ranges as in the -dem_* options.
const Key kKeys[] = {
  {"density", &DemMaterial::density, 0, PETSC_MAX_REAL, true},
  {"youngs_modulus", &DemMaterial::youngs, 0, PETSC_MAX_REAL, true},
  {"poisson_ratio", &DemMaterial::poisson, -1, 0.5, true},
  {"restitution", &DemMaterial::restitution, 0, 1, true},
  {"friction", &DemMaterial::friction, 0, PETSC_MAX_REAL, false},
  {"rolling_friction", &DemMaterial::rollingFriction, 0, PETSC_MAX_REAL, false},
  {"surface_energy", &DemMaterial::surfaceEnergy, 0, PETSC_MAX_REAL, false},
};

std::string At(const std::string &path, const yaml_mark_t &m) {
  std::ostringstream s;
  s << path << ":" << m.line + 1;
  return s.str();
}

}  // namespace

bool ReadMaterialFile(const std::string &path, DemMaterial *m, std::string *message) {
  std::unique_ptr<FILE, int (*)(FILE *)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) {
    *message = path + ": cannot open the material file";
    return false;
  }
  yaml_parser_t parser;
  if (!yaml_parser_initialize(&parser)) {
    *message = path + ": cannot initialise the YAML parser";
    return false;
  }
  yaml_parser_set_input_file(&parser, file.get());
  DemMaterial out = *m;
  bool        ok = true, done = false;
  int         depth = 0;
  std::string key;  // the pending key of the top-level mapping
  while (ok && !done) {
    yaml_event_t ev;
    if (!yaml_parser_parse(&parser, &ev)) {
      *message = At(path, parser.problem_mark) + ": malformed YAML: " + (parser.problem ? parser.problem : "parse error");
      ok       = false;
      break;
    }
    switch (ev.type) {
    case YAML_MAPPING_START_EVENT:
    case YAML_SEQUENCE_START_EVENT:
      if (depth > 0 || ev.type == YAML_SEQUENCE_START_EVENT) {
        *message = At(path, ev.start_mark) + ": a material file is a mapping of names to numbers (e.g. density: 2500)";
        ok       = false;
      }
      ++depth;
      break;
    case YAML_SCALAR_EVENT: {
      const std::string text((const char *)ev.data.scalar.value, ev.data.scalar.length);
      if (depth == 0) {
        *message = At(path, ev.start_mark) + ": a material file is a mapping of names to numbers (e.g. density: 2500)";
        ok       = false;
      } else if (key.empty()) {
        key = text;
        bool known = false;
        for (const auto &k : kKeys) known = known || key == k.name;
        if (!known) {
          *message = At(path, ev.start_mark) + ": unknown key '" + key +
                     "' (known: density, youngs_modulus, poisson_ratio, restitution, friction, rolling_friction, surface_energy)";
          ok = false;
        }
      } else {
        for (const auto &k : kKeys) {
          if (key != k.name) continue;
          PetscReal v;
          if (!ParseReal(text, &v)) {
            *message = At(path, ev.start_mark) + ": " + key + ": '" + text + "' is not a number";
            ok       = false;
          } else if (!((k.loOpen ? v > k.lo : v >= k.lo) && v <= k.hi)) {
            std::ostringstream s;
            s << At(path, ev.start_mark) << ": " << key << " = " << text << " is out of range " << (k.loOpen ? "(" : "[") << k.lo << ", "
              << (k.hi == PETSC_MAX_REAL ? std::string("inf)") : std::to_string(k.hi) + "]");
            *message = s.str();
            ok       = false;
          } else {
            out.*(k.field) = v;
          }
        }
        key.clear();
      }
      break;
    }
    case YAML_MAPPING_END_EVENT:
    case YAML_SEQUENCE_END_EVENT: --depth; break;
    case YAML_STREAM_END_EVENT: done = true; break;
    default: break;
    }
    yaml_event_delete(&ev);
  }
  yaml_parser_delete(&parser);
  if (ok) *m = out;
  return ok;
}

void MaterialTable::Build(const std::vector<DemMaterial> &types, const std::vector<PairValues> &pairs, const WallMaterial &wall, bool linear,
                          PetscReal linearKtRatio, bool limitForce, bool jkr, const hertz::RollingParams &rollingModel) {
  nt_ = (PetscInt)types.size();
  pair_.assign(nt_ * nt_, {});
  rolling_.assign(nt_ * nt_, {});
  restitution_.assign(nt_ * nt_, 0);
  wall_.assign(nt_, {});
  wallRolling_.assign(nt_, {});
  auto pick = [](PetscReal given, PetscReal a, PetscReal b) { return given >= 0 ? given : 0.5 * (a + b); };
  for (PetscInt i = 0; i < nt_; ++i)
    for (PetscInt j = 0; j < nt_; ++j) {
      const DemMaterial &a = types[i], &b = types[j];
      const PairValues  &v = pairs[i * nt_ + j];
      const PetscReal    e = pick(v.restitution, a.restitution, b.restitution), mu = pick(v.friction, a.friction, b.friction);
      const PetscReal    w = jkr ? (v.workOfAdhesion >= 0 ? v.workOfAdhesion : a.surfaceEnergy + b.surfaceEnergy) : 0;
      pair_[i * nt_ + j]   = linear ? hertz::MakeLinearMaterial(e, mu, linearKtRatio, limitForce)
                                    : hertz::MakePairMaterial(a.youngs, a.poisson, b.youngs, b.poisson, e, mu, limitForce, w);
      rolling_[i * nt_ + j]     = {pick(v.rollingFriction, a.rollingFriction, b.rollingFriction), rollingModel.eta, rollingModel.load, rollingModel.twist};
      restitution_[i * nt_ + j] = e;
    }
  for (PetscInt t = 0; t < nt_; ++t) {
    const DemMaterial &a = types[t];
    const PetscReal    E = wall.youngs > 0 ? wall.youngs : a.youngs, nu = wall.poisson > -1 ? wall.poisson : a.poisson;
    const PetscReal    mu = wall.friction >= 0 ? wall.friction : a.friction, e = wall.restitution >= 0 ? wall.restitution : a.restitution;
    const PetscReal    w  = jkr ? a.surfaceEnergy + (wall.surfaceEnergy >= 0 ? wall.surfaceEnergy : a.surfaceEnergy) : 0;
    wall_[t]        = linear ? hertz::MakeLinearMaterial(e, mu, linearKtRatio, limitForce)
                             : hertz::MakePairMaterial(a.youngs, a.poisson, E, nu, e, mu, limitForce, w);
    wallRolling_[t] = {a.rollingFriction, rollingModel.eta, rollingModel.load, rollingModel.twist};
  }
}

}  // namespace vofdem
