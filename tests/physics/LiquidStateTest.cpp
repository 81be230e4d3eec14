// The liquid pressure of a point from its liquid content (physics/LiquidState.hpp,
// pressureOfLiquidContent): the inverse of 4.13 when saturated; the root of
// S_L(s) rho_L(p_L) = content for an unsaturated material, on either side of p_L = 0.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "argine/core/Lanes.hpp"
#include "argine/physics/BishopStress.hpp"
#include "argine/physics/LiquidState.hpp"

namespace argine {
namespace {

constexpr Real kBulk = 2.2e9, kDensity = 1000;

PointMaterial material(PhaseModel phase) {
  PointMaterial m;
  m.phase = phase;
  m.liquid.density = kDensity;
  m.liquid.bulk_modulus = kBulk;
  m.retention.model = RetentionModel::VanGenuchten;
  m.retention.reference_pressure = 10e3;
  m.retention.lambda = 0.5;
  m.retention.saturation_min = 0.05;
  m.retention.saturation_max = 0.95;
  return m;
}

/// An unsaturated material on the linear retention curve of the default scene's soil
/// (a_v = 4e-4 1/kPa, S_L from 1 down to 0 at 2.5 MPa of suction).
PointMaterial linearRetentionMaterial() {
  PointMaterial m = material(PhaseModel::Unsaturated);
  m.retention.model = RetentionModel::Linear;
  m.retention.linear_slope = 4e-7;
  m.retention.saturation_min = 0;
  m.retention.saturation_max = 1;
  return m;
}

/// S_L rho_L at p_L: the content a pressure stores (4.13 and the SWRC).
Real contentAt(const PointMaterial& m, Real pressure) {
  return saturation(m.retention, suctionOfPressure(pressure)) * liquidDensity(m.liquid, pressure);
}

TEST(BishopStress, PorePressureTermIsSaturationTimesPressureForPointsAndLanes) {
  // (4.5), chi = S_L: 0.8 x -10 kPa suction-side p_L = -8 kPa; saturated: p_L itself
  EXPECT_DOUBLE_EQ(bishopPorePressure(0.8, -10000.0), -8000.0);
  EXPECT_DOUBLE_EQ(bishopPorePressure(1.0, 2500.0), 2500.0);
  EXPECT_DOUBLE_EQ(bishopPorePressure(0.0, 2500.0), 0.0);
  const Lanes s = {0.8, 1.0, 0.5, 0.0}, p = {-10000, 2500, 400, 2500};
  const Lanes term = bishopPorePressure(s, p);
  Real lane[kLanes];
  std::memcpy(lane, &term, sizeof lane);
  EXPECT_DOUBLE_EQ(lane[0], -8000.0);
  EXPECT_DOUBLE_EQ(lane[1], 2500.0);
  EXPECT_DOUBLE_EQ(lane[2], 200.0);
  EXPECT_DOUBLE_EQ(lane[3], 0.0);
}

TEST(LiquidState, SaturatedPressureIsTheInverseOf413) {
  const PointMaterial m = material(PhaseModel::Saturated);
  for (const Real p : {-50e3, 0.0, 2e5, 3e6}) {
    const Real content = kDensity * std::exp(p / kBulk);
    EXPECT_NEAR(pressureOfLiquidContent(m, content, 0.0), p, 1e-6) << p;
  }
  EXPECT_TRUE(std::isnan(pressureOfLiquidContent(m, 0.0, 0.0)));
}

TEST(LiquidState, UnsaturatedPressureIsTheRootOnEitherSideOfZero) {
  const PointMaterial m = material(PhaseModel::Unsaturated);
  // p_L >= 0 (S_L = S_max) and suctions from 1 Pa to 80 kPa, from guesses on both sides:
  // the iteration stops when a step is below 1e-14 K_L, so the root to about that.
  for (const Real p : {2e5, 1e3, 0.0, -1.0, -500.0, -12e3, -80e3}) {
    const Real content = contentAt(m, p);
    for (const Real guess : {0.0, p / 2 - 100, 2 * p + 100})
      EXPECT_NEAR(pressureOfLiquidContent(m, content, guess), p, 1e-13 * kBulk)
          << p << " from " << guess;
  }
}

TEST(LiquidState, UnsaturatedPressureIsFoundFromAGuessWhereTheSaturationIsZero) {
  // Linear retention down to S_min = 0 (S_L = 0 beyond 2.5 MPa of suction, the default
  // scene's soil): a guess there sees a flat S_L rho_L (no slope, an infinite Newton step).
  // Found by the lanes test: a point whose content fell just below rho_L0 got the explicit
  // predictor's guess of ~-4 MPa and a NaN pressure. The root: S_L = 0.998 at ~5 kPa.
  const PointMaterial m = linearRetentionMaterial();
  const Real p = -5e3, content = contentAt(m, p);
  for (const Real guess : {-4.2e6, -1e9, 7e3})
    EXPECT_NEAR(pressureOfLiquidContent(m, content, guess), p, 1e-13 * kBulk) << guess;
}

TEST(LiquidState, LanesOfALinearCurveGetTheOnePointRootOrDeclineTheKink) {
  // pressureOfLiquidContentLanes: four points at suctions and (with occluded air) at p_L > 0,
  // each from a guess off the root, get pressureOfLiquidContent's bits; a lane whose guess
  // lies where S_L = S_min (a flat curve: a step out of any bracket), or with no content,
  // makes it decline and leave the pressures alone.
  for (const Real air : {0.0, 101325.0}) {
    PointMaterial m = linearRetentionMaterial();
    m.retention.saturation_max = air > 0 ? 0.95 : 1;
    m.retention.occluded_air_pressure = air;
    auto content = [&](Real p) {
      return saturationAtPressure(m.retention, p) * liquidDensity(m.liquid, p);
    };
    const Lanes roots = {-5e3, -31e3, -700.0, air > 0 ? 3e3 : -2e5};
    const Lanes guesses = roots + Lanes{40.0, -250.0, 3.0, air > 0 ? 90.0 : -1e3};
    Lanes contents;
    for (int l = 0; l < kLanes; ++l) contents[l] = content(roots[l]);
    Lanes found = {7, 7, 7, 7};
    ASSERT_TRUE(pressureOfLiquidContentLanes(m, contents, guesses, found));
    for (int l = 0; l < kLanes; ++l) {
      const Real one = pressureOfLiquidContent(m, contents[l], guesses[l]);
      EXPECT_EQ(std::memcmp(&one, &found[l], sizeof one), 0) << l << ": " << found[l];
      EXPECT_NEAR(found[l], roots[l], 1e-13 * kBulk);
    }
    Lanes across = guesses;
    across[1] = -3e6;  // S_L = S_min there: a flat curve, a step to infinity
    Lanes untouched = {7, 7, 7, 7};
    EXPECT_FALSE(pressureOfLiquidContentLanes(m, contents, across, untouched));
    Lanes empty = contents;
    empty[1] = 0;
    EXPECT_FALSE(pressureOfLiquidContentLanes(m, empty, guesses, untouched));
    for (int l = 0; l < kLanes; ++l) EXPECT_EQ(untouched[l], 7);
  }
}

TEST(LiquidState, TwoGroupsOfLanesIterateSideBySideWithEachLanesOwnRoot) {
  // pressureOfLiquidContentLanes<2>: eight points, the second group needing more iterations
  // than the first (guesses further off), get pressureOfLiquidContent's bits in every lane; a
  // flat-curve guess in either group makes the pair decline and leave both groups alone.
  const PointMaterial m = linearRetentionMaterial();
  auto content = [&](Real p) {
    return saturationAtPressure(m.retention, p) * liquidDensity(m.liquid, p);
  };
  const Lanes roots[2] = {{-5e3, -31e3, -700.0, -2e5}, {-12e3, -90e3, -1.5e3, -4e5}};
  const Lanes guesses[2] = {roots[0] + Lanes{40.0, -250.0, 3.0, -1e3},
                            roots[1] + Lanes{9e3, -4e4, 1e3, 2e5}};
  Lanes contents[2];
  for (int g = 0; g < 2; ++g)
    for (int l = 0; l < kLanes; ++l) contents[g][l] = content(roots[g][l]);
  Lanes found[2] = {{7, 7, 7, 7}, {7, 7, 7, 7}};
  ASSERT_TRUE(pressureOfLiquidContentLanes<2>(m, contents, guesses, found));
  for (int g = 0; g < 2; ++g)
    for (int l = 0; l < kLanes; ++l) {
      const Real one = pressureOfLiquidContent(m, contents[g][l], guesses[g][l]);
      EXPECT_EQ(std::memcmp(&one, &found[g][l], sizeof one), 0) << g << " " << l;
      EXPECT_NEAR(found[g][l], roots[g][l], 1e-13 * kBulk);
    }
  for (int flat = 0; flat < 2; ++flat) {
    Lanes across[2] = {guesses[0], guesses[1]};
    across[flat][2] = -3e6;  // S_L = S_min there: a flat curve, a step to infinity
    Lanes untouched[2] = {{7, 7, 7, 7}, {7, 7, 7, 7}};
    EXPECT_FALSE(pressureOfLiquidContentLanes<2>(m, contents, across, untouched)) << flat;
    for (int g = 0; g < 2; ++g)
      for (int l = 0; l < kLanes; ++l) EXPECT_EQ(untouched[g][l], 7);
  }
}

TEST(LiquidState, OccludedAirMakesThePositivePressureSoftAndIsInvertedExactly) {
  // S_max = 0.95 with its 5 % of air occluded at p_a = 101.325 kPa: the content S_L rho_L at
  // p_L > 0 is inverted to the root, and one more kilogram per cubic metre of pore space
  // raises p_L by about 2 kPa instead of K_L / rho_L0 = 2.2 MPa: by Boyle alone
  // 1000 * 0.05 p / (p_a + p) = 1, p = p_a / 49 = 2067.9 Pa; the water's own compression
  // takes 0.09 % of it.
  PointMaterial m = material(PhaseModel::Unsaturated);
  m.retention.occluded_air_pressure = 101325;
  auto content = [&](Real p) {
    return saturationAtPressure(m.retention, p) * liquidDensity(m.liquid, p);
  };
  for (const Real p : {1.0, 5e3, 1e5, 2e6})
    for (const Real guess : {0.0, -1e4, 2 * p})
      EXPECT_NEAR(pressureOfLiquidContent(m, content(p), guess), p, 1e-13 * kBulk)
          << p << " from " << guess;
  const Real rise = pressureOfLiquidContent(m, content(0.0) + 1.0, 0.0);
  EXPECT_NEAR(rise, 101325.0 / 49, 0.002 * 101325.0 / 49);
  EXPECT_LT(rise, 101325.0 / 49);
  m.retention.occluded_air_pressure = 0;  // rigid: the water's stiffness
  EXPECT_GT(pressureOfLiquidContent(m, content(0.0) + 1.0, 0.0), 1e6);
}

}  // namespace
}  // namespace argine
