#include "vofdem/grid/Grid.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace vofdem {

PetscErrorCode Grid::SetFromOptions(MPI_Comm comm) {
  PetscFunctionBeginUser;
  comm_ = comm;
  PetscOptionsBegin(comm, "grid_", "Grid: uniform box of cells", "Grid");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.IntVector("-cells", "Number of cells in x,y,z", cells_, 3, 1, 1 << 20));
    PetscCall(opt.RealVector("-lower", "Lower corner of the box x,y,z", "m", lower_, 3));
    PetscCall(opt.RealVector("-upper", "Upper corner of the box x,y,z", "m", upper_, 3));
    PetscCall(opt.IntVector("-ranks", "Ranks per direction x,y,z; 0: PETSc decides that direction (0,1,1: vertical slabs, as LIGGGHTS' processors * 1 1)", ranks_, 3, 0, 1 << 20));
    std::vector<std::string> periodic;
    PetscCall(opt.NameList("-periodic", "Periodic directions, comma-separated (default: none; the box faces are walls)", {"x", "y", "z"}, &periodic));
    for (const auto &name : periodic) periodic_[name[0] - 'x'] = true;
  }
  PetscOptionsEnd();
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscInt product = 1;
  bool     decides = false;
  for (int d = 0; d < 3; ++d) ranks_[d] ? (void)(product *= ranks_[d]) : (void)(decides = true);
  if (decides ? size % product != 0 : product != size)
    VofdemInputError(comm, "option -grid_ranks: %" PetscInt_FMT " x %" PetscInt_FMT " x %" PetscInt_FMT " does not fit the %d ranks of the run", ranks_[0], ranks_[1],
                     ranks_[2], (int)size);
  for (int d = 0; d < 3; ++d)
    if (ranks_[d] > cells_[d])
      VofdemInputError(comm, "option -grid_ranks: %" PetscInt_FMT " ranks in %c but only %" PetscInt_FMT " cells", ranks_[d], "xyz"[d], cells_[d]);
  for (int d = 0; d < 3; ++d) {
    if (!(upper_[d] > lower_[d]))
      VofdemInputError(comm, "options -grid_lower/-grid_upper: upper corner must exceed lower corner in %c (%g <= %g)", "xyz"[d],
                       (double)upper_[d], (double)lower_[d]);
    h_[d] = (upper_[d] - lower_[d]) / cells_[d];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Grid::SetUpDMDA(DM dm) const {
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  const PetscErrorCode ierr = DMSetUp(dm);
  PetscCall(PetscPopErrorHandler());
  if (ierr) {
    char *why = nullptr;
    PetscCall(PetscErrorMessage(ierr, nullptr, &why));
    VofdemInputError(comm_, "options -grid_cells %d,%d,%d and -grid_ranks: the cells cannot be split over %d ranks (PETSc: %s); give more cells per direction, fewer ranks, or a split with -grid_ranks",
                     (int)cells_[0], (int)cells_[1], (int)cells_[2], (int)size, why && why[0] ? why : "DMSetUp failed");
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Grid::SetUp(PetscBool needVertexDM) {
  PetscMPIInt     size;
  const PetscInt *l[3];
  PetscInt        m[3];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  const DMBoundaryType bc[3] = {periodic_[0] ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_NONE, periodic_[1] ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_NONE,
                                periodic_[2] ? DM_BOUNDARY_PERIODIC : DM_BOUNDARY_NONE};
  PetscInt        md[3];
  const PetscInt *lc[3];
  for (int d = 0; d < 3; ++d) {
    md[d] = !ownership_[d].empty() ? (PetscInt)ownership_[d].size() : ranks_[d] ? ranks_[d] : PETSC_DECIDE;
    lc[d] = ownership_[d].empty() ? nullptr : ownership_[d].data();
  }
  PetscCall(DMDACreate3d(comm_, bc[0], bc[1], bc[2], DMDA_STENCIL_STAR, cells_[0], cells_[1], cells_[2], md[0], md[1], md[2], 1, 1, lc[0], lc[1], lc[2],
                         &cellDM_));
  PetscCall(DMSetOptionsPrefix(cellDM_, "grid_"));
  PetscCall(SetUpDMDA(cellDM_));
  PetscCall(DMDASetUniformCoordinates(cellDM_, lower_[0] + h_[0] / 2, upper_[0] - h_[0] / 2, lower_[1] + h_[1] / 2, upper_[1] - h_[1] / 2,
                                      lower_[2] + h_[2] / 2, upper_[2] - h_[2] / 2));
  PetscCall(DMDAGetCorners(cellDM_, &start_[0], &start_[1], &start_[2], &count_[0], &count_[1], &count_[2]));
  if (needVertexDM) {
    PetscCall(DMDAGetInfo(cellDM_, nullptr, nullptr, nullptr, nullptr, &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
    PetscCall(DMDAGetOwnershipRanges(cellDM_, &l[0], &l[1], &l[2]));
    // DMDA gives element e (nodes e, e+1) to the rank that owns node e+1 (DMDAGetElements), and
    // the swarm locates points in those elements. For rank r's elements to be its cells, rank r
    // must own nodes s_r+1 .. s_r+l_r: the extra node of each direction goes to the FIRST rank.
    // (With it on the last rank, each swarm subdomain sat one cell below its fluid cells.)
    std::vector<PetscInt> lv[3];
    for (int d = 0; d < 3; ++d) {
      lv[d].assign(l[d], l[d] + m[d]);
      lv[d].front() += 1;
    }
    // BOX stencil: DMSwarmInsertPointsUsingCellDM and point location need it (notes).
    PetscCall(DMDACreate3d(comm_, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_BOX, cells_[0] + 1, cells_[1] + 1,
                           cells_[2] + 1, m[0], m[1], m[2], 1, 1, lv[0].data(), lv[1].data(), lv[2].data(), &vertexDM_));
    PetscCall(SetUpDMDA(vertexDM_));
    PetscCall(DMDASetUniformCoordinates(vertexDM_, lower_[0], upper_[0], lower_[1], upper_[1], lower_[2], upper_[2]));
  }
  PetscFunctionReturn(0);
}

void Grid::LocalBox(PetscReal lo[3], PetscReal hi[3]) const {
  for (int d = 0; d < 3; ++d) {
    lo[d] = lower_[d] + start_[d] * h_[d];
    hi[d] = (start_[d] + count_[d] == cells_[d]) ? upper_[d] : lower_[d] + (start_[d] + count_[d]) * h_[d];
  }
}

bool Grid::OwnsPoint(const PetscReal x[3]) const {
  for (int d = 0; d < 3; ++d) {
    // Same cell arithmetic as the swarm's point location, so both agree on the owner.
    PetscInt c = (PetscInt)((x[d] - lower_[d]) / h_[d]);
    if (c == cells_[d] && x[d] <= upper_[d]) c = cells_[d] - 1;
    if (x[d] < lower_[d] || c < start_[d] || c >= start_[d] + count_[d]) return false;
  }
  return true;
}

bool Grid::OwnsParticle(const PetscReal x[3]) const {
  PetscReal y[3];
  for (int d = 0; d < 3; ++d) {
    const PetscReal L = upper_[d] - lower_[d];
    y[d]              = x[d];
    if (periodic_[d]) y[d] = y[d] < lower_[d] ? y[d] + L : y[d] > upper_[d] ? y[d] - L : y[d];
    y[d] = std::min(std::max(y[d], lower_[d]), upper_[d]);
  }
  return OwnsPoint(y);
}

PetscErrorCode Grid::View(PetscViewer viewer) const {
  PetscMPIInt size;
  PetscInt    m[3];

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  PetscCall(DMDAGetInfo(cellDM_, nullptr, nullptr, nullptr, nullptr, &m[0], &m[1], &m[2], nullptr, nullptr, nullptr, nullptr, nullptr, nullptr));
  PetscCall(PetscViewerASCIIPrintf(viewer, "grid: %" PetscInt_FMT " x %" PetscInt_FMT " x %" PetscInt_FMT " cells of %g x %g x %g m, box [%g, %g] x [%g, %g] x [%g, %g] m, ranks %" PetscInt_FMT " x %" PetscInt_FMT " x %" PetscInt_FMT "\n",
                                   cells_[0], cells_[1], cells_[2], (double)h_[0], (double)h_[1], (double)h_[2], (double)lower_[0], (double)upper_[0],
                                   (double)lower_[1], (double)upper_[1], (double)lower_[2], (double)upper_[2], m[0], m[1], m[2]));
  if (periodic_[0] || periodic_[1] || periodic_[2])
    PetscCall(PetscViewerASCIIPrintf(viewer, "grid: periodic in%s%s%s\n", periodic_[0] ? " x" : "", periodic_[1] ? " y" : "", periodic_[2] ? " z" : ""));
  PetscFunctionReturn(0);
}

PetscErrorCode Grid::Destroy() {
  PetscFunctionBeginUser;
  PetscCall(DMDestroy(&vertexDM_));
  PetscCall(DMDestroy(&cellDM_));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
