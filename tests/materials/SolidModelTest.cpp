// Solid model dispatch and the suction-dependent strength parameters (Eqs. 4.23-4.26).
#include <gtest/gtest.h>

#include <algorithm>
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

// A = 0 (the thesis' Table 5.4): the update takes k and m from the material's constants and
// only the cohesion at the point's suction. The stress, plastic strain and state must be
// those of the factors derived at the point (two sines), to the bit, on elastic, plane, edge,
// apex and cut-off returns, with and without a strength reduction.
TEST(SolidModel, ConstantSuctionAnglesGiveTheBitsOfTheFactorsAtThePoint) {
  for (const Real reduction : {1.0, 1.3}) {
    SolidSpec spec = suctionSolid();
    spec.friction_suction_rate = 0;
    spec.dilatancy_angle = 0.2;
    spec.tension_cutoff = true;
    spec.tensile_strength = 2000;
    spec.strength_reduction = reduction;
    const SolidConstants constants = solidConstants(spec);
    ASSERT_TRUE(constantSuctionAngles(spec));
    const Real increments[][kStressComponents] = {{1e-5, -2e-5, 0, 3e-6},   // elastic
                                                  {-3e-3, 1e-3, 0, 2e-3},   // a plane
                                                  {2e-3, -2e-3, 0, 0},      // an edge
                                                  {4e-3, 4e-3, 0, 0},       // the apex
                                                  {3e-3, -1e-4, 0, 1e-4}};  // the cut-off
    int returns[4] = {0, 0, 0, 0};
    for (const Real suction : {0.0, 2e3, 3e4, 2e5})
      for (const auto& dstrain : increments) {
        Real fast[kStressComponents] = {-2e4, -3e4, -2.5e4, 1e3}, slow[kStressComponents];
        std::copy(fast, fast + kStressComponents, slow);
        Real fast_plastic = 0, slow_plastic = 0;
        int fast_state = 0, slow_state = 0;
        updateEffectiveStress(spec, constants, suction, dstrain, fast, fast_plastic, fast_state);
        const MohrCoulombStrength strength = mohrCoulombStrength(spec, suction);
        slow_state =
            mohrCoulombStressUpdate(constants.lambda, constants.shear_modulus, strength,
                                    mohrCoulombFactors(strength), dstrain, slow, slow_plastic);
        for (int c = 0; c < kStressComponents; ++c) EXPECT_EQ(fast[c], slow[c]) << suction;
        EXPECT_EQ(fast_plastic, slow_plastic);
        EXPECT_EQ(fast_state, slow_state);
        returns[slow_state] += 1;
      }
    EXPECT_GT(returns[kPlasticStateElastic], 0);
    EXPECT_GT(returns[kPlasticStatePlastic], 0);
    EXPECT_GT(returns[kPlasticStateApex] + returns[kPlasticStateTension], 0);
  }
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
