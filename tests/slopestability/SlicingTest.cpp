// Slicing of a circle, layer lookup and pore pressure of a section (P13, LEM core).
#include <gtest/gtest.h>

#include <cmath>

#include "argine/slopestability/Bishop.hpp"
#include "argine/slopestability/CircularSlip.hpp"
#include "argine/slopestability/SlopeSection.hpp"

namespace argine {
namespace {

constexpr Real kDegree = M_PI / 180;

// Flat ground y = 1 on [-10, 10]; a lower layer whose top is y = 0.5; phreatic line at y = 1.
SlopeSection flatTwoLayerSection() {
  SlopeSection s;
  s.ground = Polyline({-10, 10}, {1, 1});
  s.layers.push_back({"upper", Polyline({-10, 10}, {1, 1}), 18e3, 5e3, 30 * kDegree});
  s.layers.push_back({"lower", Polyline({-10, 10}, {0.5, 0.5}), 20e3, 10e3, 25 * kDegree});
  s.phreatic = Polyline({-10, 10}, {1, 1});
  return s;
}

TEST(SlopeSection, PolylineInterpolatesAndHoldsItsEnds) {
  const Polyline p({0, 10, 20}, {0, 5, 5});
  EXPECT_DOUBLE_EQ(p.at(-3), 0);
  EXPECT_DOUBLE_EQ(p.at(4), 2);
  EXPECT_DOUBLE_EQ(p.at(15), 5);
  EXPECT_DOUBLE_EQ(p.at(30), 5);
  EXPECT_THROW(Polyline({0, 0}, {1, 2}), std::invalid_argument);
}

TEST(SlopeSection, LayerAndPorePressure) {
  SlopeSection s = flatTwoLayerSection();
  EXPECT_EQ(s.layerAt(0, 0.8), 0);
  EXPECT_EQ(s.layerAt(0, 0.2), 1);
  // Below the phreatic line: gamma_w (h_w - y); above it: 0.
  EXPECT_DOUBLE_EQ(s.porePressure(0, 0.2), 9810 * 0.8);
  EXPECT_DOUBLE_EQ(s.porePressure(0, 1.5), 0);
  // A pore-pressure field replaces the phreatic line (later: material-point pressures).
  s.pore_pressure_field = [](Real x, Real y) { return 1000 * x - 10 * y; };
  EXPECT_DOUBLE_EQ(s.porePressure(2, 3), 1970);
}

// Circle centre (0, 5), R = 5, ground y = 1: the lower arc meets the ground where
// 5 - sqrt(25 - x^2) = 1, x = -3 and +3. Two slices of b = 3 with midpoints x = -/+1.5:
//   base y = 5 - sqrt(25 - 2.25) = 5 - 4.769696 = 0.230304 m, column 0.769696 m,
//   of which 0.5 m in the upper layer (18 kN/m^3) and 0.269696 m in the lower (20 kN/m^3):
//   W = 3 (18e3 * 0.5 + 20e3 * 0.269696) = 3 * 14393.92 = 43181.76 N/m;
//   sin(alpha) = -/+1.5 / 5 = -/+0.3, alpha = -/+17.4576 deg;
//   u = 9810 * (1 - 0.230304) = 7550.72 Pa; the base lies in the lower layer.
TEST(CircularSlip, TwoSlicesByHand) {
  const SlopeSection s = flatTwoLayerSection();
  const SlipMass mass = sliceCircle(s, SlipCircle{0, 5, 5}, 2);
  ASSERT_TRUE(mass.valid) << mass.reason;
  EXPECT_NEAR(mass.entry_x, -3, 1e-12);
  EXPECT_NEAR(mass.exit_x, 3, 1e-12);
  ASSERT_EQ(mass.slices.size(), 2u);
  const Real base_y = 5 - std::sqrt(25 - 2.25);
  for (int i = 0; i < 2; ++i) {
    const Slice& sl = mass.slices[static_cast<std::size_t>(i)];
    const Real side = i == 0 ? -1 : 1;
    EXPECT_NEAR(sl.x_mid, side * 1.5, 1e-12);
    EXPECT_NEAR(sl.width, 3, 1e-12);
    EXPECT_NEAR(sl.base_y, base_y, 1e-12);
    EXPECT_NEAR(sl.base_y, 0.230304, 1e-6);
    EXPECT_NEAR(sl.weight, 3 * (18e3 * 0.5 + 20e3 * (0.5 - base_y)), 1e-8);
    EXPECT_NEAR(sl.weight, 43181.76, 0.01);
    EXPECT_NEAR(sl.base_angle, side * 17.4576 * kDegree, 1e-6);
    EXPECT_NEAR(sl.pore_pressure, 7550.72, 0.01);
    EXPECT_EQ(sl.layer, 1);
    EXPECT_DOUBLE_EQ(sl.cohesion, 10e3);
    EXPECT_DOUBLE_EQ(sl.friction_angle, 25 * kDegree);
  }
  // Symmetric mass: no driving moment, no factor of safety.
  EXPECT_FALSE(bishopSimplified(mass.slices).admissible);
  EXPECT_FALSE(ordinaryMethodOfSlices(mass.slices).admissible);
}

TEST(CircularSlip, RejectsCirclesThatDoNotMakeAMass) {
  SlopeSection s = flatTwoLayerSection();
  // Entirely above the ground, and one whose lower arc never reaches the ground.
  EXPECT_FALSE(sliceCircle(s, SlipCircle{0, 20, 5}, 10).valid);
  EXPECT_FALSE(sliceCircle(s, SlipCircle{0, -2, 2}, 10).valid);
  // Cut off by the end of the ground line (one crossing at x = 0.3, the other beyond x = 10).
  EXPECT_FALSE(sliceCircle(s, SlipCircle{8, 20, 20.5}, 10).valid);
  // Below the floor of the section.
  s.floor = 0.5;
  EXPECT_FALSE(sliceCircle(s, SlipCircle{0, 5, 5}, 10).valid);
  s.floor = 0;
  EXPECT_TRUE(sliceCircle(s, SlipCircle{0, 5, 5}, 10).valid);
}

TEST(CircularSlip, GroundVerticesBecomeSliceBoundaries) {
  SlopeSection s;
  s.ground = Polyline({0, 10, 30, 60}, {0, 0, 10, 10});
  s.layers.push_back({"soil", s.ground, 18e3, 20e3, 0});
  const SlipMass mass = sliceCircle(s, SlipCircle{22, 22, 23}, 7);
  ASSERT_TRUE(mass.valid) << mass.reason;
  bool has_vertex = false;
  for (const Slice& sl : mass.slices) {
    if (std::abs(sl.x_mid - 0.5 * sl.width - 30) < 1e-9) has_vertex = true;
  }
  EXPECT_TRUE(has_vertex);
  EXPECT_EQ(mass.slices.size(), 8u);
}

}  // namespace
}  // namespace argine
