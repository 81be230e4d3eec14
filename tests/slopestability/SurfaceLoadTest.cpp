// Vertical surface loads carried as slice weight (P13, LEM): the exact integral of q over a
// slice, load ends as slice boundaries.
#include <gtest/gtest.h>

#include "argine/slopestability/PolylineSlip.hpp"
#include "argine/slopestability/SlopeSection.hpp"

namespace argine {
namespace {

// A ramp 20 -> 40 kPa on [70, 80]: over [72, 75] the mean is q(73.5) = 27 kPa, 81 kN/m; a
// strip 20 kPa on [23, 43] cut at [40, 50]: 3 m of it, 60 kN/m.
TEST(SurfaceLoad, ExactIntegralOfTheLoad) {
  SlopeSection s;
  s.loads.push_back({23, 43, 20e3, 20e3});
  s.loads.push_back({70, 80, 20e3, 40e3});
  EXPECT_NEAR(s.surfaceLoad(72, 75), 81e3, 1e-9);
  EXPECT_NEAR(s.surfaceLoad(40, 50), 60e3, 1e-9);
  EXPECT_NEAR(s.surfaceLoad(0, 100), 20 * 20e3 + 10 * 30e3, 1e-9);
  EXPECT_DOUBLE_EQ(s.surfaceLoad(50, 60), 0);
}

// Flat ground y = 2, the trapezoid surface of PolylineSlipTest (slices [-4,-2], [-2,0], [0,2],
// [2,4], 20 kN/m^3): a 10 kPa strip on [-1, 1] adds its ends as boundaries (6 slices) and
// 10 kN/m to each of the two slices it covers.
TEST(SurfaceLoad, CarriedAsSliceWeight) {
  SlopeSection s;
  s.ground = Polyline({-10, 10}, {2, 2});
  s.layers.push_back({"soil", s.ground, 20e3, 4e3, 0.5});
  s.loads.push_back({-1, 1, 10e3, 10e3});
  const SlipMass mass = slicePolyline(s, Polyline({-4, -2, 2, 4}, {2, 0, 0, 2}), 2);
  ASSERT_TRUE(mass.valid) << mass.reason;
  ASSERT_EQ(mass.slices.size(), 6u);
  Real total = 0;
  for (const Slice& sl : mass.slices) total += sl.weight;
  // Soil: 2 * (20e3 * 1 * 2) + 20e3 * 2 * 4 = 240 kN/m; load 20 kN/m.
  EXPECT_NEAR(total, 240e3 + 20e3, 1e-6);
  EXPECT_NEAR(mass.slices[2].x_mid, -0.5, 1e-12);
  EXPECT_NEAR(mass.slices[2].weight, 20e3 * 2 * 1 + 10e3, 1e-6);
}

}  // namespace
}  // namespace argine
