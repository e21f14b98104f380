static const char help[] = "Verification V3 (docs/verification.md): Popinet's (2009) static drop through the program's step (-physics flow,vof). A drop\n"
                           "(a cylinder: 2-D, one cell across z between slip walls) of diameter D = 0.4, sigma = 1, Laplace number La = rho sigma D / mu^2 = 12000\n"
                           "(-laplace), -resolution N cells across a unit box (25.6 cells per D at 64), -ratio rho_drop / rho_gas (mu the same in\n"
                           "both). -setup quarter (default, Popinet's): the quarter of the drop in [0, 0.5]^2 (N/2 cells a side), centred on the\n"
                           "corner, whose two planes through the centre are slip walls (symmetry), the far walls no-slip as in the unit box; full:\n"
                           "the whole drop in the middle of the unit box, walls no-slip (a drop free to translate: it slides a fraction of a cell\n"
                           "off the grid vertex it starts on, results/v3-drop-growth.md). Runs -viscous_times of the viscous time D^2 rho / mu\n"
                           "(default 1) and prints the spurious capillary number Ca = max|u| mu / sigma ten times on the way, and at the end the\n"
                           "pressure jump (inside: cells full within R/2 of the centre; outside: empty cells beyond 1.5 R) against sigma / R.\n"
                           "Must reach: Laplace jump within 1 percent; Ca at the end below -ca_max (default 1e-10 at ratio 1, 1e-8 otherwise)\n"
                           "after one viscous time and, at ratios above 1, still falling: below its value at half time, or at rest to round-off\n"
                           "and not growing (below 1e-12 of the capillary velocity sqrt(sigma / (rho D)), i.e. Ca < 1e-12 / sqrt(La), and at\n"
                           "most twice its value at half time); a run shorter than one viscous time checks only that Ca falls (end below half\n"
                           "time). -show_centroid: the drop's centroid at each report (full set-up).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/examples/Help.hpp"

#include <cmath>
#include <string>

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

// Mean pressure inside (full cells within R/2 of the centre) and outside (empty cells beyond 1.5 R).
PetscErrorCode PressureJump(vofdem::Simulation &sim, PetscReal R, const PetscReal centre[2], PetscReal *jump) {
  PetscScalar ***a, ***p;
  PetscInt       s[3], n[3];
  PetscReal      loc[4] = {0, 0, 0, 0}, glob[4];

  PetscFunctionBeginUser;
  vofdem::Vof  *vof  = Interface(sim);
  vofdem::Flow *flow = Fluid(sim);
  const PetscReal *h = sim.GetGrid().Spacing();
  PetscCall(DMDAGetCorners(vof->FractionDM(), &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAVecGetArray(vof->FractionDM(), vof->Fraction(), &a));
  PetscCall(DMDAVecGetArray(flow->Staggered().Cells(), flow->Pressure(), &p));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscReal r = std::hypot((i + 0.5) * h[0] - centre[0], (j + 0.5) * h[1] - centre[1]), v = PetscRealPart(a[k][j][i]);
        if (r < 0.5 * R && v >= 1 - 1e-12) loc[0] += PetscRealPart(p[k][j][i]), loc[1] += 1;
        if (r > 1.5 * R && v <= 1e-12) loc[2] += PetscRealPart(p[k][j][i]), loc[3] += 1;
      }
  PetscCall(DMDAVecRestoreArray(flow->Staggered().Cells(), flow->Pressure(), &p));
  PetscCall(DMDAVecRestoreArray(vof->FractionDM(), vof->Fraction(), &a));
  PetscCallMPI(MPI_Allreduce(loc, glob, 4, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  *jump = glob[0] / glob[1] - glob[2] / glob[3];
  PetscFunctionReturn(0);
}

// Centroid of the drop (alpha-weighted cell centres), for following its drift off the grid vertex.
PetscErrorCode DropCentroid(vofdem::Simulation &sim, PetscReal c[2]) {
  PetscScalar ***a;
  PetscInt       s[3], n[3];
  PetscReal      loc[3] = {0, 0, 0}, glob[3];

  PetscFunctionBeginUser;
  vofdem::Vof     *vof = Interface(sim);
  const PetscReal *h   = sim.GetGrid().Spacing();
  PetscCall(DMDAGetCorners(vof->FractionDM(), &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAVecGetArray(vof->FractionDM(), vof->Fraction(), &a));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscReal v = PetscRealPart(a[k][j][i]);
        loc[0] += v * (i + 0.5) * h[0], loc[1] += v * (j + 0.5) * h[1], loc[2] += v;
      }
  PetscCall(DMDAVecRestoreArray(vof->FractionDM(), vof->Fraction(), &a));
  PetscCallMPI(MPI_Allreduce(loc, glob, 3, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  c[0] = glob[0] / glob[2], c[1] = glob[1] / glob[2];
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  vofdem::Simulation sim;
  PetscInt           N = 64;
  PetscReal          La = 12000, ratio = 1, times = 1, caMax = 0;
  const PetscReal    D = 0.4, R = 0.5 * D, sigma = 1;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscBool show = PETSC_FALSE, showCentroid = PETSC_FALSE;
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-show_drop", &show, nullptr));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-show_centroid", &showCentroid, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-resolution", &N, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-laplace", &La, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-ratio", &ratio, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-viscous_times", &times, nullptr));
  char setup[16] = "quarter";
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-setup", setup, sizeof setup, nullptr));
  const std::string setupName = setup;
  if (setupName != "quarter" && setupName != "full") VofdemInputError(PETSC_COMM_WORLD, "option -setup: '%s' is neither quarter nor full", setup);
  const bool quarter = setupName == "quarter";
  if (quarter && N % 2) VofdemInputError(PETSC_COMM_WORLD, "option -resolution: the quarter set-up needs an even number of cells across the unit box, got %d", (int)N);
  caMax = ratio == 1 ? 1e-10 : 1e-8;
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-ca_max", &caMax, nullptr));
  const PetscReal rho = ratio, mu = std::sqrt(rho * sigma * D / La), tnu = D * D * rho / mu, h = 1.0 / N;
  PetscCall(Default("-physics", "flow,vof"));
  // Quarter: Popinet's (2009) drop centred on the corner of the box, the symmetry planes as slip walls;
  // it is the full set-up's mirror-symmetric solution, without the translation that symmetry forbids.
  const PetscReal centre[2] = {quarter ? 0 : 0.5, quarter ? 0 : 0.5}, areaScale = quarter ? 4 : 1;
  const PetscInt  M         = quarter ? N / 2 : N;
  // Popinet's problem is 2-D: one cell across z between slip walls (as OpenFOAM's "empty" patches). Until
  // 2026-11-27 it had 2 cells between the default walls: the same jump to 2e-4 and Ca at round-off, at 1.7x the cost.
  PetscCall(Default("-grid_cells", std::to_string(M) + "," + std::to_string(M) + ",1"));
  PetscCall(Default("-grid_upper", Str(M * h) + "," + Str(M * h) + "," + Str(h)));
  PetscCall(Default("-flow_bc_zlo", "slip"));
  PetscCall(Default("-flow_bc_zhi", "slip"));
  if (quarter) {
    PetscCall(Default("-flow_bc_xlo", "slip"));
    PetscCall(Default("-flow_bc_ylo", "slip"));
  }
  PetscCall(Default("-gravity", "0,0,0"));
  PetscCall(Default("-flow_density", "1"));
  PetscCall(Default("-flow_viscosity", Str(mu)));
  PetscCall(Default("-flow_pressure_pc", "boomeramg"));
  PetscCall(Default("-flow_pressure_ksp_rtol", "1e-12"));
  PetscCall(Default("-vof_density", Str(rho)));
  PetscCall(Default("-vof_viscosity", Str(mu)));
  PetscCall(Default("-vof_surface_tension", Str(sigma)));
  PetscCall(Default("-vof_spheres", Str(centre[0]) + "," + Str(centre[1]) + "," + Str(h) + "," + Str(R)));
  PetscCall(Default("-vof_init_samples", "32"));
  PetscCall(Default("-max_steps", "100000000"));
  PetscCall(Default("-monitor_every", "100000000"));
  PetscCall(Default("-monitor_timing", "0"));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  const PetscReal tEnd = times * tnu;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "V3 static drop (%s): %d^2 cells (%.1f per diameter), La %g, density ratio %g, viscous time %.4g s, run to %.4g s\n", setup, (int)M, (double)(D * N), (double)La,
                        (double)ratio, (double)tnu, (double)tEnd));
  if (show) {  // the curvature the first step uses
    PetscCall(Interface(sim)->SurfaceTension(*Fluid(sim)));
    const PetscScalar *k;
    PetscInt           n;
    PetscReal          lo = 1e300, hi = -1e300, sum = 0, cnt = 0;
    PetscCall(VecGetLocalSize(Interface(sim)->Curvature(), &n));
    PetscCall(VecGetArrayRead(Interface(sim)->Curvature(), &k));
    for (PetscInt i = 0; i < n; ++i)
      if (PetscRealPart(k[i]) < 1e299) lo = std::fmin(lo, PetscRealPart(k[i])), hi = std::fmax(hi, PetscRealPart(k[i])), sum += PetscRealPart(k[i]), cnt += 1;
    PetscCall(VecRestoreArrayRead(Interface(sim)->Curvature(), &k));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "curvature: %d cells, min %g max %g mean %g (exact %g)\n", (int)cnt, (double)lo, (double)hi, (double)(sum / cnt), (double)(1 / R)));
  }
  vofdem::FlowSummary fs;
  PetscReal           caHalf = 0, ca = 0;
  int                 report = 1;
  while (sim.Time() < tEnd * (1 - 1e-12)) {
    PetscCall(sim.ChooseTimeStep());
    PetscCall(sim.Step());
    if (sim.Time() >= report * tEnd / 10 * (1 - 1e-12) || sim.Time() >= tEnd * (1 - 1e-12)) {
      PetscCall(Fluid(sim)->Summarize(&fs));
      ca = fs.maxSpeed * mu / sigma;
      if (report == 5) caHalf = ca;
      vofdem::VofSummary vs;
      PetscReal          jump = 0;
      PetscCall(Interface(sim)->Summarize(&vs));
      PetscCall(PressureJump(sim, R, centre, &jump));
      PetscReal klo = 0, khi = 0;
      if (Interface(sim)->Curvature()) {
        Vec k = Interface(sim)->Curvature(), m;
        PetscCall(VecDuplicate(k, &m));
        PetscCall(VecCopy(k, m));
        PetscCall(VecMax(m, nullptr, &khi));
        PetscCall(VecScale(m, -1));
        PetscInt at;
        PetscCall(VecMax(m, &at, &klo));
        klo = -klo;
        if (show && klo < 4) {  // one rank: where, and alpha around it
          PetscScalar ***a;
          const PetscInt ci = at % M, cj = (at / M) % M;
          PetscCall(PetscPrintf(PETSC_COMM_WORLD, "lowest curvature at cell %d,%d\n", (int)ci, (int)cj));
          PetscCall(DMDAVecGetArray(Interface(sim)->FractionDM(), Interface(sim)->Fraction(), &a));
          for (PetscInt j = PetscMin(cj + 4, M - 1); j >= PetscMax(cj - 4, 0); --j) {
            std::string row;
            for (PetscInt i = PetscMax(ci - 4, 0); i <= PetscMin(ci + 4, M - 1); ++i) {
              char b[32];
              std::snprintf(b, sizeof b, " %9.2e", (double)PetscRealPart(a[0][j][i]));
              row += b;
            }
            PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s\n", row.c_str()));
          }
          PetscCall(DMDAVecRestoreArray(Interface(sim)->FractionDM(), Interface(sim)->Fraction(), &a));
        }
        PetscCall(VecDestroy(&m));
      }
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  t/t_nu %.2f  step %d  Ca %.3e  pressure jump %.6f  drop area %.10f  curvature min %.4g\n", (double)(sim.Time() / tnu), (int)sim.StepNumber(), (double)ca, (double)jump,
                            (double)(areaScale * vs.volume / (sim.GetGrid().Upper()[2] - sim.GetGrid().Lower()[2])), (double)klo));
      if (showCentroid) {
        PetscReal cxy[2] = {0, 0};
        PetscCall(DropCentroid(sim, cxy));
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "    drop centroid - centre = (%+.3e, %+.3e) cells\n", (double)((cxy[0] - centre[0]) * N), (double)((cxy[1] - centre[1]) * N)));
      }
      ++report;
    }
  }
  PetscReal jump = 0;
  PetscCall(PressureJump(sim, R, centre, &jump));
  if (show) {  // one rank: alpha of the first z layer as characters (. empty, # full, digits tenths)
    PetscScalar ***a;
    PetscCall(DMDAVecGetArray(Interface(sim)->FractionDM(), Interface(sim)->Fraction(), &a));
    for (PetscInt j = M - 1; j >= 0; --j) {
      std::string row;
      for (PetscInt i = 0; i < M; ++i) {
        const PetscReal v = PetscRealPart(a[0][j][i]);
        row += v <= 1e-12 ? '.' : v >= 1 - 1e-12 ? '#' : (char)('0' + (int)(v * 10));
      }
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s\n", row.c_str()));
    }
    PetscCall(DMDAVecRestoreArray(Interface(sim)->FractionDM(), Interface(sim)->Fraction(), &a));
  }
  vofdem::VofSummary vs;
  PetscCall(Interface(sim)->Summarize(&vs));
  const PetscReal exact = sigma / R, jerr = std::fabs(jump - exact) / exact;
  // docs/verification.md V3 judges Ca after one viscous time; a shorter run (the quick tier) must show it
  // falling (end below half time) and says that the threshold was not judged.
  const bool full = times >= 1, jumpOk = jerr <= 0.01, caOk = !full || ca < caMax, falling = (full && ratio == 1) || ca < caHalf;
  // At rest to round-off: |u| below 1e-12 of the capillary velocity sqrt(sigma / (rho D)) (V2's "to
  // round-off"), where Ca can fall no further; "not growing" (at most twice the half-time value) still
  // catches a slowly growing mode starting from round-off (the full set-up's drift, 1.5x per 0.1 t_nu).
  // Judged instead of falling once Ca is that low, so that the verdict does not depend on round-off.
  const bool roundOff = full && ratio != 1 && ca < 1e-12 / std::sqrt(La), atRest = roundOff && ca <= 2 * caHalf;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "V3 Laplace jump %.6f against sigma/R = %g: error %.3f %% (tolerance 1 %%) %s\n", (double)jump, (double)exact, (double)(100 * jerr),
                        jumpOk ? "ok" : "FAIL"));
  if (full)
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "V3 spurious Ca %.3e at t/t_nu = %.2f (tolerance %.0e) %s%s; cells without curvature %d\n", (double)ca, (double)(sim.Time() / tnu), (double)caMax,
                          caOk ? "ok" : "FAIL", ratio == 1 ? "" : roundOff ? (atRest ? ", at rest to round-off and not growing ok" : ", at round-off but growing FAIL") : falling ? ", falling ok" : ", not falling FAIL", (int)vs.missingCurvature));
  else
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "V3 spurious Ca %.3e at t/t_nu = %.2f, %s (%.3e at half time) %s; the %.0e threshold is judged after one viscous time; cells without curvature %d\n",
                          (double)ca, (double)(sim.Time() / tnu), falling ? "falling" : "not falling", (double)caHalf, falling ? "ok" : "FAIL", (double)caMax, (int)vs.missingCurvature));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(jumpOk && caOk && (roundOff ? atRest : falling) ? 0 : PETSC_ERR_NOT_CONVERGED);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-6
  atol: 1e-14
  test:
    suffix: 1
    args: -resolution 48
  test:
    suffix: 2
    nsize: 2
    args: -resolution 48
    output_file: output/ex31_static_drop_1.out
  test:
    suffix: ratio1000
    nsize: 2
    args: -resolution 48 -ratio 1000
  test:
    suffix: ratio1000_1
    args: -resolution 48 -ratio 1000
    output_file: output/ex31_static_drop_ratio1000.out
  test:
    suffix: ratio8000
    nsize: 2
    args: -resolution 48 -ratio 8000
  test:
    suffix: ratio8000_1
    args: -resolution 48 -ratio 8000
    output_file: output/ex31_static_drop_ratio8000.out
TEST*/
