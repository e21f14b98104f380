static const char help[] = "Bulk statistics of a bed of spheres dropped into a closed box (the long-horizon half of D6).\n"
                           "A granular gas (random fill, -dem_fill_velocity_spread, gravity, Hertz-Mindlin with friction) collides, falls and\n"
                           "settles in a box; after -steps steps it\n"
                           "prints statistics averaged over the last -average_steps steps: centre-of-mass height, packing fraction of a\n"
                           "horizontal slab, mean coordination number, floor load over weight, kinetic energy. DEM is chaotic: after a\n"
                           "long run on 1, 2 or 4 ranks the positions differ, and only such statistics can be compared, against the\n"
                           "spread of a 1-rank ensemble of seeds (test/statistics/d6_rank_statistics.py). Over a short horizon the\n"
                           "printed values agree across rank counts to ~1e-10 (this file's TEST block).\n\n";

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/examples/Help.hpp"

#include <petscdmswarm.h>

#include <algorithm>

namespace {

struct Settings {
  PetscInt  steps = 20000, averageSteps = 2000, sampleEvery = 10;
  PetscReal slab[2] = {2e-3, 4e-3};  // packing-fraction slab z range, m
};

PetscErrorCode ReadSettings(Settings *s) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "ex20: bed statistics", "ex20");
  {
    vofdem::OptionReader opt(PetscOptionsObject);
    PetscCall(opt.Int("-steps", "Time steps to run", &s->steps, 1));
    PetscCall(opt.Int("-average_steps", "Average the statistics over this many last steps", &s->averageSteps, 1));
    PetscCall(opt.Int("-sample_every", "Sample the statistics every this many steps inside the average", &s->sampleEvery, 1));
    PetscCall(opt.RealVector("-slab", "z range of the slab whose packing fraction is measured", "m", s->slab, 2));
  }
  PetscOptionsEnd();
  if (s->averageSteps > s->steps)
    VofdemInputError(PETSC_COMM_WORLD, "option -average_steps: %" PetscInt_FMT " exceeds -steps %" PetscInt_FMT, s->averageSteps, s->steps);
  if (!(s->slab[1] > s->slab[0])) VofdemInputError(PETSC_COMM_WORLD, "option -slab: the upper height must exceed the lower");
  PetscFunctionReturn(0);
}

// Volume of a sphere (centre height z, radius r) between the planes z = a and z = b (a < b):
// the integral of pi (r^2 - (h - z)^2) dh over [max(a, z - r), min(b, z + r)].
PetscReal SphereSlabVolume(PetscReal z, PetscReal r, PetscReal a, PetscReal b) {
  const PetscReal lo = std::max(a, z - r) - z, hi = std::min(b, z + r) - z;
  if (hi <= lo) return 0;
  return PETSC_PI * (r * r * (hi - lo) - (hi * hi * hi - lo * lo * lo) / 3);
}

// Sum over the particles of m z and of the solid volume inside the slab; global sums.
PetscErrorCode Moments(vofdem::Dem *dem, const PetscReal slab[2], PetscReal *massHeight, PetscReal *slabSolid) {
  PetscReal *x, *r, *m, local[2] = {0, 0}, global[2];
  PetscInt   n;

  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetLocalSize(dem->Swarm(), &n));
  PetscCall(DMSwarmGetField(dem->Swarm(), vofdem::field::position, nullptr, nullptr, (void **)&x));
  PetscCall(DMSwarmGetField(dem->Swarm(), vofdem::field::radius, nullptr, nullptr, (void **)&r));
  PetscCall(DMSwarmGetField(dem->Swarm(), vofdem::field::mass, nullptr, nullptr, (void **)&m));
  for (PetscInt p = 0; p < n; ++p) {
    local[0] += m[p] * x[3 * p + 2];
    local[1] += SphereSlabVolume(x[3 * p + 2], r[p], slab[0], slab[1]);
  }
  PetscCall(DMSwarmRestoreField(dem->Swarm(), vofdem::field::mass, nullptr, nullptr, (void **)&m));
  PetscCall(DMSwarmRestoreField(dem->Swarm(), vofdem::field::radius, nullptr, nullptr, (void **)&r));
  PetscCall(DMSwarmRestoreField(dem->Swarm(), vofdem::field::position, nullptr, nullptr, (void **)&x));
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  *massHeight = global[0], *slabSolid = global[1];
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  vofdem::Simulation sim;
  vofdem::DemSummary s;
  Settings           set;
  PetscReal          gz = -9.81;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(ReadSettings(&set));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  {
    PetscReal g[3] = {0, 0, -9.81};
    PetscInt  three = 3;
    PetscCall(PetscOptionsGetRealArray(nullptr, nullptr, "-gravity", g, &three, nullptr));
    gz = g[2];
  }
  PetscCall(dem->Summarize(&s));
  const PetscInt  initial = s.particles;
  const PetscReal weight = s.mass * PetscAbsReal(gz);
  const PetscReal *lo = sim.GetGrid().Lower(), *hi = sim.GetGrid().Upper();
  const PetscReal slabVolume = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (set.slab[1] - set.slab[0]);

  // Every statistic is a mean over samples in the last -average_steps steps, so that one
  // rattling particle does not decide it; the floor (z-) load is compared with the weight
  // (the side walls carry the rest through friction: Janssen).
  PetscReal height = 0, packing = 0, coordination = 0, floorLoad = 0, kinetic = 0;
  PetscInt  samples = 0;
  while (sim.StepNumber() < set.steps) {
    PetscCall(sim.Step());
    const PetscInt left = set.steps - sim.StepNumber();
    if (left < set.averageSteps && left % set.sampleEvery == 0) {
      PetscReal mz = 0, solid = 0;
      PetscCall(dem->Summarize(&s));
      PetscCall(Moments(dem, set.slab, &mz, &solid));
      height += mz / s.mass;
      packing += solid / slabVolume;
      coordination += s.coordination;
      floorLoad += -s.wallForce[4][2] / weight;
      kinetic += s.kinetic + s.rotational;
      ++samples;
    }
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "after %d steps: particles %d of %d\n", (int)set.steps, (int)s.particles, (int)initial));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "averaged over the last %d steps (%d samples):\n", (int)set.averageSteps, (int)samples));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "stat: centre-of-mass height | %.12e | m\n", (double)(height / samples)));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "stat: packing fraction in z [%g, %g] m | %.12e | -\n", (double)set.slab[0], (double)set.slab[1], (double)(packing / samples)));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "stat: coordination number | %.12e | -\n", (double)(coordination / samples)));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "stat: floor load / weight | %.12e | -\n", (double)(floorLoad / samples)));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "stat: kinetic energy | %.12e | J\n", (double)(kinetic / samples)));
  if (!dem->SaveParticlesPath().empty()) PetscCall(dem->SaveParticles(dem->SaveParticlesPath()));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(s.particles == initial ? 0 : PETSC_ERR_PLIB);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  # Short horizon: 2500 steps, the gas has begun to land (floor load > 0, contacts); every printed
  # statistic agrees to 1e-10 on 1, 2 and 4 ranks. The long horizon is test/statistics/d6_rank_statistics.py.
  args: -physics dem -grid_cells 4,4,6 -grid_upper 0.02,0.02,0.03 -dem_radius 1e-3 -dem_fill_mode random -dem_fill_count 400
        -dem_fill_lower 0,0,0.004 -dem_fill_upper 0.02,0.02,0.03 -dem_fill_velocity_spread 0.3 -dem_restitution 0.8 -dem_friction 0.5
        -seed 7 -steps 2500 -average_steps 1000 -slab 0.002,0.005
  rtol: 1e-10
  atol: 1e-20
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    args: -grid_ranks 2,1,1
    output_file: output/ex20_rank_statistics_1.out
  test:
    suffix: 4
    nsize: 4
    args: -grid_ranks 2,2,1
    output_file: output/ex20_rank_statistics_1.out
TEST*/
