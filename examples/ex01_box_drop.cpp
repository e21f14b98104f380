static const char help[] = "Spheres dropped into a closed box: lattice fill with jitter, gravity, Hertz-Mindlin contacts with friction.\n"
                           "Phase 1 prints the kinetic energy and the centre-of-mass height for -short_steps steps: DEM is chaotic, but\n"
                           "over a short horizon 1, 2 and 4 ranks agree to ~1e-10. Phase 2 lets the bed settle for -settle_steps steps\n"
                           "and checks what must hold whatever the rank count: averaged over the last -average_steps steps, the walls\n"
                           "carry the whole weight (momentum balance), and the bed has come nearly to rest.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/examples/Help.hpp"

#include <petscdmswarm.h>

// Sum of the particles' heights, for the centre of mass.
static PetscErrorCode SumHeights(vofdem::Dem *dem, PetscReal *sum) {
  PetscReal *x, local = 0;
  PetscInt   n;

  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetLocalSize(dem->Swarm(), &n));
  PetscCall(DMSwarmGetField(dem->Swarm(), vofdem::field::position, nullptr, nullptr, (void **)&x));
  for (PetscInt p = 0; p < n; ++p) local += x[3 * p + 2];
  PetscCall(DMSwarmRestoreField(dem->Swarm(), vofdem::field::position, nullptr, nullptr, (void **)&x));
  PetscCallMPI(MPI_Allreduce(&local, sum, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  vofdem::Simulation sim;
  vofdem::DemSummary s;
  PetscInt           shortSteps = 1500, printEvery = 250, settleSteps = 30000, averageSteps = 5000;
  PetscReal          z;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-short_steps", &shortSteps, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-print_every", &printEvery, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-settle_steps", &settleSteps, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-average_steps", &averageSteps, nullptr));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  for (;;) {
    if (sim.StepNumber() % printEvery == 0) {
      PetscCall(dem->Summarize(&s));
      PetscCall(SumHeights(dem, &z));
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "step %4d  particles %d  contacts %d  KE %.12e J  rotational %.12e J  mean height %.14e m\n", (int)sim.StepNumber(),
                            (int)s.particles, (int)s.pairContacts, (double)s.kinetic, (double)s.rotational, (double)(z / s.particles)));
    }
    if (sim.StepNumber() >= shortSteps) break;
    PetscCall(sim.Step());
  }
  // Momentum balance: over a window, the mean z-force of the particles on all six faces equals the
  // weight N m g up to the change of vertical momentum over the window (the side walls carry part
  // of it through friction). Spheres without rolling resistance may keep rolling, so "at rest" is
  // judged against the kinetic energy of the fall (peak ~3e-6 J), not against zero.
  PetscReal load = 0;
  const PetscInt last = shortSteps + settleSteps;
  while (sim.StepNumber() < last) {
    PetscCall(sim.Step());
    if (sim.StepNumber() > last - averageSteps) {
      PetscCall(dem->Summarize(&s));
      for (int f = 0; f < 6; ++f) load -= s.wallForce[f][2] / averageSteps;
    }
  }
  const PetscReal weight = s.mass * 9.81;
  const bool      rest = s.kinetic + s.rotational < 1e-7, balanced = PetscAbsReal(load - weight) < 5e-3 * weight,
             packed = s.coordination > 3 && s.coordination < 6;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "after %d more steps: %d particles; nearly at rest (kinetic energy below 1e-7 J): %s; mean wall load over the last %d steps equals the weight within 0.5 %%: %s; mean coordination number in (3, 6): %s\n",
                        (int)settleSteps, (int)s.particles, rest ? "yes" : "no", (int)averageSteps, balanced ? "yes" : "no", packed ? "yes" : "no"));
  if (!rest || !balanced || !packed)
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "details: kinetic %g J, wall load %.6e N, weight %.6e N, coordination %.3f\n", (double)(s.kinetic + s.rotational),
                          (double)load, (double)weight, (double)s.coordination));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  args: -physics dem -grid_cells 4,4,4 -grid_upper 0.02,0.02,0.02 -dem_radius 1e-3 -dem_fill_count -1 -dem_fill_upper 0.02,0.02,0.01
        -dem_fill_spacing 2.1e-3 -dem_fill_jitter 1 -dem_restitution 0.3 -dem_friction 0.5 -seed 7
  rtol: 1e-10
  atol: 1e-20
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    args: -grid_ranks 2,1,1
    output_file: output/ex01_box_drop_1.out
  test:
    suffix: 4
    nsize: 4
    args: -grid_ranks 2,2,1
    output_file: output/ex01_box_drop_1.out
  # A 2:1 mix by equal mass (8 small spheres to 1 large by number) in a narrower, taller box, so that
  # it still makes a bed several layers deep; R_min halves the Rayleigh step, so settling takes twice
  # the steps.
  test:
    suffix: mix_1
    nsize: 1
    args: -dem_fill_radii 1e-3,5e-4 -dem_fill_mass_fractions 0.5,0.5 -settle_steps 60000 -average_steps 10000
          -grid_cells 4,4,8 -grid_upper 0.01,0.01,0.04 -dem_fill_upper 0.01,0.01,0.04
    output_file: output/ex01_box_drop_mix.out
  test:
    suffix: mix_2
    nsize: 2
    args: -dem_fill_radii 1e-3,5e-4 -dem_fill_mass_fractions 0.5,0.5 -settle_steps 60000 -average_steps 10000
          -grid_cells 4,4,8 -grid_upper 0.01,0.01,0.04 -dem_fill_upper 0.01,0.01,0.04 -grid_ranks 2,1,1
    output_file: output/ex01_box_drop_mix.out
  test:
    suffix: mix_4
    nsize: 4
    args: -dem_fill_radii 1e-3,5e-4 -dem_fill_mass_fractions 0.5,0.5 -settle_steps 60000 -average_steps 10000
          -grid_cells 4,4,8 -grid_upper 0.01,0.01,0.04 -dem_fill_upper 0.01,0.01,0.04 -grid_ranks 2,2,1
    output_file: output/ex01_box_drop_mix.out
TEST*/
