#include "vofdem/base/Options.hpp"

#include <gtest/gtest.h>

using vofdem::ParseInt;
using vofdem::ParseReal;
using vofdem::RealRange;
using vofdem::SplitList;

TEST(Options, ParseRealAcceptsNumbersOnly) {
  PetscReal v = 0;
  EXPECT_TRUE(ParseReal("1e-3", &v));
  EXPECT_DOUBLE_EQ(v, 1e-3);
  EXPECT_TRUE(ParseReal(" -9.81 ", &v));
  EXPECT_DOUBLE_EQ(v, -9.81);
  EXPECT_FALSE(ParseReal("abc", &v));
  EXPECT_FALSE(ParseReal("1.5x", &v));
  EXPECT_FALSE(ParseReal("", &v));
  EXPECT_FALSE(ParseReal("nan", &v));
  EXPECT_FALSE(ParseReal("1e999", &v));
}

TEST(Options, ParseIntRejectsFractionsAndOverflow) {
  PetscInt v = 0;
  EXPECT_TRUE(ParseInt("42", &v));
  EXPECT_EQ(v, 42);
  EXPECT_FALSE(ParseInt("4.2", &v));
  EXPECT_FALSE(ParseInt("1e3", &v));
  EXPECT_FALSE(ParseInt("99999999999", &v));
}

TEST(Options, SplitListHandlesYamlBrackets) {
  const auto v = SplitList("[0, 0, -9.81]");
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[2], "-9.81");
  EXPECT_EQ(SplitList("1,2,").size(), 3u);  // a trailing comma is an empty (bad) item, not ignored
}

TEST(Options, RangesRespectOpenEnds) {
  EXPECT_FALSE(RealRange::Positive().Contains(0));
  EXPECT_TRUE(RealRange::NonNegative().Contains(0));
  EXPECT_TRUE(RealRange::LeftOpen(0, 1).Contains(1));
  EXPECT_FALSE(RealRange::LeftOpen(0, 1).Contains(0));
  EXPECT_EQ(RealRange::Positive().Describe(), "(0, inf]");
}
