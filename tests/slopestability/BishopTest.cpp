// Bishop's simplified and the ordinary method of slices on slice tables worked out by hand
// (P13, LEM core).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "argine/slopestability/Bishop.hpp"

namespace argine {
namespace {

constexpr Real kDegree = M_PI / 180;

Slice makeSlice(Real b, Real w, Real alpha_deg, Real c, Real phi_deg, Real u) {
  Slice s;
  s.width = b;
  s.weight = w;
  s.base_angle = alpha_deg * kDegree;
  s.cohesion = c;
  s.friction_angle = phi_deg * kDegree;
  s.pore_pressure = u;
  return s;
}

// Three slices, b = 2 m, c' = 5 kPa, phi' = 25 deg (tan = 0.466308):
//   1: W =  40 kN, alpha = -10 deg, u = 0
//   2: W = 100 kN, alpha =  15 deg, u = 10 kPa
//   3: W =  60 kN, alpha =  40 deg, u = 0
// Driving sum W sin(alpha) = -6.9459 + 25.8819 + 38.5673 = 57.5032 kN.
// Ordinary method, l = b / cos(alpha) = 2.03085, 2.07055, 2.61081 m:
//   c' l + (W cos(alpha) - u l) tan phi'
//     1: 10.1543 + 39.3923 * 0.466308            = 28.5232 kN
//     2: 10.3528 + (96.5926 - 20.7055) * 0.466308 = 45.7395 kN
//     3: 13.0541 + 45.9627 * 0.466308            = 34.4868 kN
//   F = 108.7495 / 57.5032 = 1.89119.
// Bishop, numerators c' b + (W - u b) tan phi' = 28.6523, 47.3046, 37.9785 kN; at the
// converged F = 2.05410: m_alpha = cos(alpha)(1 + tan(alpha) tan(phi') / F) = 0.945387,
// 1.024681, 0.911966; the terms 30.3075 + 46.1652 + 41.6446 = 118.1173 kN, / 57.5032 =
// 2.05410 (= F: the fixed point).
TEST(Bishop, ThreeSlicesByHand) {
  const std::vector<Slice> slices = {makeSlice(2, 40e3, -10, 5e3, 25, 0),
                                     makeSlice(2, 100e3, 15, 5e3, 25, 10e3),
                                     makeSlice(2, 60e3, 40, 5e3, 25, 0)};
  const FactorOfSafety ordinary = ordinaryMethodOfSlices(slices);
  ASSERT_TRUE(ordinary.admissible);
  EXPECT_NEAR(ordinary.driving, 57503.234, 1e-3);
  EXPECT_NEAR(ordinary.value, 1.891189, 1e-6);

  const FactorOfSafety bishop = bishopSimplified(slices);
  ASSERT_TRUE(bishop.converged);
  ASSERT_TRUE(bishop.admissible);
  EXPECT_NEAR(bishop.value, 2.054098, 1e-6);
  EXPECT_NEAR(bishop.min_m_alpha, 0.911966, 1e-6);
  EXPECT_NEAR(bishopMAlpha(-10 * kDegree, 25 * kDegree, bishop.value), 0.945387, 1e-6);
  EXPECT_LT(bishop.iterations, 30);

  // The same mass mirrored (sliding towards +x) gives the same factors.
  std::vector<Slice> mirrored = slices;
  for (Slice& s : mirrored) s.base_angle = -s.base_angle;
  EXPECT_NEAR(bishopSimplified(mirrored).value, bishop.value, 1e-12);
  EXPECT_NEAR(ordinaryMethodOfSlices(mirrored).value, ordinary.value, 1e-12);
}

// phi' = 0: m_alpha = cos(alpha), so Bishop's terms c' b / cos(alpha) = c' l are the
// ordinary method's and both give sum c' l / sum W sin(alpha) at once.
TEST(Bishop, FrictionlessEqualsOrdinary) {
  const std::vector<Slice> slices = {makeSlice(1.5, 30e3, -5, 12e3, 0, 4e3),
                                     makeSlice(1.5, 70e3, 20, 12e3, 0, 8e3),
                                     makeSlice(1.5, 45e3, 45, 12e3, 0, 0)};
  const FactorOfSafety bishop = bishopSimplified(slices);
  const FactorOfSafety ordinary = ordinaryMethodOfSlices(slices);
  ASSERT_TRUE(bishop.admissible);
  EXPECT_NEAR(bishop.value, ordinary.value, 1e-12 * ordinary.value);
  EXPECT_LE(bishop.iterations, 2);
}

// The m_alpha guard (c' = 0, phi' = 40 deg, tan = 0.839100), a slice whose base dips steeply
// against the sliding direction beside a driving slice at alpha = 50 deg:
//  alpha = -55 deg, W = 10 kN, driving W = 50 kN: F = 2.48418 and
//    m_alpha = cos(55)(1 - tan(55) 0.8391 / 2.48418) = 0.5736 (1 - 0.48241) = 0.29689 > 0.2:
//    accepted. (From the ordinary F = 1.0555, below F_zero = tan(55) 0.8391 = 1.1984 where
//    m_alpha = 0, the plain iteration's first step has m_alpha < 0; the iteration must still
//    find this root.)
//  alpha = -60 deg, W = 10 kN, driving W = 100 kN: the root with m_alpha > 0 is F = 2.10221
//    with m_alpha = 0.5 (1 - 1.7321 * 0.8391 / 2.10221) = 0.15433 < 0.2: rejected. (The plain
//    iteration from F = 1 would go to F = 0.519 with m_alpha = -0.899.)
TEST(Bishop, MAlphaGuardRejectsSteepBackSlices) {
  const FactorOfSafety accepted =
      bishopSimplified({makeSlice(1, 10e3, -55, 0, 40, 0), makeSlice(1, 50e3, 50, 0, 40, 0)});
  ASSERT_TRUE(accepted.admissible);
  EXPECT_NEAR(accepted.value, 2.484181, 1e-6);
  EXPECT_NEAR(accepted.min_m_alpha, 0.296886, 1e-6);

  const FactorOfSafety rejected =
      bishopSimplified({makeSlice(1, 10e3, -60, 0, 40, 0), makeSlice(1, 100e3, 50, 0, 40, 0)});
  EXPECT_TRUE(rejected.converged);
  EXPECT_NEAR(rejected.value, 2.102211, 1e-6);
  EXPECT_NEAR(rejected.min_m_alpha, 0.154325, 1e-6);
  EXPECT_FALSE(rejected.admissible);

  // The guard itself is a setting.
  BishopOptions strict;
  strict.min_m_alpha = 0.3;
  EXPECT_FALSE(bishopSimplified(
                   {makeSlice(1, 10e3, -55, 0, 40, 0), makeSlice(1, 50e3, 50, 0, 40, 0)}, strict)
                   .admissible);
}

}  // namespace
}  // namespace argine
