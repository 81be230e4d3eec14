// The implicit solver's conditions from the deck's hydraulic kinds (main's BoundarySpec): side
// sets and zones, time series evaluated at the end of the step, above-level options, first
// condition in deck order owns a shared node.
#include <gtest/gtest.h>

#include <map>

#include "SeepageScenes.hpp"
#include "argine/seepage/SeepageBoundary.hpp"

namespace argine {
namespace {

// One Quad4 column 0.5 m wide, 4 rows of 0.5 m: left nodes 0, 2, 4, 6, 8 at y = 0 ... 2,
// right nodes 1, 3, 5, 7, 9, top nodes 8, 9.
struct Column {
  test::SeepageColumn column{4, 0.5, 2.0, test::saturatedSoil(1e-4, 2.2e9)};
};

BoundarySpec sideSetCondition(const std::string& name, BoundaryKind kind, const std::string& set) {
  BoundarySpec spec;
  spec.name = name;
  spec.kind = kind;
  spec.side_set = set;
  return spec;
}

TimeSeriesSpec table(std::vector<Real> pairs) {
  TimeSeriesSpec series;
  series.source = TimeSeriesSpec::Source::Table;
  series.pairs = std::move(pairs);
  series.where = "test";
  return series;
}

std::map<int, Real> pressuresOf(const SeepageBoundaryConditions& c) {
  std::map<int, Real> out;
  for (std::size_t j = 0; j < c.pressure_nodes.size(); ++j)
    out[c.pressure_nodes[j]] = c.pressures[j];
  return out;
}

TEST(SeepageBoundaryPlan, TotalHeadAtTheStepEndWithSeepageFaceAboveAndRainOnTheRest) {
  Column scene;
  StageSpec stage;
  stage.name = "s";
  stage.gravity = 9.81;
  BoundarySpec river = sideSetCondition("river", BoundaryKind::TotalHead, "left");
  river.hydraulic.series = table({0, 0.5, 10, 1.5});  // H(5) = 1.0 m
  river.hydraulic.above = AboveLevel::SeepageFace;
  BoundarySpec rain = sideSetCondition("rain", BoundaryKind::Infiltration, "top");
  rain.hydraulic.series = table({0, 0, 10, 1e-4});  // q(5) = 5e-5 m/s
  stage.boundaries = {river, rain};
  const SeepageBoundaryPlan plan =
      seepageBoundaryPlan(scene.column.mesh, scene.column.points, stage);
  EXPECT_TRUE(plan.timeDependent());

  // Backward Euler step 0 -> 5 s: H = 1 m; p = 1000 x 9.81 x (1 - y) at y = 0, 0.5, 1:
  // 9810, 4905, 0 Pa; nodes 6, 8 (y = 1.5, 2) above the level: seepage face (switchable, 0).
  const SeepageBoundaryConditions be = plan.at(0, 5, 1.0);
  const auto p = pressuresOf(be);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_NEAR(p.at(0), 9810, 1e-9);
  EXPECT_NEAR(p.at(2), 4905, 1e-9);
  EXPECT_NEAR(p.at(4), 0, 1e-9);
  // Node 8 (top-left) belongs to the river (first in deck order): face node with supply 0;
  // node 9 gets the rain q(5) x L/2 = 5e-5 x 0.25 = 1.25e-5 m2/s, switchable (no ponding).
  std::map<int, std::pair<Real, int>> supply;
  for (std::size_t j = 0; j < be.supply_nodes.size(); ++j)
    supply[be.supply_nodes[j]] = {be.supplies[j], be.switchable[j]};
  ASSERT_EQ(supply.size(), 3u);
  EXPECT_EQ(supply.at(6).first, 0.0);
  EXPECT_EQ(supply.at(6).second, 1);
  EXPECT_EQ(supply.at(8).first, 0.0);
  EXPECT_NEAR(supply.at(9).first, 1.25e-5, 1e-20);
  EXPECT_EQ(supply.at(9).second, 1);

  // Crank-Nicolson 0 -> 5 s: the flux is the trapezoidal mean (0 + 5e-5)/2 x 0.25 = 6.25e-6.
  const SeepageBoundaryConditions cn = plan.at(0, 5, 0.5);
  for (std::size_t j = 0; j < cn.supply_nodes.size(); ++j)
    if (cn.supply_nodes[j] == 9) {
      EXPECT_NEAR(cn.supplies[j], 6.25e-6, 1e-20);
    }
  EXPECT_EQ(pressuresOf(cn).size(), 3u);  // the level is taken at the end by both
}

TEST(SeepageBoundaryPlan, AboveLevelLinearSuctionAndConstantPressureAreDirichlet) {
  Column scene;
  StageSpec stage;
  stage.gravity = 10;
  BoundarySpec river = sideSetCondition("river", BoundaryKind::TotalHead, "left");
  river.hydraulic.series.value = 1.0;  // constant H = 1 m
  river.hydraulic.above = AboveLevel::LinearSuction;
  stage.boundaries = {river};
  auto p = pressuresOf(seepageBoundaryPlan(scene.column.mesh, scene.column.points, stage).at(0, 1));
  ASSERT_EQ(p.size(), 5u);
  EXPECT_NEAR(p.at(8), 1000 * 10 * (1.0 - 2.0), 1e-9);  // -10 kPa at y = 2
  EXPECT_NEAR(p.at(6), -5000, 1e-9);
  stage.boundaries[0].hydraulic.above = AboveLevel::ConstantPressure;
  stage.boundaries[0].hydraulic.pressure_above = -300;
  p = pressuresOf(seepageBoundaryPlan(scene.column.mesh, scene.column.points, stage).at(0, 1));
  EXPECT_NEAR(p.at(8), -300, 1e-12);
  EXPECT_NEAR(p.at(6), -300, 1e-12);
  EXPECT_NEAR(p.at(2), 5000, 1e-9);
}

TEST(SeepageBoundaryPlan, ZoneTakesTheFreeSidesWithTheirMidpointInside) {
  Column scene;
  StageSpec stage;
  BoundarySpec face;
  face.name = "face";
  face.kind = BoundaryKind::SeepageFace;
  face.hydraulic.on_zone = true;
  face.hydraulic.zone.kind = ZoneSpec::Kind::HalfPlane;  // x >= 0.4: the right side only
  face.hydraulic.zone.point = {0.4, 0.0};
  face.hydraulic.zone.direction = {1.0, 0.0};
  BoundarySpec rain;  // ponding: always imposed, not switchable
  rain.name = "rain";
  rain.kind = BoundaryKind::Infiltration;
  rain.hydraulic.on_zone = true;  // everywhere: what the face left, i.e. left, top, bottom
  rain.hydraulic.series.value = 2e-5;
  rain.hydraulic.ponding = true;
  stage.boundaries = {face, rain};
  const SeepageBoundaryConditions c =
      seepageBoundaryPlan(scene.column.mesh, scene.column.points, stage).at(0, 1);
  std::map<int, std::pair<Real, int>> supply;
  for (std::size_t j = 0; j < c.supply_nodes.size(); ++j)
    supply[c.supply_nodes[j]] = {c.supplies[j], c.switchable[j]};
  ASSERT_EQ(supply.size(), 10u);  // every node is on the column's boundary
  for (const int node : {1, 3, 5, 7, 9}) {
    EXPECT_EQ(supply.at(node).first, 0.0);
    EXPECT_EQ(supply.at(node).second, 1);
  }
  // Node 2 (left, y = 0.5): two left sides of 0.5 m -> L = 0.5 m, q L = 1e-5 m2/s.
  EXPECT_NEAR(supply.at(2).first, 1e-5, 1e-20);
  EXPECT_EQ(supply.at(2).second, 0);
  // Node 0 (bottom-left corner): a left and a bottom side, 0.25 + 0.25 m -> 1e-5 m2/s.
  EXPECT_NEAR(supply.at(0).first, 1e-5, 1e-20);
}

TEST(SeepageBoundaryPlan, PressureLinearInXAtEachNodeAtTheStepEnd) {
  // The top nodes 8 (x = 0) and 9 (x = 0.5): p_L 100 Pa at x0 and a ramp 0 -> 1000 Pa over
  // 10 s at x1; at the end of a step to 5 s the end holds 500 Pa.
  Column scene;
  StageSpec stage;
  stage.name = "s";
  BoundarySpec top = sideSetCondition("top", BoundaryKind::PressureSeries, "top");
  top.hydraulic.series.value = 100;
  top.hydraulic.linear_in_x = true;
  top.hydraulic.x_range = {0.0, 0.5};
  top.hydraulic.end_series = table({0, 0, 10, 1000});
  stage.boundaries = {top};
  SeepageBoundaryPlan plan = seepageBoundaryPlan(scene.column.mesh, scene.column.points, stage);
  EXPECT_TRUE(plan.timeDependent());  // the end's series changes, the start's does not
  std::map<int, Real> p = pressuresOf(plan.at(0, 5, 1.0));
  EXPECT_DOUBLE_EQ(p.at(8), 100);
  EXPECT_DOUBLE_EQ(p.at(9), 500);
  // x0 = -0.5 m, x1 = 0.5 m: node 8 halfway, (100 + 500) / 2; node 9 at x1.
  stage.boundaries[0].hydraulic.x_range = {-0.5, 0.5};
  plan = seepageBoundaryPlan(scene.column.mesh, scene.column.points, stage);
  p = pressuresOf(plan.at(0, 5, 1.0));
  EXPECT_DOUBLE_EQ(p.at(8), 300);
  EXPECT_DOUBLE_EQ(p.at(9), 500);
}

TEST(SeepageBoundaryPlan, SolverTakesThePressureSeriesAtTheEndOfEachStep) {
  // No gravity, saturated: the top node is Dirichlet; after steps to 4 s and 10 s it holds
  // p(4) = 400 and p(10) = 1000 of the ramp 0 -> 1000 Pa over 10 s.
  test::SeepageColumn column(4, 0.5, 2.0, test::saturatedSoil(1e-4, 2.2e9));
  ImplicitSeepageSolver solver(column.mesh, column.points, column.materials);
  ImplicitSeepageSpec settings;
  settings.adaptive = false;
  settings.initial_step = 2;
  solver.setSettings(settings);
  solver.setGravity(0);
  StageSpec stage;
  BoundarySpec top = sideSetCondition("top", BoundaryKind::PressureSeries, "top");
  top.hydraulic.series = table({0, 0, 10, 1000});
  stage.boundaries = {top};
  solver.setBoundaryPlan(seepageBoundaryPlan(column.mesh, column.points, stage));
  solver.advanceTo(4);
  EXPECT_NEAR(solver.nodalPressure().at(9), 400, 1e-9);
  solver.advanceTo(10);
  EXPECT_NEAR(solver.nodalPressure().at(8), 1000, 1e-9);
}

}  // namespace
}  // namespace argine
