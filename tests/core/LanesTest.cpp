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

TEST(Lanes, AllComponentsAreLoadedAndStoredAsTheOneComponentLoadsAndStores) {
  // loadComponents / storeComponents take (point, 4) and (point, 2) Views by whole rows and
  // shuffles, (point, 3) component by component: every lane must hold its point's
  // component, a store must write the kLanes points' rows and nothing around them, and the
  // Real forms must do the same for one point.
  Kokkos::View<Real* [4], MemSpace> quad("quad", 9);
  Kokkos::View<Real* [2], MemSpace> pair("pair", 9);
  Kokkos::View<Real* [3], MemSpace> triple("triple", 9);
  const auto fill = [&] {
    for (int p = 0; p < 9; ++p)
      for (int c = 0; c < 4; ++c) {
        quad(p, c) = 100 * p + c;
        if (c < 2) pair(p, c) = 100 * p + c;
        if (c < 3) triple(p, c) = 100 * p + c;
      }
  };
  fill();
  const auto check = [](const auto& view, const auto& lanes, int first, int count) {
    for (int c = 0; c < count; ++c)
      for (int l = 0; l < kLanes; ++l) EXPECT_EQ(lanes[c][l], view(first + l, c)) << c << " " << l;
  };
  for (int first : {0, 3, 5}) {
    Lanes q[4], d[2], t[3];
    loadComponents(quad, first, q);
    loadComponents(pair, first, d);
    loadComponents(triple, first, t);
    check(quad, q, first, 4);
    check(pair, d, first, 2);
    check(triple, t, first, 3);
    Real one[4];
    loadComponents(quad, first, one);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(one[c], quad(first, c));
  }
  for (int first : {1, 4}) {
    fill();
    Lanes q[4], d[2], t[3];
    for (int c = 0; c < 4; ++c)
      for (int l = 0; l < kLanes; ++l) q[c][l] = -(10 * l + c + 1);
    for (int c = 0; c < 2; ++c) d[c] = q[c];
    for (int c = 0; c < 3; ++c) t[c] = q[c];
    storeComponents(quad, first, q);
    storeComponents(pair, first, d);
    storeComponents(triple, first, t);
    for (int p = 0; p < 9; ++p) {
      const bool written = p >= first && p < first + kLanes;
      for (int c = 0; c < 4; ++c) {
        const Real expected = written ? -(10 * (p - first) + c + 1) : 100 * p + c;
        EXPECT_EQ(quad(p, c), expected) << p << " " << c;
        if (c < 2) {
          EXPECT_EQ(pair(p, c), expected) << p << " " << c;
        }
        if (c < 3) {
          EXPECT_EQ(triple(p, c), expected) << p << " " << c;
        }
      }
    }
    const Real one[2] = {-1, -2}, before = pair(7, 1);
    storeComponents(pair, 8, one);
    EXPECT_EQ(pair(8, 0), -1.0);
    EXPECT_EQ(pair(8, 1), -2.0);
    EXPECT_EQ(pair(7, 1), before);
  }
}

}  // namespace
}  // namespace argine
