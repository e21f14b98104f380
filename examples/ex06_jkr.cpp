static const char help[] = "Verification D3: JKR adhesion (P6) pulled apart slowly, for two spheres and for a sphere and a wall.\n"
                           "Under displacement control the largest tension is 3 pi gamma R* = 1.5 pi w R* (within 1 %) and the bond\n"
                           "breaks at delta_c = -(3/4) (pi^2 w^2 R*/E*^2)^(1/3) (within 2 %). The spheres are made very heavy so the\n"
                           "adhesive force cannot change their pulling speed (displacement control in a dynamic code).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/examples/Help.hpp"

#include <cstdio>
#include <string>

static const PetscReal R = 1e-3, E = 1e8, nu = 0.28, gamma_ = 0.05, pull = 1e-4;

struct Pulled {
  PetscReal maxTension;   // N
  PetscReal breakOverlap; // m
};

static PetscErrorCode WriteParticles(const char *rows) {
  PetscFunctionBeginUser;
  PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, "ex06_particles.csv", std::string("x,y,z,vx,vy,vz\n") + rows, "particle file"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_particles_file", "ex06_particles.csv"));
  PetscFunctionReturn(0);
}

// Pulls particle 0 (and 1, if there is one) apart along z; `overlap` gives the current overlap.
// The tension is the force on particle 0 towards its partner; the bond has broken once that force
// is zero after contact.
template <class Overlap>
static PetscErrorCode PullApart(bool pair, Overlap overlap, Pulled *out) {
  vofdem::Simulation sim;
  PetscReal          x0[3], v0[3], x1[3], v1[3], f0[3], w[3];
  PetscBool          found;

  PetscFunctionBeginUser;
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  out->maxTension  = 0;
  out->breakOverlap = 0;
  PetscReal last = 0;
  for (int k = 0; k < 100000; ++k) {
    PetscCall(sim.Step());
    PetscCall(dem->FindParticle(0, x0, v0, &found, w, f0));
    if (pair) PetscCall(dem->FindParticle(1, x1, v1, &found));
    const PetscReal d = overlap(x0, x1), tension = pair ? f0[2] : -f0[2];  // towards the partner
    if (tension == 0 && f0[0] == 0 && f0[1] == 0 && d < 0) {
      out->breakOverlap = 0.5 * (last + d);  // broke between the last bonded step and this one
      break;
    }
    out->maxTension = PetscMax(out->maxTension, tension);
    last            = d;
  }
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

static PetscErrorCode Report(const char *what, PetscReal Rstar, PetscReal Estar, PetscReal w, const Pulled &p, PetscInt *failures) {
  const PetscReal Fmax = 1.5 * PETSC_PI * w * Rstar, dc = -0.75 * std::cbrt(PETSC_PI * PETSC_PI * w * w * Rstar / (Estar * Estar));
  const PetscReal eF = PetscAbsReal(p.maxTension - Fmax) / Fmax, eD = PetscAbsReal(p.breakOverlap - dc) / PetscAbsReal(dc);

  PetscFunctionBeginUser;
  *failures += (eF > 0.01) + (eD > 0.02);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: largest tension %.6e N (3 pi gamma R* = %.6e N, error %.3f %%, tolerance 1 %%) %s\n", what, (double)p.maxTension,
                        (double)Fmax, (double)(100 * eF), eF > 0.01 ? "FAIL" : "ok"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: breaks at overlap %.6e m (delta_c = %.6e m, error %.3f %%, tolerance 2 %%) %s\n", what, (double)p.breakOverlap,
                        (double)dc, (double)(100 * eD), eD > 0.02 ? "FAIL" : "ok"));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  PetscInt  failures = 0;
  Pulled    pair, wall;
  char      rows[256];
  const PetscReal Estar = vofdem::hertz::EffectiveModulus(E, nu, E, nu), w = 2 * gamma_, start = 1e-9;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  // Heavy spheres (density 1e12) pulled at 0.1 mm/s, 1e-6 s steps: 1e-10 m per step against a
  // break overlap of about 1e-7 m. No gravity, no damping, no friction.
  PetscCall(PetscOptionsInsertString(nullptr, "-physics dem -grid_cells 2,2,2 -grid_upper 0.01,0.01,0.01 -gravity 0,0,0 -dem_radius 1e-3 "
                                              "-dem_density 1e12 -dem_youngs_modulus 1e8 -dem_poisson_ratio 0.28 -dem_restitution 1 -dem_friction 0 "
                                              "-dem_cohesion jkr -dem_surface_energy 0.05 -dt 1e-6"));
  // Two spheres overlapping by 1e-9 m about z = 5 mm (the rank boundary with -grid_ranks 1,1,2).
  std::snprintf(rows, sizeof rows, "0.005,0.005,%.17g,0,0,%.17g\n0.005,0.005,%.17g,0,0,%.17g\n", 0.005 - R + start / 2, -pull / 2, 0.005 + R - start / 2, pull / 2);
  PetscCall(WriteParticles(rows));
  PetscCall(PullApart(true, [](const PetscReal *a, const PetscReal *b) { return 2 * R - (b[2] - a[2]); }, &pair));
  // A sphere overlapping the floor by 1e-9 m, pulled up.
  std::snprintf(rows, sizeof rows, "0.005,0.005,%.17g,0,0,%.17g\n", R - start, pull);
  PetscCall(WriteParticles(rows));
  PetscCall(PullApart(false, [](const PetscReal *a, const PetscReal *) { return R - a[2]; }, &wall));
  PetscCall(Report("two spheres", R / 2, Estar, w, pair, &failures));
  PetscCall(Report("sphere and wall", R, Estar, w, wall, &failures));
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d checks out of tolerance\n", (int)failures));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-6
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    args: -grid_ranks 1,1,2
    output_file: output/ex06_jkr_1.out
TEST*/
