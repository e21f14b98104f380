// ContactConduction.hpp: heat through the particles' contacts, docs/physics.md (P11).
#include "vofdem/coupling/ContactConduction.hpp"

#include "vofdem/coupling/HeatExchange.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

PetscErrorCode ContactConduction::Step(MPI_Comm comm, const Dem &dem, const std::vector<ThermalMaterial> &materials, ParticleArrays &a, PetscReal dt, PetscReal *conducted) {
  constexpr int kWidth = 3;  // T, C = m dh/dT, k of each particle
  const PetscInt n = a.n;

  PetscFunctionBeginUser;
  last_ = StepSummary{};
  PetscInt substeps = 1;
  for (PetscInt s = 0; s < substeps; ++s) {
    values_.resize((size_t)kWidth * n);
    for (PetscInt p = 0; p < n; ++p) {
      const ThermalMaterial &m = materials[a.type[p]];
      const PetscReal        T = a.temperature[p];
      values_[kWidth * p] = T, values_[kWidth * p + 1] = a.mass[p] * m.Capacity(T), values_[kWidth * p + 2] = m.k.At(T);
    }
    PetscCall(dem.TouchingPairs(kWidth, values_.data(), &ghost_, &pairs_));
    auto value = [&](PetscInt j, int e) { return j < n ? values_[kWidth * j + e] : ghost_[kWidth * (j - n) + e]; };
    if (s == 0) {  // the sub-steps: dt sum_j G_ij / C_i <= 1/2 for every particle
      load_.assign(n, 0);
      for (const Dem::TouchingPair &c : pairs_) {
        const PetscReal ka = value(c.a, 2), kb = value(c.b, 2), G = 4 * ka * kb / (ka + kb) * std::sqrt(PETSC_PI) * c.contactRadius;
        if (c.a < n) load_[c.a] += G / value(c.a, 1);
        if (c.b < n) load_[c.b] += G / value(c.b, 1);
      }
      PetscReal worst = 0;
      for (PetscInt p = 0; p < n; ++p) worst = std::max(worst, load_[p] * dt);
      PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPIU_REAL, MPIU_MAX, comm));
      substeps = std::max((PetscInt)1, (PetscInt)std::ceil(2 * worst));
      PetscCheck(substeps < 100000, comm, PETSC_ERR_ARG_OUTOFRANGE, "contact conduction: %" PetscInt_FMT " sub-steps in a step of %g s", substeps, (double)dt);
    }
    const PetscReal h = dt / substeps;
    heat_.assign(n, 0);
    PetscReal power = 0, count = 0;
    for (const Dem::TouchingPair &c : pairs_) {
      const PetscReal ka = value(c.a, 2), kb = value(c.b, 2), G = 4 * ka * kb / (ka + kb) * std::sqrt(PETSC_PI) * c.contactRadius;
      const PetscReal inv = 1 / value(c.a, 1) + 1 / value(c.b, 1);
      const PetscReal Q   = (value(c.b, 0) - value(c.a, 0)) * -std::expm1(-G * h * inv) / inv;  // into a
      if (c.a < n) heat_[c.a] += Q;
      if (c.b < n) heat_[c.b] -= Q;
      const PetscReal share = c.a < n && c.b < n ? 1 : 0.5;  // a pair with a ghost is seen by two ranks
      power += share * std::fabs(Q) / dt, count += share;
    }
    for (PetscInt p = 0; p < n; ++p)
      if (heat_[p] != 0) {
        a.enthalpy[p] += heat_[p] / a.mass[p];
        a.temperature[p] = heat::TemperatureOf(materials[a.type[p]], a.enthalpy[p], a.temperature[p]);
        conducted[p] += heat_[p];
      }
    PetscReal sums[2] = {power, count};
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPIU_REAL, MPIU_SUM, comm));
    last_.power += sums[0];
    if (s == 0) last_.contacts = (PetscInt)std::llround(sums[1]);
  }
  last_.substeps = substeps;
  PetscFunctionReturn(0);
}

}  // namespace vofdem
