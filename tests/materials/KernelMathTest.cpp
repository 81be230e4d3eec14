// kmath::fmin and fmax (written out for speed) against the C99 rules they replace.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "argine/materials/KernelMath.hpp"

namespace argine {
namespace {

TEST(KernelMath, FminFmaxOrderedValues) {
  EXPECT_EQ(kmath::fmax(1.5, -2.0), 1.5);
  EXPECT_EQ(kmath::fmax(-2.0, 1.5), 1.5);
  EXPECT_EQ(kmath::fmin(1.5, -2.0), -2.0);
  EXPECT_EQ(kmath::fmin(-2.0, 1.5), -2.0);
  EXPECT_EQ(kmath::fmax(3.0, 3.0), 3.0);
  const Real inf = std::numeric_limits<Real>::infinity();
  EXPECT_EQ(kmath::fmax(-inf, 7.0), 7.0);
  EXPECT_EQ(kmath::fmin(inf, 7.0), 7.0);
}

TEST(KernelMath, FminFmaxIgnoreOneNaN) {  // C99 7.12.12: a NaN argument gives the other
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_EQ(kmath::fmax(nan, 2.0), 2.0);
  EXPECT_EQ(kmath::fmax(2.0, nan), 2.0);
  EXPECT_EQ(kmath::fmin(nan, -2.0), -2.0);
  EXPECT_EQ(kmath::fmin(-2.0, nan), -2.0);
  EXPECT_TRUE(std::isnan(kmath::fmax(nan, nan)));
  EXPECT_TRUE(std::isnan(kmath::fmin(nan, nan)));
}

TEST(KernelMath, FminFmaxAgreeWithTheLibrary) {
  const Real values[] = {-1e300, -3.25, -1e-310, 0.0, 1e-310, 0.5, 4.0, 1e300};
  for (Real x : values)
    for (Real y : values) {
      EXPECT_EQ(kmath::fmax(x, y), std::fmax(x, y)) << x << " " << y;
      EXPECT_EQ(kmath::fmin(x, y), std::fmin(x, y)) << x << " " << y;
    }
}

}  // namespace
}  // namespace argine
