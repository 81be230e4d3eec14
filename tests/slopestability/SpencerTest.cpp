// Spencer's method (and Janbu's simplified method, its force equation at theta = 0) on slice
// tables whose answer is known independently (P13, rigorous LEM).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "argine/slopestability/Bishop.hpp"
#include "argine/slopestability/Spencer.hpp"

namespace argine {
namespace {

constexpr Real kDegree = M_PI / 180;

// The three slices of BishopTest (b = 2 m, c' = 5 kPa, phi' = 25 deg; W = 40, 100, 60 kN;
// alpha = -10, 15, 40 deg; u = 0, 10, 0 kPa), placed on the circle centre (0, 10), R = 10:
// base midpoints x = R sin(alpha), y = 10 - R cos(alpha).
std::vector<Slice> threeSlicesOnACircle() {
  std::vector<Slice> slices;
  const Real w[] = {40e3, 100e3, 60e3}, a[] = {-10, 15, 40}, u[] = {0, 10e3, 0};
  for (int i = 0; i < 3; ++i) {
    Slice s;
    s.width = 2;
    s.weight = w[i];
    s.base_angle = a[i] * kDegree;
    s.cohesion = 5e3;
    s.friction_angle = 25 * kDegree;
    s.pore_pressure = u[i];
    s.x_mid = 10 * std::sin(s.base_angle);
    s.base_y = 10 - 10 * std::cos(s.base_angle);
    s.top_y = s.base_y + 5;
    slices.push_back(s);
  }
  return slices;
}

// Reference computed independently (a short Python script, not argine's formulation): per
// slice N and Q from a 2 x 2 linear solve of the force equilibrium with
// S = (c' l + (N - u l) tan phi') / F, and as residuals sum Q and the moment of W, N and S
// about the centre taken from the forces themselves; 2-D Newton with finite-difference
// Jacobian: F = 2.052940759, theta = 0.244941918 rad (14.0341 deg), residuals 4e-12 N and
// 6e-11 N m. At theta = 0 Janbu's simplified F (fixed point of
// F = sum[(c' b + (W - u b) tan phi') / (cos(alpha) m_alpha)] / sum[W tan(alpha)]) is
// 1.883727487, and Bishop's (moment about the centre) is 2.054098 (BishopTest).
TEST(Spencer, ThreeSlicesAgainstAnIndependentSolution) {
  const std::vector<Slice> slices = threeSlicesOnACircle();
  SpencerOptions about_centre;
  about_centre.use_moment_point = true;
  about_centre.moment_x = 0;
  about_centre.moment_y = 10;
  const SpencerFactor s = spencer(slices, about_centre);
  ASSERT_TRUE(s.factor.converged);
  ASSERT_TRUE(s.factor.admissible);
  EXPECT_NEAR(s.factor.value, 2.052940759, 1e-8);
  EXPECT_NEAR(s.theta, 0.244941918, 1e-8);

  // The two partial factors at theta = 0 are the simplified methods.
  EXPECT_NEAR(spencerForceFactor(slices, 0).value, 1.883727487, 1e-8);
  EXPECT_NEAR(janbuSimplified(slices).value, 1.883727487, 1e-8);
  BishopOptions tight;  // Bishop's default stops at a relative change of 1e-8
  tight.tolerance = 1e-13;
  EXPECT_NEAR(spencerMomentFactor(slices, 0, 0, 10).value, bishopSimplified(slices, tight).value,
              1e-9);
  // At the solution both partial factors meet.
  EXPECT_NEAR(spencerForceFactor(slices, s.theta).value, s.factor.value, 1e-9);
  EXPECT_NEAR(spencerMomentFactor(slices, s.theta, 0, 10).value, s.factor.value, 1e-9);
}

// Where sum Q = 0 the moment is the same about every point: the converged (F, theta) must not
// depend on the moment point (the default point above the mass, the centre, one far below).
TEST(Spencer, SolutionDoesNotDependOnTheMomentPoint) {
  const std::vector<Slice> slices = threeSlicesOnACircle();
  const SpencerFactor by_default = spencer(slices);
  ASSERT_TRUE(by_default.factor.converged);
  for (const auto& point : {std::pair<Real, Real>{0, 10}, std::pair<Real, Real>{3, -4},
                            std::pair<Real, Real>{-40, 60}}) {
    SpencerOptions options;
    options.use_moment_point = true;
    options.moment_x = point.first;
    options.moment_y = point.second;
    const SpencerFactor other = spencer(slices, options);
    ASSERT_TRUE(other.factor.converged) << point.first << ", " << point.second;
    EXPECT_NEAR(other.factor.value, by_default.factor.value, 1e-9);
    EXPECT_NEAR(other.theta, by_default.theta, 1e-8);
  }
  EXPECT_NEAR(by_default.factor.value, 2.052940759, 1e-8);
}

// The same mass mirrored (x -> -x, alpha -> -alpha: sliding towards +x) has the same F and the
// interslice forces mirrored, theta -> -theta.
TEST(Spencer, MirroredMass) {
  const std::vector<Slice> slices = threeSlicesOnACircle();
  std::vector<Slice> mirrored = slices;
  for (Slice& s : mirrored) {
    s.base_angle = -s.base_angle;
    s.x_mid = -s.x_mid;
  }
  const SpencerFactor a = spencer(slices), b = spencer(mirrored);
  ASSERT_TRUE(b.factor.converged);
  EXPECT_NEAR(b.factor.value, a.factor.value, 1e-9);
  EXPECT_NEAR(b.theta, -a.theta, 1e-8);
  EXPECT_NEAR(janbuSimplified(mirrored).value, janbuSimplified(slices).value, 1e-12);
}

// Matric suction as apparent cohesion: every method must give with suction_strength S the
// same F as with c' + S and S = 0, and a higher F than without it.
TEST(SuctionStrength, EveryMethodAddsItToTheCohesion) {
  const std::vector<Slice> base = threeSlicesOnACircle();
  std::vector<Slice> with_suction = base, as_cohesion = base;
  for (std::size_t i = 0; i < base.size(); ++i) {
    const Real suction = 2e3 + 1e3 * static_cast<Real>(i);  // 2, 3, 4 kPa
    with_suction[i].suction_strength = suction;
    as_cohesion[i].cohesion += suction;
  }
  const auto spencerF = [](const std::vector<Slice>& s) { return spencer(s).factor.value; };
  const auto bishopF = [](const std::vector<Slice>& s) { return bishopSimplified(s).value; };
  const auto ordinaryF = [](const std::vector<Slice>& s) {
    return ordinaryMethodOfSlices(s).value;
  };
  const auto janbuF = [](const std::vector<Slice>& s) { return janbuSimplified(s).value; };
  for (const auto& method : {std::function<Real(const std::vector<Slice>&)>(spencerF),
                             std::function<Real(const std::vector<Slice>&)>(bishopF),
                             std::function<Real(const std::vector<Slice>&)>(ordinaryF),
                             std::function<Real(const std::vector<Slice>&)>(janbuF)}) {
    const Real f_suction = method(with_suction);
    EXPECT_NEAR(f_suction, method(as_cohesion), 1e-9 * f_suction);
    EXPECT_GT(f_suction, method(base) * 1.05);
  }
}

// phi' = 0: m = cos(alpha - theta) and about the centre of a circle the moment arm of Q is
// R cos(alpha - theta), so F_m(theta) = sum c' l / sum W sin(alpha) for every theta: Spencer
// equals Bishop and the ordinary method to round-off.
TEST(Spencer, FrictionlessCircleEqualsBishop) {
  std::vector<Slice> slices = threeSlicesOnACircle();
  for (Slice& s : slices) s.friction_angle = 0;
  const SpencerFactor s = spencer(slices);
  ASSERT_TRUE(s.factor.admissible);
  EXPECT_NEAR(s.factor.value, bishopSimplified(slices).value, 1e-9);  // one iteration at phi' = 0
  EXPECT_NEAR(s.factor.value, ordinaryMethodOfSlices(slices).value, 1e-9);
}

TEST(Spencer, NoDrivingNoFactor) {
  std::vector<Slice> slices = threeSlicesOnACircle();
  for (Slice& s : slices) s.base_angle = 0;
  EXPECT_FALSE(spencer(slices).factor.admissible);
  EXPECT_FALSE(janbuSimplified(slices).admissible);
}

}  // namespace
}  // namespace argine
