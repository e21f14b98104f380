static const char help[] = "Load balancing (-dem_balance histogram): spheres thrown down from the upper half of a box that is split along\n"
                           "its height. Without balancing the bed ends on the lower rank(s) alone; with it the ownership ranges follow the\n"
                           "load per cell layer (particles + -dem_balance_contact_weight x their contacts) whenever largest / mean load per\n"
                           "rank exceeds -dem_balance_threshold. Prints the kinetic energy, the mean height and the contacts every\n"
                           "-print_every steps for -steps steps (1, 2 and 4 ranks agree to ~1e-10, repartitions or not), then checks that\n"
                           "the loads per rank at the end are even: largest / mean at most -max_imbalance (layers are whole cells, so the\n"
                           "best cut is not exact), and prints whether the rank holding the floor has at most the mean number of particles\n"
                           "(with contacts weighing in, the settled bed's rank takes fewer than the loose spheres' ranks).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/examples/Help.hpp"

#include <petscdmswarm.h>

#include <vector>

static PetscErrorCode Run() {
  vofdem::Simulation sim;
  vofdem::DemSummary s;
  PetscInt           steps = 4000, printEvery = 500, n;
  PetscReal          maxImbalance = 1.25;
  PetscMPIInt        size;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-steps", &steps, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-print_every", &printEvery, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-max_imbalance", &maxImbalance, nullptr));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  for (;;) {
    if (sim.StepNumber() % printEvery == 0) {
      PetscReal *x, local = 0, z;
      PetscCall(DMSwarmGetLocalSize(dem->Swarm(), &n));
      PetscCall(DMSwarmGetField(dem->Swarm(), vofdem::field::position, nullptr, nullptr, (void **)&x));
      for (PetscInt p = 0; p < n; ++p) local += x[3 * p + 2];
      PetscCall(DMSwarmRestoreField(dem->Swarm(), vofdem::field::position, nullptr, nullptr, (void **)&x));
      PetscCallMPI(MPI_Allreduce(&local, &z, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
      PetscCall(dem->Summarize(&s));
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "step %4d  particles %d  contacts %d  wall %d  KE %.12e J  rotational %.12e J  mean height %.14e m\n",
                            (int)sim.StepNumber(), (int)s.particles, (int)s.pairContacts, (int)s.wallContacts, (double)s.kinetic, (double)s.rotational,
                            (double)(z / s.particles)));
    }
    if (sim.StepNumber() >= steps) break;
    PetscCall(sim.Step());
  }
  PetscReal load, most, total;
  PetscCall(dem->BalanceLoad(&load));
  PetscCallMPI(MPI_Allreduce(&load, &most, 1, MPIU_REAL, MPI_MAX, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(&load, &total, 1, MPIU_REAL, MPI_SUM, PETSC_COMM_WORLD));
  const PetscReal imbalance = most * size / total;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "loads per rank at the end even (largest / mean at most -max_imbalance): %s\n", imbalance <= maxImbalance ? "yes" : "no"));
  // The floor's rank is rank 0 (the box is split along z only); one rank holds all particles.
  PetscInt    floorCount = 0, all = 0;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCall(DMSwarmGetLocalSize(dem->Swarm(), &n));
  if (rank == 0) floorCount = n;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &floorCount, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(&n, &all, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "the floor's rank holds at most the mean number of particles: %s\n", floorCount * size <= all ? "yes" : "no"));
  if (imbalance > maxImbalance) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "details: largest / mean %.3f, -max_imbalance %.3f\n", (double)imbalance, (double)maxImbalance));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(imbalance > maxImbalance ? PETSC_ERR_NOT_CONVERGED : 0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  args: -physics dem -grid_cells 4,4,16 -grid_upper 0.01,0.01,0.02 -dem_radius 5e-4 -dem_fill_count -1 -dem_fill_lower 0,0,0.01
        -dem_fill_upper 0.01,0.01,0.02 -dem_fill_jitter 1 -dem_fill_velocity 0,0,-0.7 -dem_restitution 0.3 -dem_friction 0.5 -seed 5
        -dem_balance histogram -dem_balance_monitor 0
  rtol: 1e-10
  atol: 1e-20
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    args: -grid_ranks 1,1,2
    output_file: output/ex15_balance_1.out
  test:
    suffix: 4
    nsize: 4
    args: -grid_ranks 1,1,4 -max_imbalance 1.5
    output_file: output/ex15_balance_1.out
TEST*/
