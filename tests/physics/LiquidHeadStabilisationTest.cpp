// The liquid head stabilisation against the Tri3 pressure checkerboard
// (physics/LiquidHeadStabilisation.hpp): hand values on four squares, liquid mass
// conservation, no action on a linear head field (saturated, or unsaturated with k varying by
// orders of magnitude), and the checkerboard damped.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "HeadScene.hpp"

namespace argine {
namespace {

using test::checkerboardSign;
using test::fourSquaresHandChange;
using test::HeadScene;
using test::hostCopy;
using test::kConductivity;

// 2 x 2 unit squares split along their rising diagonals: 8 triangles, one point at each
// centroid, saturated, no gravity, p_L 2500 + 1500 Pa below each diagonal and 2500 - 1500 Pa
// above it (the checkerboard). The node centres, gradients, slopes and the changes worked by
// hand (exact fractions) are in HeadScene.hpp (fourSquaresHandChange); they sum to zero.
TEST(LiquidHeadStabilisation, CheckerboardOnFourSquaresByHand) {
  HeadScene scene(2, 2, 1.0, 0.1);
  scene.setPressure([](Real x, Real y) { return 2500.0 + 1500.0 * checkerboardSign(x, y); });
  const auto position = hostCopy(scene.points.position);
  // Uncapped: dt g = 1e-3 * 0.1 * 1e-4 / 9.81 = 1.02e-9 kg/Pa < storage / 4 = 2.3e-8.
  const Real dt = 1e-3, conductance = 0.1 * kConductivity / 9.81;
  const std::vector<Real> change = scene.massChanges(dt, 0.0);
  for (int q = 0; q < scene.points.count; ++q) {
    const Real x = position(q, 0), y = position(q, 1);
    const Real expected = fourSquaresHandChange(x, y, dt * conductance);
    EXPECT_NE(expected, 0.0);
    EXPECT_NEAR(change[q], expected, 1e-9 * dt * conductance * 1500.0)
        << "point at " << x << ", " << y;
  }
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

// On a deforming skeleton the exchange must still move exactly its mass: the flux divergence
// is taken with the volume V^k the point has when the exchange is formed (updatePointStates
// multiplies it by V^k), not rescaled by (1 + d eps_vol).
TEST(LiquidHeadStabilisation, MovesTheSameMassOnADeformingSkeleton) {
  HeadScene scene(2, 2, 1.0, 0.1);
  scene.setPressure([](Real x, Real y) { return 2500.0 + 1500.0 * checkerboardSign(x, y); });
  const Real dt = 1e-3;
  const std::vector<Real> rigid = scene.massChanges(dt, 0.0);
  Kokkos::deep_copy(Kokkos::subview(scene.rates.strain_increment_p, Kokkos::ALL, 0), 0.02);
  const std::vector<Real> deforming = scene.massChanges(dt, 0.0);
  for (std::size_t q = 0; q < rigid.size(); ++q)
    EXPECT_NEAR(deforming[q], rigid[q], 1e-12 * std::fabs(rigid[q])) << "point " << q;
}

// Hydrostatic (phi uniform): nothing moves anywhere. A linear phi: nothing moves at any point,
// the edges included (each node's plane is phi itself).
TEST(LiquidHeadStabilisation, LeavesHydrostaticAndLinearHeadsAlone) {
  // alpha 1e-3: uncapped (dt g = 1e-11 kg/Pa < storage / 4 = 5.7e-11).
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
  for (int q = 0; q < scene.points.count; ++q)
    EXPECT_LT(std::fabs(change[q]), 1e-9 * scale)
        << "point at " << position(q, 0) << ", " << position(q, 1);
}

// A steady unsaturated flow: phi linear, p_L from -2 to -22 kPa, so k (van Genuchten-Mualem)
// and the conductances g_p vary by orders of magnitude across the block, three points per
// triangle. No point may gain or lose liquid: a plain g-weighted node average is pulled towards
// the wet points and the edges' inner points, and moved liquid here at O(h grad phi).
TEST(LiquidHeadStabilisation, LeavesASteadyUnsaturatedFlowAlone) {
  const Real dt = 1e-3, alpha = 0.1;
  HeadScene scene(8, 8, 0.05, alpha, /*three_per_triangle=*/true, ConductivityModel::Mualem);
  const Real gravity = 9.81;
  // phi = p_L + rho g y = -2000 - 50000 y + 9810 y: the head falls downwards, flow down.
  scene.setPressure([&](Real x, Real y) { return -2000.0 - 50000.0 * y - 3000.0 * x; });
  const auto k = hostCopy(scene.points.conductivity);
  Real k_min = k(0), k_max = k(0);
  for (int q = 0; q < scene.points.count; ++q) {
    k_min = std::min(k_min, k(q));
    k_max = std::max(k_max, k(q));
  }
  ASSERT_GT(k_max / k_min, 100.0);
  const std::vector<Real> change = scene.massChanges(dt, gravity);
  // The change of a point of the wettest conductance across a 1 Pa difference.
  const Real scale = dt * alpha * k_max / 9.81;
  const auto position = hostCopy(scene.points.position);
  for (int q = 0; q < scene.points.count; ++q)
    EXPECT_LT(std::fabs(change[q]), 1e-6 * scale)
        << "point at " << position(q, 0) << ", " << position(q, 1);
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
