// Spencer against Bishop on circles (P13, rigorous LEM): for circular surfaces in dry
// homogeneous slopes with phi' > 0 Bishop's simplified method is known to lie within about
// 1 % of the methods that satisfy all equilibrium conditions (Fredlund & Krahn 1977: 2.080
// against Spencer 2.073; Duncan & Wright 2005, Sec. 7.11), and for phi' = 0 every moment method
// reduces to sum c l / sum W sin(alpha), the slice sums of the exact c L R / (W d) (see
// UndrainedCircleTest for the independent exact value).
#include <gtest/gtest.h>

#include <cmath>

#include "argine/slopestability/Bishop.hpp"
#include "argine/slopestability/CircularSlip.hpp"
#include "argine/slopestability/Spencer.hpp"

namespace argine {
namespace {

constexpr Real kDegree = M_PI / 180;

SlopeSection acadsSimpleSlope(Real c, Real phi) {
  SlopeSection s;
  s.ground = Polyline({20, 30, 50, 70}, {25, 25, 35, 35});
  s.layers.push_back({"soil", s.ground, 20e3, c, phi});
  return s;
}

TEST(SpencerOnCircles, WithinOnePercentOfBishopInADryHomogeneousSlope) {
  const SlopeSection s = acadsSimpleSlope(3e3, 19.6 * kDegree);
  // A toe circle, a deeper one and a shallow face circle.
  for (const SlipCircle& c :
       {SlipCircle{33, 50, 25.5}, SlipCircle{38, 45, 22}, SlipCircle{40, 40, 12}}) {
    const SlipMass mass = sliceCircle(s, c, 50);
    ASSERT_TRUE(mass.valid) << mass.reason;
    const FactorOfSafety bishop = bishopSimplified(mass.slices);
    SpencerOptions about_centre;
    about_centre.use_moment_point = true;
    about_centre.moment_x = c.centre_x;
    about_centre.moment_y = c.centre_y;
    const SpencerFactor spencer_f = spencer(mass.slices, about_centre);
    ASSERT_TRUE(bishop.admissible);
    ASSERT_TRUE(spencer_f.factor.admissible);
    EXPECT_NEAR(spencer_f.factor.value, bishop.value, 0.01 * bishop.value)
        << "circle (" << c.centre_x << ", " << c.centre_y << ", " << c.radius << ")";
    // The default moment point gives the same converged F.
    EXPECT_NEAR(spencer(mass.slices).factor.value, spencer_f.factor.value, 1e-8);
  }
}

TEST(SpencerOnCircles, FrictionlessEqualsBishopExactly) {
  const SlopeSection s = acadsSimpleSlope(20e3, 0);
  const SlipMass mass = sliceCircle(s, SlipCircle{33, 50, 25.5}, 100);
  ASSERT_TRUE(mass.valid) << mass.reason;
  const SpencerFactor spencer_f = spencer(mass.slices);
  ASSERT_TRUE(spencer_f.factor.admissible);
  EXPECT_NEAR(spencer_f.factor.value, bishopSimplified(mass.slices).value,
              1e-9 * spencer_f.factor.value);
}

}  // namespace
}  // namespace argine
