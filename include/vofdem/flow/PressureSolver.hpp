// The pressure Poisson solve of the projection (docs/physics.md F1, F2):  -div(beta grad p) = rhs
// on the cell-centred DMDA of Grid (STAR, width 1), beta = eps/rho in the volume-averaged form.
//
// Discretisation: second-order 7-point finite volumes on the uniform grid. beta is given at CELL
// centres (SetCoefficient); a face takes the harmonic mean of its two cells,
//     beta_f = 2 beta_L beta_R / (beta_L + beta_R)   (with beta = 1/rho: 1/rho_f, rho_f = mean of rho),
// which keeps the flux continuous across a density jump (a metal/gas interface) and is what a
// later balanced-force surface tension must use for its face accelerations.
// Boundaries, per box face: Neumann (zero normal flux: walls, velocity inflow, where the boundary
// velocity enters through the rhs), Dirichlet p = value at the face (pressure outflow; beta of the
// boundary cell, half-cell distance), periodic (from -grid_periodic). With no Dirichlet face the
// constant null space is attached to the matrix and removed from (a copy of) the rhs.
//
// Solver: KSP with options prefix flow_pressure_; defaults CG + hypre BoomerAMG with the tuned
// settings of docs/petsc-notes.md (inserted only where the user gave none), or hypre's structured
// PFMG (-flow_pressure_pc pfmg; matrix type hyprestruct). The preconditioner is kept while the
// coefficient has changed by less than -flow_pressure_reuse_threshold (relative, per cell) since
// it was built. The initial guess is the p passed to Solve (the previous pressure).
//
// Save/Load: the state that changes the arithmetic of the next solve is (1) the initial guess,
// i.e. the pressure itself (saved by the flow module), and (2) the coefficient the preconditioner
// was built from (ReferenceCoefficient()) plus whether one exists. Save writes (2); Load restores
// it and rebuilds the preconditioner from it, so the next Solve repeats the original run's arithmetic.
#pragma once

#include "vofdem/grid/Grid.hpp"

#include <petscksp.h>

#include <string>

namespace vofdem {

enum class PressureBoundary { Neumann, Dirichlet, Periodic };
enum class PressurePreconditioner { BoomerAMG, PFMG };

class PressureSolver {
public:
  // Box faces in the order xlo, xhi, ylo, yhi, zlo, zhi.
  static const char *FaceName(int face);

  PetscErrorCode Create(const Grid &grid);
  // Programmatic defaults for the box faces (the flow module will derive them from its velocity
  // boundaries); options -flow_pressure_bc_<face> override them in SetFromOptions.
  PetscErrorCode SetBoundary(int face, PressureBoundary type, PetscReal value = 0);
  // Programmatic default of -flow_pressure_pc (before SetFromOptions).
  void SetPreconditioner(PressurePreconditioner pc) { pc_ = pc; }
  PressurePreconditioner Preconditioner() const { return pc_; }
  PetscErrorCode SetFromOptions();
  // Solid cells (a global vector of the cell layout, 1 solid, 0 fluid; SolidMask.hpp), before SetUp:
  // identity rows, no flux between fluid and solid, and with closed boundaries the constant on the
  // fluid cells as the null space. The vector is referenced, not copied.
  PetscErrorCode SetSolid(Vec solid);
  PetscErrorCode SetUp();
  // beta at cell centres (a vector of Grid::CellDM()), all > 0; `what` names its origin in the
  // one-line input error raised otherwise (e.g. "option -density_heavy"). Assembles the matrix;
  // decides whether the preconditioner is reused.
  PetscErrorCode SetCoefficient(Vec beta, const char *what);
  // Cells whose coefficient is 0 are held (the flow's cells held at rest, Flow::SetFaceDamping): identity
  // rows of 2 scale sum(1/h^2), no flux to their neighbours, and with closed boundaries the null space is the
  // constant on the other cells. scale > 0 allows zeros in SetCoefficient (0: every coefficient must be positive).
  void AllowHeldCells(PetscReal scale) { heldScale_ = scale; }
  // Solves with p as the initial guess; rhs is not changed.
  PetscErrorCode Solve(Vec rhs, Vec p);
  PetscErrorCode View(PetscViewer viewer) const;
  PetscErrorCode Save(PetscViewer viewer) const;
  PetscErrorCode Load(PetscViewer viewer);
  PetscErrorCode Destroy();

  // For the monitor: the last solve.
  PetscInt  Iterations() const { return iterations_; }
  PetscReal ResidualNorm() const { return residual_; }
  PetscBool PreconditionerReused() const { return reused_; }
  // Flow::Load: the saved run's reuse decision, so that the monitor reports it (and the KSP's reuse
  // setting matches) until the next SetCoefficient decides anew.
  PetscErrorCode RestoreReuseFlag(PetscBool reused);
  // Flow::Load: the operator from beta, with the saved run's preconditioner, reference and count of
  // solves since the build left as Load restored them (SetCoefficient would decide reuse anew). Without
  // a saved reference, SetCoefficient.
  PetscErrorCode SetOperatorAfterLoad(Vec beta, const char *what);
  PetscInt  PreconditionerBuilds() const { return builds_; }
  // Solves whose CG broke down by round-off within kFloorFactor of the absolute tolerance, taken as converged (Solve).
  PetscInt  FloorStops() const { return floorStops_; }
  static constexpr PetscReal kFloorFactor = 10;
  bool      HasNullSpace() const { return nullSpace_ != nullptr; }
  PressureBoundary BoundaryType(int face) const { return bc_[face]; }
  PetscReal        BoundaryValue(int face) const { return bcValue_[face]; }
  Mat       Operator() const { return A_; }
  KSP       Solver() const { return ksp_; }

private:
  PetscErrorCode Assemble(Vec beta);
  PetscErrorCode HeldNullSpace(Vec beta);  // the constant on the cells neither solid nor held
  PetscErrorCode InsertBoomerAMGDefaults();

  MPI_Comm               comm_ = MPI_COMM_NULL;
  const Grid            *grid_ = nullptr;
  DM                     dm_   = nullptr;  // the grid's cell DMDA (referenced in SetUp)
  PetscReal              h_[3] = {1, 1, 1};
  PetscInt               cells_[3] = {0, 0, 0};
  PressureBoundary       bc_[6] = {PressureBoundary::Neumann, PressureBoundary::Neumann, PressureBoundary::Neumann,
                                   PressureBoundary::Neumann, PressureBoundary::Neumann, PressureBoundary::Neumann};
  PetscReal              bcValue_[6] = {0, 0, 0, 0, 0, 0};
  PressurePreconditioner pc_ = PressurePreconditioner::BoomerAMG;
  PetscReal              reuseThreshold_ = 0.05;
  PetscInt               reuseSteps_ = 0, sinceBuild_ = 0;  // -flow_pressure_reuse_steps; solves since the last build
  Mat                    A_ = nullptr;
  KSP                    ksp_ = nullptr;
  MatNullSpace           nullSpace_ = nullptr;
  Vec                    betaLocal_ = nullptr;  // ghosted coefficient for assembly
  Vec                    betaAssembled_ = nullptr;  // betaLocal_ of the last assembly (rows whose coefficients match it are not set again)
  bool                   assembled_ = false;
  Vec                    betaRef_ = nullptr;    // coefficient the preconditioner was built from
  Vec                    bDirichlet_ = nullptr; // rhs contribution of Dirichlet faces (depends on beta)
  Vec                    work_ = nullptr;       // rhs copy
  Vec                    solid_ = nullptr, solidLocal_ = nullptr;  // SetSolid
  bool                   hasRef_ = false;
  PetscReal              heldScale_ = 0;   // AllowHeldCells
  PetscInt               heldCells_ = 0;   // zero coefficients in the last SetCoefficient
  PetscInt               iterations_ = 0, builds_ = 0, floorStops_ = 0;
  PetscReal              residual_ = 0;
  PetscBool              reused_ = PETSC_FALSE;
};

}  // namespace vofdem
