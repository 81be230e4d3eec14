// The liquid pressure of a point from its liquid content (physics/LiquidState.hpp,
// pressureOfLiquidContent): the inverse of 4.13 when saturated, the same closed form for an
// unsaturated material at or above the content of its pore space filled at p_L = 0, and the
// Newton root of S_L(s) rho_L(p_L) = content below it.

#include <gtest/gtest.h>

#include <cmath>

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

/// S_L rho_L at p_L: the content a pressure stores (4.13 and the SWRC).
Real contentAt(const PointMaterial& m, Real pressure) {
  return saturation(m.retention, suctionOfPressure(pressure)) * liquidDensity(m.liquid, pressure);
}

TEST(LiquidState, SaturatedPressureIsTheInverseOf413) {
  const PointMaterial m = material(PhaseModel::Saturated);
  for (const Real p : {-50e3, 0.0, 2e5, 3e6}) {
    const Real content = kDensity * std::exp(p / kBulk);
    EXPECT_NEAR(pressureOfLiquidContent(m, content, 0.0), p, 1e-6) << p;
  }
  EXPECT_TRUE(std::isnan(pressureOfLiquidContent(m, 0.0, 0.0)));
}

TEST(LiquidState, UnsaturatedAboveTheFilledContentHasTheClosedForm) {
  const PointMaterial m = material(PhaseModel::Unsaturated);
  const Real filled = 0.95 * kDensity;
  for (const Real p : {0.0, 1e3, 2e5}) {
    const Real content = filled * std::exp(p / kBulk);
    // from any guess: no iteration
    for (const Real guess : {-30e3, 0.0, 5e5})
      EXPECT_NEAR(pressureOfLiquidContent(m, content, guess), p, 1e-6) << p << " from " << guess;
    EXPECT_NEAR(contentAt(m, pressureOfLiquidContent(m, content, 0.0)), content, 1e-13 * content);
  }
}

TEST(LiquidState, UnsaturatedBelowTheFilledContentIsTheNewtonRoot) {
  const PointMaterial m = material(PhaseModel::Unsaturated);
  for (const Real s : {1.0, 500.0, 12e3, 80e3}) {  // suctions (Pa)
    const Real content = contentAt(m, -s);
    for (const Real guess : {0.0, -s / 2, -2 * s}) {
      const Real p = pressureOfLiquidContent(m, content, guess);
      // the iteration stops when a step is below 1e-14 K_L: the root to about that
      EXPECT_NEAR(p, -s, 1e-13 * kBulk) << "suction " << s << " from " << guess;
    }
  }
  // Across the switch the pressure is continuous: both sides within a pascal of 0.
  const Real filled = 0.95 * kDensity;
  EXPECT_LT(std::fabs(pressureOfLiquidContent(m, filled * (1 + 1e-13), 0.0)), 1.0);
  EXPECT_LT(std::fabs(pressureOfLiquidContent(m, filled * (1 - 1e-13), 0.0)), 1.0);
  EXPECT_GE(pressureOfLiquidContent(m, filled * (1 + 1e-13), -1e3), 0.0);
  EXPECT_LT(pressureOfLiquidContent(m, filled * (1 - 1e-13), 0.0), 0.0);
}

}  // namespace
}  // namespace argine
