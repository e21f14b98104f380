static const char help[] = "Verification F3 (docs/verification.md): plane Poiseuille flow between no-slip walls at y = 0 and y = H = 1 m (rho 1 kg/m^3,\n"
                           "nu -nu, default 1 m^2/s; centre-line velocity U_c = 1 m/s; 3 periodic cells in z), run to steady state.\n"
                           " (a) periodic in x, driven by gravity g = 8 nu U_c / H^2 along x: u = g/(2 nu) y (H - y); from rest to -final_time_a\n"
                           "     with dt = -dt_a; the maximum velocity error over the channel.\n"
                           " (b) a 2 H long channel with a parabolic inflow (-flow_bc_xlo inflow, _profile parabolic, U_c) at x = 0 and an outflow\n"
                           "     at x = 2 H; from the exact solution to -final_time_b with dt = -cfl h / U_c (default 0.4): the profile half a height\n"
                           "     before the outlet, and dp/dx (least squares over the downstream half) against -8 mu U_c / H^2.\n"
                           " (c) driven by the pressure difference of two outflow faces (-flow_bc_xlo/xhi outflow, _pressure 8 mu U_c L/H^2 and 0) across\n"
                           "     a channel L = 4 cells long: the same profile as (a), from rest to -final_time_a with dt = -dt_a.\n"
                           "Grids of -cells_list (default 24,48) cells across H; -parts a, b, c or any set (default ab). The MAC wall treatment (ghost = -u, half\n"
                           "a cell out) makes the discrete profile of (a) the exact one plus (h/H)^2 U_c: second order. The 0.1 % tolerance is checked\n"
                           "on the finest grid, the order (>= 1.8) between the two finest, and every run must be steady (the last step changed u by\n"
                           "less than 1e-6 U_c). Flow options (-flow_advection, ...) apply. Exits non-zero on failure.\n"
                           "-solid (part a only): the box extends H/4 beyond each wall and the walls are solid cells (-flow_solid_boxes) instead of\n"
                           "the box's: the wall then sits at the face of the first solid cell and the errors must equal those of the box walls.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/flow/Flow.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace {

const PetscReal kUc = 1, kH = 1;  // centre-line velocity (m/s), channel height (m)
const PetscReal kTolerance = 1e-3, kMinOrder = 1.8;
// Steady: the last step changed u by less than kSteady U_c. The slowest mode (the lowest Stokes mode,
// decaying by 8-10 % a step at the default steps) then has less than ~1.5e-5 U_c left, under 4 % of
// the smallest error measured (4e-4 U_c).
const PetscReal kSteady = 1e-6;
PetscInt        gSolidRows = 0;  // -solid: rows of solid cells below and above the channel (ny/4)

using vofdem::example::SetOption;

using vofdem::example::Num;

PetscReal Exact(PetscReal y) { return 4 * kUc * y * (kH - y) / (kH * kH); }

struct Result {
  PetscReal profile = 0;   // max |u - exact| / U_c (a: everywhere; b: the face column half a height before the outlet)
  PetscReal centre = 0;    // the discrete centre-line velocity there / U_c (cell-centred: the mean of the two middle faces)
  PetscReal gradient = 0;  // b: relative error of dp/dx
  PetscReal change = 0;    // max |u^{n+1} - u^n| / U_c over the last step
  PetscReal crossMax = 0;  // max |v|, |w| / U_c
  PetscInt  steps = 0;
};

// Max |u - exact| over the u faces with index i in [i0, i1) along x (all of them for (a)), and the
// mean of the two faces either side of the centre line.
PetscErrorCode ProfileError(vofdem::Flow &flow, PetscInt i0, PetscInt i1, Result *r) {
  vofdem::LocalField u;
  PetscInt           s[3], n[3];
  PetscReal          mx = 0, centre = 0, cells = 0, g[3];

  PetscFunctionBeginUser;
  const vofdem::StaggeredGrid &sg = flow.Staggered();
  const PetscReal             *h  = sg.Base().Spacing();
  const PetscInt               ny = sg.Base().Cells()[1];
  sg.Owned(0, s, n);
  PetscCall(sg.GetGlobal(0, flow.Velocity(0), &u));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = std::max(s[0], i0); i < std::min(s[0] + n[0], i1); ++i) {
        const PetscInt jc = j - gSolidRows;  // the row in the channel
        if (jc < 0 || jc >= ny - 2 * gSolidRows) continue;
        const PetscReal v = PetscRealPart(u.at(i, j, k));
        mx = std::fmax(mx, std::fabs(v - Exact((jc + 0.5) * h[1])) / kUc);
        if (jc == (ny - 2 * gSolidRows) / 2 - 1 || jc == (ny - 2 * gSolidRows) / 2) {
          centre += 0.5 * v / kUc;
          if (jc == (ny - 2 * gSolidRows) / 2) cells += 1;
        }
      }
  PetscCall(sg.RestoreGlobal(0, flow.Velocity(0), &u));
  PetscReal loc[2] = {centre, cells};
  PetscCallMPI(MPI_Allreduce(&mx, &g[0], 1, MPIU_REAL, MPI_MAX, PETSC_COMM_WORLD));
  PetscCallMPI(MPI_Allreduce(loc, &g[1], 2, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  r->profile = g[0];
  r->centre  = g[1] / g[2];
  PetscFunctionReturn(0);
}

// dp/dx by least squares over the cells with index in [i0, nx): the y-z mean of p per column, then a line.
PetscErrorCode PressureGradient(vofdem::Flow &flow, PetscInt i0, PetscReal *dpdx) {
  vofdem::LocalField p;
  PetscInt           s[3], n[3];

  PetscFunctionBeginUser;
  const vofdem::StaggeredGrid &sg = flow.Staggered();
  const vofdem::Grid          &grid = sg.Base();
  const PetscInt               nx = grid.Cells()[0];
  std::vector<PetscReal>       col(nx, 0), sum(nx, 0);
  sg.Owned(3, s, n);
  PetscCall(sg.GetGlobal(3, flow.Pressure(), &p));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) col[i] += PetscRealPart(p.at(i, j, k)) / (grid.Cells()[1] * grid.Cells()[2]);
  PetscCall(sg.RestoreGlobal(3, flow.Pressure(), &p));
  PetscCallMPI(MPI_Allreduce(col.data(), sum.data(), (PetscMPIInt)nx, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  PetscReal sx = 0, sp = 0, sxx = 0, sxp = 0, m = 0;
  for (PetscInt i = i0; i < nx; ++i) {
    const PetscReal x = (i + 0.5) * grid.Spacing()[0];
    sx += x, sp += sum[i], sxx += x * x, sxp += x * sum[i], m += 1;
  }
  *dpdx = (m * sxp - sx * sp) / (m * sxx - sx * sx);
  PetscFunctionReturn(0);
}

PetscErrorCode RunChannel(bool inflow, bool pressureDriven, PetscInt ny, PetscReal nu, PetscReal dtA, PetscReal cfl, PetscReal finalTime, Result *r) {
  vofdem::Grid       grid;
  vofdem::Flow       flow;
  vofdem::LocalField u;
  PetscInt           s[3], n[3];
  Vec                before;

  PetscFunctionBeginUser;
  const PetscReal h = kH / ny;
  // (a) a few cells along x suffice (nothing varies along x); (b) a channel 2 H long.
  const PetscInt nx = inflow ? 2 * ny : 4, nz = 3;
  const PetscInt  rows = inflow ? 0 : gSolidRows, nyBox = ny + 2 * rows;  // -solid: solid rows beyond each wall
  PetscCall(SetOption("-grid_cells", std::to_string(nx) + "," + std::to_string(nyBox) + "," + std::to_string(nz)));
  PetscCall(SetOption("-grid_lower", "0," + Num(-rows * h) + ",0"));
  PetscCall(SetOption("-grid_upper", Num(nx * h) + "," + Num(kH + rows * h) + "," + Num(nz * h)));
  if (rows) PetscCall(SetOption("-flow_solid_boxes", "-1," + Num(-2 * rows * h) + ",-1," + Num(nx * h + 1) + ",0," + Num(nz * h + 1) + ",-1," + Num(kH) + ",-1," + Num(nx * h + 1) + "," +
                                                         Num(kH + 2 * rows * h) + "," + Num(nz * h + 1)));
  PetscCall(SetOption("-grid_periodic", inflow || pressureDriven ? "z" : "x,z"));
  PetscCall(SetOption("-flow_density", "1"));
  PetscCall(SetOption("-flow_viscosity", Num(nu)));
  if (inflow) {
    PetscCall(SetOption("-flow_bc_xlo", "inflow"));
    PetscCall(SetOption("-flow_bc_xlo_velocity", Num(kUc) + ",0,0"));
    PetscCall(SetOption("-flow_bc_xlo_profile", "parabolic"));
    PetscCall(SetOption("-flow_bc_xhi", "outflow"));
  }
  if (pressureDriven) {  // mu u'' = dp/dx = -(p_lo - p_hi)/L, so U_c = (p_lo - p_hi) H^2 / (8 mu L)
    PetscCall(SetOption("-flow_bc_xlo", "outflow"));
    PetscCall(SetOption("-flow_bc_xlo_pressure", Num(8 * nu * kUc * nx * h / (kH * kH))));
    PetscCall(SetOption("-flow_bc_xhi", "outflow"));
    PetscCall(SetOption("-flow_bc_xhi_pressure", "0"));
  }
  PetscCall(grid.SetFromOptions(PETSC_COMM_WORLD));
  PetscCall(flow.SetFromOptions(grid));
  PetscCall(grid.SetUp(PETSC_FALSE));
  // Poiseuille: mu u'' = dp/dx - rho g, so U_c = g H^2 / (8 nu) for (a).
  const PetscReal gravity[3] = {inflow || pressureDriven ? 0 : 8 * nu * kUc / (kH * kH), 0, 0};
  PetscCall(flow.SetUp(gravity));
  // (a) starts from rest. (b) starts from the exact solution (the profile everywhere, p linear with
  // p = 0 at the outlet face): what is left to settle is the discrete solution's O(h^2) departure,
  // which is what (b) measures.
  if (inflow) {
    const vofdem::StaggeredGrid &sg = flow.Staggered();
    sg.Owned(0, s, n);
    PetscCall(sg.GetGlobal(0, flow.Velocity(0), &u));
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) u.at(i, j, k) = Exact((j + 0.5) * h);
    PetscCall(sg.RestoreGlobal(0, flow.Velocity(0), &u));
    sg.Owned(3, s, n);
    PetscCall(sg.GetGlobal(3, flow.Pressure(), &u));
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) u.at(i, j, k) = 8 * nu * kUc / (kH * kH) * (nx - i - 0.5) * h;
    PetscCall(sg.RestoreGlobal(3, flow.Pressure(), &u));
  }
  // (b): -cfl 0.4, not the module's 0.5. At extrema the TVD flux is upwind, whose x-checkerboard has
  // eigenvalue -2 U/h; AB2 is stable on [-1, 0] dt, and Crank-Nicolson at nu dt/h^2 >> 1 (10-20 here)
  // adds almost no damping to it: at U dt/h = 0.5 the mode is neutral (the start's mismatch at the
  // inlet then rings for hundreds of steps) and above 0.5 it grows.
  const PetscReal dt    = inflow ? cfl * h / kUc : dtA;
  const PetscInt  steps = (PetscInt)std::ceil(finalTime / dt - 1e-9);
  PetscCall(VecDuplicate(flow.Velocity(0), &before));
  for (PetscInt m = 0; m < steps; ++m) {
    if (m == steps - 1) PetscCall(VecCopy(flow.Velocity(0), before));
    PetscCall(flow.Step(m * dt, dt));
  }
  PetscCall(VecAXPY(before, -1, flow.Velocity(0)));
  {
    const vofdem::StaggeredGrid &sg = flow.Staggered();
    PetscReal                    mx = 0;
    sg.Owned(0, s, n);
    PetscCall(sg.GetGlobal(0, before, &u));
    for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
      for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
        for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) mx = std::fmax(mx, std::fabs(PetscRealPart(u.at(i, j, k))));
    PetscCall(sg.RestoreGlobal(0, before, &u));
    PetscCallMPI(MPI_Allreduce(&mx, &r->change, 1, MPIU_REAL, MPI_MAX, PETSC_COMM_WORLD));
    r->change /= kUc;
  }
  PetscCall(VecDestroy(&before));
  PetscReal vmax, wmax;
  PetscCall(VecNorm(flow.Velocity(1), NORM_INFINITY, &vmax));
  PetscCall(VecNorm(flow.Velocity(2), NORM_INFINITY, &wmax));
  r->crossMax = std::fmax(vmax, wmax) / kUc;
  r->steps    = steps;
  if (inflow) {
    const PetscInt iOut = nx - ny / 2;  // x = 2H - H/2
    PetscCall(ProfileError(flow, iOut, iOut + 1, r));
    PetscReal dpdx = 0;
    PetscCall(PressureGradient(flow, nx / 2, &dpdx));
    const PetscReal exact = -8 * nu * kUc / (kH * kH);  // mu = rho nu, rho = 1
    r->gradient           = std::fabs(dpdx - exact) / std::fabs(exact);
  } else PetscCall(ProfileError(flow, 0, nx + 1, r));
  PetscCall(flow.Destroy());
  PetscCall(grid.Destroy());
  if (rows) PetscCall(PetscOptionsClearValue(nullptr, "-flow_solid_boxes"));
  if (inflow)
    for (const char *o : {"-flow_bc_xlo", "-flow_bc_xlo_velocity", "-flow_bc_xlo_profile", "-flow_bc_xhi"}) PetscCall(PetscOptionsClearValue(nullptr, o));
  if (pressureDriven)
    for (const char *o : {"-flow_bc_xlo", "-flow_bc_xlo_pressure", "-flow_bc_xhi", "-flow_bc_xhi_pressure"}) PetscCall(PetscOptionsClearValue(nullptr, o));
  PetscFunctionReturn(0);
}

using vofdem::example::Verdict;

PetscErrorCode Run() {
  PetscInt  list[8] = {24, 48}, nlist = 8;
  PetscReal nu = 1, dtA = 0.01, cfl = 0.4, finalTime[3] = {2.5, 1.5, 2.5};
  PetscBool set;
  char      parts[8] = "ab";

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-parts", parts, sizeof parts, nullptr));
  PetscBool solid = PETSC_FALSE;
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-solid", &solid, nullptr));
  PetscCall(PetscOptionsGetIntArray(nullptr, nullptr, "-cells_list", list, &nlist, &set));
  if (!set) nlist = 2;
  if (solid) {
    for (PetscInt g = 0; g < nlist; ++g)
      if (list[g] % 4) VofdemInputError(PETSC_COMM_WORLD, "option -cells_list: with -solid every grid needs a multiple of 4 cells (H/4 of solid each side), got %d", (int)list[g]);
    if (std::strchr(parts, 'b') || std::strchr(parts, 'c')) VofdemInputError(PETSC_COMM_WORLD, "option -solid: only with -parts a (the inflow profile and the pressure faces span the box)");
  }
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-nu", &nu, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-dt_a", &dtA, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-cfl", &cfl, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-final_time_a", &finalTime[0], nullptr));
  finalTime[2] = finalTime[0];
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-final_time_b", &finalTime[1], nullptr));
  // The discretisation error is measured: the solvers' share must be negligible.
  PetscBool userRtol;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-flow_pressure_ksp_rtol", &userRtol));
  if (!userRtol) PetscCall(SetOption("-flow_pressure_ksp_rtol", "1e-11"));
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-flow_viscous_ksp_rtol", &set));
  if (!set) PetscCall(SetOption("-flow_viscous_ksp_rtol", "1e-12"));  // |v|, |w| < 1e-10 and steadiness need converged solves
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Poiseuille channel, H = %g m, U_c = %g m/s, nu = %g m^2/s (Re = U_c H / nu = %g)\n", (double)kH, (double)kUc, (double)nu,
                        (double)(kUc * kH / nu)));
  int failures = 0;
  for (int part = 0; part < 3; ++part) {
    const bool inflow = part == 1, pressureDriven = part == 2;
    if (!std::strchr(parts, "abc"[part])) continue;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, inflow           ? "(b) parabolic inflow at x = 0, outflow at x = 2 H, from the exact profile to t = %g s, dt = %g h/U_c\n"
                                            : pressureDriven ? "(c) outflow faces at x = 0 and x = L = 4 h with p = 8 mu U_c L/H^2 and 0, from rest to t = %g s, dt = %g s%s\n"
                                                             : "(a) periodic in x, driven by g = 8 nu U_c/H^2, from rest to t = %g s, dt = %g s%s\n",
                          (double)finalTime[part], (double)(inflow ? cfl : dtA), solid ? "; walls: solid cells, H/4 of them beyond each wall" : ""));
    std::vector<Result> r(nlist);
    for (PetscInt g = 0; g < nlist; ++g) {
      gSolidRows = solid ? list[g] / 4 : 0;
      // (c): the pressure solves' absolute floor (Flow::Project: rtol sqrt(N) max|u|/(h dt)) leaves
      // ~2e-10 U_c of cross flow at rtol 1e-11 once two outflow faces hold a pressure difference.
      if (!userRtol) PetscCall(SetOption("-flow_pressure_ksp_rtol", pressureDriven ? "1e-13" : "1e-11"));
      PetscCall(RunChannel(inflow, pressureDriven, list[g], nu, dtA, cfl, finalTime[part], &r[g]));
      const bool steady = r[g].change < kSteady;
      failures += !steady;
      char line[320];
      std::snprintf(line, sizeof line, "  %3d cells across: steps %4d  max |u - u_exact|/U_c %.4e  centre %.8f U_c", (int)list[g], (int)r[g].steps, (double)r[g].profile,
                    (double)r[g].centre);
      std::string text = line;
      if (inflow) {
        std::snprintf(line, sizeof line, "  dp/dx error %.4e", (double)r[g].gradient);
        text += line;
      }
      if (g) {
        const PetscReal q = std::log((PetscReal)list[g] / list[g - 1]);
        std::snprintf(line, sizeof line, "  order %.2f", (double)(std::log(r[g - 1].profile / r[g].profile) / q));
        text += line;
        if (inflow) {
          std::snprintf(line, sizeof line, " dp/dx %.2f", (double)(std::log(r[g - 1].gradient / r[g].gradient) / q));
          text += line;
        }
      }
      // (a): v and w stay zero (printed as a bound, not a round-off value). In (b) they are not: the
      // exact inflow profile adjusts to the discrete one within a few cells of the inlet.
      std::snprintf(line, sizeof line, "  steady %s", steady ? "yes" : "NO");
      text += line;
      if (!inflow) {
        if (!(r[g].crossMax < 1e-10)) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  (max |v|, |w| = %.3e U_c)\n", (double)r[g].crossMax));
        std::snprintf(line, sizeof line, "  |v|,|w| < 1e-10 U_c %s", r[g].crossMax < 1e-10 ? "yes" : "NO");
        failures += !(r[g].crossMax < 1e-10);
        text += line;
      }
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s\n", text.c_str()));
    }
    const Result &f  = r[nlist - 1];
    const char   *id = inflow ? "F3b" : pressureDriven ? "F3c" : "F3a";
    bool          ok = f.profile < kTolerance;
    failures += !ok;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s velocity profile error%s on %d cells: %.4e U_c (tolerance %g) %s\n", id, inflow ? " half a height before the outlet" : "",
                          (int)list[nlist - 1], (double)f.profile, (double)kTolerance, Verdict(ok)));
    if (inflow) {
      ok = f.gradient < kTolerance;
      failures += !ok;
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s dp/dx error against -8 mu U_c/H^2 on %d cells: %.4e (tolerance %g) %s\n", id, (int)list[nlist - 1], (double)f.gradient,
                            (double)kTolerance, Verdict(ok)));
    }
    // (b)'s profile error is (h/H)^2 (1 - 3 h/H + ...) U_c at the wall face: 1.90 between 24 and 48.
    if (nlist >= 2) {
      const PetscReal order = std::log(r[nlist - 2].profile / f.profile) / std::log((PetscReal)list[nlist - 1] / list[nlist - 2]);
      ok                    = order >= kMinOrder;
      failures += !ok;
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s profile error order between %d and %d cells: %.2f (tolerance >= %.1f) %s\n", id, (int)list[nlist - 2], (int)list[nlist - 1],
                            (double)order, (double)kMinOrder, Verdict(ok)));
    }
  }
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}
/*TEST
  rtol: 1e-5
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    output_file: output/ex25_poiseuille_1.out
  test:
    suffix: pressure_1
    nsize: 1
    args: -parts c
  test:
    suffix: pressure_2
    nsize: 2
    args: -parts c
    output_file: output/ex25_poiseuille_pressure_1.out
  test:
    suffix: solid_1
    nsize: 1
    args: -parts a -solid
  test:
    suffix: solid_2
    nsize: 2
    args: -parts a -solid
    output_file: output/ex25_poiseuille_solid_1.out
TEST*/
