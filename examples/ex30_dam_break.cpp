static const char help[] = "Verification V5 (docs/verification.md): the dam break of Martin & Moyce (1952), n^2 = 2, through the program's own step\n"
                           "(Simulation with -physics flow,vof; scene config/scenes/dam-break.yaml, density ratio 1000). The front position\n"
                           "Z = x_front / a, x_front = sum of alpha h along the floor row of cells, against T = t sqrt(2 g / a) is compared with the\n"
                           "measured front at the measured times up to the end of the run (linear interpolation in the run's history). Must reach:\n"
                           "every |Z - Z_measured| / Z_measured <= 5 percent, volume change <= 1e-12, bound violation <= 1e-12. The scene's options are\n"
                           "set here (command-line options override them) with -resolution N = a/h cells across the column (default 8; the scene\n"
                           "file has 16). -front_check 0: a front error above 5 percent is printed (FAIL) but does not fail the run (the quick tier's\n"
                           "regression test; the front is then compared with the reference output).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/examples/Help.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace {

// Martin & Moyce (1952), Phil. Trans. R. Soc. A 244, 312-324, square column (n^2 = 2, a = 2.25 in):
// the surge front Z = x/a at the times T = t sqrt(2 g/a) it passed each gauge, as tabulated from their
// paper in later studies (e.g. Koshizuka & Oka 1996); the gauges are 0.5 in (0.222 a) apart.
const double kT[] = {0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32, 2.51, 2.65, 2.83, 2.98, 3.11, 3.33};
const double kZ[] = {1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.00, 3.22, 3.44, 3.67, 3.89, 4.11};

// x_front: sum of alpha h_x over the floor row (j = 0) of the first z layer (the surge is one
// connected layer on the floor before it reaches the far wall).
PetscErrorCode FrontPosition(vofdem::Vof &vof, const vofdem::Grid &grid, PetscReal *x) {
  PetscScalar ***a;
  PetscInt       s[3], n[3];
  PetscReal      local = 0;

  PetscFunctionBeginUser;
  PetscCall(DMDAGetCorners(vof.FractionDM(), &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAVecGetArray(vof.FractionDM(), vof.Fraction(), &a));
  if (s[1] == 0 && s[2] == 0)
    for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) local += PetscRealPart(a[0][0][i]) * grid.Spacing()[0];
  PetscCall(DMDAVecRestoreArray(vof.FractionDM(), vof.Fraction(), &a));
  PetscCallMPI(MPI_Allreduce(&local, x, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  PetscFunctionReturn(0);
}

PetscErrorCode Default(const char *name, const std::string &value) {
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, name, &set));
  if (!set) PetscCall(PetscOptionsSetValue(nullptr, name, value.c_str()));
  PetscFunctionReturn(0);
}

// config/scenes/dam-break.yaml at N cells per column width.
PetscErrorCode SetScene(PetscReal a, PetscInt N) {
  PetscFunctionBeginUser;
  const PetscReal h = a / N;
  const std::string L = std::to_string((double)(5 * a)), H = std::to_string((double)(2.5 * a)), D = std::to_string((double)h);
  PetscCall(Default("-physics", "flow,vof"));
  // The 2-D problem (OpenFOAM's "empty" patches): one cell across z between slip walls. Walls with no
  // slip there, as the scene had until 2026-11-23, brake the surge (a/h = 32: 18.5 % ahead of the
  // measurement instead of 19.2 %); two layers between slip walls give the same fronts (test _2layers: its
  // reference differs from _1's in the cell count only).
  PetscCall(Default("-grid_cells", std::to_string(5 * N) + "," + std::to_string((5 * N) / 2) + ",1"));
  PetscCall(Default("-grid_upper", L + "," + H + "," + D));
  PetscCall(Default("-flow_bc_zlo", "slip"));
  PetscCall(Default("-flow_bc_zhi", "slip"));
  PetscCall(Default("-gravity", "0,-9.81,0"));
  PetscCall(Default("-flow_density", "1"));
  PetscCall(Default("-flow_viscosity", "1.8e-5"));
  PetscCall(Default("-flow_pressure_pc", "pfmg"));  // 2x cheaper per step than boomeramg here
  PetscCall(Default("-flow_pressure_pc_pfmg_relax_type", "symmetric-Red/Black-Gauss-Seidel"));  // cheaper set-up than weighted Jacobi
  PetscCall(Default("-flow_viscous", "explicit"));  // its limit h^2/(12 nu) is ~100x the CFL step
  PetscCall(Default("-flow_pressure_ksp_rtol", "1e-12"));
  // PFMG's set-up was a tenth of the step; built every other step, CG takes 1 % more iterations
  // (a/h = 32: 4621 against 4567) and the fronts are the same to the printed digits.
  PetscCall(Default("-flow_pressure_reuse_steps", "1"));
  PetscCall(Default("-vof_density", "1000"));
  PetscCall(Default("-vof_viscosity", "1e-3"));
  PetscCall(Default("-vof_boxes", "0,0,0," + std::to_string((double)a) + "," + std::to_string((double)(2 * a)) + "," + D));
  PetscCall(Default("-final_time", std::to_string((double)(3 / std::sqrt(2 * 9.81 / a)))));
  PetscCall(Default("-max_steps", "1000000"));
  PetscCall(Default("-monitor_every", "1000000"));
  PetscCall(Default("-monitor_timing", "0"));
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  vofdem::Simulation sim;
  PetscReal          a = 0.05715, finalTime = 0;
  PetscInt           N = 8;
  PetscBool          frontCheck = PETSC_TRUE;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-resolution", &N, nullptr));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-front_check", &frontCheck, nullptr));
  if (N < 2 || N % 2) VofdemInputError(PETSC_COMM_WORLD, "option -resolution: give an even number of cells per column width (>= 2)");
  PetscCall(SetScene(a, N));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-final_time", &finalTime, nullptr));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  if (!Interface(sim)) VofdemInputError(PETSC_COMM_WORLD, "ex30: give a dam-break scene with -physics flow,vof (-options_file_yaml config/scenes/dam-break.yaml)");
  const vofdem::Grid &grid = sim.GetGrid();
  const PetscReal     g = 9.81, scale = std::sqrt(2 * g / a);
  vofdem::VofSummary  s0, s1;
  PetscCall(Interface(sim)->Summarize(&s0));
  std::vector<PetscReal> T, Z;
  PetscReal              x;
  PetscCall(FrontPosition(*Interface(sim), grid, &x));
  T.push_back(0);
  Z.push_back(x / a);
  while (sim.Time() < finalTime * (1 - 1e-12)) {
    PetscCall(sim.ChooseTimeStep());
    PetscCall(sim.Step());
    PetscCall(FrontPosition(*Interface(sim), grid, &x));
    T.push_back(sim.Time() * scale);
    Z.push_back(x / a);
  }
  PetscCall(Interface(sim)->Summarize(&s1));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "V5 dam break, %d x %d x %d cells (a/h = %.0f), %d steps to T = %.3f\n", (int)grid.Cells()[0], (int)grid.Cells()[1], (int)grid.Cells()[2],
                        (double)(a / grid.Spacing()[0]), (int)sim.StepNumber(), (double)T.back()));
  PetscReal worst = 0;
  for (size_t m = 0; m < sizeof kT / sizeof kT[0]; ++m) {
    if (kT[m] > T.back()) break;
    size_t k = 1;
    while (T[k] < kT[m]) ++k;
    const PetscReal w = (kT[m] - T[k - 1]) / (T[k] - T[k - 1]), z = Z[k - 1] + w * (Z[k] - Z[k - 1]);
    const PetscReal e = (z - kZ[m]) / kZ[m];
    worst             = std::fmax(worst, std::fabs(e));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  T %.2f: Z %.3f, measured %.2f, error %+.1f %%\n", kT[m], (double)z, kZ[m], (double)(100 * e)));
  }
  const PetscReal dv = std::fabs(s1.volume - s0.volume) / s0.volume;
  const bool      ok = worst <= 0.05, volOk = dv <= 1e-12, boundOk = s1.boundViolation <= 1e-12;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "V5 largest front error %.1f %% (tolerance 5 %%) %s; volume change %s 1e-12 %s; bound violation %s 1e-12 %s\n", (double)(100 * worst),
                        ok ? "ok" : "FAIL", volOk ? "<=" : ">", volOk ? "ok" : "FAIL", boundOk ? "<=" : ">", boundOk ? "ok" : "FAIL"));
  PetscCall(sim.Destroy());
  PetscFunctionReturn((ok || !frontCheck) && volOk && boundOk ? 0 : PETSC_ERR_NOT_CONVERGED);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-4
  test:
    suffix: 1
    nsize: 2
    args: -front_check 0
  test:
    suffix: 2layers
    nsize: 2
    args: -front_check 0 -grid_cells 40,20,2 -grid_upper 0.28575,0.142875,0.0142875 -vof_boxes 0,0,0,0.05715,0.1143,0.0142875
TEST*/
