// Hydraulic conductivity curves (thesis Eqs. 4.29-4.31): hand values, continuity at s = 0,
// derivative against finite differences.
#include <gtest/gtest.h>

#include <cmath>

#include "argine/materials/ConductivityCurve.hpp"

namespace argine {
namespace {

RetentionSpec vanGenuchtenCurve() {  // thesis Sec. 6: p_ref 3 kPa, lambda 0.7, S 0.125..1
  RetentionSpec spec;
  spec.model = RetentionModel::VanGenuchten;
  spec.reference_pressure = 3000;
  spec.lambda = 0.7;
  spec.saturation_min = 0.125;
  spec.saturation_max = 1.0;
  return spec;
}

ConductivitySpec curve(ConductivityModel model, bool effective = false) {
  ConductivitySpec spec;
  spec.model = model;
  spec.saturated_conductivity = 1e-4;
  spec.hillel_exponent = 3;
  spec.mualem_lambda = 0.7;
  spec.gardner_alpha = 2e-4;
  spec.use_effective_saturation = effective;
  return spec;
}

// At s = 3 kPa the van Genuchten curve gives S_e = 2^-0.7 = 0.61557220667 and
// S_L = 0.125 + 0.875 S_e = 0.66362568084 (see RetentionCurveTest).
constexpr Real kSuction = 3000;

TEST(Conductivity, SaturatedConductivityFromPermeability) {
  // kappa = 1e-11 m^2, rho_L = 1000, mu_L = 1e-3, g = 9.81: k = 1e-11*1000*9.81/1e-3 = 9.81e-5
  EXPECT_NEAR(saturatedConductivityFromPermeability(1e-11, 1000, 1e-3, 9.81), 9.81e-5, 1e-18);
}

TEST(Conductivity, ConstantIsSaturatedValue) {
  const RetentionSpec swrc = vanGenuchtenCurve();
  EXPECT_EQ(relativeConductivity(curve(ConductivityModel::Constant), swrc, kSuction), 1.0);
  EXPECT_EQ(conductivity(curve(ConductivityModel::Constant), swrc, kSuction), 1e-4);
  EXPECT_EQ(
      relativeConductivitySuctionDerivative(curve(ConductivityModel::Constant), swrc, kSuction),
      0.0);
}

TEST(Conductivity, HillelHandValues) {
  const RetentionSpec swrc = vanGenuchtenCurve();
  // Eq. 4.30 with S_L: 0.66362568084^3 = 0.29226011559.
  EXPECT_NEAR(relativeConductivity(curve(ConductivityModel::Hillel), swrc, kSuction), 0.29226011559,
              1e-10);
  EXPECT_NEAR(conductivity(curve(ConductivityModel::Hillel), swrc, kSuction), 2.9226011559e-5,
              1e-15);
  // With S_e: 0.61557220667^3 = 0.23325824788.
  EXPECT_NEAR(relativeConductivity(curve(ConductivityModel::Hillel, true), swrc, kSuction),
              0.23325824788, 1e-10);
}

TEST(Conductivity, MualemHandValues) {
  const RetentionSpec swrc = vanGenuchtenCurve();
  // Eq. 4.31 with S = 0.66362568084, lambda* = 0.7:
  //   S^(1/0.7) = exp(ln(0.66362568)/0.7) = exp(-0.58574296) = 0.5566798
  //   w = 1 - (1 - 0.5566798)^0.7 = 1 - 0.4433202^0.7 = 1 - 0.5658551 = 0.4341449
  //   k_r = sqrt(0.66362568) * 0.4341449^2 = 0.8146322 * 0.1884818 = 0.15354534
  EXPECT_NEAR(relativeConductivity(curve(ConductivityModel::Mualem), swrc, kSuction), 0.15354534238,
              1e-9);
  // With S_e = 0.61557220667 the same steps give 0.11594954772.
  EXPECT_NEAR(relativeConductivity(curve(ConductivityModel::Mualem, true), swrc, kSuction),
              0.11594954772, 1e-9);
}

TEST(Conductivity, GardnerHandValues) {
  const RetentionSpec swrc = vanGenuchtenCurve();
  // k_r = exp(-2e-4 * 5000) = e^-1 = 0.36787944117; dk_r/ds = -2e-4 e^-1.
  EXPECT_NEAR(relativeConductivity(curve(ConductivityModel::Gardner), swrc, 5000), 0.36787944117,
              1e-10);
  EXPECT_NEAR(relativeConductivitySuctionDerivative(curve(ConductivityModel::Gardner), swrc, 5000),
              -7.3575888234e-5, 1e-14);
}

TEST(Conductivity, ContinuousAtZeroSuction) {
  const RetentionSpec swrc = vanGenuchtenCurve();
  for (ConductivityModel model : {ConductivityModel::Constant, ConductivityModel::Hillel,
                                  ConductivityModel::Mualem, ConductivityModel::Gardner}) {
    for (bool effective : {false, true}) {
      const ConductivitySpec spec = curve(model, effective);
      EXPECT_EQ(relativeConductivity(spec, swrc, 0.0), 1.0);
      EXPECT_EQ(relativeConductivity(spec, swrc, -1e4), 1.0);
      EXPECT_NEAR(relativeConductivity(spec, swrc, 1e-3), 1.0, 1e-6);
      EXPECT_EQ(relativeConductivitySuctionDerivative(spec, swrc, -1e4), 0.0);
    }
  }
}

TEST(Conductivity, HillelWithSmaxBelowOneIsContinuousAtZero) {
  RetentionSpec swrc = vanGenuchtenCurve();
  swrc.saturation_max = 0.9;
  // k_r(s <= 0) = 0.9^3 = 0.729 = the limit from the unsaturated side.
  const ConductivitySpec spec = curve(ConductivityModel::Hillel);
  EXPECT_NEAR(relativeConductivity(spec, swrc, -1.0), 0.729, 1e-12);
  EXPECT_NEAR(relativeConductivity(spec, swrc, 1e-3), 0.729, 1e-9);
}

TEST(Conductivity, DerivativeMatchesFiniteDifference) {
  const RetentionSpec swrc = vanGenuchtenCurve();
  for (ConductivityModel model :
       {ConductivityModel::Hillel, ConductivityModel::Mualem, ConductivityModel::Gardner}) {
    for (bool effective : {false, true}) {
      const ConductivitySpec spec = curve(model, effective);
      for (Real s : {800.0, 3000.0, 9000.0}) {
        const Real h = 1e-4 * s;
        const Real fd =
            (relativeConductivity(spec, swrc, s + h) - relativeConductivity(spec, swrc, s - h)) /
            (2 * h);
        const Real exact = relativeConductivitySuctionDerivative(spec, swrc, s);
        EXPECT_NEAR(exact, fd, 1e-5 * std::abs(fd))
            << "model " << static_cast<int>(model) << " effective " << effective << " s " << s;
        EXPECT_LE(exact, 0.0);
      }
    }
  }
}

TEST(Conductivity, MualemVanishesAtZeroEffectiveSaturation) {
  RetentionSpec swrc;  // linear: reaches S_min = 0.2 at s = 8e4 Pa
  swrc.model = RetentionModel::Linear;
  swrc.linear_slope = 1e-5;
  swrc.saturation_min = 0.2;
  EXPECT_EQ(relativeConductivity(curve(ConductivityModel::Mualem, true), swrc, 1e5), 0.0);
  // With S_L (thesis form) it stays positive: S = 0.2, 0.2^(1/0.7) = 0.1003394,
  // w = 1 - 0.8996606^0.7 = 0.0713435, k_r = sqrt(0.2) * 0.0713435^2 = 2.27627e-3.
  EXPECT_NEAR(relativeConductivity(curve(ConductivityModel::Mualem), swrc, 1e5), 2.27627e-3, 1e-8);
}

TEST(Conductivity, WithTheSaturationGivenEqualsTheCurve) {
  // conductivityAt (S_L from the caller, as the point update has it) = conductivity().
  const RetentionSpec swrc = vanGenuchtenCurve();
  for (ConductivityModel model : {ConductivityModel::Constant, ConductivityModel::Hillel,
                                  ConductivityModel::Mualem, ConductivityModel::Gardner})
    for (bool effective : {false, true})
      for (Real suction : {-1e3, 0.0, 10.0, kSuction, 1e5}) {
        const ConductivitySpec spec = curve(model, effective);
        EXPECT_EQ(conductivityAt(spec, swrc, suction, saturation(swrc, suction)),
                  conductivity(spec, swrc, suction))
            << static_cast<int>(model) << " " << effective << " " << suction;
      }
}

}  // namespace
}  // namespace argine
