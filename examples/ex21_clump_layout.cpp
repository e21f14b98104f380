static const char help[] = "The particle layout of rigid clumps (P10; their rigid-body dynamics: src/dem/Clumps.cpp, test/clumps):\n"
                           "two overlapping spheres of one clump feel no contact with each other, while two free overlapping spheres\n"
                           "push each other apart; the clump's spheres live on one rank even when they straddle a rank boundary, and stay\n"
                           "together through migrations (the clump is located by its lowest-id sphere). Exits non-zero on failure.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/examples/Help.hpp"

#include <cstdio>

// Global ids 0 and 1 form clump 7, ids 2 and 3 are free. Which rank holds each (-1: none) and how many do.
static PetscErrorCode Owners(DM swarm, PetscMPIInt owner[3], PetscInt holders[3]) {
  PetscInt    n, local[3] = {0, 0, 0};
  PetscInt64 *id;
  PetscMPIInt rank, mine[3] = {-1, -1, -1};

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCall(DMSwarmGetLocalSize(swarm, &n));
  PetscCall(DMSwarmGetField(swarm, "id", nullptr, nullptr, (void **)&id));
  for (PetscInt p = 0; p < n; ++p)
    if (id[p] >= 0 && id[p] < 3) mine[id[p]] = rank, local[id[p]] = 1;
  PetscCall(DMSwarmRestoreField(swarm, "id", nullptr, nullptr, (void **)&id));
  PetscCallMPI(MPI_Allreduce(mine, owner, 3, MPI_INT, MPI_MAX, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(local, holders, 3, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  vofdem::Simulation sim;
  PetscInt           failures = 0;
  const PetscReal    R        = 1e-3;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  // Clump spheres (radius 1 mm) at x = 5.6 and 4.4 mm, overlapping by 0.8 mm, across the boundary
  // x = 5 mm of -grid_ranks 2,1,1, moving at -0.25 m/s in x; two free spheres 3 mm above overlap by 0.1 mm.
  PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, "ex21_particles.csv",
                                  "x,y,z,vx,vy,vz,clump\n"
                                  "0.0056,0.005,0.005,-0.25,0,0,7\n"
                                  "0.0044,0.005,0.005,-0.25,0,0,7\n"
                                  "0.005,0.002,0.008,0,0,0,-1\n"
                                  "0.005,0.0039,0.008,0,0,0,-1\n",
                                  "particle file"));
  PetscCall(PetscOptionsInsertString(nullptr, "-physics dem -grid_cells 4,4,4 -grid_upper 0.01,0.01,0.01 -gravity 0,0,0 -dem_radius 1e-3 "
                                              "-dem_particles_file ex21_particles.csv -dem_skin 2e-4 -monitor_every 100000"));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  PetscMPIInt  owner[3];
  PetscInt     holders[3];
  PetscReal    x0[3], x1[3], v[3], f[3], w[3], xs[3];
  PetscBool    found;
  PetscCall(Owners(dem->Swarm(), owner, holders));
  const bool together0 = holders[0] == 1 && holders[1] == 1 && owner[0] == owner[1];
  failures += !together0;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "at the start, the clump's spheres (x = 5.6 and 4.4 mm, the first one listed leads) on one rank: %s\n", together0 ? "yes" : "NO"));
  // The clump's spheres move together (no force between them) and their lead crosses the rank
  // boundary within 500 steps (about 1 mm); every rebuild migrates.
  PetscReal gapStart, gapEnd, vStart[3];
  PetscCall(dem->FindParticle(0, x0, vStart, &found));
  PetscCall(dem->FindParticle(1, x1, v, &found));
  gapStart = x0[0] - x1[0];
  PetscReal ys[3];
  PetscCall(dem->FindParticle(2, xs, v, &found));
  PetscCall(dem->FindParticle(3, ys, v, &found));
  const PetscReal freeGapStart = ys[1] - xs[1];
  bool            together  = true;
  for (int k = 0; k < 20; ++k) {
    for (int s = 0; s < 25; ++s) PetscCall(sim.Step());
    PetscCall(Owners(dem->Swarm(), owner, holders));
    together = together && holders[0] == 1 && holders[1] == 1 && owner[0] == owner[1];
  }
  failures += !together;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "after 500 steps with migrations, still on one rank at every check: %s\n", together ? "yes" : "NO"));
  PetscCall(dem->FindParticle(0, x0, v, &found, w, f));
  PetscCall(dem->FindParticle(1, x1, v, &found));
  gapEnd = x0[0] - x1[0];
  const bool noInner = PetscAbsReal(gapEnd - gapStart) < 1e-15 && PetscAbsReal(v[0] - vStart[0]) < 1e-15;
  failures += !noInner;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "no contact inside the clump (overlap %.1f mm kept, velocity unchanged): %s\n", (double)(1e3 * (2 * R - gapStart)),
                        noInner ? "yes" : "NO"));
  PetscCall(dem->FindParticle(2, xs, v, &found));
  PetscCall(dem->FindParticle(3, ys, v, &found));
  const bool pushed = ys[1] - xs[1] > freeGapStart + 1e-5;
  failures += !pushed;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "two overlapping free spheres push each other apart (no longer overlapping): %s\n", pushed ? "yes" : "NO"));
  PetscCall(sim.Destroy());
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d checks\n", (int)failures));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    args: -grid_ranks 2,1,1
    output_file: output/ex21_clump_layout_1.out
TEST*/
