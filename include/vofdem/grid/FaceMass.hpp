// The fluid mass per face volume of the momentum equation, (eps rho)_f (grid/FaceProperties.hpp), at the owned faces
// of one velocity component, from ghosted cell fields of eps and rho: the one definition the flow's predictor, the
// coupling's deposits by face mass and the melt's momentum share all read.
#pragma once

#include "vofdem/grid/StaggeredGrid.hpp"

namespace vofdem {

// out (a global vector of sg.Face(d)) = scale (eps rho)_f at every owned face of component d; 0 on the wall faces of a
// non-periodic direction d (their velocity is the boundary's). eps, rho: local (ghosted) fields of sg.Cells().
PetscErrorCode FaceMass(const StaggeredGrid &sg, int d, LocalField &eps, LocalField &rho, PetscReal scale, Vec out);

}  // namespace vofdem
