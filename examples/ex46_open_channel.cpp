static const char help[] = "VOF inflow and outflow faces (issue 8; src/vof/VofOpenFaces.cpp): a channel L = 1 m long (x), W = 0.25 m wide (y), 2 cells\n"
                           "thick (z), free-slip side walls, no gravity, filled with gas (1 kg/m^3); liquid (-ratio times denser, default 1000)\n"
                           "enters through the inflow face xlo at U = 1 m/s (-vof_bc_xlo_alpha 1), leaves through the outflow face xhi. -resolution N\n"
                           "cells along x (default 32; W/h = N/4). Plug flow: the exact solution keeps u = U and moves the front at x_f = U t.\n"
                           "Run to t = 2 L/U (the front leaves at t = L/U; the smeared tail of a jet's corners follows). Cases:\n"
                           " - default: the whole face (alpha_in = 1);\n"
                           " - -band lo,hi: a liquid jet through y in [lo, hi] of the face only (-vof_bc_xlo_alpha_band), gas elsewhere;\n"
                           " - -drain: the channel starts full of liquid and gas (alpha_in = 0) pushes it out;\n"
                           " - -backflow: both x faces are outflow faces, xlo at 2 Pa, xhi at 0 Pa, the gas at rest: the pressure drives the flow\n"
                           "   in through xlo (backflow), which brings liquid (-vof_bc_xlo_alpha 1); the velocity stays uniform in x but grows in\n"
                           "   time (-dt 2e-3 for the first step, then the adaptive one, to t = 1 s): the front is at x_f = (volume in)/(W depth), (c) and (d) are taken against it\n"
                           "   (the shape check, and max |u - mean u_x| / max u_x for (d)).\n"
                           "Checked (measured value next to its tolerance, non-zero exit on failure):\n"
                           " (a) volume balance: max over the steps of |V(t) - V(0) - (in - out)| / max(V, in, out) <= 1e-12, in and out the\n"
                           "     sums of the geometric fluxes through the open faces (Vof::Summarize);\n"
                           " (b) alpha within [0, 1] to 1e-12;\n"
                           " (c) front: at t = L/(4U), L/(2U), 3L/(4U) and the end, the shape error sum |alpha - alpha_exact| dV / (A_jet h) <= 0.5\n"
                           "     (less than half a cell of smearing; alpha_exact = f_j clamp((U t - x_i)/h, 0, 1), f_j the band's share of row j),\n"
                           "     and after the front has left, the outflow rate of liquid equals the inflow rate to 1e-12 (steady) and the inflow\n"
                           "     rate equals U A_jet alpha_in to 1e-12;\n"
                           " (d) the velocity stays U: max |u - U| / U over the run <= 1e-8 at the density ratio (stable, no spurious momentum).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/flow/Flow.hpp"
#include "vofdem/vof/Vof.hpp"
#include "vofdem/examples/Help.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace {

const PetscReal kL = 1, kW = 0.25, kU = 1;
const PetscReal kTolBalance = 1e-12, kTolBounds = 1e-12, kTolShape = 0.5, kTolRate = 1e-12, kTolVelocity = 1e-8;

PetscErrorCode Default(const char *name, const std::string &value) {
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, name, &set));
  if (!set) PetscCall(PetscOptionsSetValue(nullptr, name, value.c_str()));
  PetscFunctionReturn(0);
}

std::string Str(PetscReal v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", (double)v);
  return b;
}

// Share of the band [lo, hi] in the cell row [y0, y0 + h] (1 without a band).
PetscReal RowShare(bool band, const PetscReal b[2], PetscReal y0, PetscReal h) {
  if (!band) return 1;
  return std::max((PetscReal)0, std::min(y0 + h, b[1]) - std::max(y0, b[0])) / h;
}

// max over faces of |u_d - U_d| (collective), U = (ux, 0, 0); NaN propagates.
PetscErrorCode VelocityError(vofdem::Flow &flow, PetscReal ux, PetscReal *err) {
  PetscFunctionBeginUser;
  *err = 0;
  for (int d = 0; d < 3; ++d) {
    Vec       w;
    PetscReal m;
    PetscCall(VecDuplicate(flow.Velocity(d), &w));
    PetscCall(VecCopy(flow.Velocity(d), w));
    PetscCall(VecShift(w, d == 0 ? -ux : 0));
    PetscCall(VecNorm(w, NORM_INFINITY, &m));
    PetscCall(VecDestroy(&w));
    *err = std::isnan(m) || std::isnan(*err) ? NAN : std::fmax(*err, m);
  }
  PetscFunctionReturn(0);
}

// sum |alpha - alpha_exact| dV / (A_jet h) with the front at xf (collective).
PetscErrorCode ShapeError(vofdem::Simulation &sim, bool band, const PetscReal b[2], bool drain, PetscReal xf, PetscReal ajet, PetscReal *err) {
  vofdem::Vof *vof = Interface(sim);
  DM           da  = vof->FractionDM();
  PetscScalar ***a;
  PetscInt      s[3], n[3];

  PetscFunctionBeginUser;
  const PetscReal *h = sim.GetGrid().Spacing();
  PetscCall(DMDAGetCorners(da, &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAVecGetArrayRead(da, vof->Fraction(), &a));
  PetscReal loc = 0;
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscReal front = std::min((PetscReal)1, std::max((PetscReal)0, (xf - i * h[0]) / h[0]));  // share of the cell the front has passed
        const PetscReal fresh = drain ? 0 : RowShare(band, b, j * h[1], h[1]);                              // what enters row j
        const PetscReal exact = fresh * front + (drain ? 1 : 0) * (1 - front);
        loc += std::fabs(PetscRealPart(a[k][j][i]) - exact);
      }
  PetscCall(DMDAVecRestoreArrayRead(da, vof->Fraction(), &a));
  PetscCallMPI(MPI_Allreduce(&loc, err, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  *err *= h[0] * h[1] * h[2] / (ajet * h[0]);
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  vofdem::Simulation sim;
  PetscInt           N = 32;
  PetscReal          ratio = 1000, b[2] = {0, 0};
  PetscInt           nb = 2;
  PetscBool          band = PETSC_FALSE, drain = PETSC_FALSE, back = PETSC_FALSE;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-resolution", &N, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-ratio", &ratio, nullptr));
  PetscCall(PetscOptionsGetRealArray(nullptr, nullptr, "-band", b, &nb, &band));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-drain", &drain, nullptr));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-backflow", &back, nullptr));
  if (N < 8 || N % 4) VofdemInputError(PETSC_COMM_WORLD, "ex46: option -resolution: give a multiple of 4, at least 8 (got %d)", (int)N);
  if (band && (nb != 2 || !(0 <= b[0] && b[0] < b[1] && b[1] <= kW))) VofdemInputError(PETSC_COMM_WORLD, "ex46: option -band: give lo,hi with 0 <= lo < hi <= %g m", (double)kW);
  if ((int)band + (int)drain + (int)back > 1) VofdemInputError(PETSC_COMM_WORLD, "ex46: options -band, -drain and -backflow: choose one case");
  const PetscReal h = kL / N, tEnd = back ? 1 : 2 * kL / kU;
  PetscCall(Default("-physics", "flow,vof"));
  PetscCall(Default("-grid_cells", std::to_string(N) + "," + std::to_string(N / 4) + ",2"));
  PetscCall(Default("-grid_upper", Str(kL) + "," + Str(kW) + "," + Str(2 * h)));
  for (const char *f : {"ylo", "yhi", "zlo", "zhi"}) PetscCall(Default((std::string("-flow_bc_") + f).c_str(), "slip"));
  if (back) {
    PetscCall(Default("-flow_bc_xlo", "outflow"));
    PetscCall(Default("-flow_bc_xlo_pressure", "2"));
    PetscCall(Default("-dt", "2e-3"));
  } else {
    PetscCall(Default("-flow_bc_xlo", "inflow"));
    PetscCall(Default("-flow_bc_xlo_velocity", Str(kU) + ",0,0"));
  }
  PetscCall(Default("-flow_bc_xhi", "outflow"));
  PetscCall(Default("-gravity", "0,0,0"));
  PetscCall(Default("-flow_density", "1"));
  PetscCall(Default("-flow_viscosity", "1e-5"));
  PetscCall(Default("-flow_initial_velocity", back ? "0,0,0" : Str(kU) + ",0,0"));
  PetscCall(Default("-flow_pressure_ksp_rtol", "1e-12"));
  PetscCall(Default("-vof_density", Str(ratio)));
  PetscCall(Default("-vof_viscosity", "1e-3"));
  if (drain) {
    PetscCall(Default("-vof_boxes", "0,0,0," + Str(kL) + "," + Str(kW) + "," + Str(2 * h)));
    PetscCall(Default("-vof_bc_xlo_alpha", "0"));
  } else if (band) PetscCall(Default("-vof_bc_xlo_alpha_band", Str(b[0]) + "," + Str(b[1])));
  else PetscCall(Default("-vof_bc_xlo_alpha", "1"));  // the inflow's, or with -backflow what comes back in
  PetscCall(Default("-final_time", Str(tEnd)));
  PetscCall(Default("-max_steps", "100000000"));
  PetscCall(Default("-monitor_every", "100000000"));
  PetscCall(Default("-monitor_timing", "0"));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Vof  *vof  = Interface(sim);
  vofdem::Flow *flow = Fluid(sim);
  // The liquid's cross-section at the inflow (A_jet) for the front and the rates; the drained liquid
  // leaves through the whole face.
  const PetscReal depth = 2 * h, ajet = (band ? b[1] - b[0] : kW) * depth;
  const PetscReal alphaIn = drain ? 0 : 1;
  vofdem::VofSummary v0, vs, mark;
  PetscCall(vof->Summarize(&v0));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "open channel (%s): %d x %d x 2 cells, h = %g m, density ratio %g, U = %g m/s, run to t = %g s\n",
                        drain ? "gas pushes the liquid out" : back ? "backflow through an outflow face brings liquid" : band ? "liquid jet through a band of the inflow face" : "liquid enters through the whole inflow face", (int)N, (int)(N / 4),
                        (double)h, (double)ratio, (double)kU, (double)tEnd));
  PetscReal balance = 0, velocity = 0, shape = 0, markTime = -1;
  bool      blown = false;
  int       report = 1;
  vs             = v0;
  while (sim.Time() < tEnd * (1 - 1e-12)) {
    PetscCall(sim.ChooseTimeStep());
    PetscCall(sim.Step());
    PetscCall(vof->Summarize(&vs));
    const PetscReal scale = std::max({v0.volume, vs.volume, vs.inflowVolume, vs.outflowVolume});
    balance               = std::max(balance, std::fabs(vs.volume - v0.volume - (vs.inflowVolume - vs.outflowVolume)) / scale);
    PetscReal e, ux = kU;
    if (back) {  // the mean x velocity (uniform in x: incompressible 1-D flow) and its scale
      PetscInt nx;
      PetscCall(VecSum(flow->Velocity(0), &ux));
      PetscCall(VecGetSize(flow->Velocity(0), &nx));
      ux /= nx;
    }
    PetscCall(VelocityError(*flow, ux, &e));
    velocity = std::isnan(e) || std::isnan(velocity) ? NAN : std::fmax(velocity, e / std::fabs(ux));
    if (std::isnan(e) || e > 1e3 * kU) {
      blown = true;
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  blew up at step %d, t = %.4g s: max|u - U| = %.3e m/s\n", (int)sim.StepNumber(), (double)sim.Time(), (double)e));
      break;
    }
    if (markTime < 0 && sim.Time() >= 1.75 * kL / kU) markTime = sim.Time(), mark = vs;  // start of the window of the rates
    const bool last = sim.Time() >= tEnd * (1 - 1e-12);
    if ((report <= 3 && sim.Time() >= report * tEnd / (back ? 4 : 8) * (1 - 1e-12)) || last) {
      PetscReal       err;
      const PetscReal xf = back ? vs.inflowVolume / (kW * depth) : kU * sim.Time();
      PetscCall(ShapeError(sim, band, b, drain, xf, ajet, &err));
      shape = std::max(shape, err);
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  t %.4f  step %d  liquid volume %.10e m^3  in %.10e  out %.10e  shape error %.3e\n", (double)sim.Time(), (int)sim.StepNumber(),
                            (double)vs.volume, (double)vs.inflowVolume, (double)vs.outflowVolume, (double)err));
      ++report;
    }
  }
  // Rates over the last eighth of the run, from t >= 1.75 L/U (the front left at t = L/U).
  const PetscReal window = sim.Time() - markTime;
  const PetscReal rateIn = (vs.inflowVolume - mark.inflowVolume) / window, rateOut = (vs.outflowVolume - mark.outflowVolume) / window;
  const PetscReal exactIn = kU * ajet * alphaIn;
  // Draining: nothing enters, all the liquid is gone at the end (out = V(0)); filling: out = in at steady state.
  const PetscReal rateErr = drain ? std::fabs(vs.outflowVolume - v0.volume) / v0.volume + rateIn / (kU * ajet) : std::fabs(rateOut - rateIn) / rateIn;
  const PetscReal inErr   = drain ? vs.inflowVolume / v0.volume : std::fabs(rateIn - exactIn) / exactIn;
  const bool      balOk = !blown && balance <= kTolBalance, boundOk = !blown && vs.boundViolation <= kTolBounds, shapeOk = !blown && shape <= kTolShape;
  const bool      rateOk = back || (!blown && rateErr <= kTolRate && inErr <= kTolRate), velOk = !blown && velocity <= kTolVelocity;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(a) volume balance |V - V0 - (in - out)| / scale, max over %d steps: %.2e (tolerance %.0e) %s\n", (int)sim.StepNumber(), (double)balance,
                        (double)kTolBalance, balOk ? "ok" : "FAIL"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(b) alpha outside [0, 1] by %.2e (tolerance %.0e) %s\n", (double)vs.boundViolation, (double)kTolBounds, boundOk ? "ok" : "FAIL"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(c) front: largest shape error %.3e cells (tolerance %g) %s\n", (double)shape, (double)kTolShape, shapeOk ? "ok" : "FAIL"));
  if (back)
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(c) backflow: liquid in %.10e m^3, out %.2e m^3, front at %.6f m\n", (double)vs.inflowVolume, (double)vs.outflowVolume,
                          (double)(vs.inflowVolume / (kW * depth))));
  else if (drain)
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(c) drained: out - V(0) %.2e of V(0), in %.2e of V(0), inflow rate over the last eighth %.2e of U A (tolerance %.0e each) %s\n",
                          (double)(std::fabs(vs.outflowVolume - v0.volume) / v0.volume), (double)inErr, (double)(rateIn / (kU * ajet)), (double)kTolRate, rateOk ? "ok" : "FAIL"));
  else
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(c) steady: inflow rate %.10e m^3/s (U A_jet alpha_in %.10e, error %.2e), outflow rate %.10e m^3/s (error %.2e; tolerance %.0e) %s\n",
                          (double)rateIn, (double)exactIn, (double)inErr, (double)rateOut, (double)rateErr, (double)kTolRate, rateOk ? "ok" : "FAIL"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "(d) density ratio %g: max|u - U|/U (U %s) over the run %.2e (tolerance %.0e) %s\n", (double)ratio, back ? "the mean u_x" : "the inflow's", (double)velocity, (double)kTolVelocity,
                        velOk ? "ok" : "FAIL"));
  const bool pass = balOk && boundOk && shapeOk && rateOk && velOk;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s\n", pass ? "all checks passed" : "FAILED"));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(pass ? 0 : PETSC_ERR_NOT_CONVERGED);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-4
  test:
    suffix: fill
    nsize: 1
  test:
    suffix: fill_2
    nsize: 2
  test:
    suffix: jet
    nsize: 2
    args: -band 0.0625,0.1875
  test:
    suffix: jet_partial
    nsize: 2
    args: -band 0.1,0.17 -resolution 64
  test:
    suffix: drain
    nsize: 1
    args: -drain
  test:
    suffix: backflow
    nsize: 2
    args: -backflow
TEST*/
