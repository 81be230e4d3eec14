// Jaumann rotation of the stress (ObjectiveStressRate.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "argine/materials/ObjectiveStressRate.hpp"

namespace argine {
namespace {

constexpr Real kPi = 3.14159265358979323846;

TEST(ObjectiveStressRate, SpinOfRigidRotation) {
  // v = omega (-y, x): dv_x/dy = -omega, dv_y/dx = omega -> w = dt (-omega - omega)/2.
  EXPECT_DOUBLE_EQ(spinIncrement(0.1, -2.0, 2.0), -0.2);
  // Pure shear v = (g y, 0): w = dt g / 2.
  EXPECT_DOUBLE_EQ(spinIncrement(0.1, 3.0, 0.0), 0.15);
}

TEST(ObjectiveStressRate, FirstOrderIsJaumann) {
  // sigma = (xx, yy, zz, xy) = (-3, -1, -2, 0.5); w = 1e-6:
  // d xx = 2 w xy = 1e-6, d yy = -1e-6, d xy = w (yy - xx) = 2e-6; the second-order terms
  // are w^2 (yy - xx) = 2e-12 and w^2 xy = 5e-13, below the 1e-11 tolerance.
  Real s[4] = {-3, -1, -2, 0.5};
  rotateStressBySpin(1e-6, s);
  EXPECT_NEAR(s[0], -3 + 1e-6, 1e-11);
  EXPECT_NEAR(s[1], -1 - 1e-6, 1e-11);
  EXPECT_EQ(s[2], -2);
  EXPECT_NEAR(s[3], 0.5 + 2e-6, 1e-11);
}

TEST(ObjectiveStressRate, RigidRotationKeepsInvariantsAndTurnsTheStress) {
  // A body stressed uniaxially along x (sigma_xx = -100, others 0 except zz = -30) rotates
  // counter-clockwise by 90 degrees in 1000 steps at omega = 1 rad/s. The stress must turn
  // with it: at the end sigma_yy = -100, sigma_xx = 0, xy = 0; trace and the in-plane
  // principal values are kept at every step.
  const int steps = 1000;
  const Real omega = 1.0, total = kPi / 2, dt = total / omega / steps;
  // The Hughes-Winget rotation angle per step is 2 atan(w/2), not w: the spin is integrated
  // with second-order accuracy, so the end angle is pi/2 up to O(dt^2).
  Real s[4] = {-100, 0, -30, 0};
  for (int n = 0; n < steps; ++n) {
    rotateStressBySpin(spinIncrement(dt, -omega, omega), s);
    const Real trace = s[0] + s[1];
    const Real radius = std::sqrt(0.25 * (s[0] - s[1]) * (s[0] - s[1]) + s[3] * s[3]);
    ASSERT_NEAR(trace, -100, 1e-10);
    ASSERT_NEAR(radius, 50, 1e-10);
    ASSERT_EQ(s[2], -30);
  }
  // End angle 1000 * 2 atan(w/2) with w = pi/2000: pi/2 - O(1e-7): sigma_yy = -100 cos^2(err).
  EXPECT_NEAR(s[1], -100, 1e-6);
  EXPECT_NEAR(s[0], 0, 1e-6);
  EXPECT_NEAR(s[3], 0, 1e-3);
  // Sense: after a small ccw rotation theta the tensor is R sigma R^T, xy = -100 sin cos < 0.
  Real t[4] = {-100, 0, 0, 0};
  rotateStressBySpin(spinIncrement(0.01, -1.0, 1.0), t);
  EXPECT_LT(t[3], 0);
}

}  // namespace
}  // namespace argine
