static const char help[] = "Verification V7 (docs/verification.md): seed 000's particle-laden dam break (Sun & Sakai 2015) with -physics dem,flow,vof.\n"
                           "A closed tank 0.2 x 0.1 x 0.3 m (x, y, z; gravity -z), a water column 0.05 x 0.1 x 0.1 m at x = 0 under air, and glass\n"
                           "beads (d 2.7 mm, 2500 kg/m^3; config/materials/glass.yaml) settled at the column's base (-bed FILE, a CSV written by\n"
                           "config/scenes/particle-dam-break-bed.yaml; without it -bed_count beads are poured at random into the base,\n"
                           "0.05 x 0.1 x -bed_height m). -mode semi (cells of 0.8 d, the seed's semi-resolved VOF-DEM, smooth kernel H = 1.5 d)\n"
                           "or unresolved (cells of 3 d, the particle's own cell: the seed's comparison); -grid_cells overrides the cells.\n"
                           "The seed's observation points, from the water fraction alpha averaged over y (ParaView output with\n"
                           "-output_dir and -flow_output_every / -dem_output_every):\n"
                           "  A: the water front on the floor at -time_front (default 0.1 s): the largest x where the floor row's alpha >= 0.5;\n"
                           "  B: the impact height on the far wall at -time_impact (0.2 s): the largest z where the wall column's alpha >= 0.5;\n"
                           "  C: the thickness of the water layer on the far wall at -layer_height (0.05 m) at -time_layer (0.3 s): the run of\n"
                           "     cells with alpha >= 0.5 from the wall inwards.\n"
                           "Crossings of 0.5 are interpolated linearly between cell centres.\n"
                           "Each is linearly interpolated in time between the two steps around its time; the particle front (largest x of\n"
                           "a bead) is reported beside A. -profiles PREFIX writes, at the first step at or after each observation time, the\n"
                           "y-averaged alpha (PREFIX_<t>_alpha.csv: rows z, columns x) and the beads' x, z (PREFIX_<t>_beads.csv) for\n"
                           "scripts/plot_particle_dam_break.py; -progress N prints the step, time and wall time every N steps. Checked (exit non-zero on failure): water and air volumes (eps alpha V and\n"
                           "eps (1 - alpha) V) within 1e-10 of their start, no bead lost, alpha within 1e-10 of [0, 1] (the split sweeps of\n"
                           "eps alpha overshoot where eps changes fast in a part-filled cell; -vof_redistribute hands the excess to the\n"
                           "neighbours, conserving the volumes). The experiment's values are read off figures (seed 000, Fig. 5) that are not in\n"
                           "this repository: the quantities are printed, not judged.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/vof/Vof.hpp"
#include "vofdem/examples/Help.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

const PetscReal kL[3] = {0.2, 0.1, 0.3}, kColumn[3] = {0.05, 0.1, 0.1}, kD = 2.7e-3, kTolVolume = 1e-10;

PetscErrorCode Default(const char *name, const std::string &value) {
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, name, &set));
  if (!set) PetscCall(PetscOptionsSetValue(nullptr, name, value.c_str()));
  PetscFunctionReturn(0);
}

std::string Triple(PetscReal a, PetscReal b, PetscReal c) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", (double)a, (double)b, (double)c);
  return buf;
}

// The scene (config/scenes/particle-dam-break.yaml says the same), leaving every option the user gave.
PetscErrorCode SetScene(const std::string &mode, const std::string &bed, PetscInt bedCount, PetscReal bedHeight) {
  PetscFunctionBeginUser;
  const bool semi = mode == "semi";
  PetscCall(Default("-physics", "dem,flow,vof"));
  PetscCall(Default("-grid_cells", semi ? "92,46,138" : "25,12,37"));  // 2.17 mm = 0.80 d; 8.0-8.3 mm = 3.0 d
  PetscCall(Default("-grid_upper", Triple(kL[0], kL[1], kL[2])));
  PetscCall(Default("-gravity", "0,0,-9.81"));
  PetscCall(Default("-flow_density", "1.2"));
  PetscCall(Default("-flow_viscosity", "1.8e-5"));
  PetscCall(Default("-flow_pressure_pc", "boomeramg"));
  PetscCall(Default("-flow_pressure_ksp_rtol", "1e-12"));  // the volumes to 1e-10 (F1b)
  PetscCall(Default("-flow_viscous", "explicit"));
  PetscCall(Default("-vof_density", "1000"));
  PetscCall(Default("-vof_viscosity", "1e-3"));
  PetscCall(Default("-vof_boxes", "0,0,0," + Triple(kColumn[0], kColumn[1], kColumn[2])));
  PetscCall(Default("-dem_radius", std::to_string(kD / 2)));
  PetscCall(Default("-dem_density", "2500"));
  PetscCall(Default("-dem_youngs_modulus", "1e8"));
  PetscCall(Default("-dem_poisson_ratio", "0.25"));
  PetscCall(Default("-dem_restitution", "0.9"));
  PetscCall(Default("-dem_friction", "0.3"));
  if (!bed.empty()) PetscCall(Default("-dem_particles_file", bed));
  else {
    PetscCall(Default("-dem_fill_mode", "random"));
    PetscCall(Default("-dem_fill_count", std::to_string((long long)bedCount)));
    PetscCall(Default("-dem_fill_lower", "0,0,0"));
    PetscCall(Default("-dem_fill_upper", Triple(kColumn[0], kColumn[1], bedHeight)));
  }
  PetscCall(Default("-coupling_drag", "gidaspow"));  // seed 000 (F6)
  // The bed's fluid relaxation time eps rho/beta (about 1e-3 s in water at a slip of 1 m/s) is near the fluid
  // step: the explicit exchange oscillated and blew up within 8 steps at 0.8 d; the implicit one is stable.
  PetscCall(Default("-coupling_fluid_drag", "implicit"));
  if (!semi) PetscCall(Default("-coupling_kernel", "unresolved"));
  PetscCall(Default("-max_steps", "10000000"));
  PetscCall(Default("-monitor_every", "100"));
  PetscFunctionReturn(0);
}

// alpha averaged over y, a[k nx + i], on every rank.
PetscErrorCode ProfileXZ(vofdem::Vof &vof, PetscInt nx, PetscInt ny, PetscInt nz, std::vector<PetscReal> &a, std::vector<PetscReal> &local) {
  PetscScalar ***f;
  PetscInt       s[3], n[3];

  PetscFunctionBeginUser;
  std::fill(local.begin(), local.end(), 0);
  PetscCall(DMDAGetCorners(vof.FractionDM(), &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAVecGetArrayRead(vof.FractionDM(), vof.Fraction(), &f));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) local[k * nx + i] += PetscRealPart(f[k][j][i]) / ny;
  PetscCall(DMDAVecRestoreArrayRead(vof.FractionDM(), vof.Fraction(), &f));
  PetscCallMPI(MPI_Allreduce(local.data(), a.data(), (int)(nx * nz), MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  PetscFunctionReturn(0);
}

// Positions along a row of cell values (centres (m + 1/2) h, m = 0..n-1) where the water fraction crosses 0.5,
// linear between the two cell centres around the crossing.
PetscReal Between(PetscReal a, PetscReal b, PetscInt m, PetscReal h) { return (m + 0.5) * h + h * (a - 0.5) / (a - b); }

// The largest position with a value >= 0.5 (0 if none): a front, or the top of the water on a wall,
// not misled by cells of the bed where alpha is off.
PetscReal Farthest(const std::vector<PetscReal> &v, PetscReal h) {
  const PetscInt n = (PetscInt)v.size();
  PetscInt       m = n - 1;
  while (m >= 0 && v[m] < 0.5) --m;
  if (m < 0) return 0;
  return m == n - 1 ? n * h : Between(v[m], v[m + 1], m, h);
}

// The length of the run of values >= 0.5 that starts at the row's far end (a layer on the far wall).
PetscReal FromFarEnd(const std::vector<PetscReal> &v, PetscReal h) {
  const PetscInt n = (PetscInt)v.size();
  if (v[n - 1] < 0.5) return 0;
  PetscInt m = 0;  // counted from the far end
  while (m + 1 < n && v[n - 2 - m] >= 0.5) ++m;
  return m + 1 == n ? n * h : Between(v[n - 1 - m], v[n - 2 - m], m, h);
}

struct Observation {
  const char *name;
  PetscReal   time, previous = 0, value = 0, previousTime = 0, particleFront = 0, previousFront = 0;
  bool        done = false;
};

// The three observation quantities from the y-averaged alpha.
void Measure(const std::vector<PetscReal> &a, PetscInt nx, PetscInt nz, const PetscReal *h, PetscInt layerRow, PetscReal out[3]) {
  std::vector<PetscReal> row(a.begin(), a.begin() + nx), wall(nz), layer(a.begin() + layerRow * nx, a.begin() + (layerRow + 1) * nx);
  for (PetscInt k = 0; k < nz; ++k) wall[k] = a[k * nx + nx - 1];
  out[0] = Farthest(row, h[0]);     // A: the front on the floor
  out[1] = Farthest(wall, h[2]);    // B: the top of the water on the far wall
  out[2] = FromFarEnd(layer, h[0]);  // C: the layer on the far wall
}

PetscErrorCode WriteProfiles(const std::string &prefix, PetscReal t, const std::vector<PetscReal> &a, PetscInt nx, PetscInt nz, vofdem::Dem &dem) {
  vofdem::ParticleArrays p;
  PetscMPIInt            rank, size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  char tag[32];
  std::snprintf(tag, sizeof tag, "_%.3f", (double)t);
  PetscCall(dem.Particles().GetArrays(&p));
  std::vector<PetscReal> xz(2 * (size_t)p.n);
  for (PetscInt q = 0; q < p.n; ++q) xz[2 * q] = p.x[3 * q], xz[2 * q + 1] = p.x[3 * q + 2];
  PetscCall(dem.Particles().RestoreArrays(&p));
  PetscMPIInt              mine = (PetscMPIInt)xz.size();
  std::vector<PetscMPIInt> counts(size), offsets(size, 0);
  PetscCallMPI(MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, PETSC_COMM_WORLD));
  for (PetscMPIInt r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<PetscReal> all(rank == 0 ? (size_t)(offsets[size - 1] + counts[size - 1]) : 0);
  PetscCallMPI(MPI_Gatherv(xz.data(), mine, MPIU_REAL, all.data(), counts.data(), offsets.data(), MPIU_REAL, 0, PETSC_COMM_WORLD));
  if (rank == 0) {
    const std::string fa = prefix + tag + "_alpha.csv", fb = prefix + tag + "_beads.csv";
    FILE             *f  = std::fopen(fa.c_str(), "w");
    FILE             *g  = f ? std::fopen(fb.c_str(), "w") : nullptr;
    if (!f || !g) {
      if (f) std::fclose(f);
      VofdemInputError(PETSC_COMM_SELF, "option -profiles: cannot write %s", (f ? fb : fa).c_str());
    }
    for (PetscInt k = 0; k < nz; ++k)
      for (PetscInt i = 0; i < nx; ++i) std::fprintf(f, "%.6g%c", (double)a[k * nx + i], i + 1 == nx ? '\n' : ',');
    std::fprintf(g, "x,z\n");
    for (size_t q = 0; q + 1 < all.size(); q += 2) std::fprintf(g, "%.6g,%.6g\n", (double)all[q], (double)all[q + 1]);
    std::fclose(f);
    std::fclose(g);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleFront(vofdem::Dem &dem, PetscReal *x) {
  vofdem::ParticleArrays p;
  PetscReal              m = 0;

  PetscFunctionBeginUser;
  PetscCall(dem.Particles().GetArrays(&p));
  for (PetscInt q = 0; q < p.n; ++q) m = std::max(m, p.x[3 * q] + p.radius[q]);
  PetscCall(dem.Particles().RestoreArrays(&p));
  PetscCallMPI(MPI_Allreduce(&m, x, 1, MPIU_REAL, MPIU_MAX, PETSC_COMM_WORLD));
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  char        mode[32] = "semi", bed[PETSC_MAX_PATH_LEN] = "", prefix[PETSC_MAX_PATH_LEN] = "";
  PetscInt    bedCount = 3883, progress = 0;
  PetscReal   bedHeight = 0.03, layerHeight = 0.05, times[3] = {0.1, 0.2, 0.3};
  PetscBool   hasPrefix = PETSC_FALSE;
  const char *names[3] = {"-time_front", "-time_impact", "-time_layer"};

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-mode", mode, sizeof mode, nullptr));
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-bed", bed, sizeof bed, nullptr));
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-profiles", prefix, sizeof prefix, &hasPrefix));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-bed_count", &bedCount, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-progress", &progress, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-bed_height", &bedHeight, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-layer_height", &layerHeight, nullptr));
  for (int q = 0; q < 3; ++q) PetscCall(PetscOptionsGetReal(nullptr, nullptr, names[q], &times[q], nullptr));
  for (const char *o : {"-mode", "-bed", "-profiles", "-progress", "-bed_count", "-bed_height", "-layer_height", "-time_front", "-time_impact", "-time_layer"})
    PetscCall(PetscOptionsClearValue(nullptr, o));
  if (std::string(mode) != "semi" && std::string(mode) != "unresolved") VofdemInputError(PETSC_COMM_WORLD, "option -mode: '%s' is neither semi nor unresolved", mode);
  if (!(times[0] <= times[1] && times[1] <= times[2] && times[0] > 0))
    VofdemInputError(PETSC_COMM_WORLD, "options -time_front, -time_impact, -time_layer: give positive times in this order");
  if (!(layerHeight > 0 && layerHeight < kL[2])) VofdemInputError(PETSC_COMM_WORLD, "option -layer_height: %g m is outside the tank (0, %g)", (double)layerHeight, (double)kL[2]);
  PetscCall(SetScene(mode, bed, bedCount, bedHeight));
  PetscCall(Default("-final_time", std::to_string((double)times[2])));

  vofdem::Simulation sim;
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  const vofdem::Grid &grid = sim.GetGrid();
  const PetscInt      nx = grid.Cells()[0], ny = grid.Cells()[1], nz = grid.Cells()[2];
  const PetscReal    *h = grid.Spacing();
  const PetscInt      layerRow = std::min(nz - 1, (PetscInt)(layerHeight / h[2]));
  vofdem::VofSummary  v0, vs;
  PetscCall(Interface(sim)->Summarize(&v0));
  vofdem::DemSummary d0;
  PetscCall(Particles(sim)->Summarize(&d0));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "V7 particle-laden dam break, %s: %d x %d x %d cells of %.3g m (%.2f d), %d beads of d %g m\n", mode, (int)nx, (int)ny, (int)nz, (double)h[0],
                        (double)(h[0] / kD), (int)d0.particles, (double)kD));

  std::vector<PetscReal> a(nx * nz), scratch(nx * nz);
  Observation            obs[3] = {{"A front on the floor (m)", times[0]}, {"B impact height on the far wall (m)", times[1]}, {"C layer thickness at the far wall (m)", times[2]}};
  PetscReal              now[3], front, dvol = 0, bound = 0;
  PetscCall(ProfileXZ(*Interface(sim), nx, ny, nz, a, scratch));
  Measure(a, nx, nz, h, layerRow, now);
  PetscCall(ParticleFront(*Particles(sim), &front));
  for (int q = 0; q < 3; ++q) obs[q].previous = now[q], obs[q].previousFront = front;
  bool           written[3] = {!hasPrefix, !hasPrefix, !hasPrefix};
  PetscLogDouble start;
  PetscCall(PetscTime(&start));
  while (!obs[2].done) {
    PetscCall(sim.ChooseTimeStep());
    PetscCall(sim.Step());
    PetscCall(ProfileXZ(*Interface(sim), nx, ny, nz, a, scratch));
    Measure(a, nx, nz, h, layerRow, now);
    PetscCall(ParticleFront(*Particles(sim), &front));
    PetscCall(Interface(sim)->Summarize(&vs));
    dvol  = std::max(dvol, std::max(std::fabs(vs.volume / v0.volume - 1), std::fabs(vs.otherVolume / v0.otherVolume - 1)));
    bound = std::max(bound, vs.boundViolation);
    const PetscReal t = sim.Time();
    if (progress > 0 && sim.StepNumber() % progress == 0) {
      PetscLogDouble wall;
      PetscCall(PetscTime(&wall));
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  step %d  t %.5f s  dt %.3e s  front %.4f m  wall %.0f s\n", (int)sim.StepNumber(), (double)t, (double)sim.Dt(), (double)now[0], wall - start));
    }
    for (int q = 0; q < 3; ++q) {
      Observation &o = obs[q];
      if (!o.done && t >= o.time * (1 - 1e-12)) {
        const PetscReal w = (o.time - o.previousTime) / (t - o.previousTime);
        o.value           = o.previous + w * (now[q] - o.previous);
        o.particleFront   = o.previousFront + w * (front - o.previousFront);
        o.done            = true;
      }
      if (!o.done) o.previous = now[q], o.previousFront = front, o.previousTime = t;
      if (o.done && !written[q]) {
        PetscCall(WriteProfiles(prefix, t, a, nx, nz, *Particles(sim)));
        written[q] = true;
      }
    }
    if (sim.StepNumber() >= 10000000) break;
  }
  vofdem::DemSummary d1;
  PetscCall(Particles(sim)->Summarize(&d1));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "V7 %s after %d steps:\n", mode, (int)sim.StepNumber()));
  for (const Observation &o : obs)
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  t %.3f s: %-38s %.4f%s\n", (double)o.time, o.name, (double)o.value,
                          &o == &obs[0] ? (" (bead front " + std::to_string((double)o.particleFront).substr(0, 6) + " m)").c_str() : ""));
  const bool volOk = dvol <= kTolVolume, countOk = d1.particles == d0.particles, boundOk = bound <= kTolVolume;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "V7 largest relative volume change of water or air %.1e (tolerance %g) %s; beads %d of %d %s; alpha outside [0, 1] by %.1e (tolerance %g) %s\n", (double)dvol,
                        (double)kTolVolume, volOk ? "ok" : "FAIL", (int)d1.particles, (int)d0.particles, countOk ? "ok" : "FAIL", (double)bound, (double)kTolVolume, boundOk ? "ok" : "FAIL"));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(volOk && countOk && boundOk ? 0 : PETSC_ERR_NOT_CONVERGED);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-3
  atol: 1e-6
  timeout: 600
  test:
    suffix: unresolved_1
    nsize: 1
    args: -mode unresolved -bed_count 600 -bed_height 0.02 -time_front 0.04 -time_impact 0.05 -time_layer 0.06
  test:
    suffix: unresolved_2
    nsize: 2
    args: -mode unresolved -bed_count 600 -bed_height 0.02 -time_front 0.04 -time_impact 0.05 -time_layer 0.06
    output_file: output/ex42_particle_dam_break_unresolved_1.out
  test:
    suffix: semi_1
    nsize: 1
    args: -mode semi -grid_cells 46,24,70 -bed_count 600 -bed_height 0.02 -time_front 0.02 -time_impact 0.025 -time_layer 0.03
  test:
    suffix: semi_2
    nsize: 2
    args: -mode semi -grid_cells 46,24,70 -bed_count 600 -bed_height 0.02 -time_front 0.02 -time_impact 0.025 -time_layer 0.03
    output_file: output/ex42_particle_dam_break_semi_1.out
TEST*/
