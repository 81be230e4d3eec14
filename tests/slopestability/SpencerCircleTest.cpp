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

// phi' = 0 on a circle cutting a straight ground line y = x tan(beta): the mass is a circular
// segment, so the exact moment equilibrium F = c L R / (W d) is in closed form. With p the
// distance of the centre from the line and 2 psi the angle the chord subtends,
// cos(psi) = p / R, L = 2 R psi, area A = R^2 (2 psi - sin(2 psi)) / 2, and the centroid lies
// 4 R sin^3(psi) / (3 (2 psi - sin(2 psi))) from the centre along the normal to the line,
// (sin(beta), -cos(beta)): d = that distance times sin(beta). Bishop, the ordinary method and
// Spencer's moment factor about the centre (for every theta) are midpoint sums of the same
// integrals, error O(1 / n^2): 1e-5 at n = 1000. This mass has no Spencer solution: the force
// factor F_f(theta) stays above the moment factor for every admissible theta (its minimum is
// about 1.647 near theta = 8 deg, against F = 1.6007), so spencer() must say so instead of
// returning a number.
TEST(SpencerOnCircles, FrictionlessSegmentMatchesTheClosedForm) {
  const Real beta = 30 * kDegree, yc = 10, r = 12, gamma = 18e3, c = 25e3;
  SlopeSection s;
  s.ground = Polyline({-100, 100}, {-100 * std::tan(beta), 100 * std::tan(beta)});
  s.layers.push_back({"clay", s.ground, gamma, c, 0});
  const Real p = yc * std::cos(beta), psi = std::acos(p / r);
  const Real area = 0.5 * r * r * (2 * psi - std::sin(2 * psi));
  const Real arm =
      4 * r * std::pow(std::sin(psi), 3) / (3 * (2 * psi - std::sin(2 * psi))) * std::sin(beta);
  const Real exact = c * 2 * r * psi * r / (gamma * area * arm);
  const SlipMass mass = sliceCircle(s, SlipCircle{0, yc, r}, 1000);
  ASSERT_TRUE(mass.valid) << mass.reason;
  EXPECT_NEAR(bishopSimplified(mass.slices).value, exact, 1e-5 * exact);
  EXPECT_NEAR(ordinaryMethodOfSlices(mass.slices).value, exact, 1e-5 * exact);
  for (const Real theta : {-10 * kDegree, 0.0, 20 * kDegree, 60 * kDegree}) {
    EXPECT_NEAR(spencerMomentFactor(mass.slices, theta, 0, yc).value, exact, 1e-5 * exact);
    EXPECT_GT(spencerForceFactor(mass.slices, theta).value, 1.01 * exact);
  }
  EXPECT_FALSE(spencer(mass.slices).factor.admissible);
}

}  // namespace
}  // namespace argine
