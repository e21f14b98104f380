// ParticleMelt.hpp: melted particles into the melt (docs/physics.md P12).
#include "vofdem/coupling/ParticleMelt.hpp"

#include "vofdem/base/Runtime.hpp"
#include "vofdem/grid/FaceMass.hpp"

#include <petscdmda.h>

#include <algorithm>
#include <cmath>

namespace vofdem {

PetscErrorCode ParticleMelt::SetUp(Coupling &coupling, Flow &flow, Vof &vof, Dem &dem, Energy &energy, const std::vector<ThermalMaterial> &particles) {
  PetscFunctionBeginUser;
  coupling_ = &coupling, flow_ = &flow, vof_ = &vof, dem_ = &dem, energy_ = &energy, materials_ = particles;
  const StaggeredGrid &sg = flow.Staggered();
  for (Vec *v : {&volume_, &enthalpy_, &kernel_, &before_, &gas_}) PetscCall(DMCreateGlobalVector(sg.Cells(), v));
  for (int d = 0; d < 3; ++d) {
    PetscCall(DMCreateGlobalVector(sg.Face(d), &massBefore_[d]));
    PetscCall(VecDuplicate(massBefore_[d], &massAfter_[d]));
    PetscCall(VecDuplicate(massBefore_[d], &momentum_[d]));
  }
  PetscCall(DMCreateLocalVector(sg.Cells(), &cellLocal_));
  PetscCall(VecDuplicate(cellLocal_, &rhoLocal_));
  PetscFunctionReturn(0);
}

bool ParticleMelt::MeltsAt(PetscReal T, PetscInt type) const {
  const ThermalMaterial &m = materials_[type];
  if (m.melt == MeltLaw::Erf) return m.MeltFraction(T) >= 1 - 1e-3;
  return T >= m.liquidus;
}

// (eps rho)_f V of each owned face, the flow's definition (FaceAverage); 0 on the walls (their velocity is set).
PetscErrorCode ParticleMelt::FaceMasses(Vec M[3]) {
  const StaggeredGrid &sg = flow_->Staggered();
  const PetscReal     *h  = sg.Base().Spacing();
  const PetscReal      V  = h[0] * h[1] * h[2];
  LocalField           eps, rho;

  PetscFunctionBeginUser;
  PetscCall(DMGlobalToLocal(sg.Cells(), flow_->FluidFraction(), INSERT_VALUES, cellLocal_));
  PetscCall(DMGlobalToLocal(sg.Cells(), flow_->Density(), INSERT_VALUES, rhoLocal_));
  PetscCall(sg.GetLocal(3, cellLocal_, &eps));
  PetscCall(sg.GetLocal(3, rhoLocal_, &rho));
  for (int d = 0; d < 3; ++d) PetscCall(FaceMass(sg, d, eps, rho, V, M[d]));
  PetscCall(sg.RestoreLocal(3, rhoLocal_, &rho));
  PetscCall(sg.RestoreLocal(3, cellLocal_, &eps));
  PetscFunctionReturn(0);
}

// Every rank walks the same lattice of every melted sphere (samples_ per cell edge, centred in their sub-cells) and
// keeps the owned cells' and faces' counts; the shares are count / (the sphere's samples inside the box).
PetscErrorCode ParticleMelt::Share(const std::vector<Melted> &all) {
  const StaggeredGrid &sg = flow_->Staggered();
  const Grid          &g  = sg.Base();
  const PetscReal     *h = g.Spacing(), *lo = g.Lower();
  const PetscInt      *N = g.Cells();
  const PetscInt       ns = samples_;
  const PetscReal      rhoM = vof_->Density();
  LocalField           Vf, Hf, Af;
  PetscInt             cs[3], cn[3], fs[3][3], fn[3][3];

  PetscFunctionBeginUser;
  PetscCall(sg.GetGlobal(3, volume_, &Vf));
  PetscCall(sg.GetGlobal(3, enthalpy_, &Hf));
  PetscCall(VecCopy(vof_->Fraction(), gas_));  // alpha before the conversion (gas_ is free until step 3 of Melt)
  PetscCall(sg.GetGlobal(3, gas_, &Af));
  around_.assign(all.size(), 0);
  sg.Owned(3, cs, cn);
  for (int d = 0; d < 3; ++d) sg.Owned(d, fs[d], fn[d]);
  faces_.assign(all.size(), {});
  auto owned = [](const PetscInt q[3], const PetscInt *s, const PetscInt *n) {
    for (int e = 0; e < 3; ++e)
      if (q[e] < s[e] || q[e] >= s[e] + n[e]) return false;
    return true;
  };
  for (size_t pi = 0; pi < all.size(); ++pi) {
    const Melted &p = all[pi];
    PetscInt I0[3], I1[3];  // the sub-grid's index range (global, may leave the box: wrapped or dropped below)
    for (int d = 0; d < 3; ++d) {
      const PetscReal sh = h[d] / ns;
      I0[d] = (PetscInt)std::floor((p.x[d] - p.r - lo[d]) / sh), I1[d] = (PetscInt)std::ceil((p.x[d] + p.r - lo[d]) / sh);
      if (!g.Periodic(d)) I0[d] = std::max(I0[d], (PetscInt)0), I1[d] = std::min(I1[d], N[d] * ns);
    }
    // Pass 0 counts the samples inside (the normaliser), pass 1 shares.
    PetscReal total = 0;
    for (int pass = 0; pass < 2; ++pass)
      for (PetscInt K = I0[2]; K < I1[2]; ++K)
        for (PetscInt J = I0[1]; J < I1[1]; ++J)
          for (PetscInt I = I0[0]; I < I1[0]; ++I) {
            const PetscInt  S[3] = {I, J, K};
            PetscReal       r2   = 0;
            for (int d = 0; d < 3; ++d) {
              const PetscReal x = lo[d] + (S[d] + 0.5) * h[d] / ns - p.x[d];
              r2 += x * x;
            }
            if (r2 > p.r * p.r) continue;
            if (pass == 0) {
              total += 1;
              continue;
            }
            const PetscReal w = 1 / total;
            PetscInt        c[3];
            for (int d = 0; d < 3; ++d) {
              c[d] = (S[d] >= 0 ? S[d] / ns : -((-S[d] + ns - 1) / ns));  // floor division
              if (g.Periodic(d)) c[d] = ((c[d] % N[d]) + N[d]) % N[d];
            }
            if (owned(c, cs, cn)) Vf.at(c) += w * p.m / rhoM, Hf.at(c) += w * p.m * p.h, around_[pi] += w * Af.at(c);
            for (int d = 0; d < 3; ++d) {  // the face whose control volume holds the sample: floor(S/ns + 1/2)
              PetscInt f[3] = {c[0], c[1], c[2]};
              const PetscInt two = 2 * S[d] + 1 + ns;  // the sample's centre plus half a cell, in half samples
              f[d] = two >= 0 ? two / (2 * ns) : -((-two + 2 * ns - 1) / (2 * ns));
              if (g.Periodic(d)) f[d] = ((f[d] % N[d]) + N[d]) % N[d];
              else f[d] = std::min(std::max(f[d], (PetscInt)1), N[d] - 1);  // interior faces only (walls hold their velocity)
              if (owned(f, fs[d], fn[d])) faces_[pi].push_back({(PetscInt)d, f[0], f[1], f[2]});
            }
          }
    std::sort(faces_[pi].begin(), faces_[pi].end());
    faces_[pi].erase(std::unique(faces_[pi].begin(), faces_[pi].end()), faces_[pi].end());
  }
  PetscCall(sg.RestoreGlobal(3, gas_, &Af));
  PetscCall(sg.RestoreGlobal(3, enthalpy_, &Hf));
  PetscCall(sg.RestoreGlobal(3, volume_, &Vf));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, around_.data(), (PetscMPIInt)around_.size(), MPIU_REAL, MPIU_SUM, g.Comm()));
  PetscFunctionReturn(0);
}

// Each particle's momentum m v to the faces its sphere reaches, in proportion to the mass each gained, max(M' - M, 0)
// (the flow's face masses): the faces' velocities become mass averages of u and v, and the fluid's momentum grows by
// m v exactly. A particle whose faces gained nothing (not met in practice) shares by its faces' count.
PetscErrorCode ParticleMelt::ShareMomentum(const std::vector<Melted> &all) {
  const StaggeredGrid &sg = flow_->Staggered();
  LocalField           Mb[3], Ma[3], P[3];
  MPI_Comm             comm = sg.Base().Comm();

  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) {
    PetscCall(sg.GetGlobal(d, massBefore_[d], &Mb[d]));
    PetscCall(sg.GetGlobal(d, massAfter_[d], &Ma[d]));
    PetscCall(sg.GetGlobal(d, momentum_[d], &P[d]));
  }
  std::vector<PetscReal> sums(6 * all.size(), 0);  // per particle and component: gained mass, faces
  auto gain = [&](const std::array<PetscInt, 4> &f) {
    const PetscInt q[3] = {f[1], f[2], f[3]};
    return std::max((PetscReal)0, PetscRealPart(Ma[f[0]].at(q)) - PetscRealPart(Mb[f[0]].at(q)));
  };
  for (size_t p = 0; p < all.size(); ++p)
    for (const auto &f : faces_[p]) {
      const PetscInt q[3] = {f[1], f[2], f[3]};
      if (PetscRealPart(Ma[f[0]].at(q)) > 0) sums[6 * p + 2 * f[0]] += gain(f), sums[6 * p + 2 * f[0] + 1] += 1;
    }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums.data(), (int)sums.size(), MPIU_REAL, MPI_SUM, comm));
  for (size_t p = 0; p < all.size(); ++p)
    for (const auto &f : faces_[p]) {
      const PetscInt q[3] = {f[1], f[2], f[3]};
      if (!(PetscRealPart(Ma[f[0]].at(q)) > 0)) continue;
      const PetscReal *sum = &sums[6 * p + 2 * f[0]];
      const PetscReal  w   = sum[0] > 0 ? gain(f) / sum[0] : 1 / sum[1];
      P[f[0]].at(q) += w * all[p].m * all[p].v[f[0]];
    }
  for (int d = 0; d < 3; ++d) {
    PetscCall(sg.RestoreGlobal(d, momentum_[d], &P[d]));
    PetscCall(sg.RestoreGlobal(d, massAfter_[d], &Ma[d]));
    PetscCall(sg.RestoreGlobal(d, massBefore_[d], &Mb[d]));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleMelt::OpenLog(const std::string &dir, bool restarting) {
  PetscMPIInt rank;
  int         ok = 1;

  PetscFunctionBeginUser;
  MPI_Comm comm = flow_->Staggered().Base().Comm();
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    const std::string path = dir + "/melted_particles.csv";
    FILE             *old  = restarting ? std::fopen(path.c_str(), "r") : nullptr;
    if (old) std::fclose(old);
    log_ = std::fopen(path.c_str(), old ? "a" : "w");
    ok   = log_ != nullptr;
    if (log_ && !old)
      std::fprintf(log_, "time_s,id,type,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,radius_m,mass_kg,temperature_K,metal_around,absorbed_J,exchanged_J,conducted_J,enthalpy_change_J,sensible_J,latent_J,account_error,spin_energy_J\n");
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  if (!ok) VofdemInputError(comm, "option -output_dir: cannot write melted_particles.csv in '%s'", dir.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleMelt::WriteLog(const std::vector<Melted> &all, PetscReal time, const std::vector<PetscReal> &T0) {
  PetscFunctionBeginUser;
  if (!log_) PetscFunctionReturn(0);
  for (size_t k = 0; k < all.size(); ++k) {
    const Melted          &p  = all[k];
    const ThermalMaterial &mt = materials_[(size_t)p.type];
    const PetscReal        h0 = mt.Enthalpy(T0[(size_t)p.type]);
    const PetscReal latent = p.m * mt.latentHeat * mt.MeltFraction(p.T), change = p.m * (p.h - h0);
    const PetscReal error  = std::fabs(change - p.absorbed + p.exchanged - p.conducted) / std::max(std::fabs(p.m * p.h), (PetscReal)PETSC_MIN_REAL);
    const PetscReal spin   = 0.2 * p.m * p.r * p.r * (p.w[0] * p.w[0] + p.w[1] * p.w[1] + p.w[2] * p.w[2]);
    std::fprintf(log_, "%.10e,%lld,%d,%.10e,%.10e,%.10e,%.8e,%.8e,%.8e,%.8e,%.8e,%.8f,%.6e,%.12e,%.12e,%.12e,%.12e,%.12e,%.12e,%.3e,%.6e\n", (double)time, (long long)p.id, (int)p.type, (double)p.x[0],
                 (double)p.x[1], (double)p.x[2], (double)p.v[0], (double)p.v[1], (double)p.v[2], (double)p.r, (double)p.m, (double)p.T, (double)around_[k], (double)p.absorbed,
                 (double)p.exchanged, (double)p.conducted, (double)change, (double)(change - latent), (double)latent, (double)error, (double)spin);
  }
  std::fflush(log_);  // a run killed now loses none of it
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleMelt::Melt(PetscReal time, const std::vector<PetscReal> &T0) {
  ParticleArrays a;
  MPI_Comm       comm = flow_->Staggered().Base().Comm();

  PetscFunctionBeginUser;
  // 1. Who melts: this rank's, then everyone's.
  const ParticleSwarm  &sw = dem_->Particles();
  std::vector<PetscInt> local;
  std::vector<Melted>   mine;
  std::vector<PetscReal> H, vol, xs;
  PetscCall(sw.GetArrays(&a));
  for (PetscInt p = 0; p < a.n; ++p)
    if (a.temperature[p] > 0 && MeltsAt(a.temperature[p], a.type[p])) {
      local.push_back(p);
      Melted m;
      for (int d = 0; d < 3; ++d) m.x[d] = a.x[3 * p + d], m.v[d] = a.v[3 * p + d], m.w[d] = a.omega[3 * p + d];
      m.r = a.radius[p], m.m = a.mass[p], m.h = a.enthalpy[p], m.T = a.temperature[p], m.id = (PetscReal)a.id[p];
      m.absorbed = a.heatAbsorbed[p], m.exchanged = a.heatExchanged[p], m.conducted = a.heatConducted[p], m.type = (PetscReal)a.type[p];
      mine.push_back(m);
      H.push_back(coupling_->KernelWidth(2 * m.r));
      vol.push_back(4.0 / 3.0 * PETSC_PI * m.r * m.r * m.r);
      xs.insert(xs.end(), m.x, m.x + 3);
    }
  PetscCall(sw.RestoreArrays(&a));
  const int   width = (int)(sizeof(Melted) / sizeof(PetscReal));
  PetscMPIInt count = (PetscMPIInt)(mine.size() * width), size;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), offsets(size, 0);
  PetscCallMPI(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  const PetscMPIInt totalReals = offsets[size - 1] + counts[size - 1];
  if (totalReals == 0) PetscFunctionReturn(0);
  std::vector<Melted> all((size_t)totalReals / width);
  PetscCallMPI(MPI_Allgatherv(mine.data(), count, MPIU_REAL, all.data(), counts.data(), offsets.data(), MPIU_REAL, comm));
  // The books before: metal volume, energy of the cells and particles, the faces' momentum.
  const StaggeredGrid &sg = flow_->Staggered();
  const PetscReal     *h  = sg.Base().Spacing();
  const PetscReal      V  = h[0] * h[1] * h[2];
  Vec                  eps = flow_->FluidFraction();
  PetscReal            metal0, melt[3] = {0, 0, 0}, meltP[3] = {0, 0, 0}, spin = 0, energy0, p0[3] = {0, 0, 0};
  for (const Melted &m : all) {
    melt[0] += m.m / vof_->Density(), melt[1] += m.m * m.h, melt[2] += m.m;
    for (int d = 0; d < 3; ++d) meltP[d] += m.m * m.v[d];
    spin += 0.5 * 0.4 * m.m * m.r * m.r * (m.w[0] * m.w[0] + m.w[1] * m.w[1] + m.w[2] * m.w[2]);
  }
  PetscCall(VecCopy(eps, before_));  // between steps: alpha is relative to the flow's eps
  PetscCall(VecDot(before_, vof_->Fraction(), &metal0));
  {
    EnergySummary es;
    PetscCall(energy_->Summarize(&es));  // cells and particles
    energy0 = es.total;
  }
  PetscCall(FaceMasses(massBefore_));
  for (int d = 0; d < 3; ++d) PetscCall(VecDot(massBefore_[d], flow_->Velocity(d), &p0[d]));
  // 2. The shares, the kernel volume given back.
  for (Vec v : {volume_, enthalpy_, kernel_}) PetscCall(VecSet(v, 0));
  for (int d = 0; d < 3; ++d) PetscCall(VecSet(momentum_[d], 0));
  PetscCall(Share(all));
  PetscCall(coupling_->Averager().Deposit(3, (PetscInt)mine.size(), xs.data(), H.data(), vol.data(), 1, kernel_));
  // 3. eps (both levels), alpha, the gas moved, the enthalpy.
  PetscCall(VecAXPY(eps, 1 / V, kernel_));
  PetscCall(VecWAXPY(gas_, -1, volume_, kernel_));  // m^3 of gas each cell gains (the freed kernel volume less the metal)
  Vec after;
  PetscCall(VecDuplicate(before_, &after));
  PetscCall(VecWAXPY(after, 1 / V, kernel_, before_));
  PetscCall(vof_->AddPhaseVolume(volume_, before_, after));
  PetscCall(energy_->AddEnthalpy(enthalpy_, gas_));
  PetscCall(vof_->BoundAt(after));  // the excess of alpha over 1 to neighbours, the energy with it
  PetscCall(vof_->UpdateProperties(*flow_));  // rho from the new alpha (and PropertiesChanged)
  // 4. The momentum: u' = (M u + dp)/M' on every owned interior face.
  PetscCall(FaceMasses(massAfter_));
  PetscCall(ShareMomentum(all));
  PetscReal p1[3];
  for (int d = 0; d < 3; ++d) {
    PetscScalar       *u;
    const PetscScalar *Mb, *Ma, *dp;
    PetscInt           n;
    PetscCall(VecGetLocalSize(flow_->Velocity(d), &n));
    PetscCall(VecGetArray(flow_->Velocity(d), &u));
    PetscCall(VecGetArrayRead(massBefore_[d], &Mb));
    PetscCall(VecGetArrayRead(massAfter_[d], &Ma));
    PetscCall(VecGetArrayRead(momentum_[d], &dp));
    for (PetscInt i = 0; i < n; ++i)
      if (PetscRealPart(Ma[i]) > 0 && (dp[i] != 0 || Ma[i] != Mb[i])) u[i] = (Mb[i] * u[i] + dp[i]) / Ma[i];
    PetscCall(VecRestoreArrayRead(momentum_[d], &dp));
    PetscCall(VecRestoreArrayRead(massAfter_[d], &Ma));
    PetscCall(VecRestoreArrayRead(massBefore_[d], &Mb));
    PetscCall(VecRestoreArray(flow_->Velocity(d), &u));
    PetscCall(VecDot(massAfter_[d], flow_->Velocity(d), &p1[d]));
  }
  // 5. Out of the swarm, through the deletion books.
  PetscCall(dem_->RemoveParticles(local));
  // 6. The books after.
  PetscReal metal1, energy1;
  PetscCall(VecDot(after, vof_->Fraction(), &metal1));
  PetscCall(VecDestroy(&after));
  {
    EnergySummary es;
    PetscCall(energy_->Summarize(&es));
    energy1 = es.total;
  }
  PetscReal pnorm = 0, perr = 0;
  for (int d = 0; d < 3; ++d) pnorm += std::fabs(p0[d]) + std::fabs(meltP[d]), perr = std::max(perr, std::fabs(p1[d] - p0[d] - meltP[d]));
  summary_.volumeError   = std::fabs((metal1 - metal0) * V - melt[0]) / std::max(metal1 * V, melt[0]);
  summary_.energyError   = std::fabs(energy1 - energy0) / std::max(std::fabs(energy0), std::fabs(melt[1]));
  summary_.momentumError = pnorm > 0 ? perr / pnorm : 0;
  summary_.melted += (PetscInt64)all.size(), summary_.mass += melt[2], summary_.spin += spin;
  PetscCall(WriteLog(all, time, T0));
  if (summary_.volumeError > 1e-12 || summary_.energyError > 1e-12 || summary_.momentumError > 1e-12)
    VofdemInputError(comm, "coupling: melting %d particle(s) broke the books (physics.md P12): metal volume %.2e, energy %.2e, momentum %.2e (relative; tolerance 1e-12)", (int)all.size(),
                     (double)summary_.volumeError, (double)summary_.energyError, (double)summary_.momentumError);
  PetscFunctionReturn(0);
}

PetscErrorCode ParticleMelt::Destroy() {
  PetscFunctionBeginUser;
  if (log_) std::fclose(log_);
  log_ = nullptr;
  for (Vec *v : {&volume_, &enthalpy_, &kernel_, &before_, &gas_, &cellLocal_, &rhoLocal_}) PetscCall(VecDestroy(v));
  for (int d = 0; d < 3; ++d) {
    PetscCall(VecDestroy(&massBefore_[d]));
    PetscCall(VecDestroy(&massAfter_[d]));
    PetscCall(VecDestroy(&momentum_[d]));
  }
  PetscFunctionReturn(0);
}

}  // namespace vofdem
