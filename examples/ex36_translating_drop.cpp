static const char help[] = "Mass-consistent momentum at large density ratios (docs/physics.md F2; issue 8): a dense drop (a cylinder, quasi-2-D, 2 cells in z) of\n"
                           "diameter D = 0.4 in the unit box (periodic in x and y, free-slip in z), density -ratio times the surrounding phase's\n"
                           "(1 kg/m^3), no gravity, through the program's step (-physics flow,vof) for -periods crossings of the box (t = periods / U_x:\n"
                           "the drop is back where it started), -resolution N cells across the box, -vof_surface_tension sigma (default 0).\n"
                           "Two set-ups:\n"
                           " - uniform (default): everything moves with U = (1, 1) m/s; the exact solution keeps u = U and the shape. Prints the\n"
                           "   largest |u - U| / |U| over the run and the shape error sum |alpha - alpha_0| dV / V_drop at the end. Must reach:\n"
                           "   velocity error below -velocity_tol (1e-8), shape error below -shape_tol (0.05).\n"
                           " - -still_gas: u = U only inside the drop, the light phase at rest (then projected). In the periodic box without\n"
                           "   forces the total momentum sum rho_f u_f dV is conserved, and the drop slows only by the light phase's drag, well\n"
                           "   under 1 percent over one crossing at ratio >= 1000 (drag 0.5 rho_g |U|^2 C_d D per unit depth with C_d up to 4 on the drop's\n"
                           "   mass rho_l pi D^2 / 4: 0.2 percent per unit time at ratio 1000). Must reach: momentum change below -momentum_tol (1e-4),\n"
                           "   heavy-phase speed change (sum alpha u / sum alpha) below 1 percent.\n"
                           "Both: volume change below 1e-12, no blow-up. -vof_momentum advective (the flow's non-conservative transport) prints the\n"
                           "same numbers for comparison; -expect_fail 1 turns the verdict around (the run must miss a tolerance).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/examples/Help.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace {

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

// max over faces of |u_d - U_d| (collective); NaN propagates (a blow-up is not small).
PetscErrorCode VelocityError(vofdem::Flow &flow, const PetscReal U[3], PetscReal *err) {
  PetscFunctionBeginUser;
  *err = 0;
  for (int d = 0; d < 3; ++d) {
    Vec       w;
    PetscReal m;
    PetscCall(VecDuplicate(flow.Velocity(d), &w));
    PetscCall(VecCopy(flow.Velocity(d), w));
    PetscCall(VecShift(w, -U[d]));
    PetscCall(VecNorm(w, NORM_INFINITY, &m));
    PetscCall(VecDestroy(&w));
    *err = std::isnan(m) || std::isnan(*err) ? NAN : std::fmax(*err, m);
  }
  PetscFunctionReturn(0);
}

// Face momentum sum rho_f u_f dV per component (rho_f the mean of the two cells' densities, the
// flow's face density; collective) and the speed of the heavy phase, sum alpha u / sum alpha at cells.
PetscErrorCode Momentum(vofdem::Simulation &sim, PetscReal P[3], PetscReal dropU[3]) {
  vofdem::Flow               &flow = *Fluid(sim);
  const vofdem::StaggeredGrid &sg   = flow.Staggered();
  Vec                          rhoL, aL;
  vofdem::LocalField           rho, a;
  PetscReal                    loc[7] = {0, 0, 0, 0, 0, 0, 0}, glob[7];

  PetscFunctionBeginUser;
  const PetscReal *h = sim.GetGrid().Spacing(), V = h[0] * h[1] * h[2];
  PetscCall(DMGetLocalVector(sg.Cells(), &rhoL));
  PetscCall(DMGlobalToLocal(sg.Cells(), flow.Density(), INSERT_VALUES, rhoL));
  PetscCall(DMGetLocalVector(sg.Cells(), &aL));
  PetscCall(DMGlobalToLocal(sg.Cells(), Interface(sim)->Fraction(), INSERT_VALUES, aL));
  PetscCall(sg.GetLocal(3, rhoL, &rho));
  PetscCall(sg.GetLocal(3, aL, &a));
  for (int d = 0; d < 3; ++d) {
    Vec                uL;
    vofdem::LocalField u;
    PetscInt           s[3], n[3];
    PetscCall(DMGetLocalVector(sg.Face(d), &uL));
    PetscCall(DMGlobalToLocal(sg.Face(d), flow.Velocity(d), INSERT_VALUES, uL));
    PetscCall(sg.GetLocal(d, uL, &u));
    sg.Owned(3, s, n);
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
          PetscInt q[3] = {i, j, k}, cm[3] = {i, j, k}, qp[3] = {i, j, k};
          cm[d] -= 1;
          qp[d] += 1;
          loc[d] += 0.5 * PetscRealPart(rho.at(cm) + rho.at(q)) * PetscRealPart(u.at(q)) * V;  // face q (periodic: one per cell)
          loc[3 + d] += PetscRealPart(a.at(q)) * 0.5 * PetscRealPart(u.at(q) + u.at(qp));
          if (d == 0) loc[6] += PetscRealPart(a.at(q));
        }
    PetscCall(sg.RestoreLocal(d, uL, &u));
    PetscCall(DMRestoreLocalVector(sg.Face(d), &uL));
  }
  PetscCall(sg.RestoreLocal(3, aL, &a));
  PetscCall(sg.RestoreLocal(3, rhoL, &rho));
  PetscCall(DMRestoreLocalVector(sg.Cells(), &aL));
  PetscCall(DMRestoreLocalVector(sg.Cells(), &rhoL));
  PetscCallMPI(MPI_Allreduce(loc, glob, 7, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  for (int d = 0; d < 3; ++d) P[d] = glob[d], dropU[d] = glob[3 + d] / glob[6];
  PetscFunctionReturn(0);
}

// -still_gas: u = U on the faces inside the drop, 0 outside, then projected (div u = 0).
PetscErrorCode StillGas(vofdem::Simulation &sim, const PetscReal U[3], PetscReal R) {
  vofdem::Flow               &flow = *Fluid(sim);
  const vofdem::StaggeredGrid &sg   = flow.Staggered();

  PetscFunctionBeginUser;
  const PetscReal *h = sim.GetGrid().Spacing();
  for (int d = 0; d < 3; ++d) {
    vofdem::LocalField u;
    PetscInt           s[3], n[3];
    sg.Owned(d, s, n);
    PetscCall(sg.GetGlobal(d, flow.Velocity(d), &u));
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
          const PetscInt q[3] = {i, j, k};
          PetscReal      x[2];
          for (int c = 0; c < 2; ++c) x[c] = (c == d ? q[c] : q[c] + 0.5) * h[c];
          u.at(q) = std::hypot(x[0] - 0.5, x[1] - 0.5) < R ? U[d] : 0;
        }
    PetscCall(sg.RestoreGlobal(d, flow.Velocity(d), &u));
  }
  PetscCall(flow.ProjectInitialVelocity());
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  vofdem::Simulation sim;
  PetscInt           N = 32, periods = 1;
  PetscReal          ratio = 1000, velTol = 1e-8, shapeTol = 0.05, momTol = 1e-4;
  PetscBool          expectFail = PETSC_FALSE, stillGas = PETSC_FALSE;
  const PetscReal    D = 0.4, R = 0.5 * D, U[3] = {1, 1, 0};

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-resolution", &N, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-periods", &periods, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-ratio", &ratio, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-velocity_tol", &velTol, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-shape_tol", &shapeTol, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-momentum_tol", &momTol, nullptr));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-expect_fail", &expectFail, nullptr));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-still_gas", &stillGas, nullptr));
  if (stillGas) PetscCall(Default("-flow_initial_velocity", "0,0,0"));
  if (stillGas) PetscCall(Default("-dt", Str(0.125 / N)));  // nothing moves before StillGas: a fixed step (Courant 0.125 per direction at U)
  const PetscReal h = 1.0 / N;
  PetscCall(Default("-physics", "flow,vof"));
  PetscCall(Default("-grid_cells", std::to_string(N) + "," + std::to_string(N) + ",2"));
  PetscCall(Default("-grid_upper", "1,1," + Str(2 * h)));
  PetscCall(Default("-grid_periodic", "x,y"));
  PetscCall(Default("-flow_bc_zlo", "slip"));  // quasi-2-D: free-slip planes in z
  PetscCall(Default("-flow_bc_zhi", "slip"));
  PetscCall(Default("-gravity", "0,0,0"));
  PetscCall(Default("-flow_density", "1"));
  PetscCall(Default("-flow_viscosity", "1e-3"));
  PetscCall(Default("-flow_initial_velocity", Str(U[0]) + "," + Str(U[1]) + ",0"));
  PetscCall(Default("-flow_pressure_pc", "boomeramg"));
  PetscCall(Default("-flow_pressure_ksp_rtol", "1e-12"));
  PetscCall(Default("-vof_density", Str(ratio)));
  PetscCall(Default("-vof_viscosity", "1e-2"));
  PetscCall(Default("-vof_spheres", "0.5,0.5," + Str(h) + "," + Str(R)));
  PetscCall(Default("-vof_init_samples", "16"));
  PetscCall(Default("-final_time", Str(periods / U[0])));
  PetscCall(Default("-max_steps", "100000000"));
  PetscCall(Default("-monitor_every", "100000000"));
  PetscCall(Default("-monitor_timing", "0"));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Vof  *vof  = Interface(sim);
  vofdem::Flow *flow = Fluid(sim);
  if (stillGas) PetscCall(StillGas(sim, U, R));
  PetscReal P0[3], P1[3], drop0[3], drop1[3];
  PetscCall(Momentum(sim, P0, drop0));
  Vec           alpha0;
  PetscCall(VecDuplicate(vof->Fraction(), &alpha0));
  PetscCall(VecCopy(vof->Fraction(), alpha0));
  vofdem::VofSummary vs0;
  PetscCall(vof->Summarize(&vs0));
  const PetscReal speed = std::sqrt(U[0] * U[0] + U[1] * U[1]), tEnd = periods / U[0];
  const char     *scheme = vof->ConsistentMomentum() ? "consistent" : "advective";
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "translating drop%s: %d^2 cells (%.1f per diameter), density ratio %g, %s momentum, sigma %g N/m, U = (%g, %g) m/s, run to t = %g s\n",
                        stillGas ? " in still gas" : "", (int)N, (double)(D * N), (double)ratio, scheme, (double)vof->SurfaceTensionCoefficient(), (double)U[0], (double)U[1], (double)tEnd));
  PetscReal worst = 0;
  bool      blown = false;
  int       report = 1;
  while (sim.Time() < tEnd * (1 - 1e-12)) {
    PetscCall(sim.ChooseTimeStep());
    PetscCall(sim.Step());
    PetscReal e;
    PetscCall(VelocityError(*flow, U, &e));
    worst = std::isnan(e) || std::isnan(worst) ? NAN : std::fmax(worst, e / speed);
    if (std::isnan(e) || e > 1e3 * speed) {
      blown = true;
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  blew up at step %d, t = %.4g s: max|u - U| = %.3e m/s\n", (int)sim.StepNumber(), (double)sim.Time(), (double)e));
      break;
    }
    if (!stillGas && sim.Time() >= report * tEnd / 4 * (1 - 1e-12)) {
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  t %.3f  step %d  max|u - U|/|U| %.3e\n", (double)sim.Time(), (int)sim.StepNumber(), (double)(e / speed)));
      ++report;
    }
  }
  PetscCall(Momentum(sim, P1, drop1));
  const PetscReal dP = std::hypot(P1[0] - P0[0], P1[1] - P0[1]) / std::hypot(P0[0], P0[1]);
  vofdem::VofSummary vs;
  PetscCall(vof->Summarize(&vs));
  PetscReal shape;
  PetscCall(VecAXPY(alpha0, -1, vof->Fraction()));
  PetscCall(VecNorm(alpha0, NORM_1, &shape));
  shape *= h * h * (2 * h) / (M_PI * R * R * 2 * h);
  PetscCall(VecDestroy(&alpha0));
  const PetscReal dvol = std::fabs(vs.volume - vs0.volume) / vs0.volume;
  const bool      volOk = !blown && dvol <= 1e-12;
  bool            pass;
  if (stillGas) {
    const PetscReal dU = std::hypot(drop1[0] - drop0[0], drop1[1] - drop0[1]) / std::hypot(drop0[0], drop0[1]);
    const bool      momOk = !blown && dP < momTol, dropOk = !blown && dU < 0.01;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s momentum, ratio %g, still gas: total momentum change %.3e (tolerance %.0e) %s; heavy-phase speed change %.3e (tolerance 1e-2) %s\n", scheme,
                          (double)ratio, (double)(blown ? NAN : dP), (double)momTol, momOk ? "ok" : "FAIL", (double)(blown ? NAN : dU), dropOk ? "ok" : "FAIL"));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s momentum, ratio %g, still gas: heavy-phase velocity (%.4f, %.4f) m/s at the start, (%.4f, %.4f) at the end; volume change %.1e (tolerance 1e-12) %s\n", scheme,
                          (double)ratio, (double)drop0[0], (double)drop0[1], (double)drop1[0], (double)drop1[1], (double)dvol, volOk ? "ok" : "FAIL"));
    pass = momOk && dropOk && volOk;
  } else {
    const bool velOk = !blown && worst < velTol, shapeOk = !blown && shape < shapeTol, boundOk = !blown && vs.boundViolation <= 1e-12;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s momentum, ratio %g: max|u - U|/|U| over the run %.3e (tolerance %.0e) %s\n", scheme, (double)ratio, (double)worst, (double)velTol, velOk ? "ok" : "FAIL"));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s momentum, ratio %g: shape error %.4e (tolerance %g) %s, volume change %.1e (tolerance 1e-12) %s, bounds %.1e (tolerance 1e-12) %s\n", scheme,
                          (double)ratio, (double)shape, (double)shapeTol, shapeOk ? "ok" : "FAIL", (double)dvol, volOk ? "ok" : "FAIL", (double)vs.boundViolation, boundOk ? "ok" : "FAIL"));
    pass = velOk && shapeOk && volOk && boundOk;
  }
  if (expectFail) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "expected to miss a tolerance: %s\n", pass ? "it did not (FAIL)" : "it did (ok)"));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(pass != (bool)expectFail ? 0 : PETSC_ERR_NOT_CONVERGED);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

// surface_tension_1000: with sigma = 1 N/m (We 800) the consistent transport's capillary currents reach about
// 1e-2 of U (README, "Not yet"), so that test holds them under 2e-2 only as a regression bound; what it guards is the
// interface staying bounded (1e-12) and its volume exact at the step the time-step control allows.
/*TEST
  rtol: 1e-4
  test:
    suffix: 1000
    nsize: 1
    args: -ratio 1000
  test:
    suffix: 8000
    nsize: 2
    args: -ratio 8000
  test:
    suffix: still_gas_1000
    nsize: 1
    args: -ratio 1000 -still_gas
  test:
    suffix: still_gas_8000
    nsize: 2
    args: -ratio 8000 -still_gas
  test:
    suffix: still_gas_advective
    nsize: 2
    args: -ratio 1000 -still_gas -vof_momentum advective -expect_fail 1
  test:
    suffix: surface_tension_1000
    nsize: 2
    args: -ratio 1000 -vof_surface_tension 1 -velocity_tol 2e-2
  test:
    suffix: surface_tension_1000_serial
    nsize: 1
    args: -ratio 1000 -vof_surface_tension 1 -velocity_tol 2e-2
TEST*/
