static const char help[] = "Particle types with their own materials (config/materials) and the mixing of unlike pairs (P3).\n"
                           "A glass sphere (R 1 mm) and a steel sphere (R 0.5 mm) meet head on. Checks: the pair's restitution is the mean\n"
                           "of the two materials' (0.9 and 0.6) unless -dem_pair_glass_steel_restitution is given (within 2 %); with e = 1\n"
                           "the contact time is Hertz' t_c with the mixed E* and R*, m* of the unlike pair (within 1 %); momentum with\n"
                           "the masses from the two densities is conserved (1e-12); each type bounces off the floor with its own\n"
                           "restitution (within 2 %). Exits non-zero on failure.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cstdio>
#include <string>

using vofdem::hertz::EffectiveModulus;

// The two materials as config/materials states them (read by the code from the files; repeated
// here only to compute the reference values).
struct Material {
  PetscReal rho, E, nu, e;
};
static const Material       glass{2500, 1e8, 0.25, 0.9}, steel{7900, 2e8, 0.3, 0.6};
static const PetscReal Ra = 1e-3, Rb = 5e-4;

using vofdem::example::Num;

static PetscErrorCode UseParticles(const char *path, const std::string &rows) {
  PetscFunctionBeginUser;
  PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, path, "x,y,z,vx,vy,vz,radius,type\n" + rows, "particle file"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_particles_file", path));
  PetscFunctionReturn(0);
}

// Steps until gap() has gone negative and positive again; returns the interpolated contact time.
template <class Gap>
static PetscErrorCode RunContact(vofdem::Simulation &sim, Gap gap, PetscReal *duration) {
  PetscReal g0 = 0, tStart = -1, tEnd = -1;

  PetscFunctionBeginUser;
  PetscCall(gap(&g0));
  for (int k = 0; k < 100000 && tEnd < 0; ++k) {
    const PetscReal t0 = sim.Time();
    PetscReal       g1 = 0;
    PetscCall(sim.Step());
    PetscCall(gap(&g1));
    const PetscReal t1 = sim.Time();
    if (tStart < 0 && g0 > 0 && g1 <= 0) tStart = t0 + (t1 - t0) * g0 / (g0 - g1);
    if (tStart >= 0 && g0 <= 0 && g1 > 0) tEnd = t0 + (t1 - t0) * g0 / (g0 - g1);
    g0 = g1;
  }
  PetscCheck(tEnd > 0, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the contact never ended");
  *duration = tEnd - tStart;
  PetscFunctionReturn(0);
}

static PetscReal Mass(const Material &m, PetscReal R) { return m.rho * 4.0 / 3.0 * PETSC_PI * R * R * R; }

// Glass (id 0) at z = 3 mm and steel (id 1) at z = 7 mm approach at +-v0/2.
static PetscErrorCode Binary(const char *pairRestitution, PetscReal v0, PetscReal dt, PetscReal *restitution, PetscReal *duration, PetscReal *momentumError) {
  vofdem::Simulation sim;
  PetscReal          xa[3], va[3], xb[3], vb[3];
  PetscBool          found;

  PetscFunctionBeginUser;
  PetscCall(UseParticles("ex12_binary.csv", "0.005,0.005,0.003,0,0," + Num(v0 / 2) + "," + Num(Ra) + ",0\n0.005,0.005,0.007,0,0," + Num(-v0 / 2) + "," +
                                              Num(Rb) + ",1\n"));
  if (pairRestitution) PetscCall(PetscOptionsSetValue(nullptr, "-dem_pair_glass_steel_restitution", pairRestitution));
  PetscCall(PetscOptionsSetValue(nullptr, "-dt", Num(dt).c_str()));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  auto         gap = [&](PetscReal *g) {
    PetscFunctionBeginUser;
    PetscCall(dem->FindParticle(0, xa, va, &found));
    PetscCall(dem->FindParticle(1, xb, vb, &found));
    *g = xb[2] - xa[2] - Ra - Rb;
    PetscFunctionReturn(0);
  };
  PetscCall(RunContact(sim, gap, duration));
  const PetscReal ma = Mass(glass, Ra), mb = Mass(steel, Rb), p0 = (ma - mb) * v0 / 2;
  *restitution   = (vb[2] - va[2]) / v0;
  *momentumError = PetscAbsReal(ma * va[2] + mb * vb[2] - p0) / (mb * v0 / 2);
  PetscCall(sim.Destroy());
  if (pairRestitution) PetscCall(PetscOptionsClearValue(nullptr, "-dem_pair_glass_steel_restitution"));
  PetscFunctionReturn(0);
}

// One sphere of type t, R/100 above the floor, falling at v0.
static PetscErrorCode Floor(int t, PetscReal v0, PetscReal dt, PetscReal *restitution) {
  vofdem::Simulation sim;
  const PetscReal    R = t ? Rb : Ra;
  PetscReal          x[3], v[3];
  PetscBool          found;

  PetscFunctionBeginUser;
  PetscCall(UseParticles("ex12_floor.csv", "0.005,0.005," + Num(1.01 * R) + ",0,0," + Num(-v0) + "," + Num(R) + "," + std::to_string(t) + "\n"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dt", Num(dt).c_str()));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  PetscReal    duration;
  auto         gap = [&](PetscReal *g) {
    PetscFunctionBeginUser;
    PetscCall(dem->FindParticle(0, x, v, &found));
    *g = x[2] - R;
    PetscFunctionReturn(0);
  };
  PetscCall(RunContact(sim, gap, &duration));
  *restitution = v[2] / v0;
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

static PetscErrorCode Check(const char *what, PetscReal value, PetscReal exact, PetscReal tol, PetscInt *failures) {
  const PetscReal err = PetscAbsReal(value - exact) / exact;

  PetscFunctionBeginUser;
  *failures += err > tol;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: measured %.6e, expected %.6e, error %.3f %% (tolerance %.0f %%) %s\n", what, (double)value, (double)exact,
                        (double)(100 * err), (double)(100 * tol), err > tol ? "FAIL" : "ok"));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  PetscInt        failures = 0;
  const PetscReal v0 = 0.5;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsInsertString(nullptr, "-physics dem -grid_cells 2,2,2 -grid_upper 0.01,0.01,0.01 -gravity 0,0,0 -dem_radius 1e-3 "
                                              "-dem_types glass,steel -dem_type_glass_material glass -dem_type_steel_material steel"));
  // Reference: Hertz contact time of the unlike pair (E* from both materials, R*, m* of the pair).
  const PetscReal ma = Mass(glass, Ra), mb = Mass(steel, Rb), mstar = ma * mb / (ma + mb), Rstar = Ra * Rb / (Ra + Rb);
  const PetscReal Estar = EffectiveModulus(glass.E, glass.nu, steel.E, steel.nu);
  const PetscReal tc    = vofdem::hertz::HertzContactTime(mstar, Rstar, Estar, v0), dt = tc / 200;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "glass R %g m, steel R %g m at %g m/s: E* %.6e Pa, R* %.6e m, m* %.6e kg, Hertz contact time %.6e s\n", (double)Ra,
                        (double)Rb, (double)v0, (double)Estar, (double)Rstar, (double)mstar, (double)tc));
  PetscReal e, duration, dp;
  PetscCall(Binary(nullptr, v0, dt, &e, &duration, &dp));
  PetscCall(Check("glass-steel restitution, mixed (mean of 0.9 and 0.6)", e, 0.5 * (glass.e + steel.e), 0.02, &failures));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "momentum with masses from the two densities: relative error %.1e (tolerance 1e-12) %s\n", (double)dp,
                        dp > 1e-12 ? "FAIL" : "ok"));
  failures += dp > 1e-12;
  PetscCall(Binary("0.4", v0, dt, &e, &duration, &dp));
  PetscCall(Check("glass-steel restitution, -dem_pair_glass_steel_restitution 0.4", e, 0.4, 0.02, &failures));
  PetscCall(Binary("1", v0, dt, &e, &duration, &dp));
  PetscCall(Check("glass-steel elastic contact time (e = 1) / Hertz", duration, tc, 0.01, &failures));
  // Each type against the floor (the walls take each type's restitution; their E, nu are the type's).
  for (int t = 0; t < 2; ++t) {
    const Material      &m = t ? steel : glass;
    const PetscReal R = t ? Rb : Ra, tcw = vofdem::hertz::HertzContactTime(Mass(m, R), R, EffectiveModulus(m.E, m.nu, m.E, m.nu), v0);
    PetscCall(Floor(t, v0, tcw / 200, &e));
    PetscCall(Check(t ? "steel on the floor, restitution" : "glass on the floor, restitution", e, m.e, 0.02, &failures));
  }
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
    output_file: output/ex12_materials_1.out
TEST*/
