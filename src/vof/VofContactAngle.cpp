// Static contact angles of the VOF module on the box faces (Vof.hpp; docs/physics.md F4: normals and
// height-function curvature).
//
// Method (Afkhami & Bussmann 2008, Int. J. Numer. Meth. Fluids 57: 453-472, in 2-D; 2009, 61: 827-847,
// in 3-D; Basilisk's contact.h does the same on its height fields): the angle enters through the
// ghost cells beyond the wall. The interface is continued into the wall as the plane that makes the
// angle theta with it, so that every reconstruction that reads across the wall - Youngs' normal,
// the height-function normal of the PLIC planes (VofAdvect.cpp) and the height-function curvature
// (VofSurfaceTension.cpp) - sees the interface meet the wall at theta. With n = cos(theta) e_w +
// sin(theta) t (n out of phase 1, e_w the wall normal into the box, t in the wall's plane), the
// interface at depth D below the first row of cells lies D cot(theta) further along t than in that
// row; Afkhami & Bussmann's ghost height h_ghost = h_adjacent + dx / tan(theta) is the same statement
// for one layer, in 3-D divided by the cosine between t and the height's direction (their 2009 paper).
//
// Here the ghost layer m (1-4, at depth m h_w below the first row's centres) is the first row
// translated by m h_w cot(theta) t: each ghost value is the first row's alpha interpolated (bilinear
// in the wall's plane) at the point m h_w cot(theta) t back from it. Interpolation moves every column
// sum of the row, a height in cells, by exactly the translation when the column ends full and empty,
// so the ghost heights are the Afkhami-Bussmann ones. t is the direction of -grad alpha in the wall's
// plane, summed over the first row within 3 cells (weights 4 - |offset|), so that it is known where the
// translated interface comes from; without a gradient there (no interface near) the ghost is the row
// (zero gradient, as at 90 degrees). The translation is capped at 3 cells (the ghost width is 4): only
// layers deeper than 3 / cot(theta) are affected (none above 45 degrees; heights along the wall and
// Youngs' normal read the first layer only).
//
// Volume: the wall's face velocity is zero, so no flux crosses it, whatever the ghosts hold (the
// advection reads them only for the planes of the cells inside). With the angle at 90 degrees on every
// face nothing here runs: the ghosts stay zero-gradient, bitwise as before.
//
// Parallel: a ghost value needs the first row within 4 cells of its own position, more than the
// ghost layer of a rank holds at its edges. So each rank computes the ghost layers of its own part of
// the face, stores layer m in the m-th row inside the box of a global vector (a reflection), and the
// DMDA's ghost exchange brings the neighbours' parts: the same numbers on any rank count.
#include "vofdem/vof/Vof.hpp"
#include "vofdem/vof/GhostSlab.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/flow/Flow.hpp"
#include "vofdem/flow/FlowBoundary.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

namespace {

const PetscInt kLayers = 4;       // ghost layers (the alpha DMDA's width)
const PetscInt kWindow = 3;       // half width of the in-plane gradient's window
const double   kMaxShift = 3.0;   // cells: the translation's cap (window + interpolation stay inside the ghosts)

// Face index from a name: the flow's names (xlo ... zhi) or xmin ... zmax.
int FaceIndex(const std::string &name) {
  static const char *lo[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"}, *mm[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  for (int f = 0; f < 6; ++f)
    if (name == lo[f] || name == mm[f]) return f;
  return -1;
}

}  // namespace

PetscErrorCode Vof::ReadContactAngleOptions(OptionReader &opt) {
  std::vector<PetscReal>   angles = {90};
  std::vector<std::string> faces;
  PetscBool                given = PETSC_FALSE, facesGiven = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(opt.RealList("-contact_angle",
                         "Static contact angle at the walls, measured through phase 1 (alpha = 1); 90 is the neutral wall (zero-gradient alpha). One value: every wall and slip face "
                         "(or the faces of -vof_contact_angle_faces); six values: xlo,xhi,ylo,yhi,zlo,zhi. Imposed through the ghost cells (Afkhami & Bussmann 2008): "
                         "verified for 60-120 degrees (ex37)",
                         "degrees", &angles, 6, RealRange{0, 180, true, true}, &given));
  PetscCall(opt.NameList("-contact_angle_faces", "Faces that take a single -vof_contact_angle (the others stay at 90 degrees)",
                         {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi", "xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}, &faces, &facesGiven));
  const MPI_Comm comm = grid_->Comm();
  if (angles.size() != 1 && angles.size() != 6)
    VofdemInputError(comm, "option -vof_contact_angle: give one angle or six (xlo,xhi,ylo,yhi,zlo,zhi), got %d", (int)angles.size());
  if (facesGiven && angles.size() == 6) VofdemInputError(comm, "option -vof_contact_angle_faces: give one -vof_contact_angle with it, not six");
  if (facesGiven && !given) VofdemInputError(comm, "option -vof_contact_angle_faces: needs -vof_contact_angle");
  for (int f = 0; f < 6; ++f) contactNamed_[f] = false;
  for (const std::string &name : faces) contactNamed_[FaceIndex(name)] = true;
  for (int f = 0; f < 6; ++f) {
    const bool periodic = grid_->Periodic(f / 2);
    PetscReal  theta    = 90;
    if (angles.size() == 6) theta = angles[f];
    else if (facesGiven) theta = contactNamed_[f] ? angles[0] : 90;
    else if (!periodic) theta = angles[0];  // every face but periodic ones; open faces are left out in CheckContactAngleFaces
    if (periodic && theta != 90)
      VofdemInputError(comm, "option -vof_contact_angle%s: face %s is periodic (-grid_periodic): a contact angle needs a wall", facesGiven ? "_faces" : "", FlowBoundary::FaceName(f));
    if (theta != 90 && grid_->Cells()[f / 2] < kLayers)
      VofdemInputError(comm, "option -vof_contact_angle: face %s needs at least %d cells across the box in %c, got %d (-vof_contact_angle_faces names the faces that take it)", FlowBoundary::FaceName(f), (int)kLayers, "xyz"[f / 2],
                       (int)grid_->Cells()[f / 2]);
    contactAngle_[f] = theta;
    if (angles.size() == 6 && theta != 90) contactNamed_[f] = true;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::CheckContactAngleFaces(const Flow &flow) {
  PetscFunctionBeginUser;
  for (int f = 0; f < 6; ++f) {
    const FlowBoundaryType t = flow.Boundary().Face(f).type;
    if (contactAngle_[f] == 90 || t == FlowBoundaryType::Wall || t == FlowBoundaryType::Slip) continue;
    // A single angle for all faces leaves the open ones (inflow, outflow) neutral; a face named for it may not be open.
    if (contactNamed_[f])
      VofdemInputError(grid_->Comm(), "option -vof_contact_angle: face %s is %s (-flow_bc_%s): a contact angle needs a wall or slip face", FlowBoundary::FaceName(f),
                       FlowBoundary::TypeName(t), FlowBoundary::FaceName(f));
    contactAngle_[f] = 90;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::ContactAngleGhosts(Vec local) {
  PetscInt s[3], n[3], gs[3], gm[3];

  PetscFunctionBeginUser;
  bool any = false;
  for (int f = 0; f < 6; ++f) any = any || contactAngle_[f] != 90;
  if (!any) PetscFunctionReturn(0);
  const PetscInt  *N = grid_->Cells();
  const PetscReal *h = grid_->Spacing();
  PetscCall(DMDAGetCorners(da_, &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAGetGhostCorners(da_, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  if (!contactLocal_) PetscCall(DMCreateLocalVector(da_, &contactLocal_));
  // 1. Every angled face's ghost layers of this rank's part of the face, from the zero-gradient state
  // of `local` (no face reads another's result: the order of the faces does not matter).
  const PetscScalar ***a;
  PetscCall(DMDAVecGetArrayRead(da_, local, &a));
  for (int f = 0; f < 6; ++f) {
    if (contactAngle_[f] == 90) continue;
    if (!contactGhost_[f]) PetscCall(DMCreateGlobalVector(da_, &contactGhost_[f]));
    const int    d = f / 2, side = f % 2, t1 = (d + 1) % 3, t2 = (d + 2) % 3;
    const double cot = 1 / std::tan(contactAngle_[f] * PETSC_PI / 180);
    const PetscInt row = side == 0 ? 0 : N[d] - 1;  // the first row of cells inside
    PetscScalar ***g;
    PetscCall(DMDAVecGetArray(da_, contactGhost_[f], &g));
    auto A = [&](PetscInt i1, PetscInt i2) {  // first-row alpha at in-plane indices (t1, t2)
      PetscInt q[3];
      q[d] = row, q[t1] = i1, q[t2] = i2;
      return (double)PetscRealPart(a[q[2]][q[1]][q[0]]);
    };
    // Owned cells of the reflected rows: layer m lives in the m-th row from the face. The in-plane
    // direction is found once per position of the face and serves all its layers.
    PetscInt lo[3] = {s[0], s[1], s[2]}, hi[3] = {s[0] + n[0], s[1] + n[1], s[2] + n[2]};
    if (side == 0) hi[d] = std::min(hi[d], kLayers);
    else lo[d] = std::max(lo[d], N[d] - kLayers);
    if (lo[d] >= hi[d]) {  // this rank holds none of them
      PetscCall(DMDAVecRestoreArray(da_, contactGhost_[f], &g));
      continue;
    }
    for (PetscInt p2 = lo[t2]; p2 < hi[t2]; ++p2)
      for (PetscInt p1 = lo[t1]; p1 < hi[t1]; ++p1) {
        // -grad alpha in the wall's plane (physical units), weighted sum over the window.
        double gx = 0, gy = 0;
        for (PetscInt c = -kWindow; c <= kWindow; ++c)
          for (PetscInt b = -kWindow; b <= kWindow; ++b) {
            const double w = (double)((kWindow + 1 - std::abs(b)) * (kWindow + 1 - std::abs(c)));
            gx -= w * (A(p1 + b + 1, p2 + c) - A(p1 + b - 1, p2 + c)) / h[t1];
            gy -= w * (A(p1 + b, p2 + c + 1) - A(p1 + b, p2 + c - 1)) / h[t2];
          }
        const double norm = std::hypot(gx, gy);
        for (PetscInt r = lo[d]; r < hi[d]; ++r) {
          const PetscInt m = side == 0 ? r + 1 : N[d] - r;
          double         value;
          if (!(norm > 0)) value = A(p1, p2);
          else {
            // Translation of layer m in cells of t1 and t2 (capped), and the point it comes from.
            const double   S1 = std::clamp(m * h[d] * cot * gx / norm / h[t1], -kMaxShift, kMaxShift);
            const double   S2 = std::clamp(m * h[d] * cot * gy / norm / h[t2], -kMaxShift, kMaxShift);
            const double   x1 = p1 - S1, x2 = p2 - S2;
            const PetscInt i1 = (PetscInt)std::floor(x1), i2 = (PetscInt)std::floor(x2);
            const double   f1 = x1 - i1, f2 = x2 - i2;
            value = (1 - f2) * ((1 - f1) * A(i1, i2) + (f1 > 0 ? f1 * A(i1 + 1, i2) : 0.0)) +
                    (f2 > 0 ? f2 * ((1 - f1) * A(i1, i2 + 1) + (f1 > 0 ? f1 * A(i1 + 1, i2 + 1) : 0.0)) : 0.0);
          }
          PetscInt q[3];
          q[d] = r, q[t1] = p1, q[t2] = p2;
          g[q[2]][q[1]][q[0]] = value;
        }
      }
    PetscCall(DMDAVecRestoreArray(da_, contactGhost_[f], &g));
  }
  PetscCall(DMDAVecRestoreArrayRead(da_, local, &a));
  // 2. The neighbours' parts, then the layers themselves: ghost cell (layer m, in-plane position p)
  // from the reflected row; in-plane positions beyond another non-periodic face take the nearest
  // inside (zero gradient across that face, as MirrorBoundary does at edges and corners).
  for (int f = 0; f < 6; ++f) {
    if (contactAngle_[f] == 90) continue;
    const int d = f / 2, side = f % 2;
    PetscCall(DMGlobalToLocal(da_, contactGhost_[f], INSERT_VALUES, contactLocal_));
    const PetscScalar ***r;
    PetscScalar       ***out;
    PetscCall(DMDAVecGetArrayRead(da_, contactLocal_, &r));
    PetscCall(DMDAVecGetArray(da_, local, &out));
    PetscInt lo[3], hi[3];
    GhostSlabBeyondFace(f, gs, gm, N, lo, hi);
    for (PetscInt k = lo[2]; k < hi[2]; ++k)
      for (PetscInt j = lo[1]; j < hi[1]; ++j)
        for (PetscInt i = lo[0]; i < hi[0]; ++i) {
          PetscInt q[3] = {i, j, k};
          q[d]          = side == 0 ? -q[d] - 1 : 2 * N[d] - 1 - q[d];  // the reflected row
          for (int e = 0; e < 3; ++e)
            if (e != d && !grid_->Periodic(e)) q[e] = std::min(std::max(q[e], (PetscInt)0), N[e] - 1);
          out[k][j][i] = r[q[2]][q[1]][q[0]];
        }
    PetscCall(DMDAVecRestoreArray(da_, local, &out));
    PetscCall(DMDAVecRestoreArrayRead(da_, contactLocal_, &r));
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
