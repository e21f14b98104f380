static const char help[] = "Verification D1 on the walls of -dem_walls: a sphere hits a tilted plane, the inside of a cylinder, and an STL\n"
                           "floor (landing on a vertex shared by 6 triangles) head on, without gravity. Each restitution must meet the input\n"
                           "e = 0.6 within 2 % (D1) and equal the box floor's (the same impact on a box face) within 1e-6: walls are spheres of\n"
                           "infinite radius and mass (P3) whatever their shape, and a mesh vertex is one contact. Exits non-zero on failure.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/dem/StlMesh.hpp"
#include "vofdem/io/TextFile.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

static const PetscReal R = 1e-3, v0 = 0.5, e = 0.6;

using vofdem::example::Num;

// One impact: the particle starts at x moving at -v0 along the wall's normal n (towards it);
// gap(x) is its distance from the wall minus R. Returns the restitution (normal speed after / before).
static PetscErrorCode Impact(const std::vector<std::pair<std::string, std::string>> &wallOptions, const PetscReal x0[3], const PetscReal n[3],
                             const std::function<PetscReal(const PetscReal *)> &gap, PetscReal dt, PetscReal *restitution) {
  vofdem::Simulation sim;
  PetscReal          x[3], v[3];
  PetscBool          found;
  char               buf[256];

  PetscFunctionBeginUser;
  std::snprintf(buf, sizeof buf, "x,y,z,vx,vy,vz\n%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", (double)x0[0], (double)x0[1], (double)x0[2], (double)(-v0 * n[0]),
                (double)(-v0 * n[1]), (double)(-v0 * n[2]));
  PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, "ex10_particle.csv", buf, "particle file"));
  for (const auto &[name, value] : wallOptions) PetscCall(PetscOptionsSetValue(nullptr, name.c_str(), value.c_str()));
  PetscCall(PetscOptionsSetValue(nullptr, "-dt", Num(dt).c_str()));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  PetscReal    gOld = gap(x0);
  bool         started = false, ended = false;
  for (int k = 0; k < 100000 && !ended; ++k) {
    PetscCall(sim.Step());
    PetscCall(dem->FindParticle(0, x, v, &found));
    PetscCheck(found, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "particle 0 missing");
    const PetscReal g = gap(x);
    started           = started || (gOld > 0 && g <= 0);
    ended             = started && gOld <= 0 && g > 0;
    gOld              = g;
  }
  PetscCheck(ended, PETSC_COMM_WORLD, PETSC_ERR_PLIB, "the sphere never left the wall");
  *restitution = (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) / v0;
  PetscCall(sim.Destroy());
  for (const auto &[name, value] : wallOptions) PetscCall(PetscOptionsClearValue(nullptr, name.c_str()));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  const PetscReal rho = 2500, E = 1e8, nu = 0.28, c = 0.005, gap0 = R / 100;
  PetscInt        failures = 0;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  for (const auto &[name, value] : std::vector<std::pair<const char *, std::string>>{
         {"-physics", "dem"}, {"-grid_cells", "2,2,2"}, {"-grid_upper", "0.01,0.01,0.01"}, {"-gravity", "0,0,0"}, {"-dem_radius", Num(R)},
         {"-dem_density", Num(rho)}, {"-dem_youngs_modulus", Num(E)}, {"-dem_poisson_ratio", Num(nu)}, {"-dem_restitution", Num(e)},
         {"-dem_particles_file", "ex10_particle.csv"}})
    PetscCall(PetscOptionsSetValue(nullptr, name, value.c_str()));
  const PetscReal m = rho * 4.0 / 3.0 * PETSC_PI * R * R * R, tc = vofdem::hertz::HertzContactTime(m, R, vofdem::hertz::EffectiveModulus(E, nu, E, nu), v0);
  const PetscReal dt = tc / 200;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "sphere R %g m at %g m/s along each wall's normal, e %g, Hertz contact time %.6e s, 200 steps per contact\n", (double)R,
                        (double)v0, (double)e, (double)tc));

  // The box floor, the reference.
  PetscReal eBox;
  {
    const PetscReal x0[3] = {c, c, R + gap0}, n[3] = {0, 0, 1};
    PetscCall(Impact({}, x0, n, [&](const PetscReal *x) { return x[2] - R; }, dt, &eBox));
  }
  struct Case {
    const char *what;
    PetscReal   e;
  };
  std::vector<Case> cases;
  {  // A plane through the box centre tilted 30 degrees about y.
    const PetscReal n[3] = {std::sin(PETSC_PI / 6), 0, std::cos(PETSC_PI / 6)}, x0[3] = {c + (R + gap0) * n[0], c, c + (R + gap0) * n[2]};
    PetscReal       r;
    PetscCall(Impact({{"-dem_walls", "tilt"}, {"-dem_wall_tilt_type", "plane"}, {"-dem_wall_tilt_point", "0.005,0.005,0.005"},
                      {"-dem_wall_tilt_normal", Num(n[0]) + ",0," + Num(n[2])}},
                     x0, n, [&](const PetscReal *x) { return (x[0] - c) * n[0] + (x[2] - c) * n[2] - R; }, dt, &r));
    cases.push_back({"tilted plane (30 deg)", r});
  }
  {  // The inside of a cylinder of radius 4 mm about the vertical axis through the box centre.
    const PetscReal Rc = 0.004, n[3] = {-1, 0, 0}, x0[3] = {c + Rc - R - gap0, c, c};
    PetscReal       r;
    PetscCall(Impact({{"-dem_walls", "drum"}, {"-dem_wall_drum_type", "cylinder"}, {"-dem_wall_drum_point", "0.005,0.005,0"},
                      {"-dem_wall_drum_axis", "0,0,1"}, {"-dem_wall_drum_radius", Num(Rc)}},
                     x0, n, [&](const PetscReal *x) { return Rc - std::hypot(x[0] - c, x[1] - c) - R; }, dt, &r));
    cases.push_back({"inside a cylinder", r});
  }
  {  // An STL floor at z = 2 mm: a hexagonal fan of 6 triangles, the sphere lands on its centre vertex.
    std::vector<PetscReal> corners;
    const PetscReal        fc = (PetscReal)(float)c, fz = (PetscReal)(float)0.002;  // binary STL holds floats
    for (int k = 0; k < 6; ++k) {
      const PetscReal a0 = k * PETSC_PI / 3, a1 = ((k + 1) % 6) * PETSC_PI / 3, rr = 0.004;
      corners.insert(corners.end(), {c, c, 0.002, c + rr * std::cos(a0), c + rr * std::sin(a0), 0.002, c + rr * std::cos(a1), c + rr * std::sin(a1), 0.002});
    }
    PetscCall(vofdem::WriteTextFile(PETSC_COMM_WORLD, "ex10_fan.stl", vofdem::BinaryStl(corners), "STL file"));
    const PetscReal n[3] = {0, 0, 1}, x0[3] = {fc, fc, fz + R + gap0};
    PetscReal       r;
    PetscCall(Impact({{"-dem_walls", "fan"}, {"-dem_wall_fan_type", "stl"}, {"-dem_wall_fan_file", "ex10_fan.stl"}}, x0, n,
                     [&](const PetscReal *x) { return x[2] - fz - R; }, dt, &r));
    cases.push_back({"STL floor, on a vertex of 6 triangles", r});
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "box floor: restitution %.6f, error %.3f %% (tolerance 2 %%)\n", (double)eBox, (double)(100 * std::abs(eBox - e) / e)));
  failures += std::abs(eBox - e) / e > 0.02;
  for (const Case &k : cases) {
    const PetscReal errInput = std::abs(k.e - e) / e, errBox = std::abs(k.e - eBox) / eBox;
    const bool      bad      = errInput > 0.02 || errBox > 1e-6;
    failures += bad;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: restitution %.6f, error %.3f %% (tolerance 2 %%), differs from the box floor's by %.1e (tolerance 1e-6) %s\n",
                          k.what, (double)k.e, (double)(100 * errInput), (double)errBox, bad ? "FAIL" : "ok"));
  }
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d of %d checks out of tolerance\n", (int)failures, (int)cases.size() + 1));
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
    output_file: output/ex17_wall_shapes_1.out
TEST*/
