// The strength a limit-equilibrium slip surface takes through a material (P13):
// simulation/SlipSurfaceStrength.hpp, each suction form against hand-computed values.
// Material: c' = 5 kPa, phi' = 30 deg; p_L = -20 kPa (s = 20 kPa), S_L = 0.6; retention
// S_min = 0.2, S_max = 1 (S_e = 0.5).
#include <gtest/gtest.h>

#include <cmath>

#include "argine/simulation/SlipSurfaceStrength.hpp"

namespace argine {
namespace {

constexpr Real kDegree = 3.14159265358979323846 / 180;

MaterialSpec material() {
  MaterialSpec m;
  m.solid.model = SolidModel::MohrCoulomb;
  m.solid.cohesion = 5000;
  m.solid.friction_angle = 30 * kDegree;
  m.retention.saturation_min = 0.2;
  m.retention.saturation_max = 1.0;
  return m;
}

TEST(SlipSurfaceStrength, EachSuctionFormByHand) {
  const MaterialSpec m = material();
  const BaseStrength none = slipSurfaceStrength(m, SuctionStrength::None, 0, -20e3, 0.6);
  EXPECT_EQ(none.cohesion, 5000);
  EXPECT_EQ(none.friction_angle, 30 * kDegree);
  EXPECT_EQ(none.suction_strength, 0);
  // solid model, Bishop chi = S_L: 0.6 * 20000 * tan 30 = 6928.2032 Pa
  const BaseStrength own = slipSurfaceStrength(m, SuctionStrength::SolidModel, 0, -20e3, 0.6);
  EXPECT_EQ(own.cohesion, 5000);
  EXPECT_NEAR(own.suction_strength, 6928.203230275509, 1e-9);
  // Vanapalli (Eq. 5.1): 20000 * 0.5 * tan 30 = 5773.5027 Pa
  EXPECT_NEAR(slipSurfaceStrength(m, SuctionStrength::Vanapalli, 0, -20e3, 0.6).suction_strength,
              5773.502691896258, 1e-9);
  // Fredlund (Eq. 5.2), phi_b = 15 deg: 20000 tan 15 = 5358.9838 Pa
  EXPECT_NEAR(
      slipSurfaceStrength(m, SuctionStrength::Fredlund, 15 * kDegree, -20e3, 0.6).suction_strength,
      5358.9838486224535, 1e-9);
  // Saturated (p_L > 0): no suction strength in any form.
  for (const SuctionStrength mode : {SuctionStrength::SolidModel, SuctionStrength::Vanapalli,
                                     SuctionStrength::Fredlund, SuctionStrength::None})
    EXPECT_EQ(slipSurfaceStrength(m, mode, 15 * kDegree, 3e3, 1.0).suction_strength, 0);
}

TEST(SlipSurfaceStrength, SolidModelTakesTheSuctionDependentMohrCoulomb) {
  MaterialSpec m = material();
  m.solid.model = SolidModel::SuctionMohrCoulomb;
  m.solid.cohesion_increase_max = 15e3;  // thesis Table 5.4, MC_1
  m.solid.cohesion_suction_rate = 0.04;
  m.solid.friction_suction_rate = 2 * kDegree;  // A, to check phi(s) enters too
  const BaseStrength s = slipSurfaceStrength(m, SuctionStrength::SolidModel, 0, -20e3, 0.6);
  // c = 5000 + 15000 (1 - exp(-0.04 * 20000 / 101325)) = 5117.9645 Pa (Eq. 4.25)
  EXPECT_NEAR(s.cohesion, 5117.964491603674, 1e-8);
  // phi = 30 deg + 2 deg * 20000 / 101325 = 0.53048880 rad (Eq. 4.26)
  EXPECT_NEAR(s.friction_angle, 0.5304887997857919, 1e-14);
  EXPECT_NEAR(s.suction_strength, 0.6 * 20e3 * std::tan(0.5304887997857919), 1e-8);
  // Vanapalli and Fredlund keep the saturated c', phi' (their own suction term instead).
  EXPECT_EQ(slipSurfaceStrength(m, SuctionStrength::Vanapalli, 0, -20e3, 0.6).cohesion, 5000);
}

TEST(SlipSurfaceStrength, LinearElasticDoesNotYield) {
  MaterialSpec m = material();
  m.solid.model = SolidModel::LinearElastic;
  EXPECT_EQ(slipSurfaceStrength(m, SuctionStrength::None, 0, 0, 1).cohesion, kElasticCohesion);
}

}  // namespace
}  // namespace argine
