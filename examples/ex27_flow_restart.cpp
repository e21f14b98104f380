static const char help[] = "Flow::Save / Flow::Load: a lid-driven cavity (16 x 16 x 4 cells, periodic in z) with a heavy blob (density ratio\n"
                           "-ratio, default 1000) under gravity, run 2N steps of a constant dt; then run N steps, save into a viewer (-viewer\n"
                           "binary or hdf5) in a temporary directory, destroy everything, create a new Flow from the same options, load and\n"
                           "run N more steps. u, v, w and p must equal those of the uninterrupted run bit for bit (same rank count). The blob\n"
                           "grows heavier by -growth per step (relative), as a VOF field would change it, so that the pressure preconditioner\n"
                           "is reused for some steps and rebuilt at others: a restart that lost the preconditioner's reference coefficient\n"
                           "would rebuild it at step N and differ. Options: -half_steps N (default 12), -dt (s, default 0.005). Flow options\n"
                           "(-flow_advection, -flow_viscous, -flow_pressure_pc, ...) apply. Exits non-zero on failure.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/flow/Flow.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/examples/Help.hpp"

#include <petscviewerhdf5.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Scene {
  PetscReal   ratio = 1000, growth = 4e-3, dt = 5e-3;
  PetscInt    half = 12;
  std::string viewer = "binary";
};

// What a run leaves behind: the owned values of u, v, w, p in memory order, and reuse counts.
struct Result {
  std::vector<PetscReal> field[4];
  PetscInt               reused = 0, steps = 0;
  PetscReal              maxSpeed = 0, cfl = 0;
};

PetscErrorCode SetOption(const char *name, const char *value) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsSetValue(nullptr, name, value));
  PetscFunctionReturn(0);
}

// Density before step k: light fluid (1 kg/m^3) with a heavy disc of radius 0.2 m around (0.5, 0.6),
// ratio * (1 + growth k) inside.
PetscErrorCode SetDensity(vofdem::Flow &flow, const Scene &sc, PetscInt k) {
  vofdem::LocalField rho;
  PetscInt           s[3], n[3];

  PetscFunctionBeginUser;
  const vofdem::StaggeredGrid &sg = flow.Staggered();
  const PetscReal             *h  = sg.Base().Spacing();
  sg.Owned(3, s, n);
  PetscCall(sg.GetGlobal(3, flow.Density(), &rho));
  for (PetscInt kk = s[2]; kk < s[2] + n[2]; ++kk)
    for (PetscInt j = s[1]; j < s[1] + n[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + n[0]; ++i) {
        const PetscReal x = (i + 0.5) * h[0] - 0.5, y = (j + 0.5) * h[1] - 0.6;
        rho.at(i, j, kk) = x * x + y * y < 0.04 ? sc.ratio * (1 + sc.growth * k) : 1;
      }
  PetscCall(sg.RestoreGlobal(3, flow.Density(), &rho));
  PetscCall(flow.PropertiesChanged());
  PetscFunctionReturn(0);
}

PetscErrorCode OpenViewer(const Scene &sc, const std::string &path, PetscFileMode mode, PetscViewer *v) {
  PetscFunctionBeginUser;
  if (sc.viewer == "hdf5") PetscCall(PetscViewerHDF5Open(PETSC_COMM_WORLD, path.c_str(), mode, v));
  else PetscCall(PetscViewerBinaryOpen(PETSC_COMM_WORLD, path.c_str(), mode, v));
  PetscFunctionReturn(0);
}

// Steps [first, first + count), after loading `load` if given; saves to `save` if given.
PetscErrorCode Run(const Scene &sc, PetscInt first, PetscInt count, const std::string &load, const std::string &save, Result *res) {
  vofdem::Grid grid;
  vofdem::Flow flow;
  PetscViewer  viewer;

  PetscFunctionBeginUser;
  PetscCall(grid.SetFromOptions(PETSC_COMM_WORLD));
  PetscCall(flow.SetFromOptions(grid));
  PetscCall(grid.SetUp(PETSC_FALSE));
  const PetscReal gravity[3] = {0, -9.81, 0};
  PetscCall(flow.SetUp(gravity));
  if (!load.empty()) {
    PetscCall(OpenViewer(sc, load, FILE_MODE_READ, &viewer));
    PetscCall(flow.Load(viewer));
    PetscCall(PetscViewerDestroy(&viewer));
  }
  for (PetscInt k = first; k < first + count; ++k) {
    vofdem::FlowSummary s;
    PetscCall(SetDensity(flow, sc, k));
    PetscCall(flow.Step(k * sc.dt, sc.dt));
    PetscCall(flow.Summarize(&s));
    res->reused += s.preconditionerReused ? 1 : 0;
    res->maxSpeed = s.maxSpeed;
    res->cfl      = s.cfl;
  }
  res->steps = count;
  if (!save.empty()) {
    PetscCall(OpenViewer(sc, save, FILE_MODE_WRITE, &viewer));
    PetscCall(flow.Save(viewer));
    PetscCall(PetscViewerDestroy(&viewer));
  }
  for (int f = 0; f < 4; ++f) {
    const Vec          v = f < 3 ? flow.Velocity(f) : flow.Pressure();
    const PetscScalar *a;
    PetscInt           n;
    PetscCall(VecGetLocalSize(v, &n));
    PetscCall(VecGetArrayRead(v, &a));
    res->field[f].resize(n);
    for (PetscInt i = 0; i < n; ++i) res->field[f][i] = PetscRealPart(a[i]);
    PetscCall(VecRestoreArrayRead(v, &a));
  }
  PetscCall(flow.Destroy());
  PetscCall(grid.Destroy());
  PetscFunctionReturn(0);
}

// Largest |a - b| over all ranks; infinite where the two differ but the difference is not a number
// (NaN on one side) or the sizes differ.
PetscErrorCode MaxDifference(const std::vector<PetscReal> &a, const std::vector<PetscReal> &b, PetscReal *out) {
  PetscReal d = a.size() == b.size() ? 0 : PETSC_MAX_REAL;
  PetscFunctionBeginUser;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
    if (std::memcmp(&a[i], &b[i], sizeof(PetscReal)) == 0) continue;
    const PetscReal e = std::fabs(a[i] - b[i]);
    d = std::fmax(d, e > 0 ? e : PETSC_MAX_REAL);  // -0 against +0 or NaN: not bitwise equal either
  }
  PetscCallMPI(MPI_Allreduce(&d, out, 1, MPIU_REAL, MPIU_MAX, PETSC_COMM_WORLD));
  PetscFunctionReturn(0);
}

PetscErrorCode Main() {
  Scene     sc;
  PetscBool set;
  char      name[16] = "binary";
  char      tmp[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-half_steps", &sc.half, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-dt", &sc.dt, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-ratio", &sc.ratio, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-growth", &sc.growth, nullptr));
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-viewer", name, sizeof name, &set));
  sc.viewer = name;
  if (sc.viewer != "binary" && sc.viewer != "hdf5") VofdemInputError(PETSC_COMM_WORLD, "option -viewer: '%s' is not binary or hdf5", name);
  if (!(sc.half > 0 && sc.dt > 0)) VofdemInputError(PETSC_COMM_WORLD, "options -half_steps and -dt must be positive");
  // The cavity: lid (y = 1) moving at 1 m/s along x, Re = rho U L/mu = 100 in the light fluid.
  PetscCall(SetOption("-grid_cells", "16,16,4"));
  PetscCall(SetOption("-grid_upper", "1,1,0.25"));
  PetscCall(SetOption("-grid_periodic", "z"));
  PetscCall(SetOption("-flow_density", "1"));
  PetscCall(SetOption("-flow_viscosity", "0.01"));
  PetscCall(SetOption("-flow_bc_yhi_velocity", "1,0,0"));

  // The save goes into a directory of its own under PETSc's temporary directory (-tmp, $PETSC_TMP,
  // /tmp), created by rank 0 and removed at the end: never into the current directory.
  std::string dir;
  {
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
    PetscCall(PetscGetTmp(PETSC_COMM_WORLD, tmp, sizeof tmp));
    PetscCall(PetscStrlcat(tmp, "/vofdem-ex27-XXXXXX", sizeof tmp));
    if (rank == 0) PetscCall(PetscMkdtemp(tmp));
    PetscCallMPI(MPI_Bcast(tmp, (PetscMPIInt)sizeof tmp, MPI_CHAR, 0, PETSC_COMM_WORLD));
    dir = tmp;
  }
  const std::string file = dir + (sc.viewer == "hdf5" ? "/flow.h5" : "/flow.bin");

  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "lid-driven cavity 16 x 16 x 4 (periodic z), heavy blob ratio %g growing %g per step, gravity 9.81 m/s^2, dt %g s, viewer %s\n",
                        (double)sc.ratio, (double)sc.growth, (double)sc.dt, sc.viewer.c_str()));
  Result whole, firstHalf, secondHalf, resumed;
  // The directory goes even when a run fails (its error is returned after the clean-up).
  PetscErrorCode status = Run(sc, 0, 2 * sc.half, "", "", &whole);
  if (!status) status = Run(sc, 0, sc.half, "", file, &firstHalf);
  if (!status) status = Run(sc, sc.half, sc.half, file, "", &resumed);
  PetscCallMPI(MPI_Barrier(PETSC_COMM_WORLD));
  {
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
    if (rank == 0) PetscCall(PetscRMTree(dir.c_str()));
  }
  PetscCall(status);
  // The uninterrupted run's second half, for the reuse count of the same steps.
  secondHalf.reused = whole.reused - firstHalf.reused;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%d steps: max speed %.5e m/s, CFL of the last step %.4f\n", (int)whole.steps, (double)whole.maxSpeed, (double)whole.cfl));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "pressure preconditioner reused in steps %d-%d: uninterrupted %d, resumed %d (of %d); in steps 0-%d: %d\n", (int)sc.half,
                        (int)(2 * sc.half - 1), (int)secondHalf.reused, (int)resumed.reused, (int)sc.half, (int)(sc.half - 1), (int)firstHalf.reused));
  int         failures = resumed.reused != secondHalf.reused;
  const char *names[4] = {"u", "v", "w", "p"};
  for (int f = 0; f < 4; ++f) {
    PetscReal d;
    PetscCall(MaxDifference(whole.field[f], resumed.field[f], &d));
    failures += d != 0;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s after save at %d, load, %d more steps vs %d steps: max |difference| %g (required: exactly 0) %s\n", names[f], (int)sc.half,
                          (int)sc.half, (int)(2 * sc.half), (double)d, d != 0 ? "FAIL" : "ok"));
  }
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: the resumed run differs from the uninterrupted one\n"));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Main());
}

/*TEST
  rtol: 1e-6
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
  test:
    suffix: hdf5_2
    nsize: 2
    requires: hdf5
    args: -viewer hdf5 -half_steps 11 -flow_viscous explicit -flow_advection koren
  test:
    suffix: boomeramg_2
    nsize: 2
    args: -flow_pressure_pc boomeramg
TEST*/
