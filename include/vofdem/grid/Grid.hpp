// The Eulerian grid: a uniform box of cells on a cell-centred DMDA (STAR, width 1: the one matrices
// are assembled on), and, for particles, a vertex DMDA with one more node per direction whose
// ownership is chosen so that the swarm's elements on a rank are exactly that rank's fluid cells
// (see Grid::SetUp; docs/petsc-notes.md, DMSwarm).
#pragma once

#include <petscdmda.h>

#include <vector>

namespace vofdem {

class Grid {
public:
  PetscErrorCode SetFromOptions(MPI_Comm comm);  // -grid_cells, -grid_lower, -grid_upper, -grid_ranks, -grid_periodic
  PetscErrorCode SetUp(PetscBool needVertexDM);
  // Collective: rebuilds both DMDAs with these cells per rank in x, y, z (as many entries as ranks
  // in that direction), e.g. to balance particle counts (GridRepartition.cpp). Holders of the old
  // DMs (a swarm's cell DM, a halo's rank boxes) must be given the new ones.
  PetscErrorCode Repartition(const std::vector<PetscInt> cellsPerRank[3]);
  PetscErrorCode View(PetscViewer viewer) const;
  PetscErrorCode Destroy();
  // DMSetUp of a DMDA on this grid's cells (the cell, vertex and staggered DMDAs): a split PETSc refuses
  // (more ranks than cells in a direction, fewer cells per rank than the stencil) becomes one line
  // naming -grid_cells and -grid_ranks instead of PETSc's trace.
  PetscErrorCode SetUpDMDA(DM dm) const;

  DM CellDM() const { return cellDM_; }
  DM VertexDM() const { return vertexDM_; }
  const PetscReal *Lower() const { return lower_; }
  const PetscReal *Upper() const { return upper_; }
  const PetscReal *Spacing() const { return h_; }
  const PetscInt  *Cells() const { return cells_; }
  MPI_Comm         Comm() const { return comm_; }
  // -grid_periodic: the two faces normal to direction d are one (the cell DMDA is periodic there;
  // the particles' vertex DMDA is not: particles are wrapped by the DEM module, docs/petsc-notes.md).
  bool Periodic(int d) const { return periodic_[d]; }

  // The part of the box whose cells this rank owns: [lo, hi) (closed at the domain's upper end).
  void LocalBox(PetscReal lo[3], PetscReal hi[3]) const;
  // True when x lies in LocalBox() (the upper domain face belongs to the last rank).
  bool OwnsPoint(const PetscReal x[3]) const;
  // The same for a particle's centre as saved between list rebuilds: up to half a skin past a periodic
  // face (wrapped by one box length) or, after a wall overlap, past a wall (the nearest cell's owner).
  bool OwnsParticle(const PetscReal x[3]) const;

private:
  MPI_Comm  comm_     = MPI_COMM_NULL;
  DM        cellDM_   = nullptr;
  DM        vertexDM_ = nullptr;
  PetscInt  cells_[3] = {8, 8, 8};
  PetscReal lower_[3] = {0, 0, 0};
  PetscReal upper_[3] = {1, 1, 1};
  PetscReal h_[3]     = {0, 0, 0};
  PetscInt  start_[3] = {0, 0, 0}, count_[3] = {0, 0, 0};  // owned cells
  PetscInt  ranks_[3] = {0, 0, 0};                          // ranks per direction; 0: PETSc decides
  bool      periodic_[3] = {false, false, false};
  std::vector<PetscInt> ownership_[3];                      // cells per rank, once repartitioned; empty: PETSc decides
};

}  // namespace vofdem
