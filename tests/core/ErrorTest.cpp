#include <gtest/gtest.h>

#include "argine/core/Error.hpp"

namespace argine {

TEST(EditDistance, CountsInsertionsDeletionsSubstitutions) {
  EXPECT_EQ(editDistance("", ""), 0);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3);
  EXPECT_EQ(editDistance("Duration", "duration"), 0);  // case-insensitive
  EXPECT_EQ(editDistance("abc", ""), 3);
}

TEST(ClosestMatch, SuggestsNearKeysOnly) {
  const std::vector<std::string> keys{"Duration", "Solver", "Boundary Conditions", "Gravity"};
  EXPECT_EQ(closestMatch("Duraton", keys), "Duration");
  EXPECT_EQ(closestMatch("boundary condition", keys), "Boundary Conditions");
  EXPECT_EQ(closestMatch("Permeability", keys), "");
}

TEST(InputError, MessageNamesWhereAndWhat) {
  const InputError error("Stages/flood/Duration", "expected a positive real (s), got -1");
  EXPECT_EQ(error.where(), "Stages/flood/Duration");
  EXPECT_STREQ(error.what(), "Stages/flood/Duration: expected a positive real (s), got -1");
}

}  // namespace argine
