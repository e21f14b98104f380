static const char help[] = "Van der Waals attraction (P7, Hamaker) between two spheres and between a sphere and a wall (the box's floor, and a\n"
                           "plane wall of -dem_walls). At rest at a set gap z the force is A R* / (6 z^2) for z0 <= z < range, A R* / (6 z0^2)\n"
                           "below z0 (the largest attraction, 2 pi w R* with w = A / (12 pi z0^2)), and zero from the range on (within 1e-10).\n"
                           "With -dem_vdw_walls 0 the walls do not attract (zero force) and two spheres as before.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/examples/Help.hpp"

#include <cstdio>

static const PetscReal R = 5e-5, A = 4.3e-20, z0 = 0.165e-9, range = 1e-6;  // regolith values of seed 002

enum class Partner { Sphere, Floor, Plane };
static const PetscReal kPlaneZ = 0.003;  // the plane wall (its particles' side up); the floor is then far out of range

// Force on particle 0 after one step from rest: two spheres about z = 5 mm (the rank boundary with
// -grid_ranks 1,1,2) with the given gap, or one sphere at that gap above the floor or above a plane
// wall at z = 3 mm. `realised` is the gap the positions actually hold: near 5 mm a double carries
// ~1e-18 m of rounding, a relative error of some 1e-9 in a 0.3 nm gap.
static PetscErrorCode ForceAtGap(Partner partner, PetscReal gap, PetscReal *force, PetscReal *realised) {
  const bool pair = partner == Partner::Sphere;
  const PetscReal base = partner == Partner::Plane ? kPlaneZ : 0;
  vofdem::Simulation sim;
  PetscReal          x[3], v[3], w[3], f[3];
  PetscBool          found;
  char               rows[256];

  PetscFunctionBeginUser;
  if (pair) std::snprintf(rows, sizeof rows, "x,y,z\n0.005,0.005,%.17g\n0.005,0.005,%.17g\n", 0.005 - R - gap / 2, 0.005 + R + gap / 2);
  else std::snprintf(rows, sizeof rows, "x,y,z\n0.005,0.005,%.17g\n", base + R + gap);
  if (partner == Partner::Plane) PetscCall(PetscOptionsInsertString(nullptr, "-dem_walls plane -dem_wall_plane_type plane -dem_wall_plane_point 0,0,0.003 -dem_wall_plane_normal 0,0,1"));
  PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, "ex07_particles.csv", rows, "particle file"));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  PetscCall(sim.Step());
  PetscCall(Particles(sim)->FindParticle(0, x, v, &found, w, f));
  *force = (pair ? f[2] : -f[2]) + 0.0;  // attraction: towards the partner (up) or the floor (down); + 0.0: no -0
  if (pair) {
    PetscReal x1[3];
    PetscCall(Particles(sim)->FindParticle(1, x1, v, &found));
    *realised = x1[2] - x[2] - 2 * R;
  } else {
    *realised = x[2] - base - R;
  }
  PetscCall(sim.Destroy());
  if (partner == Partner::Plane)  // the plane's options out again: the next runs have no such wall
    for (const char *name : {"-dem_walls", "-dem_wall_plane_type", "-dem_wall_plane_point", "-dem_wall_plane_normal"}) PetscCall(PetscOptionsClearValue(nullptr, name));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  PetscInt failures = 0;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  // Very heavy spheres (density 1e15) do not move measurably in one 1e-9 s step.
  PetscCall(PetscOptionsInsertString(nullptr, "-physics dem -grid_cells 2,2,2 -grid_upper 0.01,0.01,0.01 -gravity 0,0,0 -dem_radius 5e-5 -dem_density 1e15 "
                                              "-dem_hamaker 4.3e-20 -dem_vdw_min_gap 0.165e-9 -dem_vdw_range 1e-6 -dem_particles_file ex07_particles.csv -dt 1e-9"));
  const char *names[] = {"two spheres", "sphere and wall", "sphere and plane wall"};
  for (bool walls : {true, false}) {  // the walls attract (the default), or only the spheres do (-dem_vdw_walls 0)
    if (!walls) {
      PetscCall(PetscOptionsSetValue(nullptr, "-dem_vdw_walls", "0"));
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "-dem_vdw_walls 0:\n"));
    }
    for (Partner partner : {Partner::Sphere, Partner::Floor, Partner::Plane}) {
      const PetscReal Rstar = partner == Partner::Sphere ? R / 2 : R;
      const bool      on    = walls || partner == Partner::Sphere;
      for (PetscReal gap : {0.5 * z0, 2 * z0, 1e-8, 1e-7, 5e-7, 2e-6}) {
        if (!walls && gap > 2 * z0) continue;
        PetscReal f, g;
        PetscCall(ForceAtGap(partner, gap, &f, &g));
        const PetscReal z = PetscMax(g, z0), exact = g >= range || !on ? 0 : A * Rstar / (6 * z * z);
        const PetscReal err = exact > 0 ? PetscAbsReal(f - exact) / exact : PetscAbsReal(f);
        failures += err > 1e-10;
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s, gap %.3e m: attraction %.10e N, %s %.10e N %s\n", names[(int)partner], (double)gap, (double)f,
                              on ? "A R*/(6 z^2)" : "expected", (double)exact, err > 1e-10 ? "FAIL" : "ok"));
      }
    }
  }
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d checks\n", (int)failures));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-8
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    args: -grid_ranks 1,1,2
    output_file: output/ex07_vdw_1.out
TEST*/
