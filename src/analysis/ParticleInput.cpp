// The particles the analysis reads (Analysis.hpp): gathered from a running DEM module, or read from
// a particles_<step>.h5 file that DemOutput.cpp wrote (datasets position (N x 3), radius, type and
// clump, the clump id of each sphere, -1 for a loose one; files written before it have no clump).
#include "vofdem/analysis/Analysis.hpp"

#include "vofdem/base/Runtime.hpp"
#include "vofdem/dem/Dem.hpp"
#include "vofdem/dem/ParticleSwarm.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/io/ReadAll.hpp"
#include "vofdem/io/InputPath.hpp"

#include <petscviewerhdf5.h>

#include <fstream>

namespace vofdem {

namespace {

// Every rank's values, concatenated in rank order, on every rank.
PetscErrorCode AllGather(MPI_Comm comm, const std::vector<double> &mine, std::vector<double> *all) {
  PetscMPIInt size;
  int         n = (int)mine.size();

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<int> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  all->resize((size_t)displs[size - 1] + counts[size - 1]);
  PetscCallMPI(MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all->data(), counts.data(), displs.data(), MPI_DOUBLE, comm));
  PetscFunctionReturn(0);
}


}  // namespace

PetscErrorCode PowderAnalysis::Gather(const Dem &dem, const Grid &grid, analysis::Spheres *s) {
  DM         swarm = dem.Swarm();
  PetscInt   n;
  PetscReal *x, *r;
  PetscInt  *type;
  MPI_Comm   comm;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)swarm, &comm));
  PetscCall(DMSwarmGetLocalSize(swarm, &n));
  PetscCall(DMSwarmGetField(swarm, field::position, nullptr, nullptr, (void **)&x));
  PetscCall(DMSwarmGetField(swarm, field::radius, nullptr, nullptr, (void **)&r));
  PetscCall(DMSwarmGetField(swarm, field::type, nullptr, nullptr, (void **)&type));
  std::vector<double> mx(x, x + 3 * n), mr(r, r + n), mt(type, type + n), ax, ar, at;
  PetscCall(DMSwarmRestoreField(swarm, field::type, nullptr, nullptr, (void **)&type));
  PetscCall(DMSwarmRestoreField(swarm, field::radius, nullptr, nullptr, (void **)&r));
  PetscCall(DMSwarmRestoreField(swarm, field::position, nullptr, nullptr, (void **)&x));
  PetscCall(AllGather(comm, mx, &ax));
  PetscCall(AllGather(comm, mr, &ar));
  PetscCall(AllGather(comm, mt, &at));
  *s   = analysis::Spheres();
  s->x = ax, s->r = ar;
  for (double t : at) s->type.push_back((std::int64_t)t);
  {  // Rigid clumps (P10): each member's clump id (-1: a loose sphere), none when no clump exists.
    ParticleArrays a;
    PetscCall(dem.Particles().GetArrays(&a));
    int any = 0, anyGlobal;
    for (PetscInt p = 0; p < a.n && !any; ++p) any = a.clump[p] >= 0;
    PetscCallMPI(MPI_Allreduce(&any, &anyGlobal, 1, MPI_INT, MPI_LOR, comm));
    std::vector<double> mc(a.clump, a.clump + a.n), ac;
    PetscCall(dem.Particles().RestoreArrays(&a));
    if (anyGlobal) {
      PetscCall(AllGather(comm, mc, &ac));
      for (double c : ac) s->clump.push_back((std::int64_t)c);
    }
  }
  for (int d = 0; d < 3; ++d) s->periodic[d] = grid.Periodic(d), s->lower[d] = grid.Lower()[d], s->upper[d] = grid.Upper()[d];
  PetscFunctionReturn(0);
}

PetscErrorCode PowderAnalysis::Read(MPI_Comm comm, const std::string &path, analysis::Spheres *s) {
  PetscViewer         viewer;
  std::vector<double> t;

  PetscFunctionBeginUser;
  // The HDF5 signature first, so that a wrong file is one line, not HDF5's and PETSc's traces.
  std::ifstream f(path, std::ios::binary);
  if (!f.good()) VofdemInputError(comm, "option -analysis_input: cannot open '%s'%s", path.c_str(), RelativePathNote(path).c_str());
  char sig[8] = {0};
  f.read(sig, 8);
  if (std::string(sig, 8) != std::string("\x89HDF\r\n\x1a\n", 8)) VofdemInputError(comm, "option -analysis_input: '%s' is not an HDF5 file", path.c_str());
  PetscCall(PetscViewerHDF5Open(comm, path.c_str(), FILE_MODE_READ, &viewer));
  PetscBool has[4];
  const char *names[4] = {"/position", "/radius", "/type", "/clump"};
  for (int k = 0; k < 4; ++k) PetscCall(PetscViewerHDF5HasDataset(viewer, names[k], &has[k]));
  if (!has[0] || !has[1])
    VofdemInputError(comm, "option -analysis_input: '%s' has no %s dataset (a particles_<step>.h5 file of -dem_output_every is expected)", path.c_str(), has[0] ? "radius" : "position");
  *s = analysis::Spheres();
  PetscCall(ReadAll(viewer, comm, "position", -1, 3, &s->x));
  PetscCall(ReadAll(viewer, comm, "radius", -1, 1, &s->r));
  if (has[2]) PetscCall(ReadAll(viewer, comm, "type", -1, 1, &t));
  std::vector<double> c;
  if (has[3]) PetscCall(ReadAll(viewer, comm, "clump", -1, 1, &c));
  PetscCall(PetscViewerDestroy(&viewer));
  if (s->x.size() != 3 * s->r.size()) VofdemInputError(comm, "option -analysis_input: '%s': %ld positions for %ld radii", path.c_str(), (long)s->x.size() / 3, (long)s->r.size());
  s->type.assign(s->r.size(), 0);
  for (size_t i = 0; i < t.size() && i < s->type.size(); ++i) s->type[i] = (std::int64_t)t[i];
  // Clump ids (files written before them have none: every sphere is then a particle, and a clump's
  // overlapping members count twice in a packing).
  if (!has[3]) PetscCall(PetscPrintf(comm, "analysis: '%s' has no clump dataset (written before clump ids were saved): every sphere is analysed as a particle\n", path.c_str()));
  if (has[3] && c.size() != s->r.size()) VofdemInputError(comm, "option -analysis_input: '%s': %ld clump ids for %ld particles", path.c_str(), (long)c.size(), (long)s->r.size());
  bool any = false;
  for (double v : c) any = any || v >= 0;
  if (any)
    for (double v : c) s->clump.push_back((std::int64_t)v);
  PetscFunctionReturn(0);
}

}  // namespace vofdem
