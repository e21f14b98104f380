// Velocity boundary conditions of the flow module, one per box face (xlo, xhi, ylo, yhi, zlo, zhi),
// from -flow_bc_<face> and its companions:
//   wall     no-slip; -flow_bc_<face>_velocity gives a tangential wall velocity (a lid, a belt)
//   slip     free slip (zero normal velocity, zero tangential stress)
//   inflow   velocity -flow_bc_<face>_velocity, -flow_bc_<face>_profile uniform|parabolic
//            (parabolic: the velocity given is the centre value of a duct profile, zero at the edges)
//   outflow  pressure -flow_bc_<face>_pressure, zero normal gradient of velocity
//   periodic set by -grid_periodic (and only there)
// The pressure projection sees Neumann on every face but outflow (Dirichlet) and periodic faces.
// The ghost layers outside the box are filled here (FillGhosts): odd reflection about the face for
// a prescribed tangential velocity (the face value is the mean of the two sides), even reflection
// for the normal velocity at a wall (d(u_n)/dn = 0 there by continuity), zero gradient otherwise.
#pragma once

#include "vofdem/grid/StaggeredGrid.hpp"

#include <string>

namespace vofdem {

enum class FlowBoundaryType { Wall, Slip, Inflow, Outflow, Periodic };

struct FlowFace {
  FlowBoundaryType type = FlowBoundaryType::Wall;
  PetscReal        velocity[3] = {0, 0, 0};
  PetscReal        pressure = 0;
  bool             parabolic = false;
};

class FlowBoundary {
public:
  static const char *FaceName(int face);
  static const char *TypeName(FlowBoundaryType t);

  PetscErrorCode SetFromOptions(const Grid &grid);  // reads and checks -flow_bc_*
  PetscErrorCode View(PetscViewer viewer) const;

  const FlowFace &Face(int face) const { return face_[face]; }
  bool HasOutflow() const;

  // Velocity of component d prescribed at point x on box face `face` (wall motion or inflow,
  // with the parabolic profile applied); 0 for slip/outflow.
  PetscReal Prescribed(int face, int d, const PetscReal x[3]) const;

  // Fills the ghost layers outside the box of the local vector of velocity component d.
  PetscErrorCode FillVelocityGhosts(const StaggeredGrid &sg, int d, Vec local) const;
  // Zero-gradient ghosts of a cell-centred local vector (density, viscosity, eps, pressure).
  PetscErrorCode FillCellGhosts(const StaggeredGrid &sg, Vec local) const;
  // Sets the boundary faces of velocity component d in a global vector: the prescribed normal
  // velocity on wall/slip/inflow faces, the neighbour's value (zero gradient) on outflow faces.
  // An inflow's velocity is superficial (volume flux per area, docs/physics.md F1): with particles next
  // to the face the interstitial face velocity is U/eps of the cell there, so that eps_f u_f = U
  // (eps_f is that cell's eps: FillCellGhosts mirrors it). Without particles eps = 1: unchanged.
  PetscErrorCode ApplyNormal(const StaggeredGrid &sg, int d, Vec global) const;
  // Its linear part: the normal velocity at outflow faces taken from the inner face (zero gradient).
  PetscErrorCode CopyOutflowNormal(const StaggeredGrid &sg, int d, Vec global) const;
  // The fluid fraction (cell-centred global vector) that ApplyNormal divides inflows by; none: 1.
  void SetFluidFraction(Vec epsCells) { eps_ = epsCells; }

private:
  FlowFace        face_[6];
  const Grid     *grid_ = nullptr;
  Vec             eps_  = nullptr;
};

}  // namespace vofdem
