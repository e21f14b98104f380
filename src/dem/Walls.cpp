// Walls beyond the box faces: options, set-up, motion, candidate search, loads (see Walls.hpp; the
// contact loop is in WallContacts.hpp).
#include "vofdem/dem/Walls.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

namespace vofdem {

namespace {

// Unit vector of v; false for the zero vector.
bool Normalize(PetscReal v[3]) {
  const PetscReal l = std::sqrt(wall::Dot(v, v));
  if (!(l > 0) || !std::isfinite(l)) return false;
  for (int d = 0; d < 3; ++d) v[d] /= l;
  return true;
}

// Distance of x from the line through c with unit direction a.
PetscReal DistanceFromAxis(const PetscReal c[3], const PetscReal a[3], const PetscReal x[3]) {
  PetscReal s[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
  const PetscReal along = wall::Dot(s, a);
  for (int d = 0; d < 3; ++d) s[d] -= along * a[d];
  return std::sqrt(wall::Dot(s, s));
}

}  // namespace

PetscErrorCode WallSet::ReadWall(MPI_Comm comm, PetscOptionItems *items, const std::string &name, bool help, Wall *w) {
  OptionReader opt(items);
  const std::string p = "-wall_" + name + "_";
  auto N = [&](const char *what) { return p + what; };
  auto full = [&](const char *what) { return opt.FullName(N(what).c_str()); };
  static const std::vector<std::string> types = {"plane", "cylinder", "stl"};
  std::vector<std::string> type = {"plane"};
  PetscBool typeSet = PETSC_FALSE, set = PETSC_FALSE, rotSet = PETSC_FALSE;

  PetscFunctionBeginUser;
  w->name = name;
  PetscCall(opt.NameList(N("type").c_str(), "Kind of the wall: plane, cylinder or stl (a triangle mesh)", types, &type, &typeSet));
  if (!typeSet && !help) VofdemInputError(comm, "option %s is missing: wall '%s' of -dem_walls needs a type (plane, cylinder or stl)", full("type").c_str(), name.c_str());
  if (type.size() != 1) VofdemInputError(comm, "option %s: give one type (plane, cylinder or stl)", full("type").c_str());
  w->kind = type[0] == "plane" ? WallKind::Plane : type[0] == "cylinder" ? WallKind::Cylinder : WallKind::Mesh;
  const bool plane = help || w->kind == WallKind::Plane, cyl = help || w->kind == WallKind::Cylinder, stl = help || w->kind == WallKind::Mesh;
  if (plane || cyl) PetscCall(opt.RealVector(N("point").c_str(), "Plane: a point on it; cylinder: a point on its axis", "m", w->point, 3));
  if (plane) {
    PetscCall(opt.RealVector(N("normal").c_str(), "Plane normal, pointing to the particles' side (required for a plane)", "-", w->dir, 3, RealRange::Any(), &set));
    if (!help && !set) VofdemInputError(comm, "option %s is missing: plane wall '%s' needs its normal", full("normal").c_str(), name.c_str());
    if (!help && !Normalize(w->dir)) VofdemInputError(comm, "option %s: the normal must not be zero", full("normal").c_str());
  }
  if (cyl) {
    std::vector<std::string> side = {"inside"};
    PetscReal                extent[2] = {PETSC_MIN_REAL, PETSC_MAX_REAL};
    PetscCall(opt.RealVector(N("axis").c_str(), "Cylinder axis direction (required for a cylinder)", "-", w->dir, 3, RealRange::Any(), &set));
    if (!help && !set) VofdemInputError(comm, "option %s is missing: cylinder wall '%s' needs its axis", full("axis").c_str(), name.c_str());
    if (!help && !Normalize(w->dir)) VofdemInputError(comm, "option %s: the axis must not be zero", full("axis").c_str());
    PetscCall(opt.Real(N("radius").c_str(), "Cylinder radius (required for a cylinder)", "m", &w->radius, RealRange::Positive(), &set));
    if (!help && !set) VofdemInputError(comm, "option %s is missing: cylinder wall '%s' needs its radius", full("radius").c_str(), name.c_str());
    PetscCall(opt.NameList(N("side").c_str(), "Cylinder: the particles are inside (a drum) or outside (a rod)", {"inside", "outside"}, &side));
    if (side.size() != 1) VofdemInputError(comm, "option %s: give inside or outside", full("side").c_str());
    w->inside = side[0] == "inside";
    PetscCall(opt.RealVector(N("extent").c_str(), "Cylinder: axial range lo,hi from the point along the axis, open ends (default: unbounded)", "m", extent, 2,
                             RealRange::Any(), &set));
    if (set && !(extent[1] > extent[0])) VofdemInputError(comm, "option %s: the upper end must exceed the lower", full("extent").c_str());
    w->lo = extent[0], w->hi = extent[1];
  }
  if (stl) {
    PetscCall(opt.String(N("file").c_str(), "STL file of the mesh, ASCII or binary (required for stl)", &w->file, &set));
    if (!help && !set) VofdemInputError(comm, "option %s is missing: stl wall '%s' needs its file", full("file").c_str(), name.c_str());
    PetscCall(opt.Real(N("scale").c_str(), "Factor applied to the STL coordinates (e.g. 1e-3 for a file in mm)", "-", &w->scale, RealRange::Positive()));
    PetscCall(opt.RealVector(N("offset").c_str(), "Shift added to the scaled STL coordinates", "m", w->offset, 3));
  }
  wall::Motion &m = w->motion;
  PetscCall(opt.RealVector(N("velocity").c_str(), "Constant translation velocity of the wall", "m/s", m.velocity, 3));
  PetscCall(opt.Real(N("angular_velocity").c_str(), "Angular velocity about the rotation axis (right-handed)", "rad/s", &m.omega));
  PetscCall(opt.RealVector(N("rotation_axis").c_str(), "Axis of the wall's rotation", "-", m.axis, 3));
  if (!help && !Normalize(m.axis)) VofdemInputError(comm, "option %s: the axis must not be zero", full("rotation_axis").c_str());
  PetscCall(opt.RealVector(N("rotation_point").c_str(), "Point on the rotation axis at t = 0, also where the wall's torque is taken (default: the wall's point; stl: its first vertex)",
                           "m", m.center, 3, RealRange::Any(), &rotSet));
  if (!rotSet && (plane || cyl) && !help) std::copy(w->point, w->point + 3, m.center);
  // A scene in phases without a restart (seed 001: the powder settles in the hopper, then the
  // hopper's side goes and the blade starts): a wall may wait before it moves and may be removed.
  PetscCall(opt.Real(N("start").c_str(), "Time the wall's motion starts; before it the wall rests at its initial pose", "s", &m.start, RealRange::NonNegative()));
  PetscCall(opt.Real(N("remove_time").c_str(), "Time from which the wall is gone (no contacts); default: never", "s", &w->removeTime, RealRange::NonNegative()));
  w->centerGiven = rotSet;
  PetscFunctionReturn(0);
}

PetscErrorCode WallSet::SetFromOptions(MPI_Comm comm) {
  std::string names;
  PetscBool   help = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  comm_ = comm;
  walls_.clear();
  PetscOptionsBegin(comm, "dem_", "Walls beyond the box faces", "Dem");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.String("-walls", "Names of the walls beyond the box faces, comma-separated; each is set by -dem_wall_<name>_* (e.g. -dem_wall_<name>_type)", &names));
    const std::vector<std::string> list = SplitList(names);
    if (list.size() > (size_t)kMaxWalls) VofdemInputError(comm, "option -dem_walls: at most %d walls", kMaxWalls);
    for (const std::string &n : list) {
      const bool ok = !n.empty() && std::all_of(n.begin(), n.end(), [](char c) { return std::islower((unsigned char)c) || std::isdigit((unsigned char)c); });
      if (!ok) VofdemInputError(comm, "option -dem_walls: '%s' is not a wall name (lower-case letters and digits only)", n.c_str());
      for (const Wall &w : walls_)
        if (w.name == n) VofdemInputError(comm, "option -dem_walls: the name '%s' is given twice", n.c_str());
      walls_.emplace_back();
      PetscCall(ReadWall(comm, PetscOptionsObject, n, help, &walls_.back()));
    }
    // -help lists the per-wall options once, for a wall called NAME.
    if (help && list.empty()) {
      Wall dummy;
      PetscCall(ReadWall(comm, PetscOptionsObject, "NAME", true, &dummy));
    }
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode WallSet::SetUp(const PetscReal boxLower[3], const PetscReal boxUpper[3]) {
  PetscFunctionBeginUser;
  for (Wall &w : walls_) {
    if (w.kind != WallKind::Mesh) continue;
    const std::string option = "-dem_wall_" + w.name + "_file";
    PetscCall(ReadStlMesh(comm_, w.file, w.scale, w.offset, option.c_str(), &w.mesh));
  }
  Prepare(boxLower, boxUpper);
  PetscFunctionReturn(0);
}

void WallSet::AddPlane(const std::string &name, const PetscReal point[3], const PetscReal normal[3], const wall::Motion &motion) {
  Wall w;
  w.name = name, w.kind = WallKind::Plane, w.motion = motion, w.centerGiven = true;
  std::copy(point, point + 3, w.point), std::copy(normal, normal + 3, w.dir);
  Normalize(w.dir), Normalize(w.motion.axis);
  walls_.push_back(w);
}

void WallSet::AddCylinder(const std::string &name, const PetscReal point[3], const PetscReal axis[3], PetscReal radius, bool inside, const wall::Motion &motion) {
  Wall w;
  w.name = name, w.kind = WallKind::Cylinder, w.motion = motion, w.centerGiven = true, w.radius = radius, w.inside = inside;
  std::copy(point, point + 3, w.point), std::copy(axis, axis + 3, w.dir);
  Normalize(w.dir), Normalize(w.motion.axis);
  walls_.push_back(w);
}

void WallSet::AddMesh(const std::string &name, const StlMesh &mesh, const wall::Motion &motion) {
  Wall w;
  w.name = name, w.kind = WallKind::Mesh, w.motion = motion, w.centerGiven = true, w.mesh = mesh;
  Normalize(w.motion.axis);
  walls_.push_back(w);
}

void WallSet::Prepare(const PetscReal boxLower[3], const PetscReal boxUpper[3]) {
  std::copy(boxLower, boxLower + 3, lower_);
  std::copy(boxUpper, boxUpper + 3, upper_);
  time_ = rebuildTime_ = 0;
  for (Wall &w : walls_) {
    wall::Motion &m = w.motion;
    if (w.kind == WallKind::Mesh) {
      if (!w.centerGiven) std::copy(&w.mesh.vertex[0], &w.mesh.vertex[0] + 3, m.center);
      std::copy(&w.mesh.vertex[0], &w.mesh.vertex[0] + 3, w.meshLo);
      std::copy(&w.mesh.vertex[0], &w.mesh.vertex[0] + 3, w.meshHi);
      w.reachAxis = 0;
      for (size_t v = 0; v < w.mesh.vertex.size(); v += 3) {
        for (int d = 0; d < 3; ++d) w.meshLo[d] = std::min(w.meshLo[d], w.mesh.vertex[v + d]), w.meshHi[d] = std::max(w.meshHi[d], w.mesh.vertex[v + d]);
        w.reachAxis = std::max(w.reachAxis, DistanceFromAxis(m.center, m.axis, &w.mesh.vertex[v]));
      }
      w.rotationInvariant = false;
    } else {
      // A rotation maps the surface onto itself (only the surface velocity matters) for a plane
      // turning about its normal and a cylinder about its own axis: the rollers.
      const PetscReal par = std::abs(wall::Dot(m.axis, w.dir));
      w.rotationInvariant = par > 1 - 1e-12 && (w.kind == WallKind::Plane || DistanceFromAxis(w.point, w.dir, m.center) <= 1e-12 * (1 + w.radius));
      w.reachAxis = 0;  // unbounded surface: bounded by the box in Travel()
    }
    w.pose = wall::PoseAt(m, 0);
  }
  load_.assign(6 * walls_.size(), 0);
  loadContacts_.assign(walls_.size(), 0);
}

void WallSet::Advance(PetscReal dt) {
  time_ += dt;
  for (Wall &w : walls_)
    if (w.motion.Moves()) w.pose = wall::PoseAt(w.motion, time_);
}

PetscReal WallSet::Travel(const Wall &w) const {
  const wall::Motion &m = w.motion;
  const PetscReal     dt = m.Elapsed(time_) - m.Elapsed(rebuildTime_), speed = std::sqrt(wall::Dot(m.velocity, m.velocity));
  PetscReal           travel = speed * dt;
  if (m.omega != 0 && !w.rotationInvariant) {
    PetscReal reach = w.reachAxis;  // a mesh: its farthest vertex from the axis, which moves with it
    if (w.kind != WallKind::Mesh) {
      // An unbounded surface: only the part inside the box can touch a particle; its farthest
      // point from the axis now, plus the axis' own travel since the rebuild.
      reach = 0;
      for (int c = 0; c < 8; ++c) {
        const PetscReal corner[3] = {c & 1 ? upper_[0] : lower_[0], c & 2 ? upper_[1] : lower_[1], c & 4 ? upper_[2] : lower_[2]};
        reach = std::max(reach, DistanceFromAxis(w.pose.center, m.axis, corner));
      }
      reach += travel;
    }
    travel += reach * std::min(std::abs(m.omega) * dt, (PetscReal)2);  // chord 2 rho sin(theta/2) <= rho min(theta, 2)
  }
  return travel;
}

bool WallSet::MovedBeyond(PetscReal halfSkin) const {
  for (const Wall &w : walls_) {
    if (w.motion.Moves() && Travel(w) > halfSkin) return true;
    if (w.Present(time_) != w.Present(rebuildTime_)) return true;  // removed since: drop its candidates now
  }
  return false;
}

void WallSet::SaveSprings(const ParticleArrays &a, ContactHistory *springs) const {
  for (size_t k = 0; k < part_.size(); ++k) {
    if (!touching_[k]) continue;
    const PetscReal *s = &spring_[kSpringWidth * k];
    auto            &h = (*springs)[WallElementKey(a.id[part_[k]], wallOf_[k], elem_[k])];
    std::copy(s, s + kSpringWidth, h.begin());
  }
}

void WallSet::CandidateIds(const ParticleArrays &a, std::vector<PetscReal> *ids) const {
  ids->clear();
  for (PetscInt p : part_) ids->push_back((PetscReal)a.id[p]);
}

void WallSet::BuildCandidates(const ParticleArrays &a, PetscReal reach, const ContactHistory &springs) {
  part_.clear(), elem_.clear(), group_.clear(), wallOf_.clear(), touching_.clear(), spring_.clear();
  rebuildTime_ = time_;
  auto add = [&](PetscInt p, int w, PetscInt e) {
    part_.push_back(p), wallOf_.push_back(w), elem_.push_back(e), touching_.push_back(0);
    spring_.insert(spring_.end(), kSpringWidth, 0);
    const auto it = springs.empty() ? springs.end() : springs.find(WallElementKey(a.id[p], w, e));
    if (it != springs.end()) {
      std::copy(it->second.begin(), it->second.end(), spring_.end() - kSpringWidth);
      touching_.back() = 1;
    }
  };
  // The meshes' bins must cover the largest reach asked for below (with room for larger particles
  // inserted later, so that they are not built again at every rebuild).
  PetscReal largest = 0;
  for (PetscInt p = 0; p < a.n; ++p) largest = std::max(largest, a.radius[p] + reach);
  for (Wall &w : walls_)
    if (w.kind == WallKind::Mesh && largest > 0 && w.bins.Reach() < largest) w.bins.Build(w.mesh.corner.data(), w.mesh.Triangles(), w.meshLo, w.meshHi, 1.25 * largest);
  for (PetscInt p = 0; p < a.n; ++p) {
    const PetscReal *x = &a.x[3 * p], limit = a.radius[p] + reach;
    for (int wi = 0; wi < (int)walls_.size(); ++wi) {
      const Wall &w = walls_[wi];
      if (!w.Present(time_)) continue;
      PetscReal   x0[3], n0[3], gap = 0;
      wall::ToReference(w.pose, w.motion, x, x0);
      const size_t start = part_.size();
      switch (w.kind) {
      case WallKind::Plane:
        if (wall::PlaneDistance(w.point, w.dir, x0) < limit) add(p, wi, 0);
        break;
      case WallKind::Cylinder:
        // Within reach of the open ends too: the particle may move along the axis before the next rebuild.
        if (wall::CylinderGap(w.point, w.dir, w.radius, w.inside, w.lo - limit, w.hi + limit, x0, &gap, n0) && gap < limit) add(p, wi, 0);
        break;
      case WallKind::Mesh: {
        bool near = true;
        for (int d = 0; d < 3; ++d) near = near && x0[d] > w.meshLo[d] - limit && x0[d] < w.meshHi[d] + limit;
        if (!near) break;
        const PetscReal *c = w.mesh.corner.data();
        const PetscInt  *tb, *te;
        w.bins.Near(x0, &tb, &te);  // the triangles that may be within reach, in increasing order
        for (const PetscInt *it = tb; it != te; ++it) {
          const PetscInt t = *it;
          PetscReal      q[3], s[3];
          int       which;
          wall::ClosestOnTriangle(&c[9 * t], &c[9 * t + 3], &c[9 * t + 6], x0, q, &which);
          for (int d = 0; d < 3; ++d) s[d] = x0[d] - q[d];
          if (wall::Dot(s, s) < limit * limit) add(p, wi, t);
        }
      } break;
      }
      if (part_.size() > start) group_.push_back((PetscInt)start);
    }
  }
  group_.push_back((PetscInt)part_.size());
  SizeScratch();
}

void WallSet::SizeScratch() {
  size_t largest = 1;
  for (size_t g = 0; g + 1 < group_.size(); ++g) largest = std::max(largest, (size_t)(group_[g + 1] - group_[g]));
  scratch_.resize(largest);
  covered_.reserve(6 * largest + 16);
  released_.reserve(largest);
}

PetscErrorCode WallSet::Summarize(MPI_Comm comm, std::vector<WallLoad> *loads) const {
  const size_t           nw = walls_.size();
  std::vector<PetscReal> sum(6 * nw);
  std::vector<PetscInt>  count(nw);

  PetscFunctionBeginUser;
  loads->assign(nw, WallLoad{});
  if (nw == 0) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Allreduce(load_.data(), sum.data(), (int)(6 * nw), MPIU_REAL, MPIU_SUM, comm));
  PetscCallMPI(MPI_Allreduce(loadContacts_.data(), count.data(), (int)nw, MPIU_INT, MPI_SUM, comm));
  for (size_t w = 0; w < nw; ++w) {
    WallLoad &L = (*loads)[w];
    L.name      = walls_[w].name;
    L.contacts  = count[w];
    for (int d = 0; d < 3; ++d) L.force[d] = sum[6 * w + d], L.torque[d] = sum[6 * w + 3 + d], L.point[d] = walls_[w].pose.center[d];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode WallSet::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  for (const Wall &w : walls_) {
    char geometry[320];
    if (w.kind == WallKind::Plane)
      std::snprintf(geometry, sizeof geometry, "plane through (%g, %g, %g) m, normal (%g, %g, %g)", (double)w.point[0], (double)w.point[1], (double)w.point[2],
                    (double)w.dir[0], (double)w.dir[1], (double)w.dir[2]);
    else if (w.kind == WallKind::Cylinder)
      std::snprintf(geometry, sizeof geometry, "cylinder radius %g m, axis (%g, %g, %g) through (%g, %g, %g) m, particles %s%s", (double)w.radius, (double)w.dir[0],
                    (double)w.dir[1], (double)w.dir[2], (double)w.point[0], (double)w.point[1], (double)w.point[2], w.inside ? "inside" : "outside",
                    w.lo > PETSC_MIN_REAL || w.hi < PETSC_MAX_REAL ? ", axial extent limited" : "");
    else
      std::snprintf(geometry, sizeof geometry, "STL mesh '%s': %d triangles, %d vertices, %d edges, bounds (%g, %g, %g) to (%g, %g, %g) m", w.file.c_str(),
                    (int)w.mesh.Triangles(), (int)(w.mesh.vertex.size() / 3), (int)w.mesh.edges, (double)w.meshLo[0], (double)w.meshLo[1], (double)w.meshLo[2],
                    (double)w.meshHi[0], (double)w.meshHi[1], (double)w.meshHi[2]);
    const wall::Motion &m = w.motion;
    char                motion[256] = "fixed";
    if (m.Moves())
      std::snprintf(motion, sizeof motion, "velocity (%g, %g, %g) m/s, %g rad/s about (%g, %g, %g) through (%g, %g, %g) m", (double)m.velocity[0], (double)m.velocity[1],
                    (double)m.velocity[2], (double)m.omega, (double)m.axis[0], (double)m.axis[1], (double)m.axis[2], (double)m.center[0], (double)m.center[1],
                    (double)m.center[2]);
    char phases[128] = "";
    if (m.Moves() && m.start > 0) std::snprintf(phases, sizeof phases, "; moving from t = %g s", (double)m.start);
    if (w.removeTime < PETSC_MAX_REAL) std::snprintf(phases + std::strlen(phases), sizeof phases - std::strlen(phases), "; removed at t = %g s", (double)w.removeTime);
    PetscCall(PetscViewerASCIIPrintf(viewer, "dem: wall %s: %s; %s%s\n", w.name.c_str(), geometry, motion, phases));
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
