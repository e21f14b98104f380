static const char help[] = "Verification D1 (two spheres) and D2 (oblique impact on a wall in gross sliding), Hertz-Mindlin (P3).\n"
                           "D1: two equal spheres meet head on; restitution for e = 0.3, 0.6, 0.9 within 2 %, elastic contact time for\n"
                           "e = 1 within 1 % of Hertz' t_c with R* = R/2, m* = m/2. D2: a sphere hits a wall at speed (v_t, 0, -v_n) with\n"
                           "friction mu; in gross sliding v_t' = v_t - mu (1+e) v_n and w' = 5 mu (1+e) v_n / (2R), both within 1 %.\n"
                           "D2 runs with -dem_limit_force (no tension as the contact ends, which the analytic result assumes), so e\n"
                           "there is the restitution the impact realised (printed next to the input).\n"
                           "With -grid_ranks 1,1,2 the head-on collision happens on the boundary between the two ranks.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cstdio>
#include <string>

static const PetscReal R = 1e-3, rho = 2500, E = 1e8, nu = 0.28;

using vofdem::example::Num;

// Writes the particles (x,y,z,vx,vy,vz per row) and points -dem_particles_file at them.
static PetscErrorCode UseParticles(const char *path, const std::string &rows) {
  PetscFunctionBeginUser;
  PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, path, "x,y,z,vx,vy,vz\n" + rows, "particle file"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_particles_file", path));
  PetscFunctionReturn(0);
}

// Steps until the gap function (returned by gap()) has gone negative and positive again; returns
// the interpolated contact duration.
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

// D1: spheres at z = 3 and 7 mm approach at +-v0/2 and meet at z = 5 mm.
static PetscErrorCode Binary(PetscReal e, PetscReal v0, PetscInt stepsPerContact, PetscReal *restitution, PetscReal *duration) {
  vofdem::Simulation sim;
  const PetscReal    m = rho * 4.0 / 3.0 * PETSC_PI * R * R * R;
  const PetscReal    tc = vofdem::hertz::HertzContactTime(m / 2, R / 2, vofdem::hertz::EffectiveModulus(E, nu, E, nu), v0);

  PetscFunctionBeginUser;
  PetscCall(UseParticles("ex03_binary.csv", "0.005,0.005,0.003,0,0," + Num(v0 / 2) + "\n0.005,0.005,0.007,0,0," + Num(-v0 / 2) + "\n"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_restitution", Num(e).c_str()));
  PetscCall(PetscOptionsSetValue(nullptr, "-dt", Num(tc / stepsPerContact).c_str()));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  PetscReal    xa[3], va[3], xb[3], vb[3];
  PetscBool    found;
  auto gap = [&](PetscReal *g) {
    PetscFunctionBeginUser;
    PetscCall(dem->FindParticle(0, xa, va, &found));
    PetscCall(dem->FindParticle(1, xb, vb, &found));
    *g = xb[2] - xa[2] - 2 * R;
    PetscFunctionReturn(0);
  };
  PetscCall(RunContact(sim, gap, duration));
  *restitution = (vb[2] - va[2]) / v0;
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

// D2: a sphere R/100 above the floor hits it at (vt, 0, -vn) without spin.
static PetscErrorCode Oblique(PetscReal e, PetscReal mu, PetscReal vt, PetscReal vn, PetscInt stepsPerContact, PetscReal *vtAfter,
                              PetscReal *wAfter, PetscReal *eAfter) {
  vofdem::Simulation sim;
  const PetscReal    m = rho * 4.0 / 3.0 * PETSC_PI * R * R * R;
  const PetscReal    tc = vofdem::hertz::HertzContactTime(m, R, vofdem::hertz::EffectiveModulus(E, nu, E, nu), vn);
  PetscReal          duration, x[3], v[3], w[3];
  PetscBool          found;

  PetscFunctionBeginUser;
  PetscCall(UseParticles("ex03_oblique.csv", "0.002," + Num(0.005) + "," + Num(1.01 * R) + "," + Num(vt) + ",0," + Num(-vn) + "\n"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_restitution", Num(e).c_str()));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_wall_friction", Num(mu).c_str()));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_limit_force", "1"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dt", Num(tc / stepsPerContact).c_str()));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  auto gap = [&](PetscReal *g) {
    PetscFunctionBeginUser;
    PetscCall(dem->FindParticle(0, x, v, &found, w));
    *g = x[2] - R;
    PetscFunctionReturn(0);
  };
  PetscCall(RunContact(sim, gap, &duration));
  *vtAfter = v[0];
  *wAfter  = w[1];
  *eAfter  = v[2] / vn;
  PetscCall(sim.Destroy());
  PetscCall(PetscOptionsClearValue(nullptr, "-dem_limit_force"));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  PetscInt  stepsPerContact = 200, failures = 0;
  const PetscReal v0 = 0.5;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-steps_per_contact", &stepsPerContact, nullptr));
  // Options a scene file would hold; PetscOptionsSetValue keeps anything given on the command line out.
  PetscCall(PetscOptionsInsertString(nullptr, "-physics dem -grid_cells 2,2,2 -grid_upper 0.01,0.01,0.01 -gravity 0,0,0 "
                                              "-dem_radius 1e-3 -dem_density 2500 -dem_youngs_modulus 1e8 -dem_poisson_ratio 0.28"));
  const PetscReal m = rho * 4.0 / 3.0 * PETSC_PI * R * R * R;
  const PetscReal tc = vofdem::hertz::HertzContactTime(m / 2, R / 2, vofdem::hertz::EffectiveModulus(E, nu, E, nu), v0);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "D1: two spheres R %g m meeting at %g m/s; Hertz contact time %.6e s; %d steps per contact\n", (double)R,
                        (double)v0, (double)tc, (int)stepsPerContact));
  for (PetscReal e : {0.3, 0.6, 0.9, 1.0}) {
    PetscReal en = 0, duration = 0;
    PetscCall(Binary(e, v0, stepsPerContact, &en, &duration));
    if (e < 1) {
      const PetscReal err = PetscAbsReal(en - e) / e;
      failures += err > 0.02;
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "D1 e %.1f: measured %.6f, error %.3f %% (tolerance 2 %%) %s\n", (double)e, (double)en, (double)(100 * err),
                            err > 0.02 ? "FAIL" : "ok"));
    } else {
      const PetscReal err = PetscAbsReal(duration - tc) / tc;
      failures += err > 0.01;
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "D1 e 1.0: restitution %.6f, contact time %.6e s, error %.3f %% (tolerance 1 %%) %s\n", (double)en,
                            (double)duration, (double)(100 * err), err > 0.01 ? "FAIL" : "ok"));
    }
  }
  const PetscReal e = 0.5, mu = 0.3, vn = 0.2;
  for (PetscReal vt : {0.5, 1.0, 2.0}) {
    PetscReal vtAfter = 0, w = 0, en = 0;
    PetscCall(Oblique(e, mu, vt, vn, stepsPerContact, &vtAfter, &w, &en));
    const PetscReal vtExact = vt - mu * (1 + en) * vn, wExact = 5 * mu * (1 + en) * vn / (2 * R);
    const PetscReal errV = PetscAbsReal(vtAfter - vtExact) / vtExact, errW = PetscAbsReal(w - wExact) / wExact;
    failures += (errV > 0.01) + (errW > 0.01);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "D2 v_t %.1f m/s, v_n %.1f m/s, mu %.1f, e %.1f (realised %.5f): v_t' %.6f (exact %.6f, error %.3f %%), w' %.4f rad/s (exact %.4f, error %.3f %%) (tolerance 1 %%) %s\n",
                          (double)vt, (double)vn, (double)mu, (double)e, (double)en, (double)vtAfter, (double)vtExact, (double)(100 * errV), (double)w, (double)wExact,
                          (double)(100 * errW), errV > 0.01 || errW > 0.01 ? "FAIL" : "ok"));
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
    output_file: output/ex03_impacts_1.out
TEST*/
