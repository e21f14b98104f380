// Energy.hpp: the cells' properties at the state (T, f): E, the apparent capacity C, the melt fraction's
// linearisation and k (docs/physics.md F3, F7).
#include "vofdem/energy/Energy.hpp"

#include <petscdmda.h>
#include <petsc/private/petscimpl.h>  // PetscObjectStateGet: alpha_'s state, the key of k

#include <algorithm>
#include <cstring>

namespace vofdem {

namespace {

inline bool SameBits(PetscReal a, PetscReal b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A phase's properties as the cell formulas below read them: from its tables (TablePhase), or, when every table
// holds one value, copied into locals (ConstantPhase: Properties' loop keeps them in registers). The same arithmetic:
// PropertyTable's one-value At is v[0], its Integral(a, b) v[0] (b - a).
struct TablePhase {
  const ThermalMaterial &m;
  PetscReal              Density() const { return m.density; }
  PetscReal              Latent() const { return m.latentHeat; }
  PetscReal              Sensible(PetscReal T) const { return m.Sensible(T); }
  PetscReal              Cp(PetscReal T) const { return m.cp.At(T); }
  PetscReal              K(PetscReal T) const { return m.k.At(T); }
};
struct ConstantPhase {
  PetscReal density, latent, cp, k, reference;
  explicit ConstantPhase(const ThermalMaterial &m) : density(m.density), latent(m.latentHeat), cp(m.cp.v[0]), k(m.k.v[0]), reference(m.referenceTemperature) {}
  PetscReal Density() const { return density; }
  PetscReal Latent() const { return latent; }
  PetscReal Sensible(PetscReal T) const { return cp * (T - reference); }
  PetscReal Cp(PetscReal) const { return cp; }
  PetscReal K(PetscReal) const { return k; }
};

// Per volume of fluid: alpha rho_m (int cp_m dT + L f) + (1 - alpha) rho_g int cp_g dT, f the metal's melt fraction
// (the state; f = f_l(T) once a step has converged); the cells hold eps times it (Properties).
template <class Phase>
PetscReal CellEnergyOf(const Phase &m, const Phase &g, PetscReal a, PetscReal T, PetscReal f) {
  return a * m.Density() * (m.Sensible(T) + m.Latent() * f) + (1 - a) * g.Density() * g.Sensible(T);
}
template <class Phase>
PetscReal CellSensibleCapacityOf(const Phase &m, const Phase &g, PetscReal a, PetscReal T) {
  return a * m.Density() * m.Cp(T) + (1 - a) * g.Density() * g.Cp(T);
}
template <class Phase>
PetscReal CellConductivityOf(const Phase &m, const Phase &g, PetscReal a, PetscReal T) {
  return a * m.K(T) + (1 - a) * g.K(T);
}
}  // namespace

PetscReal Energy::CellEnergy(PetscReal a, PetscReal T, PetscReal f) const { return CellEnergyOf(TablePhase{metal_}, TablePhase{gas_}, a, T, f); }
PetscReal Energy::CellSensibleCapacity(PetscReal a, PetscReal T) const { return CellSensibleCapacityOf(TablePhase{metal_}, TablePhase{gas_}, a, T); }
PetscReal Energy::CellConductivity(PetscReal a, PetscReal T) const { return CellConductivityOf(TablePhase{metal_}, TablePhase{gas_}, a, T); }

// The linearisation of the melt fraction about the state (T, f) (Voller and Swaminathan): f = f^k + F' (T - T_F),
// T_F = F^{-1}(f^k). A cell consistently solid (f = 0, T <= T_s) or liquid (f = 1, T >= T_l) has F' = 0; any other
// (in the mushy range, or one that crossed the solidus or liquidus in the last iteration) the law's slope at T_F.
PetscReal Energy::LatentSlope(PetscReal T, PetscReal f, PetscReal *TF) const {
  const ThermalMaterial &m = metal_;
  if (m.melt == MeltLaw::Linear) {
    if ((f <= 0 && T <= m.solidus) || (f >= 1 && T >= m.liquidus)) return *TF = T, 0;
    *TF = m.MeltInverse(std::min((PetscReal)1, std::max((PetscReal)0, f)));
    return 1 / (m.liquidus - m.solidus);
  }
  const PetscReal fc = std::min(1 - 1e-15, std::max((PetscReal)1e-300, f));
  *TF                = m.MeltInverse(fc);
  return m.MeltSlope(*TF);
}

// The cells' properties at the state (T, f). k depends on T only through tables: with constant conductivities and
// alpha unchanged since the last fill (no interface, or no sweep since), k_ and kLocal_ are left as they are, so that
// the face conductances (Residual) and the Jacobian (Assemble) that depend on them are kept too. C is written where
// its bits change only, and capacityVersion_ counts the calls that changed one (Assemble's key).
PetscErrorCode Energy::Properties() {
  const PetscScalar *T, *F, *al, *ep;
  PetscScalar       *E, *C, *k = nullptr, *S, *TF;
  PetscInt           n;
  PetscObjectState   alphaState;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(evProperties_, 0, 0, 0, 0));
  cacheValid_ = false;  // Residual fills or confirms the face conductances of the new state
  PetscCall(PetscObjectStateGet((PetscObject)alpha_, &alphaState));
  const bool kFixed = metal_.k.Constant() && gas_.k.Constant();
  const bool kFill  = !(kFixed && kFilled_ && alphaState == kAlphaState_);
  PetscCall(VecGetLocalSize(T_, &n));
  PetscCall(VecGetArrayRead(epsCells_, &ep));
  PetscCall(VecGetArrayRead(T_, &T));
  PetscCall(VecGetArrayRead(F_, &F));
  PetscCall(VecGetArrayRead(alpha_, &al));
  PetscCall(VecGetArray(Ecur_, &E));
  PetscCall(VecGetArray(slope_, &S));
  PetscCall(VecGetArray(TF_, &TF));
  PetscCall(VecGetArray(C_, &C));  // the state of C_ moves with each write access: capacityVersion_ is the key
  if (kFill) PetscCall(VecGetArray(k_, &k));
  const bool      linear = metal_.melt == MeltLaw::Linear;
  const PetscReal Ts = metal_.solidus, Tl = metal_.liquidus;
  bool            changed = false;
  // The outputs alias nothing else the loop reads.
  PetscScalar *__restrict Eo = E, *__restrict Co = C, *__restrict So = S, *__restrict TFo = TF, *__restrict ko = k;
  auto cells = [&](const auto &m, const auto &g) {
    for (PetscInt i = 0; i < n; ++i) {
      const PetscReal a = al[i], t = T[i], f = F[i], e = ep[i];
      PetscReal       tf = t, slope = 0;
      Eo[i] = e * CellEnergyOf(m, g, a, t, f);  // per cell volume: the fluid's share eps
      // LatentSlope's consistently solid or liquid cell of the linear law, F' = 0 and T_F = T, decided here
      if (a > 0 && !(linear && ((f <= 0 && t <= Ts) || (f >= 1 && t >= Tl)))) slope = LatentSlope(t, f, &tf);
      So[i]  = slope;
      TFo[i] = tf;
      const PetscReal c = e * (CellSensibleCapacityOf(m, g, a, t) + a * m.Density() * m.Latent() * slope);
      if (!SameBits(c, Co[i])) Co[i] = c, changed = true;
      if (kFill) ko[i] = CellConductivityOf(m, g, a, t);
    }
  };
  if (metal_.cp.Constant() && gas_.cp.Constant() && kFixed) cells(ConstantPhase(metal_), ConstantPhase(gas_));
  else cells(TablePhase{metal_}, TablePhase{gas_});
  if (kFill) PetscCall(VecRestoreArray(k_, &k));
  PetscCall(VecRestoreArray(C_, &C));
  PetscCall(VecRestoreArray(TF_, &TF));
  PetscCall(VecRestoreArray(slope_, &S));
  PetscCall(VecRestoreArray(Ecur_, &E));
  PetscCall(VecRestoreArrayRead(alpha_, &al));
  PetscCall(VecRestoreArrayRead(F_, &F));
  PetscCall(VecRestoreArrayRead(T_, &T));
  PetscCall(VecRestoreArrayRead(epsCells_, &ep));
  if (changed) ++capacityVersion_;  // this rank's (Assemble agrees over the ranks)
  if (kFill) {
    PetscCall(DMGlobalToLocal(dm_, k_, INSERT_VALUES, kLocal_));
    kFilled_ = true, kAlphaState_ = alphaState;
  }
  PetscCall(DMGlobalToLocal(dm_, T_, INSERT_VALUES, TLocal_));
  PetscCall(PetscLogEventEnd(evProperties_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
