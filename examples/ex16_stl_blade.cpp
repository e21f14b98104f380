static const char help[] = "A moving STL blade pushes a bed of a few hundred spheres across a box (-dem_walls, P3).\n"
                           "The blade is a closed box of 12 triangles written as binary STL at run time (in mm, read with scale 1e-3),\n"
                           "translating at -blade_speed in x. Phase 1 (-short_steps): the bed settles from a jittered lattice and the blade\n"
                           "meets it; printed at full precision, 1 and 2 ranks agree to 1e-10 (D6). Phase 2 (-push_steps): the blade pushes;\n"
                           "checks: particle count unchanged, no particle centre ever behind the blade's front face, the mean force of the\n"
                           "particles on the blade over the second half opposes its motion (F_x < 0) and lies between 1 %% and 100 x the bed's\n"
                           "weight times the friction coefficient. Exits non-zero on failure. -dem_save_particles writes the bed at the end.\n"
                           "The tests run at -dem_dt_factor 0.25: at the default 0.3 the pushed bed's contacts bind the step from t = 0.018 s\n"
                           "(0.287 Rayleigh times, Dem::UpdateContactStepLimit), the step then follows the chaotic push, and the blade's travel\n"
                           "in 3000 steps differs between rank counts (2.980 and 2.971 mm on 1 and 4 ranks).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/dem/StlMesh.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/examples/Help.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

// A closed box [lo, hi] as 12 outward-facing triangles (two per face).
static std::vector<PetscReal> BoxTriangles(const PetscReal lo[3], const PetscReal hi[3]) {
  std::vector<PetscReal> t;
  auto corner = [&](int i) { return std::vector<PetscReal>{i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]}; };
  // Each face as a quad of corner indices, counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto &q : quads)
    for (int half = 0; half < 2; ++half)
      for (int k : {0, half + 1, half + 2}) {
        const auto c = corner(q[k]);
        t.insert(t.end(), c.begin(), c.end());
      }
  return t;
}

// Smallest distance of a particle centre ahead of the blade's front face x = front (negative: a
// particle has passed through), over all ranks.
static PetscErrorCode SmallestLead(vofdem::Dem *dem, PetscReal front, PetscReal *lead) {
  PetscInt   n;
  PetscReal *x, local = PETSC_MAX_REAL;

  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetLocalSize(dem->Swarm(), &n));
  PetscCall(DMSwarmGetField(dem->Swarm(), vofdem::field::position, nullptr, nullptr, (void **)&x));
  for (PetscInt p = 0; p < n; ++p) local = std::min(local, x[3 * p] - front);
  PetscCall(DMSwarmRestoreField(dem->Swarm(), vofdem::field::position, nullptr, nullptr, (void **)&x));
  PetscCallMPI(MPI_Allreduce(&local, lead, 1, MPIU_REAL, MPIU_MIN, PETSC_COMM_WORLD));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  vofdem::Simulation sim;
  vofdem::DemSummary s;
  PetscInt           shortSteps = 1000, printEvery = 100, pushSteps = 3000, failures = 0;
  PetscReal          speed = 0.1, start = 2.4e-3;  // m/s; m, the blade's front face at t = 0
  const PetscReal    thick = 0.6;                  // mm

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-short_steps", &shortSteps, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-push_steps", &pushSteps, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-blade_speed", &speed, nullptr));
  // The blade in mm, its back face at x = 0: 0.6 mm thick, wider than the box in y, from 0.4 mm
  // above the floor (less than a diameter: no particle fits under it) to above the box.
  {
    const PetscReal lo[3] = {0, -0.5, 0.4}, hi[3] = {thick, 3.5, 6.5};
    PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, "ex16_blade.stl", vofdem::BinaryStl(BoxTriangles(lo, hi)), "blade STL"));
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.17g,0,0", (double)(start - thick * 1e-3));
    PetscCall(PetscOptionsSetValue(nullptr, "-dem_wall_blade_offset", buf));
    std::snprintf(buf, sizeof buf, "%.17g,0,0", (double)speed);
    PetscCall(PetscOptionsSetValue(nullptr, "-dem_wall_blade_velocity", buf));
  }
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  PetscCall(dem->Summarize(&s));
  PetscCheck(s.walls.size() == 1, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "this example needs -dem_walls blade");
  const PetscInt  count0 = s.particles;
  const PetscReal weight = s.mass * 9.81, mu = dem->Material().friction;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%d particles, bed weight %.6e N; blade front at %.3e m moving at %g m/s\n", (int)count0, (double)weight, (double)start,
                        (double)speed));
  PetscReal minLead = PETSC_MAX_REAL, lead, meanFx = 0;
  PetscInt  averaged = 0;
  for (PetscInt k = 0; k <= shortSteps + pushSteps; ++k) {
    if (k > 0) PetscCall(sim.Step());
    const PetscReal front = start + speed * sim.Time();
    PetscCall(SmallestLead(dem, front, &lead));
    minLead = std::min(minLead, lead);
    if (k <= shortSteps && k % printEvery == 0) {
      PetscCall(dem->Summarize(&s));
      const vofdem::WallLoad &b = s.walls[0];
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "step %4d  particles %d  contacts %d  blade contacts %d  KE %.12e J  blade F (%.12e, %.12e, %.12e) N  lead %.12e m\n",
                            (int)k, (int)s.particles, (int)s.pairContacts, (int)b.contacts, (double)s.kinetic, (double)b.force[0], (double)b.force[1],
                            (double)b.force[2], (double)lead));
    }
    if (k > shortSteps + pushSteps / 2) {
      PetscCall(dem->Summarize(&s));
      meanFx += s.walls[0].force[0];
      ++averaged;
    }
  }
  meanFx /= averaged;
  PetscCall(dem->Summarize(&s));
  const bool kept = s.particles == count0, ahead = minLead > 0, opposes = meanFx < 0, sized = -meanFx > 0.01 * mu * weight && -meanFx < 100 * mu * weight;
  failures = !kept + !ahead + !opposes + !sized;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "after %d push steps (blade moved %.3e m): %d particles (%s); no particle centre behind the blade's front face: %s; "
                                          "mean blade F_x over the last %d steps opposes the motion: %s, between 0.01 and 100 mu x bed weight: %s\n",
                        (int)pushSteps, (double)(speed * sim.Time()), (int)s.particles, kept ? "none lost" : "LOST", ahead ? "yes" : "NO", (int)averaged,
                        opposes ? "yes" : "NO", sized ? "yes" : "NO"));
  if (!dem->SaveParticlesPath().empty()) PetscCall(dem->SaveParticles(dem->SaveParticlesPath()));
  PetscCall(sim.Destroy());
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d of 4 blade checks\n", (int)failures));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  args: -physics dem -grid_cells 5,2,3 -grid_upper 0.01,0.003,0.006 -gravity 0,0,-9.81 -dem_radius 3e-4 -dem_youngs_modulus 1e7
        -dem_restitution 0.3 -dem_friction 0.5 -dem_fill_count -1 -dem_fill_lower 0.003,0,0 -dem_fill_upper 0.01,0.003,0.0045
        -dem_fill_jitter 0.5 -seed 3 -dem_walls blade -dem_wall_blade_type stl -dem_wall_blade_file ex16_blade.stl
        -dem_wall_blade_scale 1e-3 -dem_save_particles ex16_bed.csv -dem_dt_factor 0.25
  rtol: 1e-10
  atol: 1e-20
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    args: -grid_ranks 2,1,1
    output_file: output/ex16_stl_blade_1.out
  test:
    suffix: 4
    nsize: 4
    args: -grid_ranks 4,1,1
    output_file: output/ex16_stl_blade_1.out
TEST*/
