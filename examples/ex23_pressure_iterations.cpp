static const char help[] = "Verification F4 (docs/verification.md): iteration counts of the pressure solve -div((1/rho) grad p) = f for a\n"
                           "1e-8 reduction of the unpreconditioned residual from a zero initial guess, closed box (all Neumann,\n"
                           "constant null space), density ratios -ratios (default 1,1000,8000) in a step-density case (heavy lower\n"
                           "half) and a heavy-sphere case (radius 0.25 at the centre), on -cells_list grids (default 32). At most 20\n"
                           "iterations are allowed. Then: preconditioner reuse under a 1-percent and a 10-percent coefficient change, a restart from\n"
                           "the saved solver state (bitwise; the state file goes to -output_dir, or else to a temporary directory removed at\n"
                           "the end), and the\n"
                           "difference between this run's solution and the same solve on one rank (rank 0 alone). Exits non-zero on failure.\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/flow/PressureSolver.hpp"
#include "vofdem/grid/Grid.hpp"
#include "vofdem/examples/Help.hpp"
#include "vofdem/examples/ExampleTools.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

const PetscInt maxIterations = 20;  // docs/verification.md F4

using vofdem::example::SetOption;

// Where the restart check writes the saved solver state: -output_dir (created if needed, kept), else a new
// temporary directory (PetscGetTmp: -tmp, $PETSC_TMP or /tmp; removed by the caller), never the current
// directory. Rank 0 writes the file (binary viewer), so rank 0 makes the directory and tells the others.
PetscErrorCode StateDirectory(std::string *dir, bool *temporary) {
  char        given[PETSC_MAX_PATH_LEN] = "", tmp[PETSC_MAX_PATH_LEN] = "";
  PetscBool   set;
  PetscMPIInt rank;
  int         ok = 1;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-output_dir", given, sizeof given, &set));
  PetscCall(PetscGetTmp(PETSC_COMM_WORLD, tmp, sizeof tmp));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  *temporary = !set;
  char path[PETSC_MAX_PATH_LEN] = "";
  if (set) PetscCall(PetscStrncpy(path, given, sizeof path));
  else PetscCall(PetscSNPrintf(path, sizeof path, "%s/vofdem-ex23-XXXXXX", tmp));
  if (rank == 0) {
    std::error_code ec;
    if (set) ok = std::filesystem::create_directories(path, ec) || std::filesystem::is_directory(path, ec);
    else ok = mkdtemp(path) != nullptr;
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, PETSC_COMM_WORLD));
  if (!ok) {
    if (set) VofdemInputError(PETSC_COMM_WORLD, "option -output_dir: cannot create the folder '%s'", given);
    VofdemInputError(PETSC_COMM_WORLD, "cannot create a temporary folder in '%s' for the saved solver state (give -output_dir or -tmp)", tmp);
  }
  PetscCallMPI(MPI_Bcast(path, sizeof path, MPI_CHAR, 0, PETSC_COMM_WORLD));
  *dir = path;
  PetscFunctionReturn(0);
}

// A grid, a solver and the fields of one problem, on `comm`.
struct Problem {
  vofdem::Grid           grid;
  vofdem::PressureSolver solver;
  Vec                    beta = nullptr, rhs = nullptr, p = nullptr;

  PetscErrorCode Create(MPI_Comm comm, PetscInt n) {
    PetscFunctionBeginUser;
    PetscCall(SetOption("-grid_cells", std::to_string(n) + "," + std::to_string(n) + "," + std::to_string(n)));
    PetscCall(grid.SetFromOptions(comm));
    PetscCall(grid.SetUp(PETSC_FALSE));
    PetscCall(solver.Create(grid));
    PetscCall(solver.SetFromOptions());
    PetscCall(solver.SetUp());
    PetscCall(DMCreateGlobalVector(grid.CellDM(), &beta));
    PetscCall(VecDuplicate(beta, &rhs));
    PetscCall(VecDuplicate(beta, &p));
    PetscFunctionReturn(0);
  }
  // Heavy fluid of density `ratio` (light: 1) below z = 0.5 (step) or inside the sphere; beta = 1/rho.
  // The rhs is a smooth field, as the divergence of a provisional velocity would be.
  PetscErrorCode Fill(bool sphere, PetscReal ratio) {
    PetscScalar ***bb, ***ff;
    PetscInt       xs, ys, zs, xm, ym, zm;

    PetscFunctionBeginUser;
    DM               dm = grid.CellDM();
    const PetscReal *h  = grid.Spacing();
    PetscCall(DMDAVecGetArray(dm, beta, &bb));
    PetscCall(DMDAVecGetArray(dm, rhs, &ff));
    PetscCall(DMDAGetCorners(dm, &xs, &ys, &zs, &xm, &ym, &zm));
    for (PetscInt k = zs; k < zs + zm; ++k)
      for (PetscInt j = ys; j < ys + ym; ++j)
        for (PetscInt i = xs; i < xs + xm; ++i) {
          const PetscReal x = (i + 0.5) * h[0], y = (j + 0.5) * h[1], z = (k + 0.5) * h[2];
          const PetscReal r2    = (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5) + (z - 0.5) * (z - 0.5);
          const bool      heavy = sphere ? r2 < 0.0625 : z < 0.5;
          bb[k][j][i]           = 1 / (heavy ? ratio : 1.0);
          ff[k][j][i]           = std::cos(PETSC_PI * x) * std::cos(2 * PETSC_PI * y) * std::cos(PETSC_PI * z) + std::sin(3 * PETSC_PI * z);
        }
    PetscCall(DMDAVecRestoreArray(dm, beta, &bb));
    PetscCall(DMDAVecRestoreArray(dm, rhs, &ff));
    PetscFunctionReturn(0);
  }
  PetscErrorCode Destroy() {
    PetscFunctionBeginUser;
    PetscCall(VecDestroy(&beta));
    PetscCall(VecDestroy(&rhs));
    PetscCall(VecDestroy(&p));
    PetscCall(solver.Destroy());
    PetscCall(grid.Destroy());
    PetscFunctionReturn(0);
  }
};

PetscErrorCode Run() {
  PetscInt  cells[8] = {32}, nCells = 8, nRatios = 8, failures = 0;
  PetscReal ratios[8] = {1, 1000, 8000};
  PetscBool set;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetIntArray(nullptr, nullptr, "-cells_list", cells, &nCells, &set));
  if (!set) nCells = 1;
  PetscCall(PetscOptionsGetRealArray(nullptr, nullptr, "-ratios", ratios, &nRatios, &set));
  if (!set) nRatios = 3;
  for (PetscInt g = 0; g < nCells; ++g)
    for (bool sphere : {false, true})
      for (PetscInt r = 0; r < nRatios; ++r) {
        Problem pr;
        PetscCall(pr.Create(PETSC_COMM_WORLD, cells[g]));
        PetscCall(pr.Fill(sphere, ratios[r]));
        PetscCall(pr.solver.SetCoefficient(pr.beta, "option -ratios"));
        PetscCall(VecSet(pr.p, 0));
        PetscCall(pr.solver.Solve(pr.rhs, pr.p));
        const PetscInt its = pr.solver.Iterations();
        failures += its > maxIterations;
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%3d^3 %-6s density ratio %5g: %2d iterations (tolerance <= %d) %s\n", (int)cells[g], sphere ? "sphere" : "step",
                              (double)ratios[r], (int)its, (int)maxIterations, its > maxIterations ? "FAIL" : "ok"));
        PetscCall(pr.Destroy());
      }

  // Preconditioner reuse on the last grid, sphere at the largest ratio: a 1 % change keeps it
  // (default threshold 5 %), a 10 % change rebuilds it; the previous pressure is the initial guess.
  Problem pr;
  PetscCall(pr.Create(PETSC_COMM_WORLD, cells[nCells - 1]));
  PetscCall(pr.Fill(true, ratios[nRatios - 1]));
  PetscCall(pr.solver.SetCoefficient(pr.beta, "option -ratios"));
  PetscCall(VecSet(pr.p, 0));
  PetscCall(pr.solver.Solve(pr.rhs, pr.p));
  for (PetscReal change : {0.01, 0.1}) {
    PetscCall(VecScale(pr.beta, 1 + change));
    // p/(1 + change) solves the new problem: the previous pressure is a warm start with a residual of about `change`.
    PetscCall(pr.solver.SetCoefficient(pr.beta, "option -ratios"));
    PetscCall(pr.solver.Solve(pr.rhs, pr.p));
    const PetscInt its = pr.solver.Iterations();
    const bool     expectReuse = change < 0.05, bad = (pr.solver.PreconditionerReused() == PETSC_TRUE) != expectReuse || its > maxIterations;
    failures += bad;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "coefficient changed by %g: preconditioner %s (expected %s), %d iterations from the previous pressure, %d builds %s\n",
                          (double)change, pr.solver.PreconditionerReused() ? "reused" : "rebuilt", expectReuse ? "reused" : "rebuilt", (int)its,
                          (int)pr.solver.PreconditionerBuilds(), bad ? "FAIL" : "ok"));
  }

  // Restart: save the solver state (the coefficient its preconditioner was built from) and the
  // pressure, go on with a 1 % change; a new solver loaded from the file must repeat that solve
  // bit for bit (same preconditioner reused, same initial guess).
  {
    PetscViewer viewer;
    Vec         pSaved, pOriginal;
    PetscReal   diff;
    std::string dir;
    bool        temporary = true;
    PetscCall(StateDirectory(&dir, &temporary));
    const std::string file = dir + "/pressure-state.bin";
    PetscCall(VecDuplicate(pr.p, &pSaved));
    PetscCall(VecDuplicate(pr.p, &pOriginal));
    PetscCall(VecCopy(pr.p, pSaved));
    PetscCall(PetscViewerBinaryOpen(PETSC_COMM_WORLD, file.c_str(), FILE_MODE_WRITE, &viewer));
    PetscCall(pr.solver.Save(viewer));
    PetscCall(PetscViewerDestroy(&viewer));
    PetscCall(VecScale(pr.beta, 1.01));
    PetscCall(pr.solver.SetCoefficient(pr.beta, "option -ratios"));
    PetscCall(pr.solver.Solve(pr.rhs, pr.p));
    PetscCall(VecCopy(pr.p, pOriginal));
    vofdem::PressureSolver restarted;
    PetscCall(restarted.Create(pr.grid));
    PetscCall(restarted.SetFromOptions());
    PetscCall(restarted.SetUp());
    PetscCall(PetscViewerBinaryOpen(PETSC_COMM_WORLD, file.c_str(), FILE_MODE_READ, &viewer));
    PetscCall(restarted.Load(viewer));
    PetscCall(PetscViewerDestroy(&viewer));
    if (temporary) {
      PetscMPIInt rank;
      PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
      if (rank == 0) {
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);  // a left-over temporary folder is not worth failing the run for
      }
    }
    PetscCall(restarted.SetCoefficient(pr.beta, "option -ratios"));
    PetscCall(restarted.Solve(pr.rhs, pSaved));
    PetscCall(VecAXPY(pSaved, -1, pOriginal));
    PetscCall(VecNorm(pSaved, NORM_INFINITY, &diff));
    const bool bad = diff != 0 || !restarted.PreconditionerReused();
    failures += bad;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "restart from the saved solver state: preconditioner %s, max |p - p_original| = %g (must be 0) %s\n",
                          restarted.PreconditionerReused() ? "reused" : "rebuilt", (double)diff, bad ? "FAIL" : "ok"));
    PetscCall(restarted.Destroy());
    PetscCall(VecDestroy(&pSaved));
    PetscCall(VecDestroy(&pOriginal));
  }

  // Ranks: the same solve on rank 0 alone (PETSC_COMM_SELF), compared in natural ordering.
  {
    Vec         natural, gathered;
    VecScatter  toZero;
    PetscMPIInt rank;
    PetscReal   diff = 0, scale = 1;

    PetscCall(PetscOptionsSetValue(nullptr, "-flow_pressure_ksp_rtol", "1e-12"));  // so the difference shows round-off, not the tolerance
    PetscCall(pr.Destroy());
    PetscCall(pr.Create(PETSC_COMM_WORLD, cells[nCells - 1]));
    PetscCall(pr.Fill(true, ratios[nRatios - 1]));
    PetscCall(pr.solver.SetCoefficient(pr.beta, "option -ratios"));
    PetscCall(VecSet(pr.p, 0));
    PetscCall(pr.solver.Solve(pr.rhs, pr.p));
    PetscScalar sum;
    PetscCall(VecSum(pr.p, &sum));
    PetscCall(VecShift(pr.p, -sum / pr.grid.Cells()[0] / pr.grid.Cells()[1] / pr.grid.Cells()[2]));
    PetscCall(DMDACreateNaturalVector(pr.grid.CellDM(), &natural));
    PetscCall(DMDAGlobalToNaturalBegin(pr.grid.CellDM(), pr.p, INSERT_VALUES, natural));
    PetscCall(DMDAGlobalToNaturalEnd(pr.grid.CellDM(), pr.p, INSERT_VALUES, natural));
    PetscCall(VecScatterCreateToZero(natural, &toZero, &gathered));
    PetscCall(VecScatterBegin(toZero, natural, gathered, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(toZero, natural, gathered, INSERT_VALUES, SCATTER_FORWARD));
    PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
    if (rank == 0) {
      Problem one;
      PetscCall(one.Create(PETSC_COMM_SELF, cells[nCells - 1]));
      PetscCall(one.Fill(true, ratios[nRatios - 1]));
      PetscCall(one.solver.SetCoefficient(one.beta, "option -ratios"));
      PetscCall(VecSet(one.p, 0));
      PetscCall(one.solver.Solve(one.rhs, one.p));
      PetscScalar s;
      PetscCall(VecSum(one.p, &s));
      PetscCall(VecShift(one.p, -s / one.grid.Cells()[0] / one.grid.Cells()[1] / one.grid.Cells()[2]));
      PetscCall(VecNorm(one.p, NORM_INFINITY, &scale));
      PetscCall(VecAXPY(gathered, -1, one.p));
      PetscCall(VecNorm(gathered, NORM_INFINITY, &diff));
      diff /= scale;
      PetscCall(one.Destroy());
    }
    PetscCallMPI(MPI_Bcast(&diff, 1, MPIU_REAL, 0, PETSC_COMM_WORLD));
    const PetscReal tol = 1e-10;
    failures += !(diff <= tol);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "this run against one rank (sphere, ratio %g, rtol 1e-12): max |p - p_1|/max |p_1| = %.1e (tolerance %.0e) %s\n",
                          (double)ratios[nRatios - 1], (double)diff, (double)tol, diff <= tol ? "ok" : "FAIL"));
    PetscCall(VecScatterDestroy(&toZero));
    PetscCall(VecDestroy(&gathered));
    PetscCall(VecDestroy(&natural));
    PetscCall(pr.Destroy());
  }
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d checks\n", (int)failures));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

}  // namespace

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-6
  atol: 1e-9
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
  test:
    suffix: 4
    nsize: 4
  test:
    suffix: pfmg
    nsize: 2
    args: -flow_pressure_pc pfmg
TEST*/
