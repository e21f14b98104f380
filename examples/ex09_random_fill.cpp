static const char help[] = "Random non-overlapping fill (-dem_fill_mode random) of a box to a solid volume fraction with a lognormal size law.\n"
                           "Checks: the fraction is reached, no two particles overlap, all lie inside the region, the sample mean radius\n"
                           "agrees with the truncated law's within 4 standard errors, and prints a fingerprint of every particle's id, position\n"
                           "and radius (bits), which must be the same on any rank count. -timing also times the fill for 1e4 and 1e5 particles.\n\n";

#include "vofdem/base/Random.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/dem/RandomFill.hpp"
#include "vofdem/examples/Help.hpp"

#include <petsctime.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

static PetscErrorCode Timing() {
  vofdem::SizeDistribution s;
  PetscFunctionBeginUser;
  s.SetUniform(0.8e-4, 1.2e-4);
  for (PetscInt n : {10000, 100000}) {
    vofdem::RandomFillRequest req;
    vofdem::RandomFillResult  res;
    // A cube that holds n particles at the fraction 0.25.
    const PetscReal side = std::cbrt(n * 4.0 / 3.0 * PETSC_PI * s.MeanCube() / 0.25);
    for (int d = 0; d < 3; ++d) req.upper[d] = side;
    req.count = n;
    req.seed  = 1;
    PetscLogDouble t0, t1;
    PetscCall(PetscTime(&t0));
    vofdem::RandomFill(s, req, &res);
    PetscCall(PetscTime(&t1));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "timing: %d particles to fraction %.3f: %.3f s, %.3f us per particle, %.2f candidates per particle\n", (int)n,
                          (double)res.fraction, t1 - t0, 1e6 * (t1 - t0) / n, (double)res.candidates / n));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  vofdem::Simulation sim;
  PetscBool          timing = PETSC_FALSE;
  PetscReal          fraction = 0.25;
  PetscInt           failures = 0;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-timing", &timing, nullptr));
  if (timing) PetscCall(Timing());
  PetscCall(PetscOptionsSetValue(nullptr, "-physics", "dem"));
  PetscCall(PetscOptionsSetValue(nullptr, "-grid_cells", "4,4,4"));
  PetscCall(PetscOptionsSetValue(nullptr, "-grid_upper", "0.006,0.006,0.006"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_mode", "random"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_lower", "0.0005,0,0"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_upper", "0.006,0.006,0.0055"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_size_distribution", "lognormal"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_radius_mean", "2e-4"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_radius_std", "6e-5"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_radius_min", "1e-4"));
  PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_radius_max", "3.5e-4"));
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-dem_fill_volume_fraction", &timing));
  if (!timing) PetscCall(PetscOptionsSetValue(nullptr, "-dem_fill_volume_fraction", "0.25"));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-dem_fill_volume_fraction", &fraction, nullptr));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);

  // Every particle to rank 0: id, x, y, z, r.
  DM          swarm = dem->Swarm();
  PetscInt    n;
  PetscReal  *x, *r;
  PetscInt64 *id;
  PetscCall(DMSwarmGetLocalSize(swarm, &n));
  PetscCall(DMSwarmGetField(swarm, vofdem::field::position, nullptr, nullptr, (void **)&x));
  PetscCall(DMSwarmGetField(swarm, vofdem::field::radius, nullptr, nullptr, (void **)&r));
  PetscCall(DMSwarmGetField(swarm, vofdem::field::id, nullptr, nullptr, (void **)&id));
  std::vector<PetscReal> mine(5 * n);
  for (PetscInt p = 0; p < n; ++p) mine[5 * p] = (PetscReal)id[p], std::copy(&x[3 * p], &x[3 * p] + 3, &mine[5 * p + 1]), mine[5 * p + 4] = r[p];
  PetscCall(DMSwarmRestoreField(swarm, vofdem::field::id, nullptr, nullptr, (void **)&id));
  PetscCall(DMSwarmRestoreField(swarm, vofdem::field::radius, nullptr, nullptr, (void **)&r));
  PetscCall(DMSwarmRestoreField(swarm, vofdem::field::position, nullptr, nullptr, (void **)&x));
  PetscMPIInt size, rank, count = (PetscMPIInt)mine.size(), total = 0;
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  std::vector<PetscMPIInt> counts(size), displs(size);
  PetscCallMPI(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, PETSC_COMM_WORLD));
  for (int q = 0; q < size; ++q) displs[q] = total, total += counts[q];
  std::vector<PetscReal> all(total);
  PetscCallMPI(MPI_Allgatherv(mine.data(), count, MPIU_REAL, all.data(), counts.data(), displs.data(), MPIU_REAL, PETSC_COMM_WORLD));
  std::vector<std::array<PetscReal, 5>> rows(total / 5);
  for (size_t k = 0; k < rows.size(); ++k) std::copy(&all[5 * k], &all[5 * k] + 5, rows[k].begin());
  std::sort(rows.begin(), rows.end(), [](const auto &a, const auto &b) { return a[0] < b[0]; });

  const PetscReal lo[3] = {0.0005, 0, 0}, hi[3] = {0.006, 0.006, 0.0055};
  PetscReal       solid = 0, sum = 0, worst = 0;  // worst: largest overlap / smaller diameter
  PetscInt        outside = 0, idsWrong = 0;
  std::uint64_t   print = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto &a = rows[i];
    idsWrong += a[0] != (PetscReal)i;
    solid += 4.0 / 3.0 * PETSC_PI * a[4] * a[4] * a[4];
    sum += a[4];
    for (int d = 0; d < 3; ++d) outside += a[1 + d] - a[4] < lo[d] || a[1 + d] + a[4] > hi[d];
    for (int k = 0; k < 5; ++k) {
      std::uint64_t bits;
      std::memcpy(&bits, &a[k], sizeof bits);
      print = vofdem::random::Mix(print ^ bits);
    }
    for (size_t j = 0; j < i; ++j) {  // brute force, independent of the fill's cell hash
      const auto     &b  = rows[j];
      const PetscReal d2 = (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]) + (a[3] - b[3]) * (a[3] - b[3]);
      if (d2 < (a[4] + b[4]) * (a[4] + b[4])) worst = std::max(worst, (a[4] + b[4] - std::sqrt(d2)) / (2 * std::min(a[4], b[4])));
    }
  }
  const PetscReal volume = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]), reached = solid / volume;
  vofdem::SizeDistribution law;
  law.SetLognormal(2e-4, 6e-5, 1e-4, 3.5e-4);
  const PetscReal N = (PetscReal)rows.size(), mean = sum / N, se = std::sqrt(law.Variance() / N);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "random fill: %d particles, ids 0..%d in order: %s; fingerprint %016llx\n", (int)rows.size(), (int)rows.size() - 1,
                        idsWrong ? "no" : "yes", (unsigned long long)print));
  failures += idsWrong > 0;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "volume fraction %.6f (target %.3f; the fill reports %.6f) %s\n", (double)reached, (double)fraction,
                        (double)dem->FillVolumeFraction(), reached >= fraction && std::fabs(reached - dem->FillVolumeFraction()) < 1e-12 ? "ok" : "FAIL"));
  failures += !(reached >= fraction && std::fabs(reached - dem->FillVolumeFraction()) < 1e-12);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "largest overlap %.3e of a diameter (tolerance 0), particles outside the region %d (tolerance 0) %s\n", (double)worst,
                        (int)outside, worst == 0 && outside == 0 ? "ok" : "FAIL"));
  failures += !(worst == 0 && outside == 0);
  const PetscReal z = std::fabs(mean - law.Mean()) / se;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "mean radius %.6e m, truncated lognormal %.6e m: %.2f standard errors (tolerance 4) %s\n", (double)mean, (double)law.Mean(),
                        (double)z, z < 4 ? "ok" : "FAIL"));
  failures += !(z < 4);
  PetscCall(sim.Destroy());
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d checks\n", (int)failures));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-12
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    args: -grid_ranks 2,1,1
    output_file: output/ex09_random_fill_1.out
  test:
    suffix: 4
    nsize: 4
    args: -grid_ranks 2,2,1
    output_file: output/ex09_random_fill_1.out
TEST*/
