// The checkpoint's scene comparison (CheckpointFile.hpp, FirstDifference): option lists as
// RunDefiningOptions writes them (sorted "-name value" lines).
#include "vofdem/sim/CheckpointFile.hpp"

#include <gtest/gtest.h>

using namespace vofdem;

TEST(CheckpointFile, SceneComparisonByValueAndFreeOptions) {
  EXPECT_EQ(FirstDifference("-dem_radius 5e-4\n-physics dem\n", "-dem_radius 0.00050\n-physics dem\n"), "");
  EXPECT_EQ(FirstDifference("-dem_radius 5e-4\n-physics dem\n", "-dem_radius 4e-4\n-physics dem\n"), "'-dem_radius 5e-4' in the checkpoint, '-dem_radius 4e-4' in this run");
  EXPECT_EQ(FirstDifference("-physics dem\n", "-dem_radius 4e-4\n-physics dem\n"), "'-dem_radius 4e-4' in this run, not in the checkpoint");
  // A checkpoint of a vofdem from before -analysis_* and the output intervals were free lists them;
  // they no longer make it another scene (the D7 funnel run's checkpoints were refused so).
  EXPECT_EQ(FirstDifference("-analysis_lower -7.5e-4,-7.5e-4,1.748e-3\n-analysis_metrics repose\n-dem_output_every 10\n-physics dem\n", "-physics dem\n"), "");
  EXPECT_EQ(FirstDifference("-analysis_metrics repose\n-dem_radius 5e-4\n", "-dem_radius 4e-4\n"), "'-dem_radius 5e-4' in the checkpoint, '-dem_radius 4e-4' in this run");
}
