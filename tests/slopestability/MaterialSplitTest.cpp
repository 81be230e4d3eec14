// Slices cut where the base crosses a layer top (P13, LEM): no slice base in two materials.
#include <gtest/gtest.h>

#include <cmath>

#include "argine/slopestability/CircularSlip.hpp"
#include "argine/slopestability/PolylineSlip.hpp"

namespace argine {
namespace {

// Flat ground y = 1, a lower layer from y = 0.5 (SlicingTest's section without water). The
// circle centre (0, 5), R = 5 crosses y = 0.5 where 5 - sqrt(25 - x^2) = 0.5, x = -/+sqrt(4.75)
// = -/+2.179449; with 2 slices (boundaries -3, 0, 3) the split adds both crossings: 4 slices,
// each base in one layer (upper outside |x| = 2.179, lower inside).
TEST(MaterialSplit, CircleCutAtTheLayerTop) {
  SlopeSection s;
  s.ground = Polyline({-10, 10}, {1, 1});
  s.layers.push_back({"upper", s.ground, 18e3, 5e3, 0.5});
  s.layers.push_back({"lower", Polyline({-10, 10}, {0.5, 0.5}), 20e3, 10e3, 0.4});
  const SlipMass plain = sliceCircle(s, SlipCircle{0, 5, 5}, 2);
  const SlipMass split = sliceCircle(s, SlipCircle{0, 5, 5}, 2, true);
  ASSERT_TRUE(split.valid) << split.reason;
  EXPECT_EQ(plain.slices.size(), 2u);
  ASSERT_EQ(split.slices.size(), 4u);
  const Real crossing = std::sqrt(4.75);
  EXPECT_NEAR(split.slices[0].x_mid + 0.5 * split.slices[0].width, -crossing, 1e-12);
  EXPECT_NEAR(split.slices[3].x_mid - 0.5 * split.slices[3].width, crossing, 1e-12);
  const int layers[] = {0, 1, 1, 0};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(split.slices[i].layer, layers[i]);
}

// A polyline from (-4, 1) down to (0, 0) and up to (4, 1) crosses y = 0.5 at x = -/+2.
TEST(MaterialSplit, PolylineCutAtTheLayerTop) {
  SlopeSection s;
  s.ground = Polyline({-10, 10}, {1, 1});
  s.layers.push_back({"upper", s.ground, 18e3, 5e3, 0.5});
  s.layers.push_back({"lower", Polyline({-10, 10}, {0.5, 0.5}), 20e3, 10e3, 0.4});
  const SlipMass split = slicePolyline(s, Polyline({-4, 0, 4}, {1, 0, 1}), 1, true);
  ASSERT_TRUE(split.valid) << split.reason;
  ASSERT_EQ(split.slices.size(), 4u);  // bounds -4, -2, 0, 2, 4
  EXPECT_NEAR(split.slices[1].x_mid, -1, 1e-12);
  EXPECT_EQ(split.slices[0].layer, 0);
  EXPECT_EQ(split.slices[1].layer, 1);
}

}  // namespace
}  // namespace argine
