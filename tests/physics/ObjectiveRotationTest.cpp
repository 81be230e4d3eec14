// [Plasticity] The point update applies the Jaumann rotation of the step's spin
// (PointRates::spin_increment_p) before the constitutive increment.
#include <gtest/gtest.h>

#include <cmath>

#include "Harness.hpp"
#include "argine/physics/PointUpdates.hpp"

namespace argine {
namespace {

using test::hostCopy;

TEST(ObjectiveRotation, RigidRotationOfStressedPointsKeepsInvariants) {
  // Two dry points (linear elastic and Mohr-Coulomb, both stressed inside the elastic range)
  // spin at omega = 1 rad/s for a quarter turn in 500 steps with zero strain increments: the
  // stress turns with them (sigma_xx <-> sigma_yy, the shear changes sign twice and returns to
  // zero) and the in-plane invariants are kept.
  MaterialSpec elastic = test::elasticMaterial("elastic", PhaseModel::Dry, 1e7, 0.3, 0.4);
  MaterialSpec plastic = elastic;
  plastic.name = "mc";
  plastic.solid.model = SolidModel::MohrCoulomb;
  plastic.solid.cohesion = 1e4;
  plastic.solid.friction_angle = 0.5;
  const MaterialTable table({elastic, plastic});
  MaterialPoints points;
  points.allocate(2);
  auto material = hostCopy(points.material);
  auto stress = hostCopy(points.stress_effective);
  auto volume = hostCopy(points.volume);
  auto porosity = hostCopy(points.porosity);
  for (int p = 0; p < 2; ++p) {
    material(p) = p;
    volume(p) = 1;
    porosity(p) = 0.4;
    stress(p, XX) = -1e5, stress(p, YY) = -4e4, stress(p, ZZ) = -6e4, stress(p, XY) = 0;
  }
  Kokkos::deep_copy(points.material, material);
  Kokkos::deep_copy(points.stress_effective, stress);
  Kokkos::deep_copy(points.volume, volume);
  Kokkos::deep_copy(points.porosity, porosity);
  PointRates rates;
  rates.allocate(2);
  const int steps = 500;
  const Real dt = 0.5 * 3.14159265358979323846 / steps;
  Kokkos::deep_copy(rates.spin_increment_p, spinIncrement(dt, -1.0, 1.0));
  for (int n = 0; n < steps; ++n) {
    updatePointStates(table, rates, points);
    const auto s = hostCopy(points.stress_effective);
    for (int p = 0; p < 2; ++p) {
      ASSERT_NEAR(s(p, XX) + s(p, YY), -1.4e5, 1e-6);
      ASSERT_NEAR(0.25 * std::pow(s(p, XX) - s(p, YY), 2) + s(p, XY) * s(p, XY), 9e8, 1e-3);
      ASSERT_EQ(s(p, ZZ), -6e4);
    }
  }
  // A quarter turn: xx and yy exchanged (angle error O(dt^2) ~ 1e-6 rad -> ~0.1 Pa).
  const auto s = hostCopy(points.stress_effective);
  const auto state = hostCopy(points.plastic_state);
  for (int p = 0; p < 2; ++p) {
    EXPECT_NEAR(s(p, XX), -4e4, 1.0);
    EXPECT_NEAR(s(p, YY), -1e5, 1.0);
    EXPECT_NEAR(s(p, XY), 0, 1.0);
    EXPECT_EQ(state(p), kPlasticStateElastic);
  }
}

}  // namespace
}  // namespace argine
