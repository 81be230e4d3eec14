// Water standing on a slope (SlopeSection::pondedPressure, Slicing.hpp pondedWaterEndForces):
// its weight on the slices and its thrust on the ends of the mass. Under a horizontal water
// level the pore pressures are hydrostatic and the water is in equilibrium, so total weights
// with pore pressures and the standing water must give the same Bishop F as buoyant weights
// below the level without any water (the classical equivalence; e.g. Duncan & Wright 2005,
// Sec. 6.9): the water's own weight and boundary pressures have no moment about the centre
// of a circle. ACADS 1(a)'s slope (AcadsBenchmarkTest.cpp), water level at y = 30 (toe under
// 5 m of water, crest dry) and y = 40 (all under water).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "AcadsSlope.hpp"
#include "argine/slopestability/CircleSearch.hpp"
#include "argine/slopestability/PointSection.hpp"
#include "argine/slopestability/Slicing.hpp"
#include "argine/slopestability/Spencer.hpp"

namespace argine {
namespace {

constexpr Real kGammaW = 9810;
using acads::kCohesion;
using acads::kFriction;

TEST(PondedWater, EndThrustAndWeightOnASlice) {
  SlopeSection s = acads::problem1a();
  s.phreatic = Polyline({20, 70}, {30, 30});
  EXPECT_NEAR(s.pondedPressure(25), 5 * kGammaW, 1e-9);  // 5 m of water on the bench
  EXPECT_NEAR(s.pondedPressure(40), 0, 1e-12);           // the face at y = 30
  EXPECT_NEAR(s.pondedPressure(36), 2 * kGammaW, 1e-9);  // face at y = 28
  const auto forces = pondedWaterEndForces(s, 26, 60);   // entry under 5 m, exit dry
  ASSERT_EQ(forces.size(), 1u);
  EXPECT_NEAR(forces[0].force, 0.5 * kGammaW * 25, 1e-6);  // gamma_w d^2 / 2, towards +x
  EXPECT_NEAR(forces[0].y, 25 + 5.0 / 3, 1e-12);
}

TEST(PondedWater, SubmergedSlopeAsWithBuoyantWeights) {
  for (const Real level : {30.0, 40.0}) {
    SlopeSection wet = acads::problem1a();
    wet.phreatic = Polyline({20, 70}, {level, level});
    SlopeSection buoyant = acads::problem1a();  // total weight above the level, buoyant below
    buoyant.layers.push_back({"below the level", Polyline({20, 70}, {level, level}),
                              acads::kUnitWeight - kGammaW, kCohesion, kFriction});
    for (const int slices : {50, 400}) {
      const CriticalCircle a = searchCriticalCircle(wet, acads::problem1aGrid(slices));
      ASSERT_TRUE(a.found);
      // the buoyant section's F on the same circle
      const SlipMass mass = sliceCircle(buoyant, a.circle, slices);
      const Real b = bishopSimplified(mass.slices).value;
      std::cout << "water at y = " << level << ", " << slices << " slices: F " << a.bishop.value
                << " with water, " << b << " buoyant\n";
      // The slicing errors of the two differ (weights at slice midpoints, the water's moment
      // summed over slices): O(1/N^2).
      EXPECT_NEAR(a.bishop.value, b, (slices == 50 ? 1e-3 : 3e-5) * b);
    }
  }
}

TEST(PondedWater, SpencerSubmergedAsWithBuoyantWeights) {
  // Spencer's method on the Bishop-critical circles of the equivalence above, moments about
  // the circle's centre: the end thrusts enter the end slices' equilibrium and the moment
  // equation, and the water must again drop out.
  for (const Real level : {30.0, 40.0}) {
    SlopeSection wet = acads::problem1a();
    wet.phreatic = Polyline({20, 70}, {level, level});
    SlopeSection buoyant = acads::problem1a();
    buoyant.layers.push_back({"below the level", Polyline({20, 70}, {level, level}),
                              acads::kUnitWeight - kGammaW, kCohesion, kFriction});
    const CriticalCircle c = searchCriticalCircle(wet, acads::problem1aGrid(400));
    ASSERT_TRUE(c.found);
    SpencerOptions about_centre;
    about_centre.use_moment_point = true;
    about_centre.moment_x = c.circle.centre_x;
    about_centre.moment_y = c.circle.centre_y;
    const SlipMass wet_mass = sliceCircle(wet, c.circle, 400);
    const SlipMass dry_mass = sliceCircle(buoyant, c.circle, 400);
    const SpencerFactor a = spencer(wet_mass.slices, about_centre, wet_mass.end_forces);
    const SpencerFactor b = spencer(dry_mass.slices, about_centre);
    ASSERT_TRUE(a.factor.converged && b.factor.converged);
    std::cout << "Spencer, water at y = " << level << ": F " << a.factor.value << " (theta "
              << a.theta << ") with water, " << b.factor.value << " (theta " << b.theta
              << ") buoyant\n";
    // Exact: at theta = 0 Spencer's moment equation about the centre is Bishop's simplified
    // method, and the two take the end thrusts in independently written ways (slice terms
    // and a moment constant here, a driving moment there).
    const Real bishop =
        bishopSimplified(wet_mass.slices, {}, endForceDriving(wet_mass, c.circle)).value;
    const FactorOfSafety moment0 = spencerMomentFactor(wet_mass.slices, 0, c.circle.centre_x,
                                                       c.circle.centre_y, wet_mass.end_forces);
    // (to Bishop's iteration tolerance, 1e-8 of F a step; twice that for the last iterate)
    EXPECT_NEAR(moment0.value, bishop, 2e-8 * bishop);
    // Not exact: Spencer's constant inclination applies to the total interslice forces, which
    // carry the water's thrust, so with and without the water they are different
    // assumptions; Spencer's F is known to depend little on them.
    EXPECT_NEAR(a.factor.value, b.factor.value, 0.005 * b.factor.value);
  }
}

TEST(PondedWater, FromThePointsAsFromTheWaterLevel) {
  // The slope filled with points whose p_L is hydrostatic under a level at y = 30: the
  // surface points carry the water standing on the bench.
  const SectionPoints pts =
      acads::latticeBelow(acads::problem1aGround(), 20, 70, 20, 0.1, acads::kUnitWeight,
                          [](Real, Real y) { return kGammaW * (30 - y); });
  const SlopeSection section = sectionFromPoints(
      pts,
      [](int, Real, Real) {
        return BaseStrength{0, kCohesion, kFriction, 0};
      },
      0, nullptr, kGammaW);
  EXPECT_NEAR(section.pondedPressure(25), 5 * kGammaW, 1e-6);
  SlopeSection wet = acads::problem1a();
  wet.phreatic = Polyline({20, 70}, {30, 30});
  const Real exact = searchCriticalCircle(wet, acads::problem1aGrid(50)).bishop.value;
  const Real points = searchCriticalCircle(section, acads::problem1aGrid(50)).bishop.value;
  std::cout << "water at y = 30: F from the points " << points << ", from the level " << exact
            << "\n";
  EXPECT_NEAR(points, exact, 0.01 * exact);  // as the dry case: h / H = 1 %
}

TEST(PondedWater, StandsOnTheGivenGroundNotOnThePointsEnvelope) {
  // A 2 m x 1 m block of points (h = 0.1 m) under half a metre of water, p_L = 9810 (1.5 -
  // y): the envelope is y = 1. A ground given 5 cm higher (a deck's outline drawn outside
  // the points) takes the soil's weight up to y = 1.05 (the slicing), so the water standing
  // on it is 0.45 m deep; at the envelope it would be 0.5 m (those 5 cm counted twice, as
  // soil and as water).
  const SectionPoints pts =
      acads::latticeBelow(Polyline({0.0, 2.0}, {1.0, 1.0}), 0, 2, 0, 0.1, 20e3,
                          [](Real, Real y) { return kGammaW * (1.5 - y); });
  const Polyline ground({0.0, 2.0}, {1.05, 1.05});
  const MaterialStrength strength = [](int, Real, Real) {
    return BaseStrength{0, kCohesion, kFriction, 0};
  };
  const SlopeSection given = sectionFromPoints(pts, strength, 0, &ground, kGammaW);
  const SlopeSection envelope = sectionFromPoints(pts, strength, 0, nullptr, kGammaW);
  for (const Real x : {0.13, 0.77, 1.21, 1.9}) {
    EXPECT_NEAR(given.pondedPressure(x), kGammaW * 0.45, 1e-6) << x;
    EXPECT_NEAR(envelope.pondedPressure(x), kGammaW * 0.5, 1e-6) << x;
  }
}

}  // namespace
}  // namespace argine
