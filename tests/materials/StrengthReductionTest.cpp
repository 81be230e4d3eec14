// The strength-reduction factor of a material (P13 item 3; SolidModel.hpp reducedStrength):
// c/F, tan phi/F, the cut-off/F and psi at most the reduced phi, applied to the
// suction-dependent c(s) and phi(s) of Eqs. 4.23-4.26. Hand values.
#include <gtest/gtest.h>

#include <cmath>

#include "argine/materials/SolidModel.hpp"

namespace argine {
namespace {

constexpr Real kDegree = 3.14159265358979323846 / 180;

TEST(StrengthReduction, MohrCoulombHandValues) {
  SolidSpec spec;
  spec.model = SolidModel::MohrCoulomb;
  spec.cohesion = 10000;
  spec.friction_angle = 30 * kDegree;
  spec.dilatancy_angle = 20 * kDegree;
  spec.tensile_strength = 3000;
  spec.strength_reduction = 1.5;
  const MohrCoulombStrength s = mohrCoulombStrength(spec, 0);
  EXPECT_NEAR(s.cohesion, 6666.666666667, 1e-8);
  // atan(tan 30 deg / 1.5) = atan(0.38490018) = 0.3674219046 rad (21.05 deg)
  EXPECT_NEAR(s.friction_angle, 0.3674219046198016, 1e-14);
  EXPECT_EQ(s.dilatancy_angle, 20 * kDegree);  // 20 deg < 21.05 deg: kept
  EXPECT_NEAR(s.tensile_strength, 2000, 1e-9);
  // F = 2: phi_F = atan(0.28867513) = 16.10 deg < psi = 20 deg: psi follows phi_F.
  spec.strength_reduction = 2;
  const MohrCoulombStrength t = mohrCoulombStrength(spec, 0);
  EXPECT_NEAR(t.friction_angle, std::atan(std::tan(30 * kDegree) / 2), 1e-15);
  EXPECT_EQ(t.dilatancy_angle, t.friction_angle);
  // the precomputed constants of a Mohr-Coulomb material carry the reduction too
  EXPECT_EQ(solidConstants(spec).strength.cohesion, 5000);
}

TEST(StrengthReduction, FactorOneIsTheMaterialToTheBit) {
  SolidSpec spec;
  spec.model = SolidModel::MohrCoulomb;
  spec.cohesion = 1234.5;
  spec.friction_angle = 0.6123;
  spec.dilatancy_angle = 0.1;
  const MohrCoulombStrength s = mohrCoulombStrength(spec, 0);
  EXPECT_EQ(s.cohesion, 1234.5);
  EXPECT_EQ(s.friction_angle, 0.6123);  // no tan/atan round trip
  EXPECT_EQ(s.dilatancy_angle, 0.1);
}

TEST(StrengthReduction, SuctionTermsAreReducedWithTheStrength) {
  SolidSpec spec;
  spec.model = SolidModel::SuctionMohrCoulomb;
  spec.cohesion = 5000;
  spec.friction_angle = 0.5;
  spec.cohesion_increase_max = 20000;
  spec.cohesion_suction_rate = 1.0;
  spec.friction_suction_rate = 0.1;
  spec.atmospheric_pressure = 1e5;
  spec.dilatancy_angle = 0.4;
  spec.strength_reduction = 2;
  // s = 50 kPa: c(s) = 12869.3868 Pa (SolidModelTest), phi(s) = 0.5 + 0.1 * 0.5 = 0.55 rad;
  // reduced: c = 6434.6934 Pa, phi = atan(tan 0.55 / 2) = atan(0.30655261) = 0.29745747 rad,
  // psi = 0.4 > phi_F: psi = phi_F.
  const MohrCoulombStrength s = mohrCoulombStrength(spec, 5e4);
  EXPECT_NEAR(s.cohesion, 6434.6934028735, 1e-6);
  EXPECT_NEAR(s.friction_angle, 0.2974574660218382, 1e-14);
  EXPECT_EQ(s.dilatancy_angle, s.friction_angle);
}

}  // namespace
}  // namespace argine
