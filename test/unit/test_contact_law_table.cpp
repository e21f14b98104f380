// The DEM's law tables (ContactLawTable.hpp): every row is found by its name, binds its own values as
// compile-time constants through AtRow (the mechanism Dem::ComputeForces uses to pick its loop), and the
// help and error texts list every row.
#include "vofdem/dem/ContactLawTable.hpp"

#include <gtest/gtest.h>

#include <iterator>

using namespace vofdem;

TEST(ContactLawTable, EveryRowFoundAndBoundByIndex) {
  for (std::size_t k = 0; k < std::size(contact::kRollingLaws); ++k) {
    EXPECT_EQ(contact::Find(contact::kRollingLaws, contact::kRollingLaws[k].name), (int)k);
    // The constant the loop would be instantiated with is the row's own model.
    const hertz::Rolling bound = contact::AtRow<std::size(contact::kRollingLaws)>(k, [](auto row) {
      constexpr hertz::Rolling m = contact::kRollingLaws[decltype(row)::value].model;
      return m;
    });
    EXPECT_EQ(bound, contact::kRollingLaws[k].model);
  }
  for (std::size_t k = 0; k < std::size(contact::kCohesionLaws); ++k) {
    EXPECT_EQ(contact::Find(contact::kCohesionLaws, contact::kCohesionLaws[k].name), (int)k);
    EXPECT_EQ(contact::AtRow<std::size(contact::kCohesionLaws)>(k, [](auto row) { return contact::kCohesionLaws[decltype(row)::value].model; }), contact::kCohesionLaws[k].model);
  }
  for (std::size_t k = 0; k < std::size(contact::kNormalLaws); ++k) {
    EXPECT_EQ(contact::Find(contact::kNormalLaws, contact::kNormalLaws[k].name), (int)k);
    EXPECT_EQ(contact::AtRow<std::size(contact::kNormalLaws)>(k, [](auto row) { return (int)contact::kNormalLaws[decltype(row)::value].linear; }), (int)contact::kNormalLaws[k].linear);
  }
  EXPECT_EQ(contact::Find(contact::kRollingLaws, "epsd3"), -1);
  // Row 0 of each table is the default a scene gets without the option: Hertz, no adhesion, no rolling resistance.
  EXPECT_FALSE(contact::kNormalLaws[0].linear);
  EXPECT_EQ(contact::kCohesionLaws[0].model, kNoCohesion);
  EXPECT_EQ(contact::kRollingLaws[0].model, hertz::Rolling::None);
}

TEST(ContactLawTable, TextsListEveryRow) {
  EXPECT_EQ(contact::Choices(contact::kRollingLaws), "none, cdt, epsd or epsd2");
  EXPECT_EQ(contact::Choices(contact::kNormalLaws), "hertz or linear");
  EXPECT_EQ(contact::Help(contact::kCohesionLaws), "none (no adhesion), jkr (JKR with hysteresis, P6), sjkr (LIGGGHTS' simplified JKR, F = k A), bond (bonded particles, parallel or contact bonds that break (-dem_bond_*), P13)");
  EXPECT_EQ(contact::Names(contact::kRollingLaws).size(), std::size(contact::kRollingLaws));
}
