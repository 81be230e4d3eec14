// SIMD across points (core/Lanes.hpp): the helpers every lane kernel is built from, against
// hand-computed values.
#include <gtest/gtest.h>

#include <cmath>

#include "argine/core/Lanes.hpp"

namespace argine {
namespace {

TEST(Lanes, SelectPicksPerLaneAndSplatFillsEveryLane) {
  const Lanes a = {1, 2, 3, 4}, b = {-1, -2, -3, -4};
  const Lanes chosen = select(a > splat<Lanes>(2.5), a, b);
  const Real expected[kLanes] = {-1, -2, 3, 4};
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(chosen[l], expected[l]) << l;
  EXPECT_EQ(select(true, 1.0, 2.0), 1.0);
  EXPECT_EQ(select(false, 1.0, 2.0), 2.0);
  EXPECT_EQ(splat<Real>(7.5), 7.5);
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(splat<Lanes>(7.5)[l], 7.5);
  // -0 and NaN pass through select unchanged (it moves bits, it does not compute)
  const Lanes odd = {-0.0, std::nan(""), 1, 1};
  const Lanes kept = select(odd == odd, odd, splat<Lanes>(5));
  EXPECT_TRUE(std::signbit(kept[0]));
  EXPECT_EQ(kept[1], 5.0);  // NaN != NaN: the other side
}

TEST(Lanes, AnyLaneSeesASingleLane) {
  const Lanes x = {0, 0, 0, 0};
  EXPECT_FALSE(anyLane(x > splat<Lanes>(0)));
  for (int l = 0; l < kLanes; ++l) {
    Lanes y = x;
    y[l] = 1;
    EXPECT_TRUE(anyLane(y > splat<Lanes>(0))) << l;
  }
  EXPECT_TRUE(anyLane(true));
  EXPECT_FALSE(anyLane(false));
}

TEST(Lanes, TransposeTurnsValuesOfPointsIntoPointsOfValues) {
  Lanes in[kLanes], out[kLanes];
  for (int k = 0; k < kLanes; ++k)
    for (int l = 0; l < kLanes; ++l) in[k][l] = 10 * k + l;  // value k of point l
  transposeLanes(in, out);
  for (int l = 0; l < kLanes; ++l)
    for (int k = 0; k < kLanes; ++k) EXPECT_EQ(out[l][k], 10 * k + l) << l << " " << k;
}

TEST(Lanes, LoadAndStoreReachConsecutivePoints) {
  Kokkos::View<Real*, MemSpace> scalar("scalar", 6);
  Kokkos::View<Real* [3], MemSpace> vector("vector", 6);
  for (int p = 0; p < 6; ++p) {
    scalar(p) = p;
    for (int c = 0; c < 3; ++c) vector(p, c) = 10 * p + c;
  }
  const Lanes s = load<Lanes>(scalar, 1), v = load<Lanes>(vector, 2, 1);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(s[l], 1 + l);
    EXPECT_EQ(v[l], 10 * (2 + l) + 1);
  }
  EXPECT_EQ(load<Real>(scalar, 5), 5.0);
  EXPECT_EQ(load<Real>(vector, 5, 2), 52.0);
  store(scalar, 2, s + 100);
  store(vector, 1, 0, v * 2);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_EQ(scalar(2 + l), 101 + l);
    EXPECT_EQ(vector(1 + l, 0), 2 * (10 * (2 + l) + 1));
    EXPECT_EQ(vector(1 + l, 1), 10 * (1 + l) + 1);  // the other components untouched
  }
  EXPECT_EQ(scalar(0), 0.0);
  EXPECT_EQ(scalar(1), 1.0);
}

TEST(Lanes, LoadOfPairsAndQuadruplesGivesTheComponentOfEachPoint) {
  // (point, 2) Views are read with two vector loads and a shuffle, others lane by lane
  // (Lanes.hpp): each lane must be its point's component either way.
  Kokkos::View<Real* [2], MemSpace> pair("pair", 7);
  Kokkos::View<Real* [4], MemSpace> quad("quad", 7);
  for (int p = 0; p < 7; ++p) {
    for (int c = 0; c < 2; ++c) pair(p, c) = 10 * p + c;
    for (int c = 0; c < 4; ++c) quad(p, c) = 100 * p + c;
  }
  for (int first : {0, 3})
    for (int c = 0; c < 4; ++c) {
      const Lanes q = load<Lanes>(quad, first, c);
      for (int l = 0; l < kLanes; ++l) EXPECT_EQ(q[l], 100 * (first + l) + c) << c << " " << l;
      if (c >= 2) continue;
      const Lanes v = load<Lanes>(pair, first, c);
      for (int l = 0; l < kLanes; ++l) EXPECT_EQ(v[l], 10 * (first + l) + c) << c << " " << l;
    }
}

}  // namespace
}  // namespace argine
