static const char help[] = "A glass sphere at a still water surface, with the particles' wettability (-coupling_contact_angle; issue 9,\n"
                           "docs/physics.md P1, Capillary.hpp). The sphere (d 1 mm, 2500 kg/m^3) starts at rest, centred on the surface of\n"
                           "water (1000 kg/m^3, 1e-3 Pa s, surface tension 0.072 N/m) under air (1.2 kg/m^3, 1.8e-5 Pa s), gravity on, in a\n"
                           "closed box of 10 x 10 x 16 cells of 0.6 d, kernel width H = d, fluid step -dt (default 2.5e-4 s), -steps steps\n"
                           "(default 400); it starts -start R (default 0.3) above the surface. -angle (deg, default 120) is the contact angle; -angle -1 leaves the option out.\n"
                           "The added mass takes the fluid's acceleration from the pressure balance (-coupling_added_mass_acceleration pressure,\n"
                           "zero in the pool at rest): from the velocity read, which holds the light air the sphere pushes, the bobbing grows.\n"
                           " - hydrophobic (-angle >= 90): the sphere must float. Reference: the height s* of its centre above the surface\n"
                           "   where weight = buoyancy of the exact spherical cap below the surface + Princen's force (bisection); the run's\n"
                           "   mean height over its last third, measured from the surface far from the sphere (the liquid column at the box's\n"
                           "   corners, which the kernel does not reach), must agree within the tolerance: the coupling's buoyancy is the\n"
                           "   kernel's, V F(-s/H) of water instead of the cap; the equilibrium s_k with it differs from s* by |s_k - s*|, and\n"
                           "   the tolerance is twice that plus 1 %% of R for the kernel's view of a flat interface on cells of 0.6 H\n"
                           "   (Capillary.hpp: under 1 %% of s).\n"
                           " - perfectly wetting (-angle 0) or no option: the sphere must sink, its centre more than R below the surface (the\n"
                           "   run stops at 2 R below): Princen's force never pulls it up then. Between 0 and 90 deg a sphere this small can\n"
                           "   still float, deep in the water (the force pulls up once beta > 180 - theta); that case is not checked here.\n"
"Exits non-zero on failure.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/coupling/Capillary.hpp"
#include "vofdem/vof/Vof.hpp"
#include "vofdem/examples/Help.hpp"

#include <petscdmda.h>

#include <cmath>
#include <cstdio>

namespace {

const PetscReal kD = 1e-3, kR = kD / 2, kRhoP = 2500, kRhoW = 1000, kMuW = 1e-3, kRhoA = 1.2, kMuA = 1.8e-5, kG = 9.81, kSigma = 0.072;
const PetscReal kH = 0.6 * kD;                  // cell
const PetscInt  kNx = 10, kNz = 16, kWater = 8;  // cells across, high, of water
const PetscReal kTolFloor = 0.01;               // of R: the kernel's view of a flat interface (Capillary.hpp)

// Net upward force on the sphere with its centre s above the surface: weight, the buoyancy of the air and of
// the water below the surface (submerged fraction phi(s)) and Princen's force.
PetscReal Net(PetscReal s, PetscReal theta, PetscReal (*phi)(PetscReal)) {
  const PetscReal V = 4.0 / 3.0 * PETSC_PI * kR * kR * kR;
  return -kRhoP * V * kG + kRhoA * V * kG + (kRhoW - kRhoA) * V * kG * phi(s) + vofdem::capillary::PrincenForce(kR, kSigma, theta, s);
}
PetscReal Cap(PetscReal s) {  // the exact spherical cap below the surface
  const PetscReal hc = std::min(std::max(kR - s, (PetscReal)0), 2 * kR);
  return PETSC_PI * hc * hc * (3 * kR - hc) / 3 / (4.0 / 3.0 * PETSC_PI * kR * kR * kR);
}
vofdem::capillary::Marginal gMarginal;
PetscReal Smeared(PetscReal s) { return gMarginal.Fraction(-s / kD); }  // the kernel's (H = d)

// The stable root of Net in [0, R): Net > 0 at s = 0 (the capillary force at the centre exceeds the
// weight for these angles) and < 0 as s -> R.
PetscReal Equilibrium(PetscReal theta, PetscReal (*phi)(PetscReal)) {
  PetscReal lo = 0, hi = kR * (1 - 1e-12);
  for (int it = 0; it < 200; ++it) {
    const PetscReal mid = 0.5 * (lo + hi);
    (Net(mid, theta, phi) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The water's height in the box's four corner columns (mean), sum of alpha h.
PetscErrorCode SurfaceHeight(vofdem::Vof &vof, PetscReal *z) {
  PetscInt        s[3], n[3];
  PetscScalar ***a;
  PetscReal       sum = 0, all;

  PetscFunctionBeginUser;
  PetscCall(DMDAGetCorners(vof.FractionDM(), &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAVecGetArrayRead(vof.FractionDM(), vof.Fraction(), &a));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j : {(PetscInt)0, kNx - 1})
      for (PetscInt i : {(PetscInt)0, kNx - 1})
        if (i >= s[0] && i < s[0] + n[0] && j >= s[1] && j < s[1] + n[1]) sum += PetscRealPart(a[k][j][i]) * kH;
  PetscCall(DMDAVecRestoreArrayRead(vof.FractionDM(), vof.Fraction(), &a));
  PetscCallMPI(MPI_Allreduce(&sum, &all, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  *z = all / 4;
  PetscFunctionReturn(0);
}

PetscErrorCode Set(const char *name, PetscReal v) {
  char buf[64];
  PetscFunctionBeginUser;
  std::snprintf(buf, sizeof buf, "%.17g", (double)v);
  PetscCall(PetscOptionsSetValue(nullptr, name, buf));
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  PetscReal angle = 120, dt = 2.5e-4, start = 0.3;
  PetscInt  steps = 400;
  char      buf[256];

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-angle", &angle, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-dt", &dt, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-steps", &steps, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-start", &start, nullptr));
  PetscCall(PetscOptionsClearValue(nullptr, "-start"));
  PetscCall(PetscOptionsClearValue(nullptr, "-angle"));
  PetscCall(PetscOptionsClearValue(nullptr, "-steps"));
  const bool      wetting = angle >= 0, floats = angle >= 90;
  if (wetting && angle > 0 && angle < 90) VofdemInputError(PETSC_COMM_WORLD, "ex41: option -angle %g: checked cases are 0, 90 to 180, or -1 (no force)", (double)angle);
  const PetscReal L = kNx * kH, Z = kNz * kH, zs0 = kWater * kH;
  std::snprintf(buf, sizeof buf, "%d,%d,%d", (int)kNx, (int)kNx, (int)kNz);
  PetscCall(PetscOptionsSetValue(nullptr, "-grid_cells", buf));
  std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", (double)L, (double)L, (double)Z);
  PetscCall(PetscOptionsSetValue(nullptr, "-grid_upper", buf));
  PetscCall(PetscOptionsSetValue(nullptr, "-physics", "dem,flow,vof"));
  PetscCall(PetscOptionsSetValue(nullptr, "-gravity", "0,0,-9.81"));
  PetscCall(Set("-flow_density", kRhoA));
  PetscCall(Set("-flow_viscosity", kMuA));
  PetscCall(Set("-vof_density", kRhoW));
  PetscCall(Set("-vof_viscosity", kMuW));
  PetscCall(Set("-vof_surface_tension", kSigma));
  std::snprintf(buf, sizeof buf, "0,0,0,%.17g,%.17g,%.17g", (double)L, (double)L, (double)zs0);
  PetscCall(PetscOptionsSetValue(nullptr, "-vof_boxes", buf));
  PetscCall(PetscOptionsSetValue(nullptr, "-flow_pressure_pc", "boomeramg"));
  PetscCall(PetscOptionsSetValue(nullptr, "-flow_pressure_ksp_rtol", "1e-10"));
  PetscCall(Set("-dem_radius", kR));
  PetscCall(Set("-dem_density", kRhoP));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_count", "1"));
  std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", (double)(L / 2 - kR - 1e-9), (double)(L / 2 - kR - 1e-9), (double)(zs0 + start * kR - kR - 1e-9));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_lower", buf));
  std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", (double)(L / 2 + kR + 1e-9), (double)(L / 2 + kR + 1e-9), (double)(zs0 + start * kR + kR + 1e-9));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_upper", buf));
  PetscCall(PetscOptionsSetValue(nullptr, "-coupling_kernel_width", "1"));
  PetscCall(PetscOptionsSetValue(nullptr, "-coupling_added_mass_acceleration", "pressure"));
  if (wetting) PetscCall(Set("-coupling_contact_angle", angle));
  PetscCall(Set("-dt", dt));
  // The viscosity-jump limit of the explicit viscous term is a safe bound, not a sharp one (ex43).
  PetscCall(PetscOptionsSetValue(nullptr, "-dt_force", "1"));
  PetscCall(PetscOptionsSetValue(nullptr, "-max_steps", "1000000"));

  const PetscReal theta = angle * PETSC_PI / 180;
  gMarginal.Build(vofdem::kernel::Shape::Smooth, 1.5);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "floating sphere: d %g m, %g kg/m^3, centred on the surface of water (sigma %g N/m) under air; contact angle %s; box %d x %d x %d cells of %g m, step %g s, %d steps\n",
                        (double)kD, (double)kRhoP, (double)kSigma, wetting ? (std::to_string((double)angle) + " deg").c_str() : "not given (no capillary force)", (int)kNx, (int)kNx, (int)kNz,
                        (double)kH, (double)dt, (int)steps));
  PetscReal sStar = 0, sKernel = 0, tol = 0;
  if (floats) {
    sStar   = Equilibrium(theta, Cap);
    sKernel = Equilibrium(theta, Smeared);
    tol     = 2 * std::fabs(sKernel - sStar) / kR + kTolFloor;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "equilibrium height above the surface: exact cap buoyancy s* = %.4f R (beta %.2f deg); with the kernel's buoyancy s_k = %.4f R; tolerance 2 |s_k - s*| + %g R = %.4f R\n",
                          (double)(sStar / kR), (double)(std::acos(sStar / kR) * 180 / PETSC_PI), (double)(sKernel / kR), (double)kTolFloor, (double)tol));
  }

  vofdem::Simulation sim;
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  PetscReal x[3], u[3], zs = 0, sum = 0, lowest = PETSC_MAX_REAL, lo3 = PETSC_MAX_REAL, hi3 = -PETSC_MAX_REAL;
  PetscReal tenthLo = PETSC_MAX_REAL, tenthHi = -PETSC_MAX_REAL;
  PetscInt  count = 0;
  PetscBool found;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "     t (s)   surface (m)  centre - surface (R)  v (m/s)   centre - surface over the last tenth (R)\n"));
  for (PetscInt step = 1; step <= steps; ++step) {
    PetscCall(sim.Step());
    PetscCall(Particles(sim)->FindParticle(0, x, u, &found));
    PetscCheck(found, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the sphere was lost");
    PetscCall(SurfaceHeight(*Interface(sim), &zs));
    const PetscReal s = (x[2] - zs) / kR;
    lowest = std::min(lowest, s);
    tenthLo = std::min(tenthLo, s), tenthHi = std::max(tenthHi, s);  // printed every tenth: a bobbing period is about 40 steps
    if (3 * step > 2 * steps) sum += s, ++count, lo3 = std::min(lo3, s), hi3 = std::max(hi3, s);
    if (!floats && s < -2) {  // sunk: stop before it reaches the floor, where it bounces with the sloshing water
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  %8.4f   %.6f    %+.4f             %+.4f   (2 R below the surface: stop)\n", (double)sim.Time(), (double)zs, (double)s, (double)u[2]));
      break;
    }
    if (step % (steps / 10) == 0) {
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  %8.4f   %.6f    %+.4f             %+.4f   %+.4f to %+.4f\n", (double)sim.Time(), (double)zs, (double)s, (double)u[2], (double)tenthLo, (double)tenthHi));
      tenthLo = PETSC_MAX_REAL, tenthHi = -PETSC_MAX_REAL;
    }
  }
  PetscCall(sim.Destroy());
  bool ok;
  if (floats) {
    const PetscReal mean = sum / count, err = std::fabs(mean - sStar / kR);
    ok = err <= tol;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "floats: height over the last third between %.4f R and %.4f R (the oscillation about the equilibrium, reported)\n", (double)lo3, (double)hi3));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "floats: mean height over the last third %.4f R, s* %.4f R, error %.4f R (tolerance %.4f R) %s\n", (double)mean, (double)(sStar / kR), (double)err,
                          (double)tol, ok ? "ok" : "FAIL"));
  } else {
    ok = lowest < -1;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "sinks: lowest centre %.3f R below the surface (must exceed 1 R) %s\n", (double)-lowest, ok ? "ok" : "FAIL"));
  }
  PetscFunctionReturn(ok ? 0 : PETSC_ERR_NOT_CONVERGED);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-3
  atol: 1e-9
  timeout: 300
  test:
    suffix: float_1
    nsize: 1
  test:
    suffix: float_2
    nsize: 2
    output_file: output/ex41_floating_sphere_float_1.out
  test:
    suffix: sink_1
    nsize: 1
    args: -angle 0
  test:
    suffix: sink_2
    nsize: 2
    args: -angle 0
    output_file: output/ex41_floating_sphere_sink_1.out
TEST*/
