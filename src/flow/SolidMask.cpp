#include "vofdem/flow/SolidMask.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"

namespace vofdem {

PetscErrorCode SolidMask::SetFromOptions(const Grid &grid) {
  PetscBool setB = PETSC_FALSE, setS = PETSC_FALSE;

  PetscFunctionBeginUser;
  grid_ = &grid;
  PetscOptionsBegin(grid.Comm(), "flow_", "Flow: solid cells (walls and obstacles inside the box)", "Flow");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.RealList("-solid_boxes", "Solid boxes x0,y0,z0,x1,y1,z1 (any number of them, 6 values each); cells whose centre is inside are solid (default: none)", "m",
                           &boxes_, 6 * 1000, RealRange::Any(), &setB));
    PetscCall(opt.RealList("-solid_spheres", "Solid spheres cx,cy,cz,r (4 values each); cells whose centre is inside are solid (default: none)", "m", &spheres_, 4 * 1000,
                           RealRange::Any(), &setS));
  }
  PetscOptionsEnd();
  if (!setB) boxes_.clear();
  if (!setS) spheres_.clear();
  if (boxes_.size() % 6)
    VofdemInputError(grid.Comm(), "option -flow_solid_boxes: %d values is not a multiple of 6 (x0,y0,z0,x1,y1,z1 per box)", (int)boxes_.size());
  if (spheres_.size() % 4) VofdemInputError(grid.Comm(), "option -flow_solid_spheres: %d values is not a multiple of 4 (cx,cy,cz,r per sphere)", (int)spheres_.size());
  for (size_t b = 0; b < boxes_.size(); b += 6)
    for (int d = 0; d < 3; ++d)
      if (!(boxes_[b + 3 + d] > boxes_[b + d]))
        VofdemInputError(grid.Comm(), "option -flow_solid_boxes: box %d has upper %c %g not above lower %g", (int)(b / 6 + 1), "xyz"[d], (double)boxes_[b + 3 + d],
                         (double)boxes_[b + d]);
  for (size_t s = 0; s < spheres_.size(); s += 4)
    if (!(spheres_[s + 3] > 0)) VofdemInputError(grid.Comm(), "option -flow_solid_spheres: sphere %d has radius %g, must be positive", (int)(s / 4 + 1), (double)spheres_[s + 3]);
  PetscFunctionReturn(0);
}

PetscErrorCode SolidMask::SetUp(const StaggeredGrid &sg) {
  LocalField       c, cl;
  PetscInt         s[3], n[3];
  const PetscReal *h = grid_->Spacing(), *lo = grid_->Lower();

  PetscFunctionBeginUser;
  if (boxes_.empty() && spheres_.empty()) PetscFunctionReturn(0);
  PetscCall(DMCreateGlobalVector(sg.Cells(), &cells_));
  PetscCall(DMCreateLocalVector(sg.Cells(), &cellsLocal_));
  PetscCall(PetscObjectSetName((PetscObject)cells_, "flow_solid"));
  PetscCall(sg.GetGlobal(3, cells_, &c));
  sg.Owned(3, s, n);
  PetscInt mine = 0;
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscReal x[3] = {lo[0] + (i + 0.5) * h[0], lo[1] + (j + 0.5) * h[1], lo[2] + (k + 0.5) * h[2]};
        bool            in = false;
        for (size_t b = 0; b < boxes_.size() && !in; b += 6)
          in = x[0] > boxes_[b] && x[0] < boxes_[b + 3] && x[1] > boxes_[b + 1] && x[1] < boxes_[b + 4] && x[2] > boxes_[b + 2] && x[2] < boxes_[b + 5];
        for (size_t p = 0; p < spheres_.size() && !in; p += 4) {
          PetscReal r2 = 0;
          for (int d = 0; d < 3; ++d) r2 += (x[d] - spheres_[p + d]) * (x[d] - spheres_[p + d]);
          in = r2 < spheres_[p + 3] * spheres_[p + 3];
        }
        c.at(i, j, k) = in ? 1 : 0;
        mine += in;
      }
  PetscCall(sg.RestoreGlobal(3, cells_, &c));
  PetscCallMPI(MPI_Allreduce(&mine, &solidCells_, 1, MPIU_INT, MPI_SUM, grid_->Comm()));
  const PetscInt total = grid_->Cells()[0] * grid_->Cells()[1] * grid_->Cells()[2];
  if (solidCells_ == 0) VofdemInputError(grid_->Comm(), "options -flow_solid_boxes/-flow_solid_spheres: no cell centre lies inside the solids given");
  if (solidCells_ == total) VofdemInputError(grid_->Comm(), "options -flow_solid_boxes/-flow_solid_spheres: every cell is solid, no fluid is left");
  PetscCall(VecSet(cellsLocal_, 0));  // outside a non-periodic box: fluid (the box walls are FlowBoundary's)
  PetscCall(DMGlobalToLocal(sg.Cells(), cells_, INSERT_VALUES, cellsLocal_));

  // Blocked faces (a solid cell on either side) and wall faces (a fluid face whose tangential
  // neighbour face has solid cells on both sides).
  PetscCall(sg.GetLocal(3, cellsLocal_, &cl));
  for (int d = 0; d < 3; ++d) {
    LocalField face;  // only for the offsets of the owned array
    sg.Owned(d, s, n);
    face.g0[0] = s[0], face.g0[1] = s[1], face.g0[2] = s[2];
    face.stride[1] = n[0], face.stride[2] = n[0] * n[1];
    const PetscInt last = sg.Points(d, d) - 1;
    auto solidAt = [&](const PetscInt q[3]) { return PetscRealPart(cl.at(q)) > 0.5; };
    auto faceBlocked = [&](const PetscInt q[3], bool *both) {
      PetscInt cm[3] = {q[0], q[1], q[2]};
      cm[d] -= 1;
      const bool a = solidAt(cm), b = solidAt(q);
      if (both) *both = a && b;
      return a || b;
    };
    PetscInt q[3];
    for (q[2] = s[2]; q[2] < s[2] + n[2]; ++q[2])
      for (q[1] = s[1]; q[1] < s[1] + n[1]; ++q[1])
        for (q[0] = s[0]; q[0] < s[0] + n[0]; ++q[0]) {
          const PetscInt offset = (q[0] - s[0]) + (q[1] - s[1]) * face.stride[1] + (q[2] - s[2]) * face.stride[2];
          if (faceBlocked(q, nullptr)) {
            blocked_[d].push_back(offset);
            continue;
          }
          if (!grid_->Periodic(d) && (q[d] == 0 || q[d] == last)) continue;  // a box face: FlowBoundary's
          for (int e = 0; e < 3; ++e) {
            if (e == d) continue;
            for (int side = 0; side < 2; ++side) {
              PetscInt nb[3] = {q[0], q[1], q[2]};
              nb[e] += side ? 1 : -1;
              if (!grid_->Periodic(e) && (nb[e] < 0 || nb[e] >= grid_->Cells()[e])) continue;  // the box wall
              bool both;
              if (faceBlocked(nb, &both) && both) walls_[d].push_back({offset, {q[0], q[1], q[2]}, e, side});
            }
          }
        }
  }
  PetscCall(sg.RestoreLocal(3, cellsLocal_, &cl));
  PetscFunctionReturn(0);
}

PetscErrorCode SolidMask::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  if (!Any()) PetscFunctionReturn(0);
  const PetscInt total = grid_->Cells()[0] * grid_->Cells()[1] * grid_->Cells()[2];
  PetscCall(PetscViewerASCIIPrintf(viewer, "flow solid: %" PetscInt_FMT " of %" PetscInt_FMT " cells (%.3g %%) from %d box(es) and %d sphere(s); faces touching them held at 0\n",
                                   solidCells_, total, 100.0 * solidCells_ / total, (int)(boxes_.size() / 6), (int)(spheres_.size() / 4)));
  PetscFunctionReturn(0);
}

PetscErrorCode SolidMask::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&cells_));
  PetscCall(VecDestroy(&cellsLocal_));
  for (int d = 0; d < 3; ++d) {
    blocked_[d].clear();
    walls_[d].clear();
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
