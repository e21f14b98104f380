// Cells inside solid walls and obstacles, seen by the flow as a staircase (docs/architecture.md: the mask
// the DEM walls will share). A cell is solid when its centre is inside a solid; options
//   -flow_solid_boxes x0,y0,z0,x1,y1,z1[,...]   axis-aligned boxes (m)
//   -flow_solid_spheres cx,cy,cz,r[,...]         spheres (m)
// What the flow does with it (Flow, ViscousSolver, PressureSolver):
//  - a face touching a solid cell is blocked: its velocity is held at 0 (no penetration, no slip);
//  - a solid cell is left out of the pressure equation (identity row, no flux to its neighbours);
//    the pressure null space, with closed boundaries, is the constant on the fluid cells;
//  - the viscous stress on a fluid face whose tangential neighbour face lies in the solid (both
//    cells of that neighbour solid) sees the wall at the shared cell face, half a cell away
//    (ghost = -u, as at the box walls): "wall faces" below. Next to a blocked face that is not
//    inside the solid (a solid corner), the known value 0 at one cell's distance is used instead.
// Without any solid nothing is allocated and the flow's loops are unchanged.
#pragma once

#include "vofdem/grid/StaggeredGrid.hpp"

#include <vector>

namespace vofdem {

class SolidMask {
public:
  // A fluid face of component d (owned, `offset` into the owned array of Face(d), indices q) whose
  // neighbour along e on `side` (0: -e, 1: +e) lies inside the solid.
  struct WallFace {
    PetscInt offset;
    PetscInt q[3];
    int      e, side;
  };

  PetscErrorCode SetFromOptions(const Grid &grid);
  PetscErrorCode SetUp(const StaggeredGrid &sg);  // marks the cells, lists blocked and wall faces
  PetscErrorCode View(PetscViewer viewer) const;
  PetscErrorCode Destroy();

  bool     Any() const { return solidCells_ > 0; }   // the same on every rank
  PetscInt SolidCells() const { return solidCells_; }  // in the whole grid
  Vec      Cells() const { return cells_; }            // global vector of StaggeredGrid::Cells(): 1 solid, 0 fluid
  Vec      CellsLocal() const { return cellsLocal_; }  // ghosted; 0 outside a non-periodic box
  const std::vector<PetscInt> &Blocked(int d) const { return blocked_[d]; }
  const std::vector<WallFace> &Walls(int d) const { return walls_[d]; }

private:
  std::vector<PetscReal> boxes_, spheres_;
  const Grid            *grid_ = nullptr;
  Vec                    cells_ = nullptr, cellsLocal_ = nullptr;
  PetscInt               solidCells_ = 0;
  std::vector<PetscInt>  blocked_[3];
  std::vector<WallFace>  walls_[3];
};

}  // namespace vofdem
