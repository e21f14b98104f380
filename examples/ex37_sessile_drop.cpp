static const char help[] = "Sessile drop reaching its set contact angle (issue 8: walls with a static contact angle, -vof_contact_angle), through the\n"
                           "program's step (-physics flow,vof). 2-D (x-z plane, one cell across y between slip walls), no gravity: a half-disc of\n"
                           "phase 1 (radius R0 = 1, sigma = 1, rho = 1; the gas rho 1/-ratio, both viscosities Oh sqrt(rho sigma R0), -ohnesorge\n"
                           "default 0.3, about critical damping at ratio 1) sits on the floor z = 0, i.e. at 90 degrees; the floor takes\n"
                           "-vof_contact_angle (default 60) with -vof_contact_angle_faces zlo; x = 0 is a symmetry plane (slip, 90 degrees), so the\n"
                           "box [0, 2.5] x [0, 2] holds half the drop; -resolution N cells per R0 (default 20); -floor slip|wall (default slip;\n"
                           "wall: no-slip, where the contact line moves only by the VOF's numerical slip, several times slower). Runs to t =\n"
                           "-final_time (default 8 capillary times sqrt(rho R0^3 / sigma)) and fits a circle with its centre on the axis to the\n"
                           "interface: column heights sum(alpha) h_z where it is flatter than 45 degrees, row widths sum(alpha) h_x where it is\n"
                           "steeper (cell means of a smooth curve: second order). A circular cap of radius R whose centre lies z_c above the floor\n"
                           "meets it at cos(theta) = -z_c / R. Prints the fitted angle against the set one and the fitted R against the exact R of\n"
                           "a cap with the drop's area A (half domain: A = R^2 (theta - sin theta cos theta) / 2) at the set angle. Must reach:\n"
                           "angle within -angle_tol degrees (default h/R in radians: the angle is imposed through ghost heights one cell away, and\n"
                           "second-order heights carry an error of order h^2/R over that one-cell lever; 1.8 degrees at 20 cells per R0 and 60\n"
                           "degrees (R = 1.6), 3.6 at 120 (R = 0.79)), R within 1 percent, area to 1e-12 relative, bounds to 1e-12, and an\n"
                           "equilibrium: the capillary number max|u| mu / sigma at the end below -ca_max (default 1e-4). -dim 3: a quarter of a\n"
                           "hemisphere in [0, 2]^2 x [0, 1.5] (x = 0 and y = 0 symmetry planes), a sphere fitted to column heights and to the\n"
                           "radii of quarter discs of each layer's area, V = pi R^3 (2 - 3 cos theta + cos^3 theta) / 12; at 60 degrees the radius\n"
                           "needs 16 cells per R0 (error 1.34 % at 10, 0.49 % at 16, 0.30 % at 20: second order). -show_drop (one rank):\n"
                           "alpha at the end as characters (2-D: the first y layer).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/examples/Help.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace {

const double kPi = 3.14159265358979323846;

PetscErrorCode Default(const char *name, const std::string &value) {
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, name, &set));
  if (!set) PetscCall(PetscOptionsSetValue(nullptr, name, value.c_str()));
  PetscFunctionReturn(0);
}

std::string Str(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// The drop at the start: in 2-D a half-disc of radius 1 on the floor around the axis x = 0 (a cylinder
// along y); in 3-D a quarter of a hemisphere around the z axis (x = 0 and y = 0 are symmetry planes).
PetscReal HalfDisc(void *, const PetscReal x[3]) { return std::hypot(x[0], x[2]) - 1; }
PetscReal QuarterSphere(void *, const PetscReal x[3]) { return std::hypot(x[0], std::hypot(x[1], x[2])) - 1; }

// Column heights Z = h_z sum_k alpha, the bottom cell's alpha of each column (full: one crossing), and
// per layer k the row width X_k = h_x sum_i alpha (2-D) or the layer's area h_x h_y sum alpha (3-D),
// summed over the ranks. In 2-D the columns are the means over the y layers.
struct Profile {
  std::vector<double> Z, bottom, layer;
  PetscInt            nx = 0, ny = 0, nz = 0;  // ny = 1 in 2-D
};

PetscErrorCode Profiles(vofdem::Simulation &sim, int dim, Profile *p) {
  PetscScalar ***a;
  PetscInt       s[3], n[3];

  PetscFunctionBeginUser;
  const PetscInt  *N = sim.GetGrid().Cells();
  const PetscReal *h = sim.GetGrid().Spacing();
  p->nx = N[0], p->ny = dim == 2 ? 1 : N[1], p->nz = N[2];
  const size_t        cols = (size_t)(p->nx * p->ny);
  std::vector<double> loc(2 * cols + (size_t)N[2], 0.0), glob(loc.size());
  PetscCall(DMDAGetCorners(Interface(sim)->FractionDM(), &s[0], &s[1], &s[2], &n[0], &n[1], &n[2]));
  PetscCall(DMDAVecGetArray(Interface(sim)->FractionDM(), Interface(sim)->Fraction(), &a));
  for (PetscInt k = s[2]; k < s[2] + n[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const size_t c = (size_t)(i + (dim == 2 ? 0 : j * N[0]));
        const double v = dim == 2 ? PetscRealPart(a[k][j][i]) / N[1] : PetscRealPart(a[k][j][i]);
        loc[c] += v * h[2];
        loc[cols + (size_t)k] += dim == 2 ? v * h[0] : v * h[0] * h[1];
        if (k == 0) loc[cols + (size_t)N[2] + c] += v;
      }
  PetscCall(DMDAVecRestoreArray(Interface(sim)->FractionDM(), Interface(sim)->Fraction(), &a));
  PetscCallMPI(MPI_Allreduce(loc.data(), glob.data(), (int)loc.size(), MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD));
  p->Z.assign(glob.begin(), glob.begin() + cols);
  p->layer.assign(glob.begin() + cols, glob.begin() + cols + N[2]);
  p->bottom.assign(glob.begin() + cols + N[2], glob.end());
  PetscFunctionReturn(0);
}

struct CapFit {
  double R = 0, zc = 0, theta = 0;  // radius, centre height, contact angle (degrees)
  int    points = 0;
};

// Circle (sphere) r^2 + (z - z_c)^2 = R^2 through the interface points (r the distance from the axis),
// least squares on r^2 + z^2 = 2 z_c z + c (Kasa's algebraic fit with the centre on the axis), R^2 = c +
// z_c^2. Points: columns with one crossing (full bottom, also the neighbours') where the surface is
// flatter than 45 degrees, at their centres; layers where it is steeper, at the row width (2-D) or the
// radius of a quarter disc of the layer's area (3-D).
CapFit FitCap(const Profile &P, int dim, const PetscReal h[3]) {
  std::vector<double> px, pz;
  auto full = [&](PetscInt i, PetscInt j) { return P.bottom[(size_t)(i + j * P.nx)] > 1 - 1e-9; };
  auto Z    = [&](PetscInt i, PetscInt j) { return P.Z[(size_t)(i + j * P.nx)]; };
  for (PetscInt j = dim == 2 ? 0 : 1; j < (dim == 2 ? 1 : P.ny - 1); ++j)
    for (PetscInt i = 1; i + 1 < P.nx; ++i) {
      if (!(full(i, j) && full(i - 1, j) && full(i + 1, j))) continue;
      double slope = std::fabs(Z(i + 1, j) - Z(i - 1, j)) / (2 * h[0]);
      if (dim == 3) {
        if (!(full(i, j - 1) && full(i, j + 1))) continue;
        slope = std::hypot(slope, (Z(i, j + 1) - Z(i, j - 1)) / (2 * h[1]));
      }
      if (slope < 1 && Z(i, j) < (P.nz - 1) * h[2])
        px.push_back(dim == 2 ? (i + 0.5) * h[0] : std::hypot((i + 0.5) * h[0], (j + 0.5) * h[1])), pz.push_back(Z(i, j));
    }
  std::vector<double> X(P.layer);
  if (dim == 3)
    for (double &x : X) x = std::sqrt(4 * x / kPi);
  for (PetscInt k = 0; k + 1 < P.nz; ++k) {  // layers: steeper than 45 degrees (one-sided at the floor)
    const double slope = k == 0 ? X[1] - X[0] : 0.5 * (X[k + 1] - X[k - 1]);
    if (X[k] > h[0] && X[k + 1] > 0 && std::fabs(slope) < h[2]) px.push_back(X[k]), pz.push_back((k + 0.5) * h[2]);
  }
  double Szz = 0, Sz = 0, S1 = 0, Szr = 0, Sr = 0;
  for (size_t p = 0; p < px.size(); ++p) {
    const double r = px[p] * px[p] + pz[p] * pz[p];
    Szz += 4 * pz[p] * pz[p], Sz += 2 * pz[p], S1 += 1, Szr += 2 * pz[p] * r, Sr += r;
  }
  CapFit f;
  const double det = Szz * S1 - Sz * Sz;
  f.zc             = (Szr * S1 - Sz * Sr) / det;
  const double c   = (Szz * Sr - Sz * Szr) / det;
  f.R              = std::sqrt(c + f.zc * f.zc);
  f.theta          = std::acos(-f.zc / f.R) * 180 / kPi;
  f.points         = (int)px.size();
  return f;
}

PetscErrorCode ShowDrop(vofdem::Simulation &sim) {
  PetscScalar ***a;
  PetscMPIInt    size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  if (size > 1) VofdemInputError(PETSC_COMM_WORLD, "option -show_drop: run on one rank");
  const PetscInt *N = sim.GetGrid().Cells();
  PetscCall(DMDAVecGetArray(Interface(sim)->FractionDM(), Interface(sim)->Fraction(), &a));
  for (PetscInt k = N[2] - 1; k >= 0; --k) {
    std::string row;
    for (PetscInt i = 0; i < N[0]; ++i) {
      const PetscReal v = PetscRealPart(a[k][0][i]);
      row += v <= 1e-12 ? '.' : v >= 1 - 1e-12 ? '#' : (char)('0' + (int)(v * 10));
    }
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s\n", row.c_str()));
  }
  PetscCall(DMDAVecRestoreArray(Interface(sim)->FractionDM(), Interface(sim)->Fraction(), &a));
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  vofdem::Simulation sim;
  PetscInt           N = 20;
  PetscReal          ratio = 1, oh = 0.3, finalTime = 8, caMax = 1e-4, tol = -1;
  char               floor[16] = "slip";

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscBool show = PETSC_FALSE;
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-show_drop", &show, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-resolution", &N, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-ratio", &ratio, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-ohnesorge", &oh, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-ca_max", &caMax, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-angle_tol", &tol, nullptr));
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-floor", floor, sizeof floor, nullptr));
  PetscInt dim = 2;
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-dim", &dim, nullptr));
  if (dim != 2 && dim != 3) VofdemInputError(PETSC_COMM_WORLD, "option -dim: give 2 or 3, got %d", (int)dim);
  if (std::string(floor) != "slip" && std::string(floor) != "wall") VofdemInputError(PETSC_COMM_WORLD, "option -floor: '%s' is neither slip nor wall", floor);
  if (N < 4) VofdemInputError(PETSC_COMM_WORLD, "option -resolution: give at least 4 cells per radius, got %d", (int)N);
  if (!(ratio >= 1)) VofdemInputError(PETSC_COMM_WORLD, "option -ratio: the drop is the heavier phase, give a ratio >= 1, got %g", (double)ratio);
  const double h = 1.0 / N, sigma = 1, rho = 1, mu = oh * std::sqrt(rho * sigma * 1.0);
  PetscCall(Default("-physics", "flow,vof"));
  if (dim == 2) {
    // one cell across y between slip walls: the 2-D problem (two cells, as until 2026-11-27, cost twice as much)
    PetscCall(Default("-grid_cells", std::to_string((int)(2.5 * N)) + ",1," + std::to_string(2 * N)));
    PetscCall(Default("-grid_upper", "2.5," + Str(h) + ",2"));
    PetscCall(Default("-flow_bc_yhi", "slip"));
  } else {  // a quarter of the drop: x = 0 and y = 0 are symmetry planes
    // PFMG: the 2-D drop cannot have it (one cell across y, PressureSolver.cpp); here it is 1.4x faster than BoomerAMG
    PetscCall(Default("-flow_pressure_pc", "pfmg"));
    PetscCall(Default("-grid_cells", std::to_string(2 * N) + "," + std::to_string(2 * N) + "," + std::to_string((int)(1.5 * N))));
    PetscCall(Default("-grid_upper", "2,2," + Str(1.5)));
  }
  PetscCall(Default("-gravity", "0,0,0"));
  PetscCall(Default("-flow_bc_xlo", "slip"));
  PetscCall(Default("-flow_bc_ylo", "slip"));
  PetscCall(Default("-flow_bc_zlo", floor));
  PetscCall(Default("-flow_density", Str(rho / ratio)));
  PetscCall(Default("-flow_viscosity", Str(mu)));
  PetscCall(Default("-flow_pressure_pc", "boomeramg"));
  PetscCall(Default("-flow_pressure_ksp_rtol", "1e-12"));
  PetscCall(Default("-vof_density", Str(rho)));
  PetscCall(Default("-vof_viscosity", Str(mu)));
  PetscCall(Default("-vof_surface_tension", Str(sigma)));
  PetscCall(Default("-vof_contact_angle", "60"));
  PetscCall(Default("-vof_contact_angle_faces", "zlo"));
  PetscCall(Default("-max_steps", "100000000"));
  PetscCall(Default("-monitor_every", "100000000"));
  PetscCall(Default("-monitor_timing", "0"));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-final_time", &finalTime, nullptr));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  if (!Interface(sim)) VofdemInputError(PETSC_COMM_WORLD, "ex37: needs -physics flow,vof");
  const PetscInt samples2[3] = {32, 1, 32}, samples3[3] = {16, 16, 16};
  PetscCall(Interface(sim)->SetFraction(dim == 2 ? HalfDisc : QuarterSphere, nullptr, dim == 2 ? samples2 : samples3));
  PetscCall(Interface(sim)->UpdateProperties(*Fluid(sim)));
  const PetscReal *hs = sim.GetGrid().Spacing();
  const double     theta = Interface(sim)->ContactAngle(4), th = theta * kPi / 180;
  vofdem::VofSummary s0, s1;
  PetscCall(Interface(sim)->Summarize(&s0));
  const PetscInt *cells = sim.GetGrid().Cells();
  double          Rexact;
  if (dim == 2) {
    const double area = s0.volume / (cells[1] * hs[1]);  // of the half drop, in the x-z plane
    Rexact            = std::sqrt(2 * area / (th - std::sin(th) * std::cos(th)));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "sessile drop: %d x 2 x %d cells (%d per R0), density ratio %g, Oh %g, floor %s, contact angle %g degrees, to t = %g\n", (int)cells[0], (int)cells[2],
                          (int)N, (double)ratio, (double)oh, floor, theta, (double)finalTime));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "half-drop area %.10f (pi/2 = %.10f); a cap of this area at %g degrees: R = %.6f, base half-width %.6f, height %.6f\n", area, kPi / 2, theta,
                          Rexact, Rexact * std::sin(th), Rexact * (1 - std::cos(th))));
  } else {  // a quarter of a spherical cap: V = pi R^3 (2 - 3 cos theta + cos^3 theta) / 12
    const double c = std::cos(th);
    Rexact         = std::cbrt(12 * s0.volume / (kPi * (2 - 3 * c + c * c * c)));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "sessile drop (3-D, a quarter): %d x %d x %d cells (%d per R0), density ratio %g, Oh %g, floor %s, contact angle %g degrees, to t = %g\n",
                          (int)cells[0], (int)cells[1], (int)cells[2], (int)N, (double)ratio, (double)oh, floor, theta, (double)finalTime));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "quarter-drop volume %.10f (pi/6 = %.10f); a cap of this volume at %g degrees: R = %.6f, base radius %.6f, height %.6f\n", s0.volume, kPi / 6,
                          theta, Rexact, Rexact * std::sin(th), Rexact * (1 - c)));
  }
  if (tol < 0) tol = 180 / kPi * hs[0] / Rexact;
  Profile P;
  vofdem::FlowSummary fs;
  int                 report = 1;
  while (sim.Time() < finalTime * (1 - 1e-12)) {
    PetscCall(sim.ChooseTimeStep());
    PetscCall(sim.Step());
    if (sim.Time() >= report * finalTime / 6 * (1 - 1e-12) || sim.Time() >= finalTime * (1 - 1e-12)) {
      PetscCall(Profiles(sim, (int)dim, &P));
      const CapFit f = FitCap(P, (int)dim, hs);
      PetscCall(Fluid(sim)->Summarize(&fs));
      const double base = dim == 2 ? P.layer[0] : std::sqrt(4 * P.layer[0] / kPi);
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  t %6.2f  step %6d  Ca %.3e  fitted angle %7.3f  R %.5f  apex height %.5f  base row width %.5f\n", (double)sim.Time(), (int)sim.StepNumber(),
                            (double)(fs.maxSpeed * mu / sigma), f.theta, f.R, P.Z[0], base));
      ++report;
    }
  }
  PetscCall(Profiles(sim, (int)dim, &P));
  const CapFit f = FitCap(P, (int)dim, hs);
  PetscCall(Fluid(sim)->Summarize(&fs));
  PetscCall(Interface(sim)->Summarize(&s1));
  if (show) PetscCall(ShowDrop(sim));
  const double ca = fs.maxSpeed * mu / sigma, dA = std::fabs(s1.volume - s0.volume) / s0.volume, eR = std::fabs(f.R - Rexact) / Rexact;
  const double eTheta = f.theta - theta;
  const bool   okTheta = std::fabs(eTheta) <= tol, okR = eR <= 0.01, okCa = ca <= caMax, okVolume = dA <= 1e-12 && s1.boundViolation <= 1e-12;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "sessile drop: fitted contact angle %.3f degrees against the set %g: error %+.3f (tolerance %.2f) %s\n", f.theta, theta, eTheta, tol,
                        okTheta ? "ok" : "FAIL"));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "sessile drop: fitted radius %.5f against %.5f of a cap with the drop's area at the set angle: error %.3f %% (tolerance 1 %%) %s; %d interface points\n", f.R,
                        Rexact, 100 * eR, okR ? "ok" : "FAIL", f.points));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "sessile drop: equilibrium Ca %.2e (tolerance %.0e) %s; area change %.1e, bound violation %.1e (tolerance 1e-12) %s\n", ca, (double)caMax,
                        okCa ? "ok" : "FAIL", dA, (double)s1.boundViolation, okVolume ? "ok" : "FAIL"));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(okTheta && okR && okCa && okVolume ? 0 : PETSC_ERR_NOT_CONVERGED);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-6
  atol: 1e-13
  test:
    suffix: 60
    nsize: 1
  test:
    suffix: 60_2
    nsize: 2
    output_file: output/ex37_sessile_drop_60.out
  test:
    suffix: 120
    nsize: 2
    args: -vof_contact_angle 120
  test:
    suffix: 90
    nsize: 1
    args: -vof_contact_angle 90 -final_time 2
  test:
    suffix: ratio1000
    nsize: 1
    args: -ratio 1000 -ohnesorge 0.2 -final_time 5 -resolution 16
  test:
    suffix: 3d_90
    nsize: 2
    args: -dim 3 -resolution 10 -vof_contact_angle 90 -final_time 4
  test:
    suffix: 3d_60
    nsize: 2
    args: -dim 3 -resolution 16 -vof_contact_angle 60
  test:
    suffix: 3d_60_1
    nsize: 1
    args: -dim 3 -resolution 16 -vof_contact_angle 60
    output_file: output/ex37_sessile_drop_3d_60.out
TEST*/
