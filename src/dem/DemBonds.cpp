// Dem's bonds (docs/physics.md (P13)): made between the close pairs of the list at -dem_bond_at_time, and
// counted for the monitor. The law is BondLaw.hpp, applied in the pair loop (DemContacts.cpp); the histories
// are carried through rebuilds and across ranks like the springs (Bonds.hpp, HistoryExchange.hpp).
#include "vofdem/dem/Dem.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem {

// At SetUp: the lists reach -dem_bond_reach beyond touching (Dem's adhesion range), and the bonds' springs may
// bind the step (Bonds::StepLimit, for the lightest sphere present).
void Dem::SetUpBonds() {
  adhesionRange_ = std::max(adhesionRange_, bonds_.Reach());
  PetscReal rhoMin = PETSC_MAX_REAL;
  for (const DemMaterial &m : types_) rhoMin = std::min(rhoMin, m.density);
  bondStepLimit_ = bonds_.StepLimit(rMax_, rhoMin * 4.0 / 3.0 * PETSC_PI * rMin_ * rMin_ * rMin_);
}

// The banner's line of the bonds (none without -dem_cohesion bond).
PetscErrorCode Dem::ViewBonds(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  if (!bonds_.On()) PetscFunctionReturn(0);
  const bond::Params &b = bonds_.Law();
  PetscCall(PetscViewerASCIIPrintf(viewer, "dem: bonds (P13): %s bonds of radius %g min(r_i, r_j), k_n %g Pa/m, k_s %g Pa/m, strengths %g (tensile), %g (shear) %s; made at t = %g s between pairs closer than %g m, given up beyond a gap of %g m\n",
                                   b.moments ? "parallel" : "contact", (double)b.lambda, (double)b.kn, (double)b.ks, (double)b.tensile, (double)b.shear, b.moments ? "Pa" : "N",
                                   (double)bonds_.AtTime(), (double)bonds_.Gap(), (double)bonds_.Reach()));
  PetscFunctionReturn(0);
}

// After a force evaluation (hot_ holds the positions, ghosts' as their owners'): every pair of the list whose
// gap is below -dem_bond_gap (overlapping ones too) gets a new bond with no force, seen at its normal now.
// A pair with a ghost is made by both ranks alike (same ids, same arithmetic).
void Dem::MakeBonds() {
  const PeriodicImages &images = halo_.Images();
  const PetscInt        n      = (PetscInt)hot_.size() - halo_.Count();
  for (size_t k = 0; k < list_.Size(); ++k) {
    PetscReal *h = &bonds_.state[bond::kWidth * k];
    if (h[bond::kState] != 0) continue;
    const PetscInt   ia = list_.first[k], ib = list_.second[k];
    const PetscReal *xa = hot_[ia].x, *xb = hot_[ib].x, *sh = images.Shift(pairImage_[k]);
    const PetscReal  dx[3] = {(xa[0] - xb[0]) + sh[0], (xa[1] - xb[1]) + sh[1], (xa[2] - xb[2]) + sh[2]};
    const PetscReal  dist = std::sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
    if (!(dist - hot_[ia].r - hot_[ib].r < bonds_.Gap())) continue;
    const PetscReal nrm[3] = {dx[0] / dist, dx[1] / dist, dx[2] / dist};
    bond::Make(nrm, h);
    bonds_.madeHalves += ia < n && ib < n ? 2 : 1;
  }
  bonds_.SetMade();
}

// Collective: the bonds made, intact and broken so far over all ranks, and the largest loads of the intact ones.
PetscErrorCode Dem::SummarizeBonds(DemSummary *s) const {
  PetscFunctionBeginUser;
  s->bonds = (PetscBool)bonds_.On();
  if (!bonds_.On()) PetscFunctionReturn(0);
  PetscInt        n;
  PetscCall(DMSwarmGetLocalSize(swarm_.Dm(), &n));
  const PetscReal halves[3] = {bonds_.madeHalves, bonds_.LocalIntact(list_, n), bonds_.brokenHalves}, loads[2] = {stats_.bondSigma, stats_.bondTau};
  PetscReal       sum[3], max[2];
  PetscCallMPI(MPI_Allreduce(halves, sum, 3, MPIU_REAL, MPIU_SUM, comm_));
  PetscCallMPI(MPI_Allreduce(loads, max, 2, MPIU_REAL, MPIU_MAX, comm_));
  s->bondsMade   = (PetscInt64)std::llround(sum[0] / 2);
  s->bondsIntact = (PetscInt64)std::llround(sum[1] / 2);
  s->bondsBroken = (PetscInt64)std::llround(sum[2] / 2);
  s->bondSigma = max[0], s->bondTau = max[1];
  PetscFunctionReturn(0);
}

}  // namespace vofdem
