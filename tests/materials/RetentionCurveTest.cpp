// Retention curves (thesis Sec. 2.5): hand values, continuity at s = 0, derivative against
// finite differences, inverse round trip, and use inside a Kokkos kernel.
#include <gtest/gtest.h>

#include <cmath>

#include "argine/materials/RetentionCurve.hpp"

namespace argine {
namespace {

RetentionSpec linearCurve() {
  RetentionSpec spec;
  spec.model = RetentionModel::Linear;
  spec.linear_slope = 1e-5;  // a_v (1/Pa)
  spec.saturation_min = 0.2;
  spec.saturation_max = 1.0;
  return spec;
}

// The thesis' 1D infiltration example (Sec. 6): p_ref = 3 kPa, lambda = 0.7,
// S_min = 0.125, S_max = 1.
RetentionSpec vanGenuchtenCurve() {
  RetentionSpec spec;
  spec.model = RetentionModel::VanGenuchten;
  spec.reference_pressure = 3000;
  spec.lambda = 0.7;
  spec.saturation_min = 0.125;
  spec.saturation_max = 1.0;
  return spec;
}

RetentionSpec gardnerCurve() {
  RetentionSpec spec;
  spec.model = RetentionModel::Gardner;
  spec.gardner_alpha = 1e-4;  // 1/Pa
  spec.saturation_min = 0.1;
  spec.saturation_max = 1.0;
  return spec;
}

Real centralDifference(const RetentionSpec& spec, Real s) {
  const Real h = 1e-4 * s;
  return (saturation(spec, s + h) - saturation(spec, s - h)) / (2 * h);
}

TEST(RetentionLinear, HandValues) {
  const RetentionSpec spec = linearCurve();
  // s = 20 kPa: S = 1 - 1e-5 * 2e4 = 0.8; dS/ds = -a_v = -1e-5.
  EXPECT_DOUBLE_EQ(saturation(spec, 2e4), 0.8);
  EXPECT_DOUBLE_EQ(saturationSuctionDerivative(spec, 2e4), -1e-5);
  // s = 100 kPa: 1 - 1 = 0 < S_min, clipped to 0.2, flat there.
  EXPECT_DOUBLE_EQ(saturation(spec, 1e5), 0.2);
  EXPECT_DOUBLE_EQ(saturationSuctionDerivative(spec, 1e5), 0.0);
  // Inverse: S = 0.8 -> (1 - 0.8)/1e-5 = 2e4 Pa; S <= S_min -> (1 - 0.2)/1e-5 = 8e4 Pa.
  EXPECT_NEAR(suctionFromSaturation(spec, 0.8), 2e4, 1e-9);
  EXPECT_NEAR(suctionFromSaturation(spec, 0.2), 8e4, 1e-9);
  EXPECT_NEAR(suctionFromSaturation(spec, 0.1), 8e4, 1e-9);
}

TEST(RetentionVanGenuchten, HandValues) {
  const RetentionSpec spec = vanGenuchtenCurve();
  // m = 1/(1 - 0.7) = 10/3.
  // s = 3 kPa: x = 1, S_e = 2^-0.7 = 0.61557220667; S = 0.125 + 0.875 * S_e = 0.66362568084.
  EXPECT_NEAR(saturation(spec, 3000), 0.66362568084, 1e-10);
  // s = 6 kPa: x = 2, x^m = 2^(10/3) = 10.0793684, S_e = 11.0793684^-0.7 = 0.18571179927,
  // S = 0.125 + 0.875 * 0.18571179927 = 0.28749782436.
  EXPECT_NEAR(saturation(spec, 6000), 0.28749782436, 1e-10);
  // dS/ds at x = 1: -0.875 * 0.7 * (10/3) * 1 * 2^-1.7 / 3000
  //   = -2.0416667 * 0.30778610 / 3000 = -2.0946554e-4 1/Pa.
  EXPECT_NEAR(saturationSuctionDerivative(spec, 3000), -2.0946554e-4, 1e-11);
  // at x = 2: -2.0416667 * 2^(7/3) * 11.0793684^-1.7 / 3000 = -5.7489880e-5 1/Pa.
  EXPECT_NEAR(saturationSuctionDerivative(spec, 6000), -5.7489880e-5, 1e-12);
}

TEST(RetentionGardner, HandValues) {
  const RetentionSpec spec = gardnerCurve();
  // s = 10 kPa: S_e = exp(-1e-4 * 1e4) = e^-1 = 0.36787944; S = 0.1 + 0.9 * 0.36787944.
  EXPECT_NEAR(saturation(spec, 1e4), 0.43109149705, 1e-10);
  // dS/ds = -0.9 * 1e-4 * e^-1 = -3.3109149705e-5.
  EXPECT_NEAR(saturationSuctionDerivative(spec, 1e4), -3.3109149705e-5, 1e-14);
  // Inverse: S = 0.1 + 0.9 e^-1 -> s = -ln(e^-1) / 1e-4 = 1e4.
  EXPECT_NEAR(suctionFromSaturation(spec, 0.1 + 0.9 * std::exp(-1.0)), 1e4, 1e-6);
}

TEST(Retention, SaturatedAtZeroAndNegativeSuctionWithoutJump) {
  for (const RetentionSpec& spec : {linearCurve(), vanGenuchtenCurve(), gardnerCurve()}) {
    EXPECT_EQ(saturation(spec, 0.0), spec.saturation_max);
    EXPECT_EQ(saturation(spec, -5e4), spec.saturation_max);
    EXPECT_EQ(saturationSuctionDerivative(spec, -5e4), 0.0);
    EXPECT_EQ(saturationSuctionDerivative(spec, 0.0), 0.0);
    // Value continuous from the unsaturated side: S(1e-6 Pa) within 1e-9 of S_max.
    EXPECT_NEAR(saturation(spec, 1e-6), spec.saturation_max, 1e-9);
    EXPECT_EQ(suctionFromSaturation(spec, spec.saturation_max), 0.0);
    EXPECT_EQ(suctionFromSaturation(spec, 1.0 + 1e-3), 0.0);
  }
  // Van Genuchten's slope also goes to 0 at s -> 0+ (exponent m - 1 = 7/3 > 0).
  EXPECT_NEAR(saturationSuctionDerivative(vanGenuchtenCurve(), 1e-3), 0.0, 1e-15);
}

TEST(Retention, DerivativeMatchesFiniteDifference) {
  for (const RetentionSpec& spec : {linearCurve(), vanGenuchtenCurve(), gardnerCurve()}) {
    for (Real s : {500.0, 3000.0, 1.5e4, 6e4}) {
      const Real fd = centralDifference(spec, s);
      EXPECT_NEAR(saturationSuctionDerivative(spec, s), fd, 1e-6 * std::abs(fd) + 1e-14)
          << "model " << static_cast<int>(spec.model) << " s = " << s;
      EXPECT_LE(saturationSuctionDerivative(spec, s), 0.0);
    }
  }
}

TEST(Retention, InverseRoundTrip) {
  for (const RetentionSpec& spec : {linearCurve(), vanGenuchtenCurve(), gardnerCurve()}) {
    // (Not much below ~100 Pa for van Genuchten: there 1 - S_e ~ (s/p_ref)^(10/3) is so
    // small that rounding of S dominates the inverse.)
    for (Real s : {120.0, 250.0, 3000.0, 2.5e4, 7.9e4}) {
      const Real back = suctionFromSaturation(spec, saturation(spec, s));
      EXPECT_NEAR(back, s, 1e-7 * s) << "model " << static_cast<int>(spec.model);
    }
  }
  // Van Genuchten at a high suction (S close to S_min) still inverts.
  const RetentionSpec vg = vanGenuchtenCurve();
  EXPECT_NEAR(suctionFromSaturation(vg, saturation(vg, 1e6)), 1e6, 1e-3);
}

TEST(Retention, AsymptoticResidualSaturationHasNoFiniteInverse) {
  EXPECT_TRUE(std::isinf(suctionFromSaturation(vanGenuchtenCurve(), 0.125)));
  EXPECT_TRUE(std::isinf(suctionFromSaturation(gardnerCurve(), 0.05)));
}

TEST(Retention, UsableInsideKernel) {
  const RetentionSpec spec = vanGenuchtenCurve();
  Real sum = 0;
  Kokkos::parallel_reduce(
      "retention", Kokkos::RangePolicy<ExecSpace>(0, 2),
      KOKKOS_LAMBDA(const int i, Real& acc) { acc += saturation(spec, 3000.0 * i); }, sum);
  // S(0) + S(3 kPa) = 1 + 0.66362568084.
  EXPECT_NEAR(sum, 1.66362568084, 1e-10);
}

TEST(RetentionCurve, SaturationAndSlopeTogetherEqualEachAlone) {
  // saturationAndSlope (one x^m for van Genuchten) gives saturation() and
  // saturationSuctionDerivative() to the bit, on both sides of s = 0 and past S_min.
  for (const RetentionSpec& spec : {linearCurve(), vanGenuchtenCurve(), gardnerCurve()})
    for (Real suction : {-5e3, 0.0, 1e-3, 250.0, 3000.0, 4.7e4, 1e6}) {
      const SaturationAndSlope both = saturationAndSlope(spec, suction);
      EXPECT_EQ(both.saturation, saturation(spec, suction)) << suction;
      EXPECT_EQ(both.slope, saturationSuctionDerivative(spec, suction)) << suction;
    }
}

// Occluded air (RetentionSpec::occluded_air_pressure): Boyle's law for the 1 - S_max of air
// at p_L > 0. S_max 0.8, p_a 100 kPa: at p_L = 100 kPa the air has half its volume,
// S_L = 1 - 0.2 / 2 = 0.9, dS_L/dp_L = 0.2 * 1e5 / (2e5)^2 = 5e-7 1/Pa.
RetentionSpec occludedAirCurve() {
  RetentionSpec spec = vanGenuchtenCurve();
  spec.saturation_max = 0.8;
  spec.occluded_air_pressure = 1e5;
  return spec;
}

TEST(RetentionOccludedAir, HandValues) {
  const RetentionSpec spec = occludedAirCurve();
  EXPECT_DOUBLE_EQ(saturationAtPressure(spec, 1e5), 0.9);
  EXPECT_DOUBLE_EQ(saturationSuctionDerivativeAtPressure(spec, 1e5), -5e-7);
  EXPECT_DOUBLE_EQ(saturationAtPressure(spec, 3e5), 0.95);  // a quarter of the air left
  // at p_L = 0+ the storage's slope is (1 - S_max) / p_a = 2e-6 1/Pa, 200 x n S/K_L of water
  EXPECT_DOUBLE_EQ(saturationSuctionDerivativeAtPressure(spec, 1e-300), -2e-6);
}

TEST(RetentionOccludedAir, ContinuousAtZeroAndTheCurveAtSuction) {
  const RetentionSpec spec = occludedAirCurve();
  EXPECT_EQ(saturationAtPressure(spec, 0.0), 0.8);
  EXPECT_NEAR(saturationAtPressure(spec, 1e-3), 0.8, 1e-8);
  for (const Real p : {-1.0, -250.0, -3000.0, -4.7e4}) {
    EXPECT_EQ(saturationAtPressure(spec, p), saturation(spec, -p)) << p;
    EXPECT_EQ(saturationSuctionDerivativeAtPressure(spec, p), saturationSuctionDerivative(spec, -p))
        << p;
  }
  // the derivative against a central difference at p_L > 0 (d/ds = -d/dp)
  for (const Real p : {500.0, 2e4, 3e5}) {
    const Real h = 1e-4 * p;
    const Real difference =
        -(saturationAtPressure(spec, p + h) - saturationAtPressure(spec, p - h)) / (2 * h);
    EXPECT_NEAR(saturationSuctionDerivativeAtPressure(spec, p), difference,
                1e-6 * std::fabs(difference))
        << p;
  }
}

TEST(RetentionOccludedAir, RigidAirKeepsTheMaximumSaturationAtPositivePressure) {
  // p_a = 0 (the default, the thesis): S_max and no slope at every p_L >= 0, to the bit as
  // the suction functions at s = 0.
  RetentionSpec spec = occludedAirCurve();
  spec.occluded_air_pressure = 0;
  for (const Real p : {0.0, 1e-3, 1e5, 1e7}) {
    EXPECT_EQ(saturationAtPressure(spec, p), saturation(spec, 0.0)) << p;
    EXPECT_EQ(saturationSuctionDerivativeAtPressure(spec, p), 0.0) << p;
  }
}

TEST(RetentionOccludedAir, SaturationAndSlopeAtPressureEqualEachAlone) {
  for (const Real air : {0.0, 1e5})
    for (const Real p : {-4.7e4, -250.0, 0.0, 1e-3, 2e4, 3e5}) {
      RetentionSpec spec = occludedAirCurve();
      spec.occluded_air_pressure = air;
      const SaturationAndSlope both = saturationAndSlopeAtPressure(spec, p);
      EXPECT_EQ(both.saturation, saturationAtPressure(spec, p)) << p;
      EXPECT_EQ(both.slope, saturationSuctionDerivativeAtPressure(spec, p)) << p;
    }
}

}  // namespace
}  // namespace argine
