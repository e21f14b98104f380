static const char help[] = "Dem::Save / Dem::Load: a run that saves at step N, is destroyed, re-created from the same options, loads\n"
                           "and runs N more steps must equal the uninterrupted 2N-step run bit for bit on the same rank count (every\n"
                           "swarm field, in memory order). On several ranks also: that save loaded on 1 rank and a 1-rank save loaded\n"
                           "on all ranks, and that save loaded on as many ranks decomposed another way, agree with the uninterrupted run\n"
                           "to 1e-10 (relative) after N steps. Exits non-zero on failure.\n\n";

// The scene: spheres with random velocities under gravity in a small box, so that the first N
// steps contain contacts, wall contacts, list rebuilds and particles crossing between ranks.

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/examples/Help.hpp"

#include <petscviewerhdf5.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <string>
#include <vector>

// Per-particle values compared: every swarm field of ours, in this order.
static const char *const kFields[] = {vofdem::field::id,    vofdem::field::position, vofdem::field::velocity, vofdem::field::omega,
                                      vofdem::field::force, vofdem::field::torque,   vofdem::field::radius,   vofdem::field::mass,
                                      vofdem::field::reference};
constexpr int kWidth = 1 + 3 * 6 + 2;  // values per particle, as listed above
constexpr int kMoving = 1 + 3 * 3;     // id, position, velocity, angular velocity: what a rank-count change compares

// Every particle of the run on every rank of `world`, concatenated in rank order and memory order.
static PetscErrorCode Gather(vofdem::Dem *dem, MPI_Comm comm, std::vector<PetscReal> *all) {
  DM       swarm = dem->Swarm();
  PetscInt n;

  PetscFunctionBeginUser;
  PetscCall(DMSwarmGetLocalSize(swarm, &n));
  std::vector<PetscReal> mine((size_t)n * kWidth);
  for (int f = 0, col = 0; f < (int)(sizeof kFields / sizeof *kFields); ++f) {
    PetscInt      bs;
    PetscDataType type;
    void         *data;
    PetscCall(DMSwarmGetField(swarm, kFields[f], &bs, &type, &data));
    for (PetscInt p = 0; p < n; ++p)
      for (PetscInt c = 0; c < bs; ++c)
        mine[(size_t)p * kWidth + col + c] = type == PETSC_INT64 ? (PetscReal)((PetscInt64 *)data)[p * bs + c] : ((PetscReal *)data)[p * bs + c];
    PetscCall(DMSwarmRestoreField(swarm, kFields[f], &bs, &type, &data));
    col += bs;
  }
  PetscMPIInt size, count = (PetscMPIInt)mine.size();
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), offsets(size, 0);
  PetscCallMPI(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (int q = 1; q < size; ++q) offsets[q] = offsets[q - 1] + counts[q - 1];
  all->resize((size_t)offsets[size - 1] + counts[size - 1]);
  PetscCallMPI(MPI_Allgatherv(mine.data(), count, MPIU_REAL, all->data(), counts.data(), offsets.data(), MPIU_REAL, comm));
  PetscFunctionReturn(0);
}

// The rows of `all` sorted by id (the first value of a row).
static std::vector<PetscReal> ById(const std::vector<PetscReal> &all) {
  const size_t        n = all.size() / kWidth;
  std::vector<size_t> order(n);
  for (size_t k = 0; k < n; ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return all[a * kWidth] < all[b * kWidth]; });
  std::vector<PetscReal> out;
  for (size_t k : order) out.insert(out.end(), &all[k * kWidth], &all[(k + 1) * kWidth]);
  return out;
}

// Ranks per direction of the runs on several ranks (-grid_ranks), so that the particles at the
// bottom of the box lie on every rank; "" lets PETSc choose (1 rank).
static std::string decomposition;

// One run on `comm`: `steps` steps, after loading `loadFrom` if given; saved to `saveTo` if given.
static PetscErrorCode Run(MPI_Comm comm, PetscInt steps, const std::string &loadFrom, const std::string &saveTo, std::vector<PetscReal> *all,
                          vofdem::DemSummary *summary = nullptr) {
  vofdem::Simulation sim;
  PetscViewer        viewer;
  PetscMPIInt        size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  if (size > 1 && !decomposition.empty()) PetscCall(PetscOptionsSetValue(nullptr, "-grid_ranks", decomposition.c_str()));
  else PetscCall(PetscOptionsClearValue(nullptr, "-grid_ranks"));
  PetscCall(sim.Create(comm));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem *dem = Particles(sim);
  if (!loadFrom.empty()) {
    PetscCall(PetscViewerHDF5Open(comm, loadFrom.c_str(), FILE_MODE_READ, &viewer));
    PetscCall(dem->Load(viewer));
    PetscCall(PetscViewerDestroy(&viewer));
  }
  for (PetscInt k = 0; k < steps; ++k) PetscCall(sim.Step());
  if (!saveTo.empty()) {
    PetscCall(PetscViewerHDF5Open(comm, saveTo.c_str(), FILE_MODE_WRITE, &viewer));
    PetscCall(dem->Save(viewer));
    PetscCall(PetscViewerDestroy(&viewer));
  }
  PetscCall(Gather(dem, comm, all));
  if (summary) PetscCall(dem->Summarize(summary));
  PetscCall(sim.Destroy());
  PetscFunctionReturn(0);
}

// Largest difference of columns [c0, c1) between two row sets; positions relative to the box size
// and velocities to the largest speed when `relative`.
static PetscReal MaxDiff(const std::vector<PetscReal> &a, const std::vector<PetscReal> &b, int c0, int c1) {
  if (a.size() != b.size()) return PETSC_MAX_REAL;
  PetscReal d = 0;
  for (size_t k = 0; k < a.size(); ++k)
    if ((int)(k % kWidth) >= c0 && (int)(k % kWidth) < c1) d = std::max(d, std::abs(a[k] - b[k]));
  return d;
}

static PetscErrorCode Main() {
  PetscInt    N = 150, failures = 0, checks = 0;
  PetscMPIInt size, rank;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-half_steps", &N, nullptr));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  decomposition = size == 2 ? "2,1,1" : size == 4 ? "2,2,1" : "";
  auto report = [&](const char *what, PetscReal err, PetscReal tol, bool exact) -> PetscErrorCode {
    PetscFunctionBeginUser;
    const bool bad = exact ? err != 0 : !(err <= tol);
    failures += bad, ++checks;
    if (exact) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: max difference %g (required: exactly 0) %s\n", what, (double)err, bad ? "FAIL" : "ok"));
    else PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: max relative difference %.1e (tolerance %.0e) %s\n", what, (double)err, (double)tol, bad ? "FAIL" : "ok"));
    PetscFunctionReturn(0);
  };
  std::vector<PetscReal> reference, resumed, half;
  vofdem::DemSummary     s;
  PetscCall(Run(PETSC_COMM_WORLD, 2 * N, "", "", &reference, &s));
  const size_t n = reference.size() / kWidth;
  PetscReal    vmax = 0, wmax = 0;
  for (size_t k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c) vmax = std::max(vmax, std::abs(reference[k * kWidth + 4 + c])), wmax = std::max(wmax, std::abs(reference[k * kWidth + 7 + c]));
  // The scene must exercise what is saved: contacts with springs, wall contacts.
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%d particles, %d + %d steps; at the end %d pair and %d wall contacts\n", (int)n, (int)N, (int)N, (int)s.pairContacts,
                        (int)s.wallContacts));
  PetscCall(Run(PETSC_COMM_WORLD, N, "", "ex12-world.h5", &half));
  PetscCall(Run(PETSC_COMM_WORLD, N, "ex12-world.h5", "", &resumed));
  // Unsorted: equal rows mean the same particles in the same memory order on each rank as well.
  PetscCall(report("save at N, load, N more steps vs 2N steps, every field in memory order", MaxDiff(reference, resumed, 0, kWidth), 0, true));

  if (size > 1) {
    // 1-rank runs on rank 0's PETSC_COMM_SELF; the other ranks wait.
    const PetscReal        L = 0.01, tol = 1e-10;
    std::vector<PetscReal> fromWorld, fromSelf;
    if (rank == 0) PetscCall(Run(PETSC_COMM_SELF, N, "ex12-world.h5", "", &fromWorld));
    if (rank == 0) PetscCall(Run(PETSC_COMM_SELF, N, "", "ex12-self.h5", &half));
    PetscCallMPI(MPI_Barrier(PETSC_COMM_WORLD));
    PetscCall(Run(PETSC_COMM_WORLD, N, "ex12-self.h5", "", &fromSelf));
    // As many ranks, cut the other way: Load must notice and migrate and rebuild.
    std::vector<PetscReal> turned;
    decomposition = size == 2 ? "1,2,1" : "1,2,2";
    PetscCall(Run(PETSC_COMM_WORLD, N, "ex12-world.h5", "", &turned));
    PetscReal d[9] = {0};
    if (rank == 0) {
      const auto ref = ById(reference), a = ById(fromWorld), b = ById(fromSelf), c = ById(turned);
      d[0] = MaxDiff(ref, a, 1, 4) / L, d[1] = MaxDiff(ref, a, 4, 7) / vmax, d[2] = MaxDiff(ref, a, 7, kMoving) / wmax;
      d[3] = MaxDiff(ref, b, 1, 4) / L, d[4] = MaxDiff(ref, b, 4, 7) / vmax, d[5] = MaxDiff(ref, b, 7, kMoving) / wmax;
      d[6] = MaxDiff(ref, c, 1, 4) / L, d[7] = MaxDiff(ref, c, 4, 7) / vmax, d[8] = MaxDiff(ref, c, 7, kMoving) / wmax;
    }
    PetscCallMPI(MPI_Bcast(d, 9, MPIU_REAL, 0, PETSC_COMM_WORLD));
    const char *what[3] = {"positions / box size", "velocities / max speed", "angular velocities / max spin"};
    const char *how[3]  = {"multi-rank save loaded on 1 rank", "1-rank save loaded on all ranks", "save loaded on as many ranks cut another way"};
    char        line[160];
    for (int k = 0; k < 9; ++k) {
      std::snprintf(line, sizeof line, "%s, %s", how[k / 3], what[k % 3]);
      PetscCall(report(line, d[k], tol, false));
    }
  }
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d of %d save/load checks\n", (int)failures, (int)checks));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Main());
}

/*TEST
  atol: 1e-11
  args: -physics dem -grid_cells 4,4,4 -grid_upper 0.01,0.01,0.01 -dem_radius 5e-4 -dem_fill_count 200
        -dem_fill_jitter 0.5 -dem_fill_velocity_spread 0.3 -dem_friction 0.4 -dem_rolling epsd -dem_rolling_friction 0.1
        -output_dir ex12-output -dem_output_every 75 -dem_contacts_every 75
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
  test:
    suffix: 4
    nsize: 4
    output_file: output/ex18_save_load_2.out
  test:
    suffix: features_1
    nsize: 1
    args: -dem_types a,b -dem_type_a_material glass -dem_type_b_density 5000 -dem_type_b_restitution 0.8 -grid_periodic x
          -dem_walls lid -dem_wall_lid_type plane -dem_wall_lid_point 0,0,0.009 -dem_wall_lid_normal 0,0,-1 -dem_wall_lid_velocity 0,0,-0.02
          -dem_inserts s -dem_insert_s_lower 0.002,0.002,0.006 -dem_insert_s_upper 0.008,0.008,0.007 -dem_insert_s_rate 100000 -dem_insert_s_type b
  test:
    suffix: features_2
    nsize: 2
    args: -dem_types a,b -dem_type_a_material glass -dem_type_b_density 5000 -dem_type_b_restitution 0.8 -grid_periodic x
          -dem_walls lid -dem_wall_lid_type plane -dem_wall_lid_point 0,0,0.009 -dem_wall_lid_normal 0,0,-1 -dem_wall_lid_velocity 0,0,-0.02
          -dem_inserts s -dem_insert_s_lower 0.002,0.002,0.006 -dem_insert_s_upper 0.008,0.008,0.007 -dem_insert_s_rate 100000 -dem_insert_s_type b
TEST*/
