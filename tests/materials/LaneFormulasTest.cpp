// The material formulas that run on kLanes points at once (templates on Real and Lanes,
// core/Lanes.hpp) give each lane the bits of the one-point formula: the math functions, the
// Jaumann rotation (w = 0 included), the elastic increment, the principal stresses with
// sigma_zz in each slot, and the Mohr-Coulomb admissibility test with and without the
// tension cut-off.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "argine/materials/KernelMath.hpp"
#include "argine/materials/LinearElastic.hpp"
#include "argine/materials/MohrCoulomb.hpp"
#include "argine/materials/ObjectiveStressRate.hpp"

namespace argine {
namespace {

enum : int { XX = 0, YY = 1, ZZ = 2, XY = 3 };  // the component order of LinearElastic.hpp

bool sameBits(Real a, Real b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(LaneFormulas, MathFunctionsAreTheScalarOnesPerLane) {
  const Lanes x = {2.0, 1e-300, 0.7, 12345.678};
  const Lanes negative = {-2.0, -0.0, 0.0, -1e10};
  const Lanes root = kmath::sqrt(x), magnitude = kmath::fabs(negative);
  for (int l = 0; l < kLanes; ++l) {
    EXPECT_TRUE(sameBits(root[l], std::sqrt(x[l]))) << l;
    EXPECT_TRUE(sameBits(magnitude[l], std::fabs(negative[l]))) << l;
  }
  const Lanes mixed = {1.0, INFINITY, std::nan(""), -1e308};
  const LaneMask finite = kmath::isFinite(mixed);
  const bool expected[kLanes] = {true, false, false, true};
  for (int l = 0; l < kLanes; ++l) EXPECT_EQ(finite[l] != 0, expected[l]) << l;
}

/// Random trial stresses around the surface of `strength`, with sigma_zz above, between and
/// below the in-plane pair, and ties.
void randomStresses(Real stress[][kStressComponents], int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  for (int p = 0; p < n; ++p) {
    stress[p][XX] = -2e4 + 2e4 * u(rng);
    stress[p][YY] = -2e4 + 2e4 * u(rng);
    stress[p][XY] = 1e4 * u(rng);
    stress[p][ZZ] = -2e4 + 3e4 * u(rng);
  }
  stress[0][XY] = 0, stress[0][ZZ] = stress[0][XX];  // ties
  stress[1][XX] = stress[1][YY], stress[1][XY] = 0;
}

TEST(LaneFormulas, StressFormulasGiveEachLaneTheOnePointBits) {
  constexpr int kPoints = 64;
  Real stress[kPoints][kStressComponents], dstrain[kPoints][kStressComponents];
  randomStresses(stress, kPoints, 17);
  randomStresses(dstrain, kPoints, 19);
  for (auto& d : dstrain)
    for (Real& c : d) c *= 1e-8;
  Real spin[kPoints];
  for (int p = 0; p < kPoints; ++p) spin[p] = p % 4 == 1 ? 0.0 : 1e-3 * (p - 30);
  stress[5][XY] = -0.0;  // a w = 0 lane keeps -0

  for (const bool cutoff : {false, true}) {
    MohrCoulombStrength strength;
    strength.cohesion = 3e3;
    strength.friction_angle = 0.5;
    strength.dilatancy_angle = 0.1;
    strength.tension_cutoff = cutoff;
    strength.tensile_strength = 1e3;
    const MohrCoulombFactors factors = mohrCoulombFactors(strength);
    int outside = 0, slots[3] = {0, 0, 0};
    for (int first = 0; first < kPoints; first += kLanes) {
      const auto lanesOf = [&](auto value) {  // value(l) of the points first .. first + 3
        return Lanes{value(0), value(1), value(2), value(3)};
      };
      Lanes s[kStressComponents], d[kStressComponents];
      for (int c = 0; c < kStressComponents; ++c) {
        s[c] = lanesOf([&](int l) { return stress[first + l][c]; });
        d[c] = lanesOf([&](int l) { return dstrain[first + l][c]; });
      }
      const Lanes w = lanesOf([&](int l) { return spin[first + l]; });
      rotateStressBySpin(w, s);
      Lanes ds[kStressComponents];
      elasticStressIncrement(1e7, 2 * 7.7e6, d, ds);
      for (int c = 0; c < kStressComponents; ++c) s[c] = s[c] + ds[c];
      Lanes sigma[3];
      sortedPrincipalStresses(inPlanePrincipal(s[XX], s[YY], s[XY]), s[ZZ], sigma);
      const MohrCoulombTrialCheck<Lanes> check = checkMohrCoulombTrial(strength, factors, sigma);
      for (int l = 0; l < kLanes; ++l) {
        const int p = first + l;
        Real one[kStressComponents], one_d[kStressComponents], one_ds[kStressComponents];
        for (int c = 0; c < kStressComponents; ++c) one[c] = stress[p][c], one_d[c] = dstrain[p][c];
        rotateStressBySpin(spin[p], one);
        elasticStressIncrement(1e7, 2 * 7.7e6, one_d, one_ds);
        for (int c = 0; c < kStressComponents; ++c) one[c] += one_ds[c];
        Real one_sigma[3];
        const int slot = sortedPrincipalStresses(inPlanePrincipal(one[XX], one[YY], one[XY]),
                                                 one[ZZ], one_sigma);
        const MohrCoulombTrialCheck<Real> one_check =
            checkMohrCoulombTrial(strength, factors, one_sigma);
        for (int c = 0; c < kStressComponents; ++c)
          EXPECT_TRUE(sameBits(s[c][l], one[c])) << "point " << p << " component " << c;
        for (int k = 0; k < 3; ++k) EXPECT_TRUE(sameBits(sigma[k][l], one_sigma[k])) << p;
        EXPECT_TRUE(sameBits(check.tolerance[l], one_check.tolerance)) << p;
        EXPECT_EQ(check.outside[l] != 0, one_check.outside) << p;
        outside += one_check.outside;
        ++slots[slot];
      }
    }
    // the sample covers both sides of the surface and sigma_zz in every slot
    EXPECT_GT(outside, 5);
    EXPECT_LT(outside, kPoints - 5);
    for (int k = 0; k < 3; ++k) EXPECT_GT(slots[k], 3) << k;
  }
  Real kept[kStressComponents] = {1, 2, 3, -0.0};
  rotateStressBySpin(0.0, kept);
  EXPECT_TRUE(std::signbit(kept[XY]));
}

}  // namespace
}  // namespace argine
