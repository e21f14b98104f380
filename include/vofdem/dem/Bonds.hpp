// The bonds of -dem_cohesion bond (docs/physics.md (P13)): the options, one history of bond::kWidth values per
// pair of the neighbour list (structure of arrays beside the list's springs; empty without bonds), the
// intact bonds carried by the pair's global ids while the list is rebuilt (as the springs, ContactHistory),
// and the counts the monitor shows. The law itself is BondLaw.hpp; the pair loop (DemContacts.cpp) applies it,
// DemBonds.cpp makes the bonds at -dem_bond_at_time and counts them; HistoryExchange.hpp carries them across ranks.
#pragma once

#include "vofdem/base/Options.hpp"
#include "vofdem/dem/BondLaw.hpp"
#include "vofdem/dem/NeighbourList.hpp"

#include <petscsys.h>

#include <array>
#include <unordered_map>
#include <vector>

namespace vofdem {

using BondHistory = std::unordered_map<PairKey, std::array<PetscReal, bond::kWidth>, PairKeyHash>;

class Bonds {
public:
  // Inside Dem's options block; on: -dem_cohesion bond. A bond law without its strengths is an input error.
  PetscErrorCode SetFromOptions(OptionReader &opt, MPI_Comm comm, bool on, PetscReal radius);  // radius: -dem_radius (the default reach)
  bool             On() const { return on_; }
  const bond::Params &Law() const { return law_; }
  // The gap up to which an intact bond holds (m): the neighbour cut-off includes it (Dem's adhesion range).
  PetscReal Reach() const { return on_ ? reach_ : 0; }
  PetscReal Gap() const { return gap_; }
  PetscReal AtTime() const { return atTime_; }
  // The bonds are made at the first force evaluation at or after -dem_bond_at_time (once).
  bool Due(PetscReal time) const { return on_ && !made_ && time >= atTime_; }
  void SetMade(bool made = true) { made_ = made; }
  bool Made() const { return made_; }
  // Stable step (s) of the lightest sphere (mass m_min) held by 12 bonds of the largest section (spheres of r_max).
  PetscReal StepLimit(PetscReal rMax, PetscReal mMin) const;

  // The list's pairs: their histories (after NeighbourList::Build, from the carried ones; the map is emptied).
  template <class IdOf>
  void Attach(const NeighbourList &list, IdOf idOf) {
    state.assign(on_ ? bond::kWidth * list.Size() : 0, 0);
    for (size_t k = 0; k < list.Size() && !carried.empty(); ++k) {
      const auto it = carried.find({idOf(list.first[k]), idOf(list.second[k])});
      if (it != carried.end()) std::copy(it->second.begin(), it->second.end(), &state[bond::kWidth * k]);
    }
    carried.clear();
  }
  // The intact bonds of the list by id pair (lower id first), before the list is rebuilt.
  template <class IdOf>
  void Collect(const NeighbourList &list, IdOf idOf) {
    for (size_t k = 0; k < state.size() / bond::kWidth; ++k) {
      const PetscReal *h = &state[bond::kWidth * k];
      if (h[bond::kState] != 0) std::copy(h, h + bond::kWidth, carried[{idOf(list.first[k]), idOf(list.second[k])}].begin());
    }
  }
  // Intact bonds of this rank's list: a pair with a ghost counts half (it is in two ranks' lists).
  PetscReal LocalIntact(const NeighbourList &list, PetscInt nLocal) const;

  std::vector<PetscReal> state;    // bond::kWidth per pair of the list
  BondHistory            carried;  // only during Dem::Rebuild() (and after a Load on another rank count)
  PetscReal              brokenHalves = 0;  // bonds broken on this rank, a pair with a ghost counting 1, others 2
  PetscReal              madeHalves   = 0;  // bonds made, counted alike

private:
  bool         on_ = false, made_ = false;
  bond::Params law_{};
  PetscReal    atTime_ = 0, gap_ = 0, reach_ = -1;  // s, m, m
  PetscInt     model_ = 0;                          // 0 parallel, 1 contact
};

}  // namespace vofdem
