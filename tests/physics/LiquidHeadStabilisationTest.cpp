// The liquid head stabilisation against the Tri3 pressure checkerboard
// (physics/LiquidHeadStabilisation.hpp): hand values on two triangles, liquid mass
// conservation, no action on a linear head field, and the checkerboard damped.

#include <gtest/gtest.h>

#include <cmath>

#include "HeadScene.hpp"

namespace argine {
namespace {

using test::HeadScene;
using test::hostCopy;
using test::kConductivity;

// Two triangles of a unit square, both saturated, no gravity, p_L 4000 and 1000 Pa: with
// equal conductances the diagonal nodes average the two, the other node of each triangle
// keeps its own value, so phi_bar_1 = (2 phi_1 + phi_2) / 3 and dM_1 = -dt g (phi_1 - phi_2)/3.
TEST(LiquidHeadStabilisation, TwoTrianglesByHand) {
  HeadScene scene(1, 1, 1.0, 0.1);
  int q = 0;
  scene.setPressure([&](Real, Real) { return q++ == 0 ? 4000.0 : 1000.0; });
  const int high = 0, low = 1;
  // Uncapped: dt g = 1e-3 * 0.1 * 1e-4 / 9.81 = 1.02e-9 kg/Pa < storage / 4 = 2.3e-8.
  const Real dt = 1e-3, conductance = 0.1 * kConductivity / 9.81;
  std::vector<Real> change = scene.massChanges(dt, 0.0);
  EXPECT_NEAR(change[high], -dt * conductance * 3000.0 / 3, 1e-18);
  EXPECT_NEAR(change[low], dt * conductance * 3000.0 / 3, 1e-18);
  // Capped: dt = 1 s gives dt g = 1e-6 > storage / 4, so g = storage / (4 dt): a quarter of
  // the way to the nodal average.
  // The weights then differ with rho_L(p_L) (1.4e-6 apart), so the diagonal nodes hold
  // (g_1 phi_1 + g_2 phi_2) / (g_1 + g_2) and dM_1 = -dt g_1 (2/3) g_2 (phi_1 - phi_2) / (g_1 +
  // g_2).
  change = scene.massChanges(1.0, 0.0);
  const Real g1 = 0.25 * scene.saturatedStorage(high), g2 = 0.25 * scene.saturatedStorage(low);
  const Real expected = -g1 * 2.0 / 3 * g2 * 3000.0 / (g1 + g2);
  EXPECT_NEAR(change[high], expected, 1e-12 * std::fabs(expected));
  EXPECT_NEAR(change[low], -change[high], 1e-12 * std::fabs(expected));
}

// A partly saturated block with an irregular pressure field: the exchange moves liquid, and
// none is made or lost.
TEST(LiquidHeadStabilisation, ConservesTheLiquidMass) {
  HeadScene scene(8, 6, 0.05, 1.0);
  scene.setPressure([](Real x, Real y) {
    return 3000 * std::sin(37 * x + 11 * y) + 9810 * (0.15 - y) + 800 * std::cos(53 * x * y);
  });
  const std::vector<Real> change = scene.massChanges(1e-3, 9.81);
  Real sum = 0, moved = 0;
  for (const Real dm : change) {
    sum += dm;
    moved += std::fabs(dm);
  }
  EXPECT_GT(moved, 0.0);
  EXPECT_LT(std::fabs(sum), 1e-12 * moved);
}

// Hydrostatic (phi uniform): nothing moves anywhere. A linear phi: nothing moves at the points
// whose three nodes are inside the body (the node averages reproduce phi there).
TEST(LiquidHeadStabilisation, LeavesHydrostaticAndLinearHeadsAlone) {
  // alpha 1e-3: uncapped (dt g = 1e-11 kg/Pa < storage / 4 = 5.7e-11), so every point has the
  // same conductance and the node averages are plain averages of the centroid values.
  const Real dt = 1e-3, alpha = 1e-3;
  HeadScene scene(8, 8, 0.05, alpha);
  const Real gravity = 9.81, rho_g = 1000 * gravity;
  scene.setPressure([&](Real, Real y) { return rho_g * (0.6 - y); });  // saturated
  std::vector<Real> change = scene.massChanges(dt, gravity);
  const Real scale = dt * alpha * kConductivity / 9.81 * 100;  // the change of a 100 Pa jump
  for (const Real dm : change) EXPECT_LT(std::fabs(dm), 1e-9 * scale);

  scene.setPressure([&](Real x, Real y) { return rho_g * (0.6 - y) + 2000 * x + 500 * y; });
  change = scene.massChanges(dt, gravity);
  const auto position = hostCopy(scene.points.position);
  int interior = 0;
  for (int q = 0; q < scene.points.count; ++q) {
    const Real x = position(q, 0), y = position(q, 1);
    if (x < 0.05 || x > 0.35 || y < 0.05 || y > 0.35) continue;  // an element off the edge
    ++interior;
    EXPECT_LT(std::fabs(change[q]), 1e-9 * scale) << "point at " << x << ", " << y;
  }
  EXPECT_EQ(interior, 2 * 6 * 6);
}

// The P1-P0 checkerboard: +-1 kPa between neighbouring triangles on a hydrostatic saturated
// block. Every interior point moves towards the mean, and stepping the exchange (the point
// pressure updated from its mass, as the explicit step does) removes the pattern.
TEST(LiquidHeadStabilisation, DampsTheCheckerboard) {
  HeadScene scene(8, 8, 0.05, 0.1);
  const Real gravity = 9.81, rho_g = 1000 * gravity;
  const auto element = hostCopy(scene.points.element);
  std::vector<Real> jump(scene.points.count);
  for (int q = 0; q < scene.points.count; ++q) jump[q] = element(q) % 2 == 0 ? 1000 : -1000;
  std::vector<Real> pressure(scene.points.count);
  const auto position = hostCopy(scene.points.position);
  for (int q = 0; q < scene.points.count; ++q)
    pressure[q] = 20000 + rho_g * (0.4 - position(q, 1)) + jump[q];
  // The amplitude of the pattern: the projection of p_L - hydrostatic on the jumps (1 kPa at
  // the start), and the rms of p_L - hydrostatic (which also holds the smooth field left
  // where the pattern meets the edges; the stabilisation conserves mass, so that one only
  // spreads).
  Real rms = 0;
  auto checkerboard = [&]() {
    Real sum = 0, along = 0;
    for (int q = 0; q < scene.points.count; ++q) {
      const Real d = pressure[q] - 20000 - rho_g * (0.4 - position(q, 1));
      sum += d * d;
      along += d * jump[q];
    }
    rms = std::sqrt(sum / scene.points.count);
    return along / (1000 * scene.points.count);
  };
  const Real before = checkerboard();
  ASSERT_NEAR(before, 1000.0, 1e-6);
  ASSERT_NEAR(rms, 1000.0, 1e-6);
  int q_at = 0;
  scene.setPressure([&](Real, Real) { return pressure[q_at++]; });
  const std::vector<Real> first = scene.massChanges(1e-3, gravity);
  for (int q = 0; q < scene.points.count; ++q) {
    const Real x = position(q, 0), y = position(q, 1);
    if (x < 0.05 || x > 0.35 || y < 0.05 || y > 0.35) continue;
    EXPECT_LT(first[q] * jump[q], 0.0) << "point at " << x << ", " << y;
  }
  for (int step = 0; step < 20; ++step) {
    const std::vector<Real> change = scene.massChanges(1e-3, gravity);
    for (int q = 0; q < scene.points.count; ++q)
      pressure[q] += change[q] / scene.saturatedStorage(q);
    const Real last_rms = rms;
    checkerboard();
    EXPECT_LT(rms, last_rms) << "step " << step;
    q_at = 0;
    scene.setPressure([&](Real, Real) { return pressure[q_at++]; });
  }
  const Real after = checkerboard();
  std::printf("checkerboard amplitude %.1f Pa -> %.1f Pa in 20 steps (rms %.1f Pa)\n", before,
              after, rms);
  EXPECT_LT(after, 0.05 * before);
}

}  // namespace
}  // namespace argine
