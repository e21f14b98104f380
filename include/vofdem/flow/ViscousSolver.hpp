// The implicit half of the viscous term (Crank-Nicolson, Flow.hpp): per velocity component d,
//   (eps rho)_f/dt u - 1/2 div(eps mu grad u) = rhs
// assembled on the STAR width-1 copy of the component's face DMDA (StaggeredGrid::FaceMatrixDM).
// The matrix is symmetric positive definite: the shear coefficient between two faces is the same
// seen from either; prescribed velocities (walls, inflow) enter the rhs (BoundaryRhs); boundary
// faces of the component itself get identity rows. KSP prefix flow_viscous_ (default CG + Jacobi to a 1e-6 reduction of the residual, i.e. about 1e-6 of the velocity per step, far below the discretisation error:
// the matrix is diagonally dominant by (eps rho)/dt), one KSP per component.
#pragma once

#include "vofdem/grid/AijRowWriter.hpp"
#include "vofdem/flow/FlowBoundary.hpp"
#include "vofdem/flow/SolidMask.hpp"
#include "vofdem/grid/StaggeredGrid.hpp"

#include <petscksp.h>

namespace vofdem {

class ViscousSolver {
public:
  PetscErrorCode Create(const StaggeredGrid &sg, const FlowBoundary &bc);
  void           SetSolid(const SolidMask *solid) { solid_ = solid && solid->Any() ? solid : nullptr; }  // before Assemble
  // A drag toward rest per face (Flow::SetFaceDamping), rate c (1/s), implicit in the matrix: the diagonal gains
  // (eps rho)_f c, and kHeldFactor times the mass term where c = +inf (the face then moves by 1e-12 of what it
  // would; the flow sets it to 0 after the solve). The vectors are read at every Assemble, which then always
  // sets the diagonal. nullptr: none.
  void           SetDamping(Vec rate[3]) { for (int d = 0; d < 3; ++d) damping_[d] = rate ? rate[d] : nullptr; }
  bool           Damped() const { return damping_[0] != nullptr; }
  static constexpr PetscReal kHeldFactor = 1e12;
  PetscErrorCode SetFromOptions();
  // Cell fields as ghosted local vectors of StaggeredGrid::Cells(): eps, beta = eps/rho, eps*mu.
  // Without coefficientsChanged (and after a first assembly) only the diagonal is recomputed.
  PetscErrorCode Assemble(PetscReal dt, Vec epsLocal, Vec betaLocal, Vec emLocal, PetscBool coefficientsChanged);
  PetscErrorCode Solve(int d, Vec rhs, Vec u);  // u: initial guess in, solution out
  Vec            BoundaryRhs(int d) const { return bcRhs_[d]; }
  Mat            Operator(int d) const { return A_[d]; }  // after Assemble
  PetscInt       Iterations() const { return iterations_; }
  PetscReal      AssembledDt() const { return dt_; }
  PetscErrorCode View(PetscViewer viewer) const;
  PetscErrorCode Destroy();
  // (eps rho)_f / dt from the face means eps_f and b_f = (eps/rho)_f (harmonic), as in the rhs.
  static PetscReal MassOverDt(PetscReal eF, PetscReal bF, PetscReal dt) { return eF * eF / bF / dt; }

private:
  PetscInt Row(int d, const PetscInt q[3], PetscReal dt, const LocalField &eps, const LocalField &beta, const LocalField &em, const LocalField *solid,
               MatStencil col[7], PetscScalar val[7], PetscReal *rhs, PetscReal *K) const;

  const StaggeredGrid *sg_ = nullptr;
  const FlowBoundary  *bc_ = nullptr;
  const SolidMask     *solid_ = nullptr;
  Vec                  damping_[3] = {nullptr, nullptr, nullptr};  // SetDamping
  Mat                  A_[3] = {nullptr, nullptr, nullptr};
  KSP                  ksp_[3] = {nullptr, nullptr, nullptr};
  Vec                  bcRhs_[3] = {nullptr, nullptr, nullptr};
  Vec                  diag_[3] = {nullptr, nullptr, nullptr};  // scratch of the diagonal-only update
  Vec                  K_[3] = {nullptr, nullptr, nullptr};     // viscous part of the diagonal (identity rows: 1)
  AijRowWriter         writer_[3];  // full assemblies after the first write the values in place
  PetscBool            assembled_ = PETSC_FALSE;
  PetscReal            dt_ = -1;
  PetscInt             iterations_ = 0;
};

}  // namespace vofdem
