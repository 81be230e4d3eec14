// Mohr-Coulomb return mapping (MohrCoulomb.hpp) against hand-computed returns.
//
// Common parameters (chosen so the hand computation is exact in decimals):
//   E = 2.5e7 Pa, nu = 0.25 -> G = 1e7, lambda = 1e7, lambda + 2G = 3e7 (Pa).
//   phi = 30 deg -> sin phi = 1/2, k = (1 + 1/2)/(1 - 1/2) = 3.
//   psi = asin(1/3) -> m = (4/3)/(2/3) = 2.
//   c = 1e4/sqrt(3) -> sigma_c = 2 c sqrt(k) = 2e4, apex sigma_a = sigma_c/(k - 1) = 1e4 Pa.
//   F1 = 3 s1 - s3 - 2e4; D b1 = lambda tr(b1) (1,1,1) + 2G b1 with b1 = (2, 0, -1):
//   tr = 1 -> D b1 = (5e7, 1e7, -1e7); a1 . D b1 = 3 * 5e7 + 1e7 = 1.6e8.
#include <gtest/gtest.h>

#include <cmath>

#include "argine/materials/MohrCoulomb.hpp"
#include "argine/materials/SolidModel.hpp"

namespace argine {
namespace {

constexpr Real kLambda = 1e7, kShear = 1e7;

MohrCoulombStrength strength(bool cutoff = false, Real tensile = 0) {
  MohrCoulombStrength s;
  s.cohesion = 1e4 / std::sqrt(3.0);
  s.friction_angle = std::asin(0.5);
  s.dilatancy_angle = std::asin(1.0 / 3.0);
  s.tension_cutoff = cutoff;
  s.tensile_strength = tensile;
  return s;
}

SolidSpec solid(SolidModel model = SolidModel::MohrCoulomb) {
  SolidSpec spec;
  spec.model = model;
  spec.youngs_modulus = 2.5e7;
  spec.poisson_ratio = 0.25;
  const MohrCoulombStrength s = strength();
  spec.cohesion = s.cohesion;
  spec.friction_angle = s.friction_angle;
  spec.dilatancy_angle = s.dilatancy_angle;
  spec.tension_cutoff = false;
  return spec;
}

void expectStress(const Real actual[3], Real s1, Real s2, Real s3, Real tol = 1e-6) {
  EXPECT_NEAR(actual[0], s1, tol);
  EXPECT_NEAR(actual[1], s2, tol);
  EXPECT_NEAR(actual[2], s3, tol);
}

TEST(MohrCoulomb, FactorsAndApex) {
  EXPECT_NEAR(flowFactor(std::asin(0.5)), 3.0, 1e-14);
  EXPECT_NEAR(flowFactor(std::asin(1.0 / 3.0)), 2.0, 1e-14);
  EXPECT_NEAR(mohrCoulombApex(strength()), 1e4, 1e-9);
  // phi = 0 (Tresca-like): no apex.
  MohrCoulombStrength tresca = strength();
  tresca.friction_angle = 0;
  EXPECT_TRUE(std::isinf(mohrCoulombApex(tresca)));
}

TEST(MohrCoulomb, ElasticTrialUnchanged) {
  // F1 = 3 (-5e4) + 1e5 - 2e4 = -7e4 < 0: inside the cone.
  Real sigma[3] = {-5e4, -6e4, -1e5}, ep[3];
  EXPECT_EQ(returnToMohrCoulomb(strength(), kLambda, kShear, sigma, ep), kMohrCoulombElastic);
  expectStress(sigma, -5e4, -6e4, -1e5, 0);
  expectStress(ep, 0, 0, 0, 0);
}

TEST(MohrCoulomb, ReturnToPlaneHandValues) {
  // Trial (-1e4, -5e4, -1e5): F1 = -3e4 + 1e5 - 2e4 = 5e4; dlambda = 5e4 / 1.6e8 = 3.125e-4;
  // sigma = trial - dlambda (5e7, 1e7, -1e7) = (-25625, -53125, -96875), still sorted.
  Real sigma[3] = {-1e4, -5e4, -1e5}, ep[3];
  EXPECT_EQ(returnToMohrCoulomb(strength(), kLambda, kShear, sigma, ep), kMohrCoulombSurface);
  expectStress(sigma, -25625, -53125, -96875);
  EXPECT_NEAR(mohrCoulombYield(strength(), sigma), 0, 1e-6);
  // Plastic strain dlambda b1 = 3.125e-4 (2, 0, -1): non-associated flow with m = 2, so
  // eps_v / (eps_1 - eps_3) = (m - 1)/(m + 1) = sin psi = 1/3.
  expectStress(ep, 6.25e-4, 0, -3.125e-4, 1e-15);
  EXPECT_NEAR((ep[0] + ep[1] + ep[2]) / (ep[0] - ep[2]), 1.0 / 3.0, 1e-12);
}

TEST(MohrCoulomb, ReturnToTriaxialCompressionEdge) {
  // Trial (-1e4, -2e4, -1e5): the plane return (-25625, -23125, -96875) is unsorted, so the
  // edge s1 = s2 with F1 and F2 = 3 s2 - s3 - 2e4 active. F1 = 5e4, F2 = 2e4;
  // D b2 = (1e7, 5e7, -1e7) for b2 = (0, 2, -1); the system
  //   [1.6e8 4e7; 4e7 1.6e8] x = (5e4, 2e4) -> x = (3e-4, 5e-5),
  // sigma = trial - 3e-4 D b1 - 5e-5 D b2 = (-25500, -25500, -96500).
  Real sigma[3] = {-1e4, -2e4, -1e5}, ep[3];
  EXPECT_EQ(returnToMohrCoulomb(strength(), kLambda, kShear, sigma, ep), kMohrCoulombSurface);
  expectStress(sigma, -25500, -25500, -96500);
  // Plastic strain 3e-4 (2, 0, -1) + 5e-5 (0, 2, -1) = (6e-4, 1e-4, -3.5e-4).
  expectStress(ep, 6e-4, 1e-4, -3.5e-4, 1e-15);
}

TEST(MohrCoulomb, ReturnToTriaxialExtensionEdge) {
  // Trial (-1e4, -9.8e4, -1e5): plane return gives s2 = -101125 < s3 = -96875, so the edge
  // s2 = s3 with F1 and F3 = 3 s1 - s2 - 2e4 active. F1 = 5e4, F3 = 4.8e4;
  // b3 = (2, -1, 0) -> D b3 = (5e7, -1e7, 1e7); a1 . D b3 = a3 . D b1 = 1.4e8, a3 . D b3 = 1.6e8:
  //   [16 14; 14 16] x = (5e-3, 4.8e-3) -> x1 = 0.0128/60, x3 = 0.0068/60,
  // s1 = -1e4 - 5e7 (x1 + x3) = -1e4 - 16333.33 = -26333.33,
  // s2 = s3 = -9.8e4 - 1e7 x1 + 1e7 x3 = -99000.
  Real sigma[3] = {-1e4, -9.8e4, -1e5}, ep[3];
  EXPECT_EQ(returnToMohrCoulomb(strength(), kLambda, kShear, sigma, ep), kMohrCoulombSurface);
  expectStress(sigma, -1e4 - 49000.0 / 3.0, -99000, -99000);
  EXPECT_NEAR(mohrCoulombYield(strength(), sigma), 0, 1e-6);
}

TEST(MohrCoulomb, ReturnToApex) {
  // Trial (2e4, 1.5e4, 1e4): F1 = 3e4. Plane return (10625, 13125, 11875) unsorted; edge
  // s1 = s2 gives (10750, 10750, 12250), beyond the apex (s3 > s1); edge s2 = s3 needs
  // x3 = (0.04 - 0.042)/60 < 0. So the apex (1e4, 1e4, 1e4), with plastic strain
  // D^-1 (1e4, 5e3, 0) = (1e4, 5e3, 0)/2e7 - 1e7 * 1.5e4/(2e7 * 5e7) = (3.5e-4, 1e-4, -1.5e-4).
  Real sigma[3] = {2e4, 1.5e4, 1e4}, ep[3];
  EXPECT_EQ(returnToMohrCoulomb(strength(), kLambda, kShear, sigma, ep), kMohrCoulombApex);
  expectStress(sigma, 1e4, 1e4, 1e4);
  expectStress(ep, 3.5e-4, 1e-4, -1.5e-4, 1e-15);
}

TEST(MohrCoulomb, TensionCutOffFace) {
  // sigma_t = 2e3 < apex 1e4. Trial (5e3, -2e3, -3e3): F1 = 1.5e4 + 3e3 - 2e4 = -2e3 (MC
  // satisfied), T1 = 3e3. D (1, 0, 0) = (3e7, 1e7, 1e7), dlambda = 3e3/3e7 = 1e-4:
  // sigma = (2e3, -3e3, -4e3).
  Real sigma[3] = {5e3, -2e3, -3e3}, ep[3];
  EXPECT_EQ(returnToMohrCoulomb(strength(true, 2e3), kLambda, kShear, sigma, ep),
            kMohrCoulombTension);
  expectStress(sigma, 2e3, -3e3, -4e3);
  expectStress(ep, 1e-4, 0, 0, 1e-15);
  // Without the cut-off the same trial is elastic.
  Real same[3] = {5e3, -2e3, -3e3};
  EXPECT_EQ(returnToMohrCoulomb(strength(false, 2e3), kLambda, kShear, same, ep),
            kMohrCoulombElastic);
}

TEST(MohrCoulomb, TensionCutOffEdgeAndCorner) {
  // Trial (5e3, 4e3, 3e3), sigma_t = 2e3: the face return (2e3, 3e3, 2e3) is unsorted; edge
  // T1 = T2 = 0: [3e7 1e7; 1e7 3e7] x = (3e3, 2e3) -> x = (8.75e-5, 3.75e-5),
  // sigma = (5e3 - 2625 - 375, 4e3 - 875 - 1125, 3e3 - 875 - 375) = (2000, 2000, 1750).
  Real edge[3] = {5e3, 4e3, 3e3}, ep[3];
  EXPECT_EQ(returnToMohrCoulomb(strength(true, 2e3), kLambda, kShear, edge, ep),
            kMohrCoulombTension);
  expectStress(edge, 2000, 2000, 1750);
  // Trial (5e3, 4.5e3, 4.5e3): the edge return would give s3 = 3125 > s1 = 2000, so all three
  // at sigma_t (the tension apex).
  Real corner[3] = {5e3, 4.5e3, 4.5e3};
  EXPECT_EQ(returnToMohrCoulomb(strength(true, 2e3), kLambda, kShear, corner, ep),
            kMohrCoulombApex);
  expectStress(corner, 2e3, 2e3, 2e3);
}

TEST(MohrCoulomb, CutOffAboveApexIsIgnored) {
  // sigma_t = 5e4 > apex 1e4: the cut-off never binds; the apex case above is unchanged.
  Real sigma[3] = {2e4, 1.5e4, 1e4}, ep[3];
  EXPECT_EQ(returnToMohrCoulomb(strength(true, 5e4), kLambda, kShear, sigma, ep), kMohrCoulombApex);
  expectStress(sigma, 1e4, 1e4, 1e4);
}

TEST(MohrCoulomb, ReturnIsIdempotent) {
  // Returned stresses of every region are admissible: returning them again changes nothing.
  const Real trials[][3] = {{-1e4, -5e4, -1e5}, {-1e4, -2e4, -1e5}, {-1e4, -9.8e4, -1e5},
                            {2e4, 1.5e4, 1e4},  {5e3, -2e3, -3e3},  {5e3, 4e3, 3e3}};
  for (const auto& trial : trials) {
    Real sigma[3] = {trial[0], trial[1], trial[2]}, ep[3];
    returnToMohrCoulomb(strength(true, 2e3), kLambda, kShear, sigma, ep);
    Real again[3] = {sigma[0], sigma[1], sigma[2]};
    EXPECT_EQ(returnToMohrCoulomb(strength(true, 2e3), kLambda, kShear, again, ep),
              kMohrCoulombElastic);
    expectStress(again, sigma[0], sigma[1], sigma[2], 0);
  }
}

TEST(MohrCoulomb, RandomTrialsSatisfyKuhnTucker) {
  // Many trials around the cone: the result is admissible (F1 <= 0, sorted), and the stress
  // correction is D times a plastic strain in the cone of the active flow directions, so
  // sigma_trial - sigma has the sign pattern of sum dlambda D b: checked through the
  // plastic work (sigma_trial - sigma) . D^-1 (sigma_trial - sigma) >= 0 and, for the plane
  // and edge regions, F1 = 0 exactly.
  unsigned state = 12345u;
  auto uniform = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<Real>(state >> 8) / static_cast<Real>(1u << 24);
  };
  for (int n = 0; n < 2000; ++n) {
    Real s[3] = {-2e5 * uniform() + 3e4, -2e5 * uniform() + 3e4, -2e5 * uniform() + 3e4};
    if (s[0] < s[1]) std::swap(s[0], s[1]);
    if (s[1] < s[2]) std::swap(s[1], s[2]);
    if (s[0] < s[1]) std::swap(s[0], s[1]);
    Real sigma[3] = {s[0], s[1], s[2]}, ep[3];
    const int region = returnToMohrCoulomb(strength(), kLambda, kShear, sigma, ep);
    EXPECT_LE(mohrCoulombYield(strength(), sigma), 1e-6);
    EXPECT_GE(sigma[0], sigma[1] - 1e-6);
    EXPECT_GE(sigma[1], sigma[2] - 1e-6);
    if (region == kMohrCoulombSurface) {
      EXPECT_NEAR(mohrCoulombYield(strength(), sigma), 0, 1e-6);
    }
    if (region == kMohrCoulombApex) expectStress(sigma, 1e4, 1e4, 1e4);
    const Real work =
        (s[0] - sigma[0]) * ep[0] + (s[1] - sigma[1]) * ep[1] + (s[2] - sigma[2]) * ep[2];
    EXPECT_GE(work, -1e-9);
  }
}

TEST(MohrCoulomb, PlaneStrainUpdateKeepsPrincipalDirections) {
  // Trial with shear: in-plane (xx, yy, xy) = (-5.5e4, -5.5e4, 4.5e4) has principal values
  // -5.5e4 +- 4.5e4 = (-1e4, -1e5) along the diagonals (cos 2theta = 0, sin 2theta = 1);
  // sigma_zz = -5e4 is the intermediate one. So the sorted trial is (-1e4, -5e4, -1e5), the
  // plane return of ReturnToPlaneHandValues: (-25625, -53125, -96875), and back:
  // xx = yy = (-25625 - 96875)/2 = -61250, xy = (-25625 + 96875)/2 = 35625, zz = -53125.
  const SolidSpec spec = solid();
  Real stress[4] = {-5.5e4, -5.5e4, -5e4, 4.5e4};
  const Real zero[4] = {0, 0, 0, 0};
  Real plastic = 0.5;
  const int region = mohrCoulombStressUpdate(spec, strength(), zero, stress, plastic);
  EXPECT_EQ(region, kMohrCoulombSurface);
  EXPECT_NEAR(stress[0], -61250, 1e-6);
  EXPECT_NEAR(stress[1], -61250, 1e-6);
  EXPECT_NEAR(stress[2], -53125, 1e-6);
  EXPECT_NEAR(stress[3], 35625, 1e-6);
  // Equivalent plastic strain of (6.25e-4, 0, -3.125e-4): mean 1.0416667e-4, deviator
  // (5.2083333e-4, -1.0416667e-4, -4.1666667e-4); sqrt(2/3 * 4.5572917e-7) = 5.5120e-4.
  EXPECT_NEAR(plastic - 0.5,
              std::sqrt(2.0 / 3.0 *
                        (std::pow(6.25e-4 - 3.125e-4 / 3, 2) + std::pow(3.125e-4 / 3, 2) +
                         std::pow(-3.125e-4 - 3.125e-4 / 3, 2))),
              1e-12);
}

TEST(MohrCoulomb, SolidModelDispatchSetsStateAndElasticStaysElastic) {
  const SolidSpec spec = solid();
  Real stress[4] = {-1e5, -1e5, -1e5, 0};
  const Real dstrain[4] = {0, -1e-4, 0, 0};  // d sigma = (-1e3, -3e3, -1e3, 0): still elastic
  Real plastic = 0;
  int state = 7;
  EXPECT_TRUE(updateEffectiveStress(spec, 0.0, dstrain, stress, plastic, state));
  EXPECT_EQ(state, kPlasticStateElastic);
  EXPECT_NEAR(stress[1], -1.03e5, 1e-6);
  EXPECT_EQ(plastic, 0.0);
}

TEST(MohrCoulomb, SuctionDependentStrengthIsUsed) {
  // Suction MC with c' = 0, phi' = 30 deg, dc_max = 2e4, B = 1, A = 0.1 rad, p_atm = 1e5:
  // at s = 5e4, c = 2e4 (1 - exp(-0.5)) = 7869.3868 Pa and phi = 0.5236 + 0.05 rad.
  SolidSpec spec = solid(SolidModel::SuctionMohrCoulomb);
  spec.cohesion = 0;
  spec.cohesion_increase_max = 2e4;
  spec.cohesion_suction_rate = 1;
  spec.friction_suction_rate = 0.1;
  spec.atmospheric_pressure = 1e5;
  const MohrCoulombStrength at_suction = mohrCoulombStrength(spec, 5e4);
  EXPECT_NEAR(at_suction.cohesion, 2e4 * (1 - std::exp(-0.5)), 1e-9);
  EXPECT_NEAR(at_suction.friction_angle, std::asin(0.5) + 0.05, 1e-14);
  // A trial that fails with c' = 0 but not with the suction strength: s1 = -1e4, s3 = -6e4.
  // k(phi') = 3: F1 = -3e4 + 6e4 = 3e4 > 0 (fails dry). With phi = 0.5736, sin = 0.54271,
  // k = 3.3730, c = 7869.39: F1 = -33730 + 6e4 - 2 * 7869.39 * 1.83657 = -2635 < 0: elastic.
  Real stress[4] = {-1e4, -6e4, -3e4, 0};
  const Real zero[4] = {0, 0, 0, 0};
  Real plastic = 0;
  int state = -1;
  updateEffectiveStress(spec, 5e4, zero, stress, plastic, state);
  EXPECT_EQ(state, kPlasticStateElastic);
  EXPECT_EQ(stress[1], -6e4);
  // Saturated (s = 0): c' = 0, phi' = 30 deg, the same trial returns to the plane.
  updateEffectiveStress(spec, 0.0, zero, stress, plastic, state);
  EXPECT_EQ(state, kPlasticStatePlastic);
  Real principal[3] = {stress[0], stress[2], stress[1]};
  MohrCoulombStrength saturated = mohrCoulombStrength(spec, 0.0);
  EXPECT_NEAR(mohrCoulombYield(saturated, principal), 0, 1e-6);
  EXPECT_GT(plastic, 0);
}

}  // namespace
}  // namespace argine
