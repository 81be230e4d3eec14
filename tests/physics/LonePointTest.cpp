// [2Phase][LargeDeformation] A point alone exchanges no liquid (interpolateVelocityGradients):
// its nodes carry only its own liquid, so the grid's relative velocity there is its own
// pressure pushing liquid to and fro between itself and empty space.
#include <gtest/gtest.h>

#include <cmath>

#include "Harness.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/NodeRecords.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"

namespace argine {
namespace {

using test::hostCopy;

/// `count` points of a wet material at the given local positions of element `element` of a
/// 3 x 3 quad mesh, 1 m cells; a grid with the solid at rest and the liquid flowing (a linear
/// field, so every point has a flux); their flux increments over dt = 1e-3 s.
PointRates fluxOf(const std::vector<std::array<Real, 2>>& local, bool condition_on_a_node) {
  Mesh mesh = test::rectangleMesh(3, 3, 3.0, 3.0, ElementType::Quad4);
  MaterialPoints points;
  points.allocate(static_cast<int>(local.size()));
  for (int p = 0; p < points.count; ++p) {
    points.element(p) = 4;  // the middle cell [1, 2]^2
    points.local(p, 0) = local[p][0];
    points.local(p, 1) = local[p][1];
    points.position(p, 0) = 1.5 + 0.5 * local[p][0];
    points.position(p, 1) = 1.5 + 0.5 * local[p][1];
    points.volume(p) = 0.25;
    points.mass_solid(p) = 400;
    points.mass_liquid(p) = 100;
    points.density_liquid(p) = 1000;
    points.porosity(p) = 0.4;
    points.saturation(p) = 1;
    points.conductivity(p) = 1e-4;
  }
  PointShapes shapes;
  evaluatePointShapes(mesh, points, shapes);
  ActiveNodes active(mesh.numNodes());
  active.rebuild(mesh, points);
  GridFields grid;
  grid.allocate(mesh.numNodes());
  NodeRecords records;
  Kokkos::View<int*, MemSpace> liquid("liquid_m", 1);
  liquid(0) = 1;
  mapPointsToGrid(points, shapes, liquid, 0.0, TransferSettings{}, active, records, grid);
  computeNodalVelocities(active, grid);
  const auto X = hostCopy(mesh.coordinates);
  for (int i = 0; i < mesh.numNodes(); ++i) {
    grid.velocity_liquid_i(i, 0) = 1e-3 * X(i, 0);  // div v_L = 2e-3 1/s, v_S = 0
    grid.velocity_liquid_i(i, 1) = 1e-3 * X(i, 1);
  }
  Kokkos::View<unsigned char*, MemSpace> conditioned("conditioned_i", mesh.numNodes());
  if (condition_on_a_node) conditioned(mesh.connectivity(4, 2)) = 1;
  PointRates rates;
  interpolateVelocityGradients(points, shapes, liquid, active, grid, records, 1e-3, rates,
                               conditioned);
  return rates;
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
