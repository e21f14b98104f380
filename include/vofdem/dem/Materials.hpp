// Particle types and their materials (DEM engine issue): each type has its own density, elastic
// constants, restitution, sliding and rolling friction and surface energy, read from
// config/materials/<name>.yaml and/or options; every pair of types gets its pair constants (P3-P6)
// once, before the run, so the contact loop only indexes a small table.
#pragma once

#include "vofdem/io/MaterialFile.hpp"

#include "vofdem/dem/HertzMindlin.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace vofdem {

struct DemMaterial {
  PetscReal density         = 2500;  // kg/m^3
  PetscReal youngs          = 1e8;   // Pa
  PetscReal poisson         = 0.28;  // -
  PetscReal restitution     = 0.5;   // -
  PetscReal friction        = 0.5;   // sliding friction coefficient mu_s
  PetscReal rollingFriction = 0;     // mu_r (P5)
  PetscReal surfaceEnergy   = 0;     // gamma of one surface, J/m^2 (P6)
};

// Reads a material file: a YAML mapping of scalars with the keys density, youngs_modulus,
// poisson_ratio, restitution, friction, rolling_friction, surface_energy (all optional: missing
// keys keep the values passed in). Returns false with a one-line `message` naming file, line and
// what is wrong (unknown key, not a number, out of range, not a mapping).
bool ReadMaterialFile(const std::string &path, DemMaterial *m, std::string *message);

// Where `-dem_type_<t>_material NAME` is looked for: io/MaterialFile.hpp (FindMaterialFile).

// The constants of every pair of types and of every type against the walls, mixed from the types'
// materials: E*, G* exactly (P3); restitution, sliding and rolling friction by the arithmetic mean of
// the two types unless a pair value is given; work of adhesion w = gamma_i + gamma_j (P6 with
// gamma_12 = 0; like surfaces give w = 2 gamma).
struct PairValues {
  PetscReal restitution = -1, friction = -1, rollingFriction = -1, workOfAdhesion = -1;  // < 0: mixed
};

struct WallMaterial {
  PetscReal youngs = -1, poisson = -1, friction = -1, surfaceEnergy = -1, restitution = -1;  // < 0: the particle type's
};

class MaterialTable {
public:
  // linear: P4 (restitution damping without the Hertz factor); jkr: the pairs get a work of adhesion;
  // rollingModel: the rolling damping and load shared by all pairs (mu_r comes from the types).
  void Build(const std::vector<DemMaterial> &types, const std::vector<PairValues> &pairs /* nt*nt, symmetric */, const WallMaterial &wall,
             bool linear, PetscReal linearKtRatio, bool limitForce, bool jkr, const hertz::RollingParams &rollingModel);

  PetscInt Count() const { return nt_; }
  // Index of the pair (i, j) into Pair()/Rolling(); symmetric.
  PetscInt                      PairIndex(PetscInt i, PetscInt j) const { return i * nt_ + j; }
  const hertz::PairMaterial    &Pair(PetscInt k) const { return pair_[k]; }
  const hertz::RollingParams   &Rolling(PetscInt k) const { return rolling_[k]; }
  const hertz::PairMaterial    &Wall(PetscInt t) const { return wall_[t]; }
  const hertz::RollingParams   &WallRolling(PetscInt t) const { return wallRolling_[t]; }
  const std::vector<hertz::PairMaterial>  &Pairs() const { return pair_; }
  const std::vector<hertz::RollingParams> &Rollings() const { return rolling_; }
  PetscReal                     Restitution(PetscInt k) const { return restitution_[k]; }

private:
  PetscInt                          nt_ = 0;
  std::vector<hertz::PairMaterial>  pair_, wall_;
  std::vector<hertz::RollingParams> rolling_, wallRolling_;
  std::vector<PetscReal>            restitution_;
};

}  // namespace vofdem
