#include "vofdem/flow/FlowBoundary.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace vofdem {

const char *FlowBoundary::FaceName(int face) {
  static const char *names[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
  return names[face];
}

const char *FlowBoundary::TypeName(FlowBoundaryType t) {
  switch (t) {
  case FlowBoundaryType::Wall: return "wall";
  case FlowBoundaryType::Slip: return "slip";
  case FlowBoundaryType::Inflow: return "inflow";
  case FlowBoundaryType::Outflow: return "outflow";
  default: return "periodic";
  }
}

bool FlowBoundary::HasOutflow() const {
  for (const FlowFace &f : face_)
    if (f.type == FlowBoundaryType::Outflow) return true;
  return false;
}

PetscErrorCode FlowBoundary::SetFromOptions(const Grid &grid) {
  PetscFunctionBeginUser;
  grid_    = &grid;
  MPI_Comm comm = grid.Comm();
  PetscOptionsBegin(comm, "flow_", "Flow: velocity boundary conditions per box face", "Flow");
  {
    OptionReader opt(PetscOptionsObject);
    for (int f = 0; f < 6; ++f) {
      const int   d        = f / 2;
      const bool  periodic = grid.Periodic(d);
      FlowFace   &F        = face_[f];
      F.type               = periodic ? FlowBoundaryType::Periodic : FlowBoundaryType::Wall;
      const std::string base = std::string("-bc_") + FaceName(f);
      const char       *name = base.c_str() + 1;  // "bc_xlo", for messages naming -flow_bc_xlo
      std::vector<std::string> chosen = {TypeName(F.type)};
      PetscBool                given = PETSC_FALSE, vGiven = PETSC_FALSE, pGiven = PETSC_FALSE, prGiven = PETSC_FALSE;
      PetscCall(opt.NameList(base.c_str(), "Boundary of this box face: wall (no-slip, may slide), slip, inflow, outflow (pressure), periodic (only with -grid_periodic)",
                             {"wall", "slip", "inflow", "outflow", "periodic"}, &chosen, &given));
      if (chosen.size() != 1) VofdemInputError(comm, "option -flow_%s: give one boundary type", name);
      const std::string &t = chosen[0];
      F.type = t == "wall" ? FlowBoundaryType::Wall : t == "slip" ? FlowBoundaryType::Slip : t == "inflow" ? FlowBoundaryType::Inflow
             : t == "outflow" ? FlowBoundaryType::Outflow : FlowBoundaryType::Periodic;
      if (periodic && F.type != FlowBoundaryType::Periodic)
        VofdemInputError(comm, "option -flow_%s: '%s' on a face of the periodic direction %c (-grid_periodic): leave the option out", name, t.c_str(), "xyz"[d]);
      if (!periodic && F.type == FlowBoundaryType::Periodic)
        VofdemInputError(comm, "option -flow_%s: 'periodic' needs %c in -grid_periodic (the grid makes a direction periodic)", name, "xyz"[d]);
      PetscCall(opt.RealVector((base + "_velocity").c_str(), "Velocity of a wall (tangential only) or of an inflow (superficial: the volume flux per area; next to particles the fluid enters at U/eps)", "m/s", F.velocity, 3, RealRange::Any(), &vGiven));
      std::vector<std::string> profile = {"uniform"};
      PetscCall(opt.NameList((base + "_profile").c_str(), "Inflow profile: uniform, or parabolic (the velocity given is the centre value; zero at the face's edges)",
                             {"uniform", "parabolic"}, &profile, &prGiven));
      if (profile.size() != 1) VofdemInputError(comm, "option -flow_%s_profile: give one profile", name);
      F.parabolic = profile[0] == "parabolic";
      PetscCall(opt.Real((base + "_pressure").c_str(), "Pressure of an outflow face", "Pa", &F.pressure, RealRange::Any(), &pGiven));
      if (vGiven && (F.type == FlowBoundaryType::Slip || F.type == FlowBoundaryType::Outflow || F.type == FlowBoundaryType::Periodic))
        VofdemInputError(comm, "option -flow_%s_velocity: a %s face takes no velocity (only wall and inflow)", name, t.c_str());
      if (prGiven && F.type != FlowBoundaryType::Inflow) VofdemInputError(comm, "option -flow_%s_profile: only an inflow face has a profile", name);
      if (pGiven && F.type != FlowBoundaryType::Outflow) VofdemInputError(comm, "option -flow_%s_pressure: only an outflow face has a pressure", name);
      if (F.type == FlowBoundaryType::Wall && F.velocity[d] != 0)
        VofdemInputError(comm, "option -flow_%s_velocity: a wall cannot move along its normal (%c component %g m/s); use inflow", name, "xyz"[d],
                         (double)F.velocity[d]);
      if (F.type == FlowBoundaryType::Inflow) {
        const PetscReal inward = (f % 2 ? -1 : 1) * F.velocity[d];
        if (!(inward > 0))
          VofdemInputError(comm, "option -flow_%s_velocity: an inflow must point into the box (%c component %g m/s)", name, "xyz"[d], (double)F.velocity[d]);
      }
    }
  }
  PetscOptionsEnd();
  // With no outflow the volume in the box cannot change: an inflow would have nowhere to go (the
  // pressure equation would have no solution).
  for (int f = 0; f < 6; ++f)
    if (face_[f].type == FlowBoundaryType::Inflow && !HasOutflow())
      VofdemInputError(comm, "option -flow_bc_%s: inflow, but no face is outflow: the fluid in the closed box has nowhere to go (make another face outflow)", FaceName(f));
  PetscFunctionReturn(0);
}

PetscReal FlowBoundary::Prescribed(int f, int d, const PetscReal x[3]) const {
  const FlowFace &F = face_[f];
  if (F.type == FlowBoundaryType::Wall) return f / 2 == d ? 0 : F.velocity[d];
  if (F.type != FlowBoundaryType::Inflow) return 0;
  PetscReal v = F.velocity[d];
  if (F.parabolic) {
    const PetscReal *lo = grid_->Lower(), *hi = grid_->Upper();
    for (int e = 0; e < 3; ++e)
      if (e != f / 2 && !grid_->Periodic(e)) {
        const PetscReal s = (x[e] - lo[e]) / (hi[e] - lo[e]);
        v *= 4 * s * (1 - s);
      }
  }
  return v;
}

namespace {

// The ghost plane g along e of a ghosted region (x innermost): its index bounds, and a copy of the
// plane `mirror` into it (even reflection, or zero gradient when mirror is the boundary point).
void GhostPlane(const PetscInt gs[3], const PetscInt gm[3], int e, PetscInt g, PetscInt pl[3], PetscInt ph[3]) {
  for (int c = 0; c < 3; ++c) pl[c] = gs[c], ph[c] = gs[c] + gm[c];
  pl[e] = g;
  ph[e] = g + 1;
}

void CopyPlane(const LocalField &f, const PetscInt gs[3], const PetscInt gm[3], int e, PetscInt g, PetscInt mirror) {
  PetscInt pl[3], ph[3];
  GhostPlane(gs, gm, e, g, pl, ph);
  const PetscInt shift = (mirror - g) * f.stride[e], nx = ph[0] - pl[0];
  for (PetscInt k = pl[2]; k < ph[2]; ++k)
    for (PetscInt j = pl[1]; j < ph[1]; ++j) {
      PetscScalar *row = &f.at(pl[0], j, k);
      for (PetscInt i = 0; i < nx; ++i) row[i] = row[i + shift];
    }
}

}  // namespace

// The ghost planes are filled plane by plane, x innermost (contiguous), the directions in the order
// x, y, z so that edge and corner ghosts take the values of the planes filled before them.
PetscErrorCode FlowBoundary::FillVelocityGhosts(const StaggeredGrid &sg, int d, Vec local) const {
  LocalField u;
  PetscInt   gs[3], gm[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetGhostCorners(sg.Face(d), &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  PetscCall(sg.GetLocal(d, local, &u));
  const PetscReal *lo = grid_->Lower(), *h = grid_->Spacing();
  for (int e = 0; e < 3; ++e) {
    if (grid_->Periodic(e)) continue;
    const PetscInt last = sg.Points(d, e) - 1;  // last point along e
    for (int side = 0; side < 2; ++side) {
      const int       f = 2 * e + side;
      const FlowFace &F = face_[f];
      // Ghost indices of this side that this rank holds.
      const PetscInt a = side ? last + 1 : gs[e], b = side ? gs[e] + gm[e] : 0;
      for (PetscInt g = a; g < b; ++g) {
        const PetscInt m = side ? g - last : -g;  // 1, 2: distance in points from the boundary point/cell
        PetscInt       mirror;
        if (d == e) mirror = side ? last - m : m;        // faces: the boundary face is index 0 / last
        else mirror = side ? last - m + 1 : m - 1;       // cells: mirror about the face
        // What the ghost takes: the mirror value (even), its negative (odd about 0), the boundary
        // point's value (zero gradient), or 2 v_b - mirror (odd about a prescribed value v_b).
        enum { Even, Odd, Boundary, AboutValue, AboutProfile } mode;
        PetscScalar vb = 0;
        if (d == e) mode = F.type == FlowBoundaryType::Wall ? Even : F.type == FlowBoundaryType::Slip ? Odd : Boundary;
        else if (F.type == FlowBoundaryType::Wall || F.type == FlowBoundaryType::Inflow) {
          mode = F.type == FlowBoundaryType::Inflow && F.parabolic ? AboutProfile : AboutValue;
          if (mode == AboutValue) {
            const PetscReal x[3] = {0, 0, 0};  // a wall's or a uniform inflow's velocity does not depend on x
            vb                   = 2 * Prescribed(f, d, x);
          }
        } else mode = Even;  // slip, outflow: zero gradient
        if (mode == Boundary) mirror = side ? last : 0;
        if (mode == Even || mode == Boundary) {
          CopyPlane(u, gs, gm, e, g, mirror);
          continue;
        }
        PetscInt pl[3], ph[3];
        GhostPlane(gs, gm, e, g, pl, ph);
        const PetscInt shift = (mirror - g) * u.stride[e], nx = ph[0] - pl[0];
        for (PetscInt k = pl[2]; k < ph[2]; ++k)
          for (PetscInt j = pl[1]; j < ph[1]; ++j) {
            PetscScalar *row = &u.at(pl[0], j, k);
            switch (mode) {
            case Even:
            case Boundary:
              break;  // copied above
            case Odd:
              for (PetscInt i = 0; i < nx; ++i) row[i] = -row[i + shift];
              break;
            case AboutValue:
              for (PetscInt i = 0; i < nx; ++i) row[i] = vb - row[i + shift];
              break;
            case AboutProfile:
              for (PetscInt i = 0; i < nx; ++i) {
                const PetscInt q[3] = {pl[0] + i, j, k};
                PetscReal      x[3];
                for (int c = 0; c < 3; ++c) x[c] = lo[c] + (c == d ? q[c] : q[c] + 0.5) * h[c];
                x[e]   = side ? grid_->Upper()[e] : lo[e];
                row[i] = 2 * Prescribed(f, d, x) - row[i + shift];
              }
              break;
            }
          }
      }
    }
  }
  PetscCall(sg.RestoreLocal(d, local, &u));
  PetscFunctionReturn(0);
}

PetscErrorCode FlowBoundary::FillCellGhosts(const StaggeredGrid &sg, Vec local) const {
  LocalField c;
  PetscInt   gs[3], gm[3];

  PetscFunctionBeginUser;
  PetscCall(DMDAGetGhostCorners(sg.Cells(), &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  PetscCall(sg.GetLocal(3, local, &c));
  for (int e = 0; e < 3; ++e) {
    if (grid_->Periodic(e)) continue;
    const PetscInt last = grid_->Cells()[e] - 1;
    for (int side = 0; side < 2; ++side) {
      const PetscInt a = side ? last + 1 : gs[e], b = side ? gs[e] + gm[e] : 0;
      for (PetscInt g = a; g < b; ++g) {
        CopyPlane(c, gs, gm, e, g, side ? 2 * last + 1 - g : -g - 1);  // mirror about the boundary face
      }
    }
  }
  PetscCall(sg.RestoreLocal(3, local, &c));
  PetscFunctionReturn(0);
}

PetscErrorCode FlowBoundary::CopyOutflowNormal(const StaggeredGrid &sg, int d, Vec global) const {
  LocalField u;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  if (grid_->Periodic(d)) PetscFunctionReturn(0);
  sg.Owned(d, s, n);
  const PetscInt last = sg.Points(d, d) - 1;
  const int      e1 = (d + 1) % 3, e2 = (d + 2) % 3;
  PetscCall(sg.GetGlobal(d, global, &u));
  for (int side = 0; side < 2; ++side) {
    const PetscInt b = side ? last : 0;
    if (face_[2 * d + side].type != FlowBoundaryType::Outflow || b < s[d] || b >= s[d] + n[d]) continue;
    PetscInt q[3], r[3];
    for (q[e2] = s[e2]; q[e2] < s[e2] + n[e2]; ++q[e2])
      for (q[e1] = s[e1]; q[e1] < s[e1] + n[e1]; ++q[e1]) {
        q[d] = b;
        for (int c = 0; c < 3; ++c) r[c] = q[c];
        // The inner face may be on the previous rank only when that rank has a single cell,
        // which StaggeredGrid forbids (2 cells per rank at least).
        r[d]    = side ? last - 1 : 1;
        u.at(q) = u.at(r);
      }
  }
  PetscCall(sg.RestoreGlobal(d, global, &u));
  PetscFunctionReturn(0);
}

PetscErrorCode FlowBoundary::ApplyNormal(const StaggeredGrid &sg, int d, Vec global) const {
  LocalField u;
  PetscInt   s[3], n[3];

  PetscFunctionBeginUser;
  if (grid_->Periodic(d)) PetscFunctionReturn(0);
  PetscCall(CopyOutflowNormal(sg, d, global));  // reads inner faces only: independent of the prescribed ones below
  sg.Owned(d, s, n);
  const PetscInt   last = sg.Points(d, d) - 1;
  const PetscReal *lo = grid_->Lower(), *h = grid_->Spacing();
  PetscCall(sg.GetGlobal(d, global, &u));
  LocalField ec;  // the cells next to the faces: a rank owning boundary face b owns its cell too
  const bool divide = eps_ && (face_[2 * d].type == FlowBoundaryType::Inflow || face_[2 * d + 1].type == FlowBoundaryType::Inflow);
  if (divide) PetscCall(sg.GetGlobal(3, eps_, &ec));
  for (int side = 0; side < 2; ++side) {
    const PetscInt b = side ? last : 0;
    const FlowFace &F = face_[2 * d + side];
    if (F.type == FlowBoundaryType::Outflow || b < s[d] || b >= s[d] + n[d]) continue;
    PetscInt q[3];
    for (q[(d + 1) % 3] = s[(d + 1) % 3]; q[(d + 1) % 3] < s[(d + 1) % 3] + n[(d + 1) % 3]; ++q[(d + 1) % 3])
      for (q[(d + 2) % 3] = s[(d + 2) % 3]; q[(d + 2) % 3] < s[(d + 2) % 3] + n[(d + 2) % 3]; ++q[(d + 2) % 3]) {
        q[d] = b;
        PetscReal x[3];
        for (int c = 0; c < 3; ++c) x[c] = lo[c] + (c == d ? q[c] : q[c] + 0.5) * h[c];
        u.at(q) = Prescribed(2 * d + side, d, x);
        if (divide && F.type == FlowBoundaryType::Inflow) {
          PetscInt c[3] = {q[0], q[1], q[2]};
          c[d]          = side ? last - 1 : 0;  // faces 0..N, cells 0..N-1
          u.at(q) /= PetscRealPart(ec.at(c));
        }
      }
  }
  if (divide) PetscCall(sg.RestoreGlobal(3, eps_, &ec));
  PetscCall(sg.RestoreGlobal(d, global, &u));
  PetscFunctionReturn(0);
}

PetscErrorCode FlowBoundary::View(PetscViewer viewer) const {
  std::string text;

  PetscFunctionBeginUser;
  char buf[160];
  for (int f = 0; f < 6; ++f) {
    const FlowFace &F = face_[f];
    std::snprintf(buf, sizeof buf, "%s%s %s", f ? ", " : "", FaceName(f), TypeName(F.type));
    text += buf;
    if ((F.type == FlowBoundaryType::Wall && (F.velocity[0] != 0 || F.velocity[1] != 0 || F.velocity[2] != 0)) || F.type == FlowBoundaryType::Inflow) {
      std::snprintf(buf, sizeof buf, " (%g, %g, %g) m/s%s", (double)F.velocity[0], (double)F.velocity[1], (double)F.velocity[2], F.parabolic ? " parabolic" : "");
      text += buf;
    }
    if (F.type == FlowBoundaryType::Outflow) {
      std::snprintf(buf, sizeof buf, " %g Pa", (double)F.pressure);
      text += buf;
    }
  }
  PetscCall(PetscViewerASCIIPrintf(viewer, "flow boundaries: %s\n", text.c_str()));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
