// Plane-strain Hooke's law and moduli, checked against hand values.
#include <gtest/gtest.h>

#include "argine/materials/LinearElastic.hpp"

namespace argine {
namespace {

SolidSpec solid() {
  SolidSpec spec;
  spec.youngs_modulus = 1e7;  // Pa
  spec.poisson_ratio = 0.25;
  return spec;
}

TEST(LinearElastic, Moduli) {
  const SolidSpec spec = solid();
  // G = 1e7 / (2 * 1.25) = 4e6; K = 1e7 / (3 * 0.5) = 6.666...e6;
  // lambda = 1e7 * 0.25 / (1.25 * 0.5) = 4e6; E_oed = 1e7 * 0.75 / (1.25 * 0.5) = 1.2e7.
  EXPECT_DOUBLE_EQ(shearModulus(spec), 4e6);
  EXPECT_NEAR(bulkModulus(spec), 1e7 / 1.5, 1e-6);
  EXPECT_DOUBLE_EQ(lameLambda(spec), 4e6);
  EXPECT_DOUBLE_EQ(constrainedModulus(spec), 1.2e7);
  // Consistency: E_oed = lambda + 2G = K + 4G/3.
  EXPECT_NEAR(constrainedModulus(spec), bulkModulus(spec) + 4.0 / 3.0 * shearModulus(spec), 1e-6);
}

TEST(LinearElastic, GeneralIncrementWithTensorShear) {
  const SolidSpec spec = solid();
  // dstrain = [1e-3, -2e-3, 0, eps_xy = 5e-4]; tr = -1e-3; lambda tr = -4000 Pa; 2G = 8e6.
  const Real dstrain[4] = {1e-3, -2e-3, 0, 5e-4};
  Real dstress[4];
  elasticStressIncrement(spec, dstrain, dstress);
  EXPECT_NEAR(dstress[0], -4000 + 8000, 1e-9);   // 4000
  EXPECT_NEAR(dstress[1], -4000 - 16000, 1e-9);  // -20000
  EXPECT_NEAR(dstress[2], -4000, 1e-9);          // plane strain: sigma_zz = lambda tr
  EXPECT_NEAR(dstress[3], 8e6 * 5e-4, 1e-9);     // sigma_xy = 2 G eps_xy = 4000
}

TEST(LinearElastic, OedometricStrainGivesConstrainedModulus) {
  const SolidSpec spec = solid();
  // eps_yy = -1e-3 alone: sigma_yy = E_oed eps = -1.2e4, sigma_xx = sigma_zz = lambda eps = -4e3
  // (K0 = nu / (1 - nu) = 1/3).
  const Real dstrain[4] = {0, -1e-3, 0, 0};
  Real dstress[4];
  elasticStressIncrement(spec, dstrain, dstress);
  EXPECT_NEAR(dstress[1], -1.2e4, 1e-9);
  EXPECT_NEAR(dstress[0], -4e3, 1e-9);
  EXPECT_NEAR(dstress[0] / dstress[1], 1.0 / 3.0, 1e-14);
}

TEST(LinearElastic, PureShearEngineeringStrainIsTwiceTensor) {
  const SolidSpec spec = solid();
  // gamma_xy = 2e-3 means eps_xy = 1e-3 in slot 3 -> sigma_xy = G gamma = 4e6 * 2e-3 = 8000.
  const Real dstrain[4] = {0, 0, 0, 1e-3};
  Real dstress[4];
  elasticStressIncrement(spec, dstrain, dstress);
  EXPECT_NEAR(dstress[3], 8000, 1e-9);
  EXPECT_EQ(dstress[0], 0.0);
  EXPECT_EQ(dstress[1], 0.0);
}

}  // namespace
}  // namespace argine
