// Solid model dispatch and the suction-dependent strength parameters (Eqs. 4.23-4.26).
#include <gtest/gtest.h>

#include <cmath>

#include "argine/materials/SolidModel.hpp"

namespace argine {
namespace {

SolidSpec suctionSolid() {
  SolidSpec spec;
  spec.model = SolidModel::SuctionMohrCoulomb;
  spec.youngs_modulus = 1e7;
  spec.poisson_ratio = 0.25;
  spec.cohesion = 5000;                // c' (Pa)
  spec.friction_angle = 0.5;           // phi' (rad)
  spec.cohesion_increase_max = 20000;  // dc_max (Pa)
  spec.cohesion_suction_rate = 1.0;    // B
  spec.friction_suction_rate = 0.1;    // A (rad)
  spec.atmospheric_pressure = 1e5;     // p_atm (Pa), round for the hand values
  return spec;
}

TEST(SuctionStrength, CohesionHandValues) {
  const SolidSpec spec = suctionSolid();
  // s = 50 kPa: c = 5000 + 20000 (1 - exp(-1 * 5e4 / 1e5)) = 5000 + 20000 * 0.39346934
  //   = 12869.3868 Pa.
  EXPECT_NEAR(suctionDependentCohesion(spec, 5e4), 12869.386805747, 1e-6);
  // Saturated (s <= 0): c'. Very dry: c -> c' + dc_max.
  EXPECT_EQ(suctionDependentCohesion(spec, 0.0), 5000.0);
  EXPECT_EQ(suctionDependentCohesion(spec, -2e4), 5000.0);
  EXPECT_NEAR(suctionDependentCohesion(spec, 1e8), 25000.0, 1e-6);
}

TEST(SuctionStrength, FrictionHandValues) {
  const SolidSpec spec = suctionSolid();
  // s = 50 kPa: phi = 0.5 + 0.1 * 5e4 / 1e5 = 0.55 rad.
  EXPECT_NEAR(suctionDependentFriction(spec, 5e4), 0.55, 1e-15);
  EXPECT_EQ(suctionDependentFriction(spec, 0.0), 0.5);
  EXPECT_EQ(suctionDependentFriction(spec, -1e4), 0.5);
}

TEST(SuctionStrength, ContinuousAtZeroSuction) {
  const SolidSpec spec = suctionSolid();
  EXPECT_NEAR(suctionDependentCohesion(spec, 1e-6), spec.cohesion, 1e-6);
  EXPECT_NEAR(suctionDependentFriction(spec, 1e-6), spec.friction_angle, 1e-12);
}

TEST(SolidModel, ImplementedModels) {
  EXPECT_TRUE(isImplemented(SolidModel::LinearElastic));
  EXPECT_TRUE(isImplemented(SolidModel::MohrCoulomb));
  EXPECT_TRUE(isImplemented(SolidModel::SuctionMohrCoulomb));
}

TEST(SolidModel, LinearElasticAddsIncrement) {
  SolidSpec spec = suctionSolid();
  spec.model = SolidModel::LinearElastic;
  Real stress[4] = {-1e4, -2e4, -1e4, 500};
  // eps_yy = -1e-3: d sigma = [lambda eps, E_oed eps, lambda eps, 0] = [-4e3, -1.2e4, -4e3, 0].
  const Real dstrain[4] = {0, -1e-3, 0, 0};
  Real plastic_strain = 0.25;
  int state = 7;
  EXPECT_TRUE(updateEffectiveStress(spec, 3e4, dstrain, stress, plastic_strain, state));
  EXPECT_NEAR(stress[0], -1.4e4, 1e-9);
  EXPECT_NEAR(stress[1], -3.2e4, 1e-9);
  EXPECT_NEAR(stress[2], -1.4e4, 1e-9);
  EXPECT_NEAR(stress[3], 500, 1e-9);
  EXPECT_EQ(state, kPlasticStateElastic);
  EXPECT_EQ(plastic_strain, 0.25);
}

TEST(SolidModel, UsableInsideKernel) {
  SolidSpec spec = suctionSolid();
  spec.model = SolidModel::LinearElastic;
  Kokkos::View<Real* [4], MemSpace> stress("stress", 3);
  Kokkos::parallel_for(
      "update", Kokkos::RangePolicy<ExecSpace>(0, 3), KOKKOS_LAMBDA(const int p) {
        const Real dstrain[4] = {0, -1e-3 * (p + 1), 0, 0};
        Real sigma[4] = {stress(p, 0), stress(p, 1), stress(p, 2), stress(p, 3)};
        Real eps_p = 0;
        int state = 0;
        updateEffectiveStress(spec, 0.0, dstrain, sigma, eps_p, state);
        for (int i = 0; i < 4; ++i) stress(p, i) = sigma[i];
      });
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), stress);
  // sigma_yy = E_oed * eps = 1.2e7 * (-1e-3 (p+1)).
  for (int p = 0; p < 3; ++p) EXPECT_NEAR(host(p, 1), -1.2e4 * (p + 1), 1e-9);
}

}  // namespace
}  // namespace argine
