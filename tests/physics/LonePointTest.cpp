// [2Phase][LargeDeformation] A point alone exchanges no liquid (interpolateVelocityGradients):
// its nodes carry only its own liquid, so the grid's relative velocity there is its own
// pressure pushing liquid to and fro between itself and empty space.
#include <gtest/gtest.h>

#include <cmath>

#include "Harness.hpp"
#include "WetPointsFlux.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"

namespace argine {
namespace {

/// Points in the middle cell [1, 2]^2 of a 3 x 3 grid (linear quad4 shapes), the liquid
/// flowing in a linear field (so every point has a flux), optionally a hydraulic condition on
/// one of the cell's nodes: their flux increments over dt = 1e-3 s.
PointRates fluxOf(const std::vector<std::array<Real, 2>>& local, bool condition_on_a_node) {
  std::vector<std::array<Real, 2>> inside;
  for (const auto& xi : local) inside.push_back({(xi[0] + 1) / 2, (xi[1] + 1) / 2});
  const int upper_right_of_the_cell = 2 + 4 * 2;  // node (2, 2) of 4 x 4
  return test::wetPointsFlux(
      3, ShapeFamily::Linear, 1, 1, inside,
      [](Real x, Real y) {
        return std::array<Real, 2>{1e-3 * x, 1e-3 * y};
      },
      condition_on_a_node ? std::vector<int>{upper_right_of_the_cell} : std::vector<int>{});
}

TEST(LonePoint, APointAloneHasNoRelativeFlux) {
  const PointRates alone = fluxOf({{0.2, -0.3}}, false);
  EXPECT_EQ(alone.content_flux_divergence_increment_p(0), 0.0);
  EXPECT_EQ(alone.liquid_divergence_increment_p(0), 0.0);  // = div v_S = 0
  // Two points in the cell share its nodes: the liquid flows (div(c w) = c div w here).
  const PointRates pair = fluxOf({{0.2, -0.3}, {-0.5, 0.5}}, false);
  for (int p = 0; p < 2; ++p) {
    EXPECT_NEAR(pair.liquid_divergence_increment_p(p), 2e-6, 1e-15);
    EXPECT_NEAR(pair.content_flux_divergence_increment_p(p), 400 * 2e-6, 1e-9);
  }
  // A node under a hydraulic condition: the point drains or fills through it.
  const PointRates conditioned = fluxOf({{0.2, -0.3}}, true);
  EXPECT_NEAR(conditioned.content_flux_divergence_increment_p(0), 400 * 2e-6, 1e-9);
}

/// A single wet point resting on a fixed floor in an empty 0.6 m x 0.6 m grid, 0.3 s of
/// gravity: its liquid mass relative to the start.
Real liquidMassAfterResting(PhaseModel phase, Real pressure, ShapeFamily family,
                            TransferScheme scheme) {
  MaterialSpec clod = test::elasticMaterial("clod", phase, 1e7, 0.3, 0.4, 1e-4, 8e7);
  clod.retention.linear_slope = 4e-6;
  clod.initial.liquid_pressure = pressure;
  Mesh mesh = test::rectangleMesh(6, 6, 0.6, 0.6, ElementType::Quad4);
  mesh.structured.cells[0] = mesh.structured.cells[1] = 6;
  mesh.structured.spacing[0] = mesh.structured.spacing[1] = 0.1;
  mesh.shape_functions = family;
  MaterialPoints points;
  points.allocate(1);
  points.element(0) = 2;  // bottom row
  points.local(0, 0) = points.local(0, 1) = -0.5;
  points.position(0, 0) = points.initial_position(0, 0) = 0.225;
  points.position(0, 1) = points.initial_position(0, 1) = 0.025;
  points.volume(0) = points.initial_volume(0) = 0.0025;
  std::vector<MaterialSpec> materials{clod};
  initialisePointState(materials, points);
  const Real mass0 = points.mass_liquid(0);
  ExplicitTwoPhaseSolver solver(mesh, points, materials);
  StageSpec stage = test::makeStage("rest", SolverKind::Explicit, 9.81, 0.0,
                                    {test::solidFixity("floor", "bottom", true, true)});
  stage.transfer = scheme;
  solver.beginStage(stage);
  test::runUntil(solver, 0.3);
  return points.mass_liquid(0) / mass0;
}

Real tryResting(PhaseModel phase, Real pressure, ShapeFamily family, TransferScheme scheme) {
  try {
    return liquidMassAfterResting(phase, pressure, family, scheme);
  } catch (const std::exception& e) {
    ADD_FAILURE() << e.what();
    return -1;
  }
}

TEST(LonePoint, APointRestingAloneKeepsItsLiquid) {
  // It vibrates on the floor (its own stress against its weight); before, its liquid went to
  // and fro between it and the empty cells around it: a saturated point at +10 kPa gained
  // 1.2e-4 of its liquid in 0.01 s, an unsaturated one at 10 kPa suction lost 8.7e-4.
  for (const auto family : {ShapeFamily::Linear, ShapeFamily::BSpline})
    for (const auto scheme : {TransferScheme::Flip, TransferScheme::Tpic}) {
      SCOPED_TRACE(std::string(family == ShapeFamily::Linear ? "linear" : "B-spline") +
                   (scheme == TransferScheme::Flip ? " FLIP" : " TPIC"));
      EXPECT_EQ(tryResting(PhaseModel::Saturated, 1e4, family, scheme), 1.0);
      EXPECT_EQ(tryResting(PhaseModel::Unsaturated, -1e4, family, scheme), 1.0);
    }
}

}  // namespace
}  // namespace argine
