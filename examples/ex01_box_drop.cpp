static const char help[] = "Spheres dropped into a closed box: lattice fill with jitter, gravity, Hertz contact with the walls.\n"
                           "Prints the particle count, kinetic energy and the force on the floor every -print_every steps.\n\n";

// Particles do not touch each other yet (wall contacts only), so every particle moves on its own and
// the printed totals agree across rank counts up to the order of summation. Once all have landed,
// the floor carries the whole weight: the last lines check that against N m g.

#include "vofdem/core/Runtime.hpp"
#include "vofdem/core/Simulation.hpp"

static PetscErrorCode Run() {
  vofdem::Simulation sim;
  vofdem::DemSummary s;
  PetscInt           printEvery = 1000, steps = 12000;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-print_every", &printEvery, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-steps", &steps, nullptr));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = sim.Particles();
  for (;;) {
    if (sim.StepNumber() % printEvery == 0) {
      PetscCall(dem->Summarize(&s));
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "step %5d  t %.6e s  particles %d  KE %.8e J  wall contacts %d  floor force %.8e N\n", (int)sim.StepNumber(),
                            (double)sim.Time(), (int)s.particles, (double)s.kinetic, (int)s.wallContacts, (double)s.wallForce[4][2]));
    }
    if (sim.StepNumber() >= steps) break;
    PetscCall(sim.Step());
  }
  const vofdem::DemMaterial &mat = dem->Material();
  const PetscReal r = dem->Radius(), weight = s.particles * mat.density * 4.0 / 3.0 * PETSC_PI * r * r * r * 9.81;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "weight of all particles %.8e N, load on the floor %.8e N, relative difference %.2e\n", (double)weight,
                        (double)-s.wallForce[4][2], (double)PetscAbsReal(-s.wallForce[4][2] - weight) / weight));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  args: -physics dem -grid_cells 4,4,4 -grid_upper 0.02,0.02,0.02 -dem_radius 1e-3 -dem_fill_count -1 -dem_fill_upper 0.02,0.02,0.01
        -dem_fill_jitter 0.5 -dem_restitution 0.3 -seed 7
  rtol: 1e-9
  atol: 1e-14
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
  test:
    suffix: 4
    nsize: 4
    output_file: output/ex01_box_drop_1.out
TEST*/
