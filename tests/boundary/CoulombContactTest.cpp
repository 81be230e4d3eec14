// [Boundary][Contact] Coulomb's projection at a rigid wall (CoulombContact.hpp) against
// hand-computed values: lift-off, slip, stick, an inclined wall; the total-normal-force
// coefficient and the liquid's normal lock.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "argine/boundary/CoulombContact.hpp"

namespace argine {
namespace {

std::array<Real, 2> project(std::array<Real, 2> v, std::array<Real, 2> n, Real mu) {
  std::array<Real, 2> out{};
  coulombWallVelocity(v.data(), n.data(), mu, out.data());
  return out;
}

TEST(CoulombWallVelocity, LiftOffAndMotionAlongTheWallAreFree) {
  // Floor below the soil: n = (0, -1) points into the wall. Moving up (v . n = -0.5 < 0)
  // or along the floor (v . n = 0): the wall cannot pull, nothing changes, whatever mu.
  EXPECT_EQ(project({1.0, 0.5}, {0.0, -1.0}, 100.0), (std::array<Real, 2>{1.0, 0.5}));
  EXPECT_EQ(project({2.0, 0.0}, {0.0, -1.0}, 100.0), (std::array<Real, 2>{2.0, 0.0}));
}

TEST(CoulombWallVelocity, SlipRemovesTheNormalPartAndReducesTheTangentialByMuVn) {
  // v = (2, -0.5) into the floor: v_n = 0.5, v_t = (2, 0). mu = 0.3: |v_t| 2 - 0.3 x 0.5 =
  // 1.85; mu = 0 (smooth): the normal part alone goes.
  const auto slip = project({2.0, -0.5}, {0.0, -1.0}, 0.3);
  EXPECT_DOUBLE_EQ(slip[0], 1.85);
  EXPECT_EQ(slip[1], 0.0);
  EXPECT_EQ(project({2.0, -0.5}, {0.0, -1.0}, 0.0), (std::array<Real, 2>{2.0, 0.0}));
}

TEST(CoulombWallVelocity, SticksWhenTheTangentialSpeedIsAtMostMuVn) {
  // v = (0.3, -0.5): |v_t| = 0.3 <= mu v_n = 0.7 x 0.5 = 0.35: stick. Exactly at the limit
  // (mu = 0.6: mu v_n = 0.3) it sticks too; just above (mu = 0.59) it slips by 0.005.
  EXPECT_EQ(project({0.3, -0.5}, {0.0, -1.0}, 0.7), (std::array<Real, 2>{0.0, 0.0}));
  EXPECT_EQ(project({0.25, -0.5}, {0.0, -1.0}, 0.5), (std::array<Real, 2>{0.0, 0.0}));
  const auto barely = project({0.3, -0.5}, {0.0, -1.0}, 0.59);
  EXPECT_NEAR(barely[0], 0.005, 1e-15);
  EXPECT_EQ(barely[1], 0.0);
  EXPECT_EQ(project({0.0, -0.5}, {0.0, -1.0}, 0.0), (std::array<Real, 2>{0.0, 0.0}));
}

TEST(CoulombWallVelocity, InclinedWall) {
  // A 30 degree slope falling to the right: n = (-sin 30, -cos 30) = (-1/2, -sqrt3/2),
  // tangent down-slope (cos 30, -sin 30). v = (1, -1): v_n = (sqrt3 - 1)/2, |v_t| =
  // sqrt(2 - v_n^2) = (1 + sqrt3)/2; mu = 1/2 leaves |v_t| - v_n/2 = (3 + sqrt3)/4 along
  // the tangent's direction (v_t = (1 + sqrt3)/2 (cos 30, -sin 30)).
  const Real r3 = std::sqrt(3.0);
  const std::array<Real, 2> n{-0.5, -r3 / 2};
  const auto out = project({1.0, -1.0}, n, 0.5);
  const Real speed = (3 + r3) / 4;
  EXPECT_NEAR(out[0], speed * r3 / 2, 1e-15);
  EXPECT_NEAR(out[1], -speed * 0.5, 1e-15);
  EXPECT_NEAR(out[0] * n[0] + out[1] * n[1], 0.0, 1e-15);
  // A slower body sticks: v = (0.2, -1), v_n = -0.1 + sqrt3/2 = 0.766, v_t = 0.2 cos 30 +
  // sin 30 = 0.673 <= 1 x v_n.
  EXPECT_EQ(project({0.2, -1.0}, n, 1.0), (std::array<Real, 2>{0.0, 0.0}));
  // Leaving the slope along its outward normal's opposite: free.
  EXPECT_EQ(project({0.5, r3 / 2}, n, 1.0), (std::array<Real, 2>{0.5, r3 / 2}));
}

TEST(CoulombWallVelocity, TotalNormalForceAndTheLiquidLock) {
  // The wall stops M_S + M_L = 600 + 400 kg: the solid (600 kg) sees mu (1000 / 600).
  EXPECT_DOUBLE_EQ(solidFrictionCoefficient(0.3, 600.0, 400.0), 0.5);
  EXPECT_DOUBLE_EQ(solidFrictionCoefficient(0.3, 600.0, 0.0), 0.3);
  // (v_L - v_S) . n = 0 keeps the liquid's tangential part: n = (0.6, -0.8).
  const Real n[2] = {0.6, -0.8}, solid[2] = {1.0, 2.0};
  Real liquid[2] = {3.0, -1.0};
  matchNormalComponent(solid, n, liquid);
  EXPECT_NEAR((liquid[0] - solid[0]) * n[0] + (liquid[1] - solid[1]) * n[1], 0.0, 1e-15);
  EXPECT_NEAR(liquid[0] * 0.8 + liquid[1] * 0.6, 3.0 * 0.8 - 1.0 * 0.6, 1e-15);  // tangent
}

}  // namespace
}  // namespace argine
