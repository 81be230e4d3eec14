// ACADS slope-stability test problem 1(a) (Donald & Giam 1989, the ACADS survey of slope
// stability programs; reviewed by Giam & Donald 1992): a simple homogeneous slope without
// pore pressure, the first problem of the Slide and SLOPE/W verification manuals (SLOPE/W
// Verification Manual, GeoStudio, Oct 2022, Sec. 2.1).
//   Geometry (m): toe bench y = 25 from x = 20 to 30, a 2:1 face from (30, 25) to (50, 35),
//   crest y = 35 from x = 50 to 70, base of the section y = 20 (the model's bottom boundary;
//   slip circles may not go below it).
//   Soil: c' = 3.0 kPa, phi' = 19.6 deg, gamma = 20.0 kN/m^3; dry.
//   Referee factor of safety: 1.00 (a single value; other programs' Bishop: 0.987 in Slide and
//   in xslope's reproduction, github.com/njones61/xslope benchmarks/build_lem.py and
//   docs/benchmark-run-plan.md). Asserted: argine's critical-circle Bishop F within 2 % of 1.00.
// The search grid only covers the region above the slope; nothing is tuned to the answer.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "AcadsSlope.hpp"
#include "argine/slopestability/CircleSearch.hpp"

namespace argine {
namespace {

TEST(AcadsBenchmark, Problem1aSimpleSlope) {
  const SlopeSection s = acads::problem1a();
  const CircleSearchGrid grid = acads::problem1aGrid();

  const CriticalCircle critical = searchCriticalCircle(s, grid);
  ASSERT_TRUE(critical.found);
  std::cout << "ACADS 1(a): Bishop F = " << critical.bishop.value
            << " (ordinary method on the same circle " << critical.ordinary.value << "), centre ("
            << critical.circle.centre_x << ", " << critical.circle.centre_y
            << "), R = " << critical.circle.radius << ", entry x = " << critical.mass.entry_x
            << ", exit x = " << critical.mass.exit_x << ", " << critical.mass.slices.size()
            << " slices, " << critical.evaluated << " circles (" << critical.rejected
            << " rejected), " << critical.bishop.iterations << " iterations\n";
  EXPECT_TRUE(critical.bishop.converged);
  EXPECT_GT(critical.bishop.min_m_alpha, 0.2);
  EXPECT_NEAR(critical.bishop.value, 1.00, 0.02);
  // The ordinary method neglects the interslice forces and is known to be lower than Bishop
  // for phi' > 0 (Whitman & Bailey 1967); it is reported, not benchmarked.
  EXPECT_LT(critical.ordinary.value, critical.bishop.value);
  // The critical circle is a toe circle: it leaves the ground near the toe (x = 30).
  EXPECT_NEAR(critical.mass.entry_x, 30, 3);
}

}  // namespace
}  // namespace argine
