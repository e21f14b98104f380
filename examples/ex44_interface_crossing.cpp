static const char help[] = "Particles crossing a free surface (-physics dem,flow,vof; docs/physics.md F1, F1b): 60 glass spheres (d 1 mm,\n"
                           "2500 kg/m^3) released at random in the air (1.2 kg/m^3) of a closed 8 x 8 x 16 mm box over water (1000 kg/m^3)\n"
                           "filling its lower half, 1 mm cells, fall into the water; the fluid side of the drag implicit (a dense cloud in\n"
                           "a light gas: -coupling_fluid_drag implicit). As they move, eps changes: the projection makes\n"
                           "div(eps u) = -d(eps)/dt and the interface's transport carries eps alpha. Checked at every step: the volume\n"
                           "of water, sum eps alpha V, and of air, sum eps (1 - alpha) V, within 1e-10 of their start (relative); at the\n"
                           "end, at least half of the spheres below the initial surface. Reported: the largest bound violation of alpha\n"
                           "(no clipping is done) and the continuity residual max |div(eps u) + d(eps)/dt| dt. -final_time (default 0.08 s).\n"
                           "Exits non-zero on failure.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/dem/Dem.hpp"
#include "vofdem/flow/Flow.hpp"
#include "vofdem/vof/Vof.hpp"
#include "vofdem/examples/Help.hpp"

#include <algorithm>
#include <cmath>

namespace {

const PetscReal kTolVolume = 1e-10, kSurface = 0.008;

PetscErrorCode Run() {
  PetscReal tEnd = 0.08;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-final_time", &tEnd, nullptr));
  PetscCall(PetscOptionsClearValue(nullptr, "-final_time"));
  PetscCall(PetscOptionsInsertString(nullptr, "-physics dem,flow,vof -grid_cells 8,8,16 -grid_upper 0.008,0.008,0.016 -gravity 0,0,-9.81 "
                                              "-flow_density 1.2 -flow_viscosity 1.8e-5 -flow_pressure_pc boomeramg -flow_pressure_ksp_rtol 1e-12 "
                                              "-vof_density 1000 -vof_viscosity 1e-3 -vof_boxes 0,0,0,0.008,0.008,0.008 "
                                              "-dem_radius 5e-4 -dem_density 2500 -dem_fill_count 60 -dem_fill_lower 0,0,0.0095 -dem_fill_upper 0.008,0.008,0.016 "
                                              "-dem_fill_jitter 0.5 -seed 3 -coupling_fluid_drag implicit -max_steps 1000000"));
  vofdem::Simulation sim;
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::VofSummary v0, vs;
  PetscCall(Interface(sim)->Summarize(&v0));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "60 spheres falling into water: volumes at the start: water %.10e m^3, air %.10e m^3\n", (double)v0.volume, (double)v0.otherVolume));
  PetscReal worst[2] = {0, 0}, bounds = 0, residual = 0;
  PetscInt  steps    = 0;
  while (sim.Time() < tEnd * (1 - 1e-12)) {
    PetscCall(sim.ChooseTimeStep());  // the flow's adaptive step, as Run() takes it
    PetscCall(sim.Step());
    ++steps;
    vofdem::FlowSummary fs;
    PetscCall(Interface(sim)->Summarize(&vs));
    PetscCall(Fluid(sim)->Summarize(&fs));
    worst[0] = std::max(worst[0], std::fabs(vs.volume / v0.volume - 1));
    worst[1] = std::max(worst[1], std::fabs(vs.otherVolume / v0.otherVolume - 1));
    bounds   = std::max(bounds, vs.boundViolation);
    residual = std::max(residual, fs.maxDivergence * sim.Dt());  // per step, a fraction of a cell's volume
  }
  // How many spheres are below the initial surface now.
  PetscInt below = 0, total = 0;
  for (PetscInt id = 0; id < 60; ++id) {
    PetscReal x[3], v[3];
    PetscBool found;
    PetscCall(Particles(sim)->FindParticle(id, x, v, &found));
    total += found ? 1 : 0;
    below += found && x[2] < kSurface ? 1 : 0;
  }
  PetscCall(sim.Destroy());
  const bool okVol = worst[0] <= kTolVolume && worst[1] <= kTolVolume, okCross = 2 * below >= total && total == 60;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "after %d steps to t = %g s: %d of %d spheres below the initial surface (at least half) %s\n", (int)steps, (double)tEnd, (int)below, (int)total,
                        okCross ? "ok" : "FAIL"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "largest relative volume change: water %.1e, air %.1e (tolerance %g) %s\n", (double)worst[0], (double)worst[1], (double)kTolVolume, okVol ? "ok" : "FAIL"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "reported: largest bound violation of alpha %.1e; largest |div(eps u) + d(eps)/dt| dt (per step, of a cell's volume) %.1e\n", (double)bounds, (double)residual));
  PetscFunctionReturn(okVol && okCross ? 0 : PETSC_ERR_NOT_CONVERGED);
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
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    output_file: output/ex44_interface_crossing_1.out
TEST*/
