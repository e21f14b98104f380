static const char help[] = "Love-Weber stress of a region (-dem_stress_lower/-dem_stress_upper), compression positive, checked against\n"
                           "  1. a simple-cubic lattice of n^3 spheres compressed by a known overlap between neighbours and against the\n"
                           "     walls, at rest and without gravity: every contact force is Hertz' (4/3) E* sqrt(R*) delta^1.5 (P3), so\n"
                           "     sigma = (1/V) sum F l is known exactly, for the whole box and for a region holding one layer;\n"
                           "  2. a bed falling into a box with frictionless walls, at an instant of collisions: the virial identity\n"
                           "     sigma_dd V = sum_p (F_p - m_p g)_d x_p,d + sum_faces x_face,d F_face,d (F_p the total force on particle p,\n"
                           "     F_face the force of the particles on a face) for xx, yy and zz, plus the kinetic part (-dem_stress_kinetic).\n"
                           "Relative errors within 1e-9. Exits non-zero on failure.\n\n";

// Why the identity: every particle obeys sum_c F_c = F_p - m_p g, pair forces at a shared contact
// point cancel, so sum over particles and contacts of F_c (x) (x_c - x_p) leaves only the wall
// contacts and the particle terms; Love-Weber with compression positive is minus that over V.

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cmath>
#include <cstdio>
#include <string>

using vofdem::example::Num;

static PetscErrorCode Set(const char *name, const std::string &value) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsSetValue(nullptr, name, value.c_str()));
  PetscFunctionReturn(0);
}

static PetscInt failures = 0, checks = 0;

static PetscErrorCode Report(const char *what, PetscReal got, PetscReal want, PetscReal scale) {
  PetscFunctionBeginUser;
  const PetscReal err = std::abs(got - want) / scale;
  const bool      bad = !(err <= 1e-9);
  failures += bad, ++checks;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  %-10s %.9e Pa, expected %.9e Pa, relative error %.1e (tolerance 1e-9) %s\n", what, (double)got, (double)want, (double)err,
                        bad ? "FAIL" : "ok"));
  PetscFunctionReturn(0);
}

// Part 1: n^3 spheres of radius R at spacing 2R - delta, a gap R - delta/2 from each face.
static PetscErrorCode Lattice() {
  const PetscInt  n = 4;
  const PetscReal R = 5e-4, delta = 1e-5, deltaWall = delta / 2, E = 1e8, nu = 0.28;
  const PetscReal s = 2 * R - delta, L = 2 * (R - deltaWall) + (n - 1) * s;

  PetscFunctionBeginUser;
  std::string csv = "x,y,z\n";
  for (PetscInt k = 0; k < n; ++k)
    for (PetscInt j = 0; j < n; ++j)
      for (PetscInt i = 0; i < n; ++i) csv += Num(R - deltaWall + i * s) + "," + Num(R - deltaWall + j * s) + "," + Num(R - deltaWall + k * s) + "\n";
  PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, "ex13-lattice.csv", csv, "ex13 lattice"));
  PetscCall(Set("-grid_upper", Num(L) + "," + Num(L) + "," + Num(L)));
  PetscCall(Set("-gravity", "0,0,0"));
  PetscCall(Set("-dem_radius", Num(R)));
  PetscCall(Set("-dem_youngs_modulus", Num(E)));
  PetscCall(Set("-dem_poisson_ratio", Num(nu)));
  PetscCall(Set("-dem_particles_file", "ex13-lattice.csv"));
  // Hertz (P3): pairs R* = R/2, walls R* = R (same material).
  const PetscReal Es = vofdem::hertz::EffectiveModulus(E, nu, E, nu);
  const PetscReal Fp = 4.0 / 3.0 * Es * std::sqrt(R / 2) * std::pow(delta, 1.5), Fw = 4.0 / 3.0 * Es * std::sqrt(R) * std::pow(deltaWall, 1.5);
  const PetscReal rows = n * n;  // lines of spheres along one direction
  // Region 1: the box. Along each direction n-1 contacts per line with branch length s, two wall
  // contacts per line with branch length R - deltaWall.
  // Region 2: x up to between the first layer's contact points and the second layer's centres: the
  // x- wall contacts, the first layer of x pair contacts, and the y, z contacts within layer 1.
  const PetscReal x2 = R - deltaWall + s / 2 + R / 2;
  struct Region {
    const char *name;
    PetscReal   upperX, xx, yy;
  } regions[2] = {{"the whole box", L, rows * ((n - 1) * Fp * s + 2 * Fw * (R - deltaWall)) / (L * L * L), 0},
                  {"the first layer in x", x2, rows * (Fp * s + Fw * (R - deltaWall)) / (x2 * L * L), n * ((n - 1) * Fp * s + 2 * Fw * (R - deltaWall)) / (x2 * L * L)}};
  regions[0].yy = regions[0].xx;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "simple-cubic lattice: %d^3 spheres of radius %g m, overlap %g m between neighbours and %g m with the faces\n", (int)n, (double)R,
                        (double)delta, (double)deltaWall));
  for (const Region &r : regions) {
    vofdem::Simulation sim;
    PetscReal          sigma[6];
    PetscCall(Set("-dem_stress_lower", "0,0,0"));
    PetscCall(Set("-dem_stress_upper", Num(r.upperX) + "," + Num(L) + "," + Num(L)));
    PetscCall(sim.Create(PETSC_COMM_WORLD));
    PetscCall(sim.SetFromOptions());
    PetscCall(sim.SetUp());
    PetscCall(Particles(sim)->Stress(sigma));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, " region %s:\n", r.name));
    PetscCall(Report("sigma_xx", sigma[0], r.xx, r.xx));
    PetscCall(Report("sigma_yy", sigma[1], r.yy, r.xx));
    PetscCall(Report("sigma_zz", sigma[2], r.yy, r.xx));
    PetscCall(Report("sigma_xy", sigma[3], 0, r.xx));
    PetscCall(Report("sigma_xz", sigma[4], 0, r.xx));
    PetscCall(Report("sigma_yz", sigma[5], 0, r.xx));
    PetscCall(sim.Destroy());
  }
  for (const char *o : {"-grid_upper", "-gravity", "-dem_radius", "-dem_youngs_modulus", "-dem_poisson_ratio", "-dem_particles_file"})
    PetscCall(PetscOptionsClearValue(nullptr, o));
  PetscFunctionReturn(0);
}

// Part 2: a jittered lattice falling into a box with frictionless walls; the identity at `steps`.
static PetscErrorCode FallingBed(PetscInt steps) {
  vofdem::Simulation sim;
  vofdem::DemSummary s;
  const PetscReal    g[3] = {0, 0, -9.81}, L[3] = {0.004, 0.004, 0.008};
  PetscReal          sigma[6], local[6] = {0, 0, 0, 0, 0, 0}, global[6], *x, *f, *m, *v;
  PetscInt           n;

  PetscFunctionBeginUser;
  PetscCall(Set("-grid_upper", Num(L[0]) + "," + Num(L[1]) + "," + Num(L[2])));
  PetscCall(Set("-dem_stress_upper", Num(L[0]) + "," + Num(L[1]) + "," + Num(L[2])));
  PetscCall(Set("-dem_fill_count", "36"));
  PetscCall(Set("-dem_fill_upper", "0.004,0.004,0.005"));
  PetscCall(Set("-dem_fill_jitter", "0.8"));
  PetscCall(Set("-dem_restitution", "0.1"));
  PetscCall(Set("-dem_wall_friction", "0"));
  PetscCall(Set("-dem_rolling", "epsd"));
  PetscCall(Set("-dem_rolling_friction", "0.1"));
  PetscCall(Set("-dem_stress_kinetic", "1"));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  for (PetscInt k = 0; k < steps; ++k) PetscCall(sim.Step());
  vofdem::Dem *dem = Particles(sim);
  PetscCall(dem->Stress(sigma));
  PetscCall(dem->Summarize(&s));
  DM swarm = dem->Swarm();
  PetscCall(DMSwarmGetLocalSize(swarm, &n));
  PetscCall(DMSwarmGetField(swarm, vofdem::field::position, nullptr, nullptr, (void **)&x));
  PetscCall(DMSwarmGetField(swarm, vofdem::field::force, nullptr, nullptr, (void **)&f));
  PetscCall(DMSwarmGetField(swarm, vofdem::field::mass, nullptr, nullptr, (void **)&m));
  PetscCall(DMSwarmGetField(swarm, vofdem::field::velocity, nullptr, nullptr, (void **)&v));
  for (PetscInt p = 0; p < n; ++p)
    for (int d = 0; d < 3; ++d) local[d] += (f[3 * p + d] - m[p] * g[d]) * x[3 * p + d], local[3 + d] += m[p] * v[3 * p + d] * v[3 * p + d];
  PetscCall(DMSwarmRestoreField(swarm, vofdem::field::velocity, nullptr, nullptr, (void **)&v));
  PetscCall(DMSwarmRestoreField(swarm, vofdem::field::mass, nullptr, nullptr, (void **)&m));
  PetscCall(DMSwarmRestoreField(swarm, vofdem::field::force, nullptr, nullptr, (void **)&f));
  PetscCall(DMSwarmRestoreField(swarm, vofdem::field::position, nullptr, nullptr, (void **)&x));
  PetscCallMPI(MPI_Allreduce(local, global, 6, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  const PetscReal V = L[0] * L[1] * L[2];
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "falling bed, step %d: %d pair and %d wall contacts; virial identity over the box, with the kinetic part sum m v_d^2 / V:\n",
                        (int)steps, (int)s.pairContacts, (int)s.wallContacts));
  // Lower faces at 0 contribute nothing; the upper face of direction d is at L[d].
  const char *names[3] = {"sigma_xx", "sigma_yy", "sigma_zz"};
  PetscReal   want[3];
  for (int d = 0; d < 3; ++d) want[d] = (global[d] + L[d] * s.wallForce[2 * d + 1][d] + global[3 + d]) / V;
  for (int d = 0; d < 3; ++d) PetscCall(Report(names[d], sigma[d], want[d], std::abs(want[2])));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

static PetscErrorCode Main() {
  PetscInt steps = 2000;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-fall_steps", &steps, nullptr));
  PetscCall(Set("-physics", "dem"));
  PetscCall(Set("-grid_cells", "4,4,4"));
  PetscCall(Set("-dem_fill_count", "0"));
  PetscCall(Lattice());
  PetscCall(FallingBed(steps));
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d of %d stress checks\n", (int)failures, (int)checks));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Main());
}

/*TEST
  rtol: 1e-6
  atol: 1e-9
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    output_file: output/ex19_love_weber_stress_1.out
  test:
    suffix: 4
    nsize: 4
    output_file: output/ex19_love_weber_stress_1.out
TEST*/
