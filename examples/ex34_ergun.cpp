static const char help[] = "Verification C2 (VERIFICATION.md): a packed bed with fluid rising through it (the CFDEM ErgunTestMPI set-up: spheres\n"
                           "d = 1 mm, 2000 kg/m^3; fluid 10 kg/m^3, 1.5e-3 Pa s). The bed is poured first (-physics dem: -particles spheres (default\n"
                           "1600) randomly placed in a 10 x 10 mm periodic column, settled for -settle_time s, default 0.3 s, on a grate\n"
                           "5 mm above the inflow face); its height L = 2 <z> (z from the grate) and fluid fraction eps = 1 - N V/(A L) come from the particles. Then for each superficial velocity of -velocities (m/s,\n"
                           "default 0.002,0.01) the fluid enters at the floor (-flow_bc_zlo inflow) and leaves at the top (outflow), coupled\n"
                           "(-physics dem,flow, cell = d, drag -coupling_drag, default gidaspow) for -steps fluid steps (default 30); the pressure drop\n"
                           "over the bed, p(floor row) - p(top row) - rho_f g (height between them), plane means, is compared with Ergun's\n"
                           "L [150 (1-eps)^2 mu U/(eps^3 d^2) + 1.75 (1-eps) rho U^2/(eps^3 d)] for velocities below the minimum fluidisation velocity\n"
                           "(where Ergun's drop equals the buoyant weight per area (rho_p - rho_f)(1 - eps) g L; tolerance 1 %%), and with that\n"
                           "weight above it (tolerance 1 %%). Exits non-zero on failure.\n\n";

#include "vofdem/core/Runtime.hpp"
#include "vofdem/core/Simulation.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

const PetscReal kD = 1e-3, kRhoP = 2000, kRhoF = 10, kMu = 1.5e-3, kG = 9.81, kA = 0.01, kZ = 0.04;
const PetscReal kTolerance = 0.01, kGrate = 0.005;

PetscErrorCode Set(const char *name, const std::string &v) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsSetValue(nullptr, name, v.c_str()));
  PetscFunctionReturn(0);
}
std::string Num(PetscReal v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", (double)v);
  return buf;
}

PetscErrorCode Common() {
  PetscFunctionBeginUser;
  PetscCall(Set("-grid_cells", "10,10,40"));
  PetscCall(Set("-grid_upper", Num(kA) + "," + Num(kA) + "," + Num(kZ)));
  PetscCall(Set("-grid_periodic", "x,y"));
  PetscCall(Set("-dem_radius", Num(kD / 2)));
  PetscCall(Set("-dem_density", Num(kRhoP)));
  PetscCall(Set("-dem_youngs_modulus", "5e6"));  // soft: a long DEM step; overlaps stay below 1 % of d under the bed's weight
  PetscCall(Set("-dem_restitution", "0.3"));
  PetscCall(Set("-monitor_every", "100000"));
  // The bed rests on a grate 5 mm above the inflow face (a DEM wall the fluid passes): the inflow sets
  // the velocity at the face, so it must see eps = 1 there for U to be the superficial velocity.
  PetscCall(Set("-dem_walls", "grate"));
  PetscCall(Set("-dem_wall_grate_type", "plane"));
  PetscCall(Set("-dem_wall_grate_point", "0,0," + Num(kGrate)));
  PetscCall(Set("-dem_wall_grate_normal", "0,0,1"));
  PetscCall(Set("-monitor_timing", "0"));
  PetscFunctionReturn(0);
}

// The bed: particle count, height L = 2 <z> and fluid fraction, from the saved CSV (every rank reads it).
PetscErrorCode Bed(const std::string &path, PetscInt *n, PetscReal *L, PetscReal *eps) {
  PetscFunctionBeginUser;
  std::ifstream in(path);
  std::string   line;
  std::getline(in, line);
  PetscReal sum = 0;
  *n            = 0;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string       cell;
    PetscReal         x[3];
    for (int k = 0; k < 3 && std::getline(ss, cell, ','); ++k) x[k] = std::stod(cell);
    sum += x[2] - kGrate;
    ++*n;
  }
  PetscCheck(*n > 0, PETSC_COMM_WORLD, PETSC_ERR_FILE_READ, "no particles in %s", path.c_str());
  *L   = 2 * sum / *n;
  *eps = 1 - *n * PETSC_PI * kD * kD * kD / 6 / (kA * kA * *L);
  PetscFunctionReturn(0);
}

// Plane mean of the pressure in cell row k.
PetscErrorCode RowPressure(vofdem::Flow &flow, PetscInt k, PetscReal *p) {
  vofdem::LocalField P;
  PetscInt           s[3], n[3];
  PetscReal          sum = 0, all;

  PetscFunctionBeginUser;
  const vofdem::StaggeredGrid &sg = flow.Staggered();
  PetscCall(sg.GetGlobal(3, flow.Pressure(), &P));
  sg.Owned(3, s, n);
  if (k >= s[2] && k < s[2] + n[2])
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) sum += PetscRealPart(P.at(i, j, k));
  PetscCall(sg.RestoreGlobal(3, flow.Pressure(), &P));
  PetscCallMPI(MPI_Allreduce(&sum, &all, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  *p = all / (sg.Base().Cells()[0] * sg.Base().Cells()[1]);
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  PetscReal   vel[16] = {0.002, 0.01}, settle = 0.3;
  PetscInt    nv = 16, particles = 1600, steps = 30, failures = 0;
  char        drag[64] = "gidaspow";
  PetscBool   set;
  std::string bed = "ex34_bed.csv";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetRealArray(nullptr, nullptr, "-velocities", vel, &nv, &set));
  if (!set) nv = 2;
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-settle_time", &settle, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-particles", &particles, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-steps", &steps, nullptr));
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-coupling_drag", drag, sizeof drag, nullptr));
  {  // pour the bed
    vofdem::Simulation sim;
    PetscCall(Common());
    PetscCall(Set("-physics", "dem"));
    PetscCall(Set("-allow_unused_options", "1"));  // the -coupling_* and -flow_* options are for the runs below
    PetscCall(Set("-dem_fill_mode", "random"));
    PetscCall(Set("-dem_fill_count", std::to_string((long long)particles)));
    PetscCall(Set("-dem_fill_lower", "0,0," + Num(kGrate + 0.002)));
    PetscCall(Set("-dem_fill_upper", Num(kA) + "," + Num(kA) + "," + Num(kZ)));
    PetscCall(Set("-final_time", Num(settle)));
    PetscCall(Set("-max_steps", "100000000"));
    PetscCall(Set("-dem_save_particles", bed));
    PetscCall(sim.Create(PETSC_COMM_WORLD));
    PetscCall(sim.SetFromOptions());
    PetscCall(sim.SetUp());
    PetscCall(sim.Run());
    vofdem::DemSummary s;
    PetscCall(sim.Particles()->Summarize(&s));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "bed poured: %d spheres, kinetic energy at the end %.3e J\n", (int)s.particles, (double)s.kinetic));
    PetscCall(sim.Destroy());
    for (const char *o : {"-dem_fill_mode", "-dem_fill_count", "-dem_fill_lower", "-dem_fill_upper", "-final_time", "-dem_save_particles", "-allow_unused_options"}) PetscCall(PetscOptionsClearValue(nullptr, o));
  }
  PetscInt  n;
  PetscReal L, eps;
  PetscCall(Bed(bed, &n, &L, &eps));
  const PetscReal weight = (kRhoP - kRhoF) * (1 - eps) * kG * L;
  const PetscReal a = 150 * (1 - eps) * (1 - eps) * kMu / (eps * eps * eps * kD * kD) * L, b = 1.75 * (1 - eps) * kRhoF / (eps * eps * eps * kD) * L;
  const PetscReal umf = (-a + std::sqrt(a * a + 4 * b * weight)) / (2 * b);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "bed: %d spheres, L = 2<z> = %.4f m, eps = %.4f; Ergun's minimum fluidisation velocity %.5f m/s, buoyant weight per area %.2f Pa\n",
                        (int)n, (double)L, (double)eps, (double)umf, (double)weight));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "U (m/s)   pressure drop (Pa)  reference (Pa)          error\n"));
  for (PetscInt q = 0; q < nv; ++q) {
    vofdem::Simulation sim;
    const PetscReal    U = vel[q];
    PetscCall(Common());
    PetscCall(Set("-physics", "dem,flow"));
    PetscCall(Set("-dem_particles_file", bed));
    PetscCall(Set("-flow_density", Num(kRhoF)));
    PetscCall(Set("-flow_viscosity", Num(kMu)));
    PetscCall(Set("-flow_bc_zlo", "inflow"));
    PetscCall(Set("-flow_bc_zlo_velocity", "0,0," + Num(U)));
    PetscCall(Set("-flow_bc_zhi", "outflow"));
    PetscCall(Set("-coupling_drag", drag));
    PetscCall(Set("-max_steps", std::to_string((long long)steps)));
    PetscCall(sim.Create(PETSC_COMM_WORLD));
    PetscCall(sim.SetFromOptions());
    PetscCall(sim.SetUp());
    PetscCall(sim.Run());
    PetscReal p0, p1;
    const PetscInt top = sim.GetGrid().Cells()[2] - 2;
    PetscCall(RowPressure(*sim.Fluid(), 0, &p0));
    PetscCall(RowPressure(*sim.Fluid(), top, &p1));
    const PetscReal h = sim.GetGrid().Spacing()[2];
    const PetscReal dp = p0 - p1 - kRhoF * kG * (top * h);
    const bool      fixed = U < umf;
    const PetscReal ref   = fixed ? a * U + b * U * U : weight;
    const PetscReal err   = dp / ref - 1;
    const bool      ok    = std::fabs(err) <= kTolerance;
    failures += !ok;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%-8.4f  %-18.3f  %-10.3f (%s)  %+6.2f %% %s\n", (double)U, (double)dp, (double)ref, fixed ? "Ergun" : "weight", (double)(100 * err),
                          ok ? "ok" : "FAIL"));
    PetscCall(sim.Destroy());
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "C2 packed bed: %s\n", failures ? "FAIL" : "ok"));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}
