static const char help[] = "Insertion streams and a deletion box. Source a feeds 20000 particles/s for 5 ms (by number), source b\n"
                           "1e-3 kg/s from 2 to 6 ms (by mass, uniform radii) through a slot that straddles the rank boundary; the\n"
                           "particles fall into a deletion box at the bottom. Checks: a's count is floor(rate x time) exactly at\n"
                           "every check, b's mass is within one particle mass below mass_rate x time, source c (a region too small\n"
                           "for its rate) stops at its end time short of rate x time and inserts nothing owed after it, new ids\n"
                           "continue after the fill's, the books balance: initial + inserted - deleted = present, in number\n"
                           "and in mass, and after every step no centre is inside the deletion box (a particle goes the step it\n"
                           "enters, not at the next neighbour-list rebuild).\n\n";

#include "vofdem/base/Runtime.hpp"
#include "vofdem/sim/ModuleAccess.hpp"
#include "vofdem/examples/Help.hpp"

#include <cmath>

static PetscErrorCode Run() {
  vofdem::Simulation sim;
  PetscInt           failures = 0;

  PetscFunctionBeginUser;
  {
    PetscBool help;
    PetscCall(vofdem::example::Help(&help));  // -help lists the options and runs nothing
    if (help) PetscFunctionReturn(0);
  }
  const char *opts[][2] = {{"-physics", "dem"},
                           {"-grid_cells", "4,4,8"},
                           {"-grid_upper", "0.01,0.01,0.02"},
                           {"-dem_radius", "3e-4"},
                           {"-dem_fill_count", "20"},  // a few particles present from the start: ids 0..19
                           {"-dem_fill_lower", "0,0,0.008"},
                           {"-dem_fill_upper", "0.01,0.01,0.012"},
                           {"-dem_insert_a_lower", "0.002,0.002,0.017"},
                           {"-dem_insert_a_upper", "0.008,0.008,0.018"},
                           {"-dem_insert_a_rate", "20000"},
                           {"-dem_insert_a_end", "0.005"},
                           {"-dem_insert_a_velocity", "0,0,-0.5"},
                           {"-dem_insert_a_velocity_spread", "0.05"},
                           {"-dem_insert_b_lower", "0.002,0.002,0.0185"},
                           {"-dem_insert_b_upper", "0.008,0.008,0.0185"},  // a flat slot
                           {"-dem_insert_b_mass_rate", "1e-3"},
                           {"-dem_insert_b_start", "0.002"},
                           {"-dem_insert_b_end", "0.006"},
                           {"-dem_insert_b_velocity", "0,0,-0.8"},
                           {"-dem_insert_b_size_distribution", "uniform"},
                           {"-dem_insert_b_radius_min", "2e-4"},
                           {"-dem_insert_b_radius_max", "3e-4"},
                           {"-dem_inserts", "a,b,c"},
                           {"-dem_insert_c_lower", "0.0045,0.0045,0.014"},  // room for about one sphere at a time
                           {"-dem_insert_c_upper", "0.0051,0.0051,0.0146"},
                           {"-dem_insert_c_rate", "20000"},
                           {"-dem_insert_c_end", "0.0035"},
                           {"-dem_insert_c_velocity", "0,0,-0.5"},
                           {"-dem_delete_boxes", "0,0,0,0.01,0.01,0.003"}};
  for (auto &o : opts) PetscCall(PetscOptionsSetValue(nullptr, o[0], o[1]));
  PetscCall(sim.Create(PETSC_COMM_WORLD));
  PetscCall(sim.SetFromOptions());
  PetscCall(sim.SetUp());
  vofdem::Dem     *dem = Particles(sim);
  vofdem::DemSummary s0;
  PetscCall(dem->Summarize(&s0));
  const PetscReal rho = dem->Material().density, mass = 4.0 / 3.0 * PETSC_PI * rho;  // times r^3
  const PetscReal mMaxB = mass * 2.7e-11;                                              // heaviest of source b
  PetscReal       next  = 0.001;
  PetscInt64      heldC = -1;  // c's count at the first check after its end
  PetscInt        lingered = 0, stepsInBox = 0;  // centres inside the deletion box after a step, summed; steps with any
  while (sim.Time() < 0.03) {
    PetscCall(sim.Step());
    {
      vofdem::ParticleArrays a;
      PetscInt               in = 0, all;
      PetscCall(dem->Particles().GetArrays(&a));
      for (PetscInt p = 0; p < a.n; ++p) in += a.x[3 * p + 2] <= 0.003;  // the box spans the whole x and y
      PetscCall(dem->Particles().RestoreArrays(&a));
      PetscCallMPI(MPI_Allreduce(&in, &all, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
      lingered += all, stepsInBox += all > 0;
    }
    if (sim.Time() < next && sim.Time() < 0.03) continue;
    next += 0.003;
    vofdem::DemSummary s;
    PetscCall(dem->Summarize(&s));
    const auto     &src = dem->Sources().Sources();
    const PetscReal t = sim.Time();
    const PetscInt64 wantA = (PetscInt64)std::floor(20000 * (std::min(t, 0.005)));
    const PetscReal  owedB = 1e-3 * std::max(0.0, std::min(t, 0.006) - 0.002);
    const bool okA = src[0].count == wantA, okB = src[1].mass <= owedB && owedB - src[1].mass < mMaxB;
    if (t > 0.0035 && heldC < 0) heldC = src[2].count;
    const PetscInt64 dueC = (PetscInt64)std::floor(20000 * std::min(t, 0.0035));
    const bool       okC  = src[2].count > 0 && src[2].count < dueC && (heldC < 0 || src[2].count == heldC);
    const bool books = s0.particles + s.inserted - s.deleted == s.particles &&
                       std::fabs(s0.mass + s.massInserted - s.massDeleted - s.mass) <= 1e-12 * (s0.mass + s.massInserted);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "t %.4f s: a %d (floor(rate t) = %d) %s; b %d particles, %.6e kg (owed %.6e kg, short by less than %.3e kg) %s; c %d of %d %s; present %d = %d + %d - %d, mass %.6e kg %s\n",
                          (double)t, (int)src[0].count, (int)wantA, okA ? "ok" : "FAIL", (int)src[1].count, (double)src[1].mass, (double)owedB,
                          (double)mMaxB, okB ? "ok" : "FAIL", (int)src[2].count, (int)dueC, okC ? "ok" : "FAIL", (int)s.particles, (int)s0.particles, (int)s.inserted, (int)s.deleted, (double)s.mass,
                          books ? "ok" : "FAIL"));
    failures += !okA + !okB + !okC + !books;
  }
  // Ids: the fill's 0..19, then one new id per insertion, none twice.
  vofdem::DemSummary s;
  PetscCall(dem->Summarize(&s));
  PetscReal x[3], v[3];
  PetscBool foundLast, foundNext;
  PetscCall(dem->FindParticle(s0.particles + s.inserted - 1, x, v, &foundLast));
  PetscCall(dem->FindParticle(s0.particles + s.inserted, x, v, &foundNext));
  const bool gone = s.deleted > 0;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "deleted %d (some: %s); mass flow a+b %.6e kg over 6 ms; last id %d %s, no id %d: %s\n", (int)s.deleted,
                        gone ? "yes" : "no", (double)s.massInserted, (int)(s0.particles + s.inserted - 1), foundLast ? "present" : "deleted",
                        (int)(s0.particles + s.inserted), foundNext ? "FAIL" : "ok"));
  failures += !gone + (foundNext == PETSC_TRUE);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "centres left inside the deletion box after a step: %d (in %d steps) %s\n", (int)lingered, (int)stepsInBox, lingered ? "FAIL" : "ok"));
  failures += lingered > 0;
  PetscCall(sim.Destroy());
  if (failures) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "FAILED: %d checks\n", (int)failures));
  PetscFunctionReturn(failures ? PETSC_ERR_NOT_CONVERGED : 0);
}

int main(int argc, char **argv) {
  if (int code = vofdem::Initialize(&argc, &argv, help)) return code;
  return vofdem::Finalize(Run());
}

/*TEST
  rtol: 1e-8
  test:
    suffix: 1
    nsize: 1
  test:
    suffix: 2
    nsize: 2
    args: -grid_ranks 2,1,1
    output_file: output/ex10_insertion_stream_1.out
TEST*/
