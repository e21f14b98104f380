// Walls beyond the six box faces (-dem_walls): infinite planes, cylinders and triangle meshes from
// STL, each fixed, translating, rotating about an axis, or both. Walls are spheres of infinite
// radius and mass (docs/physics.md P3): R* = R, m* = m, and the wall's surface velocity at the contact
// enters the relative velocity. The material is the -dem_wall_* one of the box faces.
//
// Candidates: at each neighbour-list rebuild, every local particle within r + skin (+ adhesion
// range) of a wall element becomes a candidate. A moving wall adds to the rebuild rule: the lists
// are rebuilt once any wall surface point may have moved half the skin since the last rebuild (a
// bound from the wall's speed and angular speed), so particle (<= skin/2) and wall (<= skin/2)
// together close at most one skin and no contact is missed.
//
// History: each (particle, wall, element) contact keeps its springs in the list, and across
// rebuilds and migration in the ContactHistory under WallElementKey (a negative second id, so it
// travels with its particle like the box faces' springs).
//
// Counted once (meshes): a sphere touching several triangles where they meet sees the same edge or
// vertex from each. Per particle and mesh, face contacts are all kept; an edge contact is dropped
// when the edge belongs to a triangle with a face contact or was already taken; a vertex contact is
// dropped when the vertex belongs to a triangle with a face contact or to a taken edge, or was taken.
// When a contact moves from one triangle to its neighbour (a sphere rolling across an edge), the new
// contact takes over the spring of the one that ended in the same step.
#pragma once

#include "vofdem/dem/HertzMindlin.hpp"
#include "vofdem/dem/Materials.hpp"
#include "vofdem/dem/NeighbourList.hpp"
#include "vofdem/dem/ParticleSwarm.hpp"
#include "vofdem/dem/StlMesh.hpp"
#include "vofdem/dem/TriangleBins.hpp"
#include "vofdem/dem/WallGeometry.hpp"

#include <string>
#include <vector>

namespace vofdem {

enum class WallKind : int { Plane = 0, Cylinder = 1, Mesh = 2 };

// Wall element contacts are keyed (particle id, -1 - (6 + wall + kMaxWalls * element)): below the
// six box faces' keys, one per triangle of a mesh (element 0 for planes and cylinders).
inline constexpr int kMaxWalls = 64;
inline PairKey WallElementKey(PetscInt64 id, int wall, PetscInt64 element) { return {id, -1 - (6 + wall + (PetscInt64)kMaxWalls * element)}; }

// What the particles exert on one wall, summed over ranks.
struct WallLoad {
  std::string name;
  PetscReal   force[3]  = {0, 0, 0};  // N
  PetscReal   torque[3] = {0, 0, 0};  // N m, about `point`
  PetscReal   point[3]  = {0, 0, 0};  // m, the wall's rotation point now (default: its first point)
  PetscInt    contacts  = 0;
};

// The contact law the walls are evaluated with (bound by the caller, like the box faces').
struct WallContactLaw {
  const hertz::PairMaterial  *material = nullptr;
  PetscReal                   linearKn = 0;
  const hertz::RollingParams *rolling  = nullptr;
  const hertz::VanDerWaals   *vdw      = nullptr;
  const MaterialTable        *table    = nullptr;  // several types: each particle's wall constants
  PetscReal                   sjkrDensity = 0;    // J/m^3 (P6)
  const hertz::Lubrication   *lubrication = nullptr;  // P8
  PetscReal                   range = 0;           // m: largest gap at which a force still acts
  bool                        fluidLubrication = false;  // -coupling_lubrication: times the particle's fluid viscosity
  PetscReal                   lubricationUniform = 0;    // Pa s: that viscosity when uniform (0: fluid_viscosity)
};

class WallSet {
public:
  // Reads -dem_walls and each wall's -dem_wall_<name>_* options (own options block, prefix dem_).
  PetscErrorCode SetFromOptions(MPI_Comm comm);
  // Reads STL files; the box bounds the displacement of rotating unbounded walls.
  PetscErrorCode SetUp(const PetscReal boxLower[3], const PetscReal boxUpper[3]);
  // Walls given in code rather than options (tests, programs): then Prepare() instead of SetUp().
  void AddPlane(const std::string &name, const PetscReal point[3], const PetscReal normal[3], const wall::Motion &motion = {});
  void AddCylinder(const std::string &name, const PetscReal point[3], const PetscReal axis[3], PetscReal radius, bool inside, const wall::Motion &motion = {});
  void AddMesh(const std::string &name, const StlMesh &mesh, const wall::Motion &motion = {});
  // The set-up after the meshes are read: rotation points, motion bounds, load arrays.
  void Prepare(const PetscReal boxLower[3], const PetscReal boxUpper[3]);
  bool   Empty() const { return walls_.empty(); }
  size_t Count() const { return walls_.size(); }

  // Moves the walls' clock on by dt (every DEM step, before the rebuild check).
  void Advance(PetscReal dt);
  // Whether a wall surface point may have moved more than halfSkin since the last BuildCandidates
  // (the same answer on every rank: it depends on the clock only).
  bool MovedBeyond(PetscReal halfSkin) const;

  // Rebuild step 1: the springs of touching contacts into `springs`, keyed by particle id.
  void SaveSprings(const ParticleArrays &a, ContactHistory *springs) const;
  // Dem::Save: the particle id of each candidate, the key that carries its spring to another rank count.
  void CandidateIds(const ParticleArrays &a, std::vector<PetscReal> *ids) const;
  // Dem::Load on another rank count (the candidates are then all saving ranks' concatenated, `ids` their
  // particle ids): the springs of touching candidates whose particle `holds(id)` says this rank now owns
  // go into `springs` under WallElementKey, where the first rebuild takes them up. False if `ids` does
  // not match the candidates (a file written before the ids were saved: the springs are then lost).
  template <class Holds>
  bool CarrySprings(const std::vector<PetscReal> &ids, Holds holds, ContactHistory *springs) const {
    if (ids.size() != part_.size()) return part_.empty();
    for (size_t k = 0; k < part_.size(); ++k) {
      if (!touching_[k] || !holds(ids[k])) continue;
      const PetscReal *s = &spring_[kSpringWidth * k];
      std::copy(s, s + kSpringWidth, (*springs)[WallElementKey((PetscInt64)ids[k], wallOf_[k], elem_[k])].begin());
    }
    return true;
  }
  // Rebuild step 6: candidates within r + reach of each wall element; springs from `springs`.
  void BuildCandidates(const ParticleArrays &a, PetscReal reach, const ContactHistory &springs);

  // Forces and torques of the candidates on the particles (P3, P5, P6, P7); the loads on the walls
  // are kept for Summarize. Defined in WallContacts.hpp (the contact loop, one instance per model).
  template <hertz::Rolling RM, int COH, bool NEAR, bool LIN, bool MULTI>
  void Evaluate(const ParticleArrays &a, const WallContactLaw &law, PetscReal dt, PetscInt *contacts, PetscReal *elastic, PetscReal *maxOverlap);

  // Collective: the loads of the last evaluation, summed over ranks, one per wall.
  PetscErrorCode Summarize(MPI_Comm comm, std::vector<WallLoad> *loads) const;
  PetscErrorCode View(PetscViewer viewer) const;

  size_t Candidates() const { return part_.size(); }
  // The state a bitwise restart needs (clock, candidates with springs, loads); Dem::Save/Load.
  template <class Archive>
  PetscErrorCode ArchiveState(Archive &ar) {
    PetscFunctionBeginUser;
    PetscCall(ar.Scalar(&time_));
    PetscCall(ar.Scalar(&rebuildTime_));
    PetscCall(ar.Array("walls_part", &part_));
    PetscCall(ar.Array("walls_elem", &elem_));
    PetscCall(ar.Array("walls_group", &group_));
    PetscCall(ar.Array("walls_wall", &wallOf_));
    PetscCall(ar.Array("walls_touching", &touching_));
    PetscCall(ar.Array("walls_spring", &spring_, kSpringWidth));
    PetscCall(ar.Array("walls_load", &load_, 6));
    PetscCall(ar.Array("walls_load_contacts", &loadContacts_));
    // The loop's scratch is not saved: a restart evaluates before its first rebuild. Only for the saving
    // decomposition: on other ranks the arrays are every saving rank's concatenated (their group offsets
    // restart at each rank's block) and Dem::Load clears them.
    if (ar.Loading() && ar.SameRanks()) SizeScratch();
    PetscFunctionReturn(0);
  }
  // Forgets the candidates (their particle indices belong to another decomposition).
  void ClearCandidates() { part_.clear(), elem_.clear(), group_.clear(), wallOf_.clear(), touching_.clear(), spring_.clear(); }
  // This rank's force (0..2) and torque (3..5) on wall w from the last evaluation.
  const PetscReal *LocalLoad(size_t w) const { return &load_[6 * w]; }
  // Monitor-table columns: ",wall_<name>_fx_N,...,wall_<name>_tz_Nm" per wall, in Summarize's order.
  std::string CsvColumns() const {
    std::string c;
    for (const Wall &w : walls_)
      for (const char *q : {"fx_N", "fy_N", "fz_N", "tx_Nm", "ty_Nm", "tz_Nm"}) c += ",wall_" + w.name + "_" + q;
    return c;
  }

private:
  struct Wall {
    std::string  name;
    WallKind     kind = WallKind::Plane;
    PetscReal    point[3] = {0, 0, 0};   // plane point or cylinder axis point, m
    PetscReal    dir[3]   = {0, 0, 1};   // plane normal or cylinder axis, unit
    PetscReal    radius   = 0;           // cylinder, m
    PetscReal    lo = PETSC_MIN_REAL, hi = PETSC_MAX_REAL;  // cylinder's axial extent from point, m
    bool         inside   = true;        // cylinder: particles inside
    std::string  file;                   // STL
    PetscReal    scale = 1, offset[3] = {0, 0, 0};
    StlMesh      mesh;
    PetscReal    meshLo[3] = {0, 0, 0}, meshHi[3] = {0, 0, 0};  // bounding box, reference frame
    TriangleBins bins;                                           // the triangles near each point, reference frame
    wall::Motion motion;
    wall::Pose   pose;
    bool         centerGiven = false;       // -dem_wall_<name>_rotation_point given
    bool         rotationInvariant = false;  // the rotation maps the surface onto itself (a roller)
    PetscReal    reachAxis = 0;             // largest distance of a relevant surface point from the rotation axis, m
    PetscReal    removeTime = PETSC_MAX_REAL;  // s: from then on the wall has no contacts
    bool         Present(PetscReal t) const { return t < removeTime; }
  };
  PetscErrorCode ReadWall(MPI_Comm comm, PetscOptionItems *items, const std::string &name, bool help, Wall *w);
  PetscReal      Travel(const Wall &w) const;  // bound on the surface displacement since the last rebuild
  void           SizeScratch();                   // the contact loop's scratch for the largest group of candidates

  std::vector<Wall> walls_;
  MPI_Comm          comm_ = MPI_COMM_NULL;
  PetscReal         lower_[3] = {0, 0, 0}, upper_[3] = {0, 0, 0};
  PetscReal         time_ = 0, rebuildTime_ = 0;
  // Candidates, grouped: [group_[g], group_[g+1]) share one particle and one wall.
  std::vector<PetscInt>  part_, elem_, group_;
  std::vector<int>       wallOf_;
  std::vector<char>      touching_;
  std::vector<PetscReal> spring_;  // kSpringWidth per candidate
  // Per-group scratch of the contact loop, sized at rebuild (no allocation in the loop).
  struct Scratch {
    PetscReal gap, n0[3];
    int       region, which;
    char      present, keep;
  };
  std::vector<Scratch>  scratch_;
  std::vector<PetscInt> covered_, released_;
  std::vector<PetscReal> load_;  // 6 per wall: force, torque of this rank's last evaluation
  std::vector<PetscInt>  loadContacts_;
};

}  // namespace vofdem
