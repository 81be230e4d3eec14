// Slicing of a polyline slip surface, and a long planar surface parallel to the ground against
// the exact infinite-slope factor of safety (P13, non-circular LEM).
#include <gtest/gtest.h>

#include <cmath>

#include "argine/slopestability/PolylineSlip.hpp"
#include "argine/slopestability/Spencer.hpp"

namespace argine {
namespace {

constexpr Real kDegree = M_PI / 180;

// Flat ground y = 2 on [-10, 10], one layer (20 kN/m^3, c' 4 kPa, phi' 30 deg), phreatic line
// y = 1. The surface (-6, 4) (-2, 0) (2, 0) (6, 4) crosses the ground where y = 2: x = -4 and
// 4. With 2 slices of equal width the surface vertices -2 and 2 are added, so 4 slices:
//   x_mid -3: b 2, base y 1, alpha = atan2(-4, 4) = -45 deg, W = 20e3 * 1 * 2 = 40 kN,
//             u = 9810 * (1 - 1) = 0;
//   x_mid -1: b 2, base y 0, alpha 0, W = 20e3 * 2 * 2 = 80 kN, u = 9810 * 1 = 9810 Pa;
// and the mirror images at +1 and +3 (alpha +45 deg).
TEST(PolylineSlip, FourSlicesByHand) {
  SlopeSection s;
  s.ground = Polyline({-10, 10}, {2, 2});
  s.layers.push_back({"soil", s.ground, 20e3, 4e3, 30 * kDegree});
  s.phreatic = Polyline({-10, 10}, {1, 1});
  const SlipMass mass = slicePolyline(s, Polyline({-6, -2, 2, 6}, {4, 0, 0, 4}), 2);
  ASSERT_TRUE(mass.valid) << mass.reason;
  EXPECT_NEAR(mass.entry_x, -4, 1e-12);
  EXPECT_NEAR(mass.exit_x, 4, 1e-12);
  ASSERT_EQ(mass.slices.size(), 4u);
  const Real x[] = {-3, -1, 1, 3}, y[] = {1, 0, 0, 1}, a[] = {-45, 0, 0, 45},
             w[] = {40e3, 80e3, 80e3, 40e3}, u[] = {0, 9810, 9810, 0};
  for (std::size_t i = 0; i < 4; ++i) {
    const Slice& sl = mass.slices[i];
    EXPECT_NEAR(sl.x_mid, x[i], 1e-12);
    EXPECT_NEAR(sl.width, 2, 1e-12);
    EXPECT_NEAR(sl.base_y, y[i], 1e-12);
    EXPECT_NEAR(sl.top_y, 2, 1e-12);
    EXPECT_NEAR(sl.base_angle, a[i] * kDegree, 1e-12);
    EXPECT_NEAR(sl.weight, w[i], 1e-8);
    EXPECT_NEAR(sl.pore_pressure, u[i], 1e-9);
    EXPECT_DOUBLE_EQ(sl.cohesion, 4e3);
    EXPECT_DOUBLE_EQ(sl.suction_strength, 0);
  }
  // The ends given on the ground are the entry and exit themselves.
  const SlipMass on_ground = slicePolyline(s, Polyline({-4, -2, 2, 4}, {2, 0, 0, 2}), 2);
  ASSERT_TRUE(on_ground.valid) << on_ground.reason;
  EXPECT_NEAR(on_ground.entry_x, -4, 1e-12);
  EXPECT_NEAR(on_ground.exit_x, 4, 1e-12);
  EXPECT_EQ(on_ground.slices.size(), 4u);
}

TEST(PolylineSlip, RejectsSurfacesThatDoNotMakeAMass) {
  SlopeSection s;
  s.ground = Polyline({-10, 10}, {2, 2});
  s.layers.push_back({"soil", s.ground, 20e3, 4e3, 30 * kDegree});
  EXPECT_FALSE(slicePolyline(s, Polyline({-3, 0, 6}, {1, 0, 4}), 10).valid);   // starts below
  EXPECT_FALSE(slicePolyline(s, Polyline({-6, 0, 3}, {4, 0, 1}), 10).valid);   // ends below
  EXPECT_FALSE(slicePolyline(s, Polyline({-6, 6}, {5, 5}), 10).valid);         // never below
  EXPECT_FALSE(slicePolyline(s, Polyline({-14, 0, 6}, {1, 0, 4}), 10).valid);  // off the section
  s.floor = 0.5;
  EXPECT_FALSE(slicePolyline(s, Polyline({-6, -2, 2, 6}, {4, 0, 0, 4}), 10).valid);
}

// The infinite slope (e.g. Duncan & Wright 2005, Sec. 6.2; Skempton & DeLory 1957): a plane
// parallel to the ground at vertical depth z, slope beta, pore pressure u on the plane,
//   F = c' / (gamma z sin(beta) cos(beta)) + (1 - r_u / cos^2(beta)) tan(phi') / tan(beta),
//   r_u = u / (gamma z).
// Every interior slice then carries Q = 0 whatever theta, so Spencer and Janbu give this F.
// Here the plane runs L = 2e6 m along the slope and is closed by two short straight ends: it
// leaves the toe bench at 10 deg (a toe wedge of about 11 m by z; a steeper toe end brings
// m = cos(alpha - theta)(...) of that slice near 0 and magnifies its end force) and reaches
// the crest corner over a run of z. The ends change the sums by O(11 z / (z L)) ~ 1e-5 of
// the total, so the test asks for 1e-4. Pore pressure: dry, and a phreatic line parallel to
// the ground 0.5 m below it, u = gamma_w (z - 0.5) on the plane.
TEST(PolylineSlip, InfiniteSlopeMatchesTheExactFormula) {
  const Real beta = 25 * kDegree, t = std::tan(beta), z = 2, length = 2e6;
  const Real gamma = 19e3, c = 3e3, phi = 28 * kDegree, depth_w = 0.5, gamma_w = 9810;
  SlopeSection s;
  s.ground = Polyline({-50, 0, length, length + 50}, {0, 0, length * t, length * t});
  s.layers.push_back({"soil", s.ground, gamma, c, phi});
  // Toe end from the bench down to the plane at x = 0, the plane, crest end up to (L, L t).
  const Real toe_x = -z / std::tan(10 * kDegree);
  const Polyline plane({toe_x, 0, length - z, length}, {0, -z, (length - z) * t - z, length * t});
  for (const bool wet : {false, true}) {
    if (wet) {
      s.phreatic = Polyline({-50, 0, length, length + 50},
                            {-depth_w, -depth_w, length * t - depth_w, length * t - depth_w});
    }
    const Real ru = wet ? gamma_w * (z - depth_w) / (gamma * z) : 0;
    const Real exact = c / (gamma * z * std::sin(beta) * std::cos(beta)) +
                       (1 - ru / (std::cos(beta) * std::cos(beta))) * std::tan(phi) / t;
    const SlipMass mass = slicePolyline(s, plane, 400);
    ASSERT_TRUE(mass.valid) << mass.reason;
    const SpencerFactor spencer_f = spencer(mass.slices);
    ASSERT_TRUE(spencer_f.factor.converged) << (wet ? "wet" : "dry");
    EXPECT_NEAR(spencer_f.factor.value, exact, 1e-4 * exact) << (wet ? "wet" : "dry");
    EXPECT_NEAR(janbuSimplified(mass.slices).value, exact, 1e-4 * exact);
    // A body slice: Q = 0 at the exact F means its base carries W cos(beta) - u l.
    const Slice& mid = mass.slices[mass.slices.size() / 2];
    EXPECT_NEAR(mid.base_angle, beta, 1e-12);
    EXPECT_NEAR(mid.weight, gamma * z * mid.width, 1e-6 * mid.weight);
    EXPECT_NEAR(mid.pore_pressure, wet ? gamma_w * (z - depth_w) : 0, 1e-6);
  }
}

}  // namespace
}  // namespace argine
