// PETSc for the unit tests that need it: started before the first test of the binary (a gtest global
// environment, registered once however many test files include this) and finalised after the last, unless
// something else had started it.
#pragma once

#include <petscsys.h>

#include <gtest/gtest.h>

namespace vofdem::test {

class PetscTestEnvironment : public ::testing::Environment {
public:
  void SetUp() override {
    PetscBool started;
    PetscInitialized(&started);
    if (!started) {
      ASSERT_EQ(PetscInitializeNoArguments(), 0);
      mine_ = true;
    }
  }
  void TearDown() override {
    if (mine_) PetscFinalize();
  }

private:
  bool mine_ = false;
};

[[maybe_unused]] inline ::testing::Environment *const petscTestEnvironment = ::testing::AddGlobalTestEnvironment(new PetscTestEnvironment);

}  // namespace vofdem::test
