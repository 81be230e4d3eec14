// [Boundary] Hydraulic conditions on the moving boundary: time series, zones, free-boundary
// detection, side integration of heads and pressures, the flux correction (4.53-4.59) and
// the per-step plan. Every expected value is computed by hand in the comments.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#include "../transfer/TestScenes.hpp"
#include "argine/boundary/FreeBoundary.hpp"
#include "argine/boundary/HydraulicAlgebra.hpp"
#include "argine/boundary/HydraulicConditions.hpp"
#include "argine/boundary/LinearInX.hpp"
#include "argine/boundary/NodalConstraints.hpp"
#include "argine/boundary/TimeSeries.hpp"
#include "argine/boundary/Zone.hpp"
#include "argine/core/Error.hpp"

namespace argine {
namespace {

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = std::string(ARGINE_BINARY_DIR) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// ------------------------------------------------------------------ time series

TEST(TimeSeries, InterpolatesLinearlyAndClampsTheEnds) {
  // rows (0, 0.2), (150, 0.85), (300, 0.4): at 75 s halfway 0.525; at 225 s 0.625
  const TimeSeries river = TimeSeries::fromPairs({0, 0.2, 150, 0.85, 300, 0.4}, "key");
  EXPECT_DOUBLE_EQ(river.at(-5), 0.2);
  EXPECT_DOUBLE_EQ(river.at(0), 0.2);
  EXPECT_NEAR(river.at(75), 0.525, 1e-15);
  EXPECT_DOUBLE_EQ(river.at(150), 0.85);
  EXPECT_NEAR(river.at(225), 0.625, 1e-15);
  EXPECT_DOUBLE_EQ(river.at(400), 0.4);
  EXPECT_DOUBLE_EQ(TimeSeries::constant(-2e-6).at(1e9), -2e-6);
}

TEST(TimeSeries, ShiftedMovesEveryRowOntoTheSimulationClock) {
  // rows (0, 2.0), (1, 0.5) shifted by 3 s: (3, 2.0), (4, 0.5); at 3.5 s halfway: 1.25;
  // before 3 s the first value 2.0 holds (unshifted, 0.5 would hold from 1 s on).
  const TimeSeries head = TimeSeries::fromPairs({0, 2.0, 1, 0.5}, "key").shifted(3.0);
  EXPECT_DOUBLE_EQ(head.times()[0], 3.0);
  EXPECT_DOUBLE_EQ(head.times()[1], 4.0);
  EXPECT_DOUBLE_EQ(head.at(2.0), 2.0);
  EXPECT_DOUBLE_EQ(head.at(3.5), 1.25);
  EXPECT_DOUBLE_EQ(head.at(9.0), 0.5);
  EXPECT_DOUBLE_EQ(TimeSeries::constant(7.0).shifted(3.0).at(0.0), 7.0);
}

TEST(TimeSeries, ReadsAGaugeCsvWithHeaderAndComments) {
  const std::string path =
      writeFile("gauge_ok.csv", "# river gauge\ntime (s), level (m)\n0, 1.0\n10;2.0\n\n20\t4.0\n");
  const TimeSeries gauge = TimeSeries::fromCsvFile(path, "Stages/s/Boundary Conditions/r/File");
  ASSERT_EQ(gauge.times().size(), 3u);
  EXPECT_DOUBLE_EQ(gauge.at(5), 1.5);   // (1 + 2) / 2
  EXPECT_DOUBLE_EQ(gauge.at(15), 3.0);  // (2 + 4) / 2
}

TEST(TimeSeries, BadFilesAreInputErrorsNamingKeyAndFile) {
  const std::string key = "Stages/flood/Boundary Conditions/river/Total Head File";
  auto expectError = [&](const std::string& path, const std::string& fragment) {
    try {
      TimeSeries::fromCsvFile(path, key);
      FAIL() << "expected InputError for " << path;
    } catch (const InputError& error) {
      EXPECT_EQ(error.where(), key);
      EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
    }
  };
  expectError(std::string(ARGINE_BINARY_DIR) + "/no_such_gauge.csv", "cannot open");
  expectError(writeFile("gauge_back.csv", "t,v\n0,1\n10,2\n5,3\n"), "increase strictly");
  expectError(writeFile("gauge_text.csv", "t,v\n0,1\n10,high\n"), "line 3");
  expectError(writeFile("gauge_empty.csv", "t,v\n"), "no (time, value) rows");
  EXPECT_THROW(TimeSeries::fromPairs({0, 1, 5}, key), InputError);     // odd count
  EXPECT_THROW(TimeSeries::fromPairs({0, 1, 0, 2}, key), InputError);  // repeated time
}

// ------------------------------------------------------------------ zones

TEST(Zone, HalfPlaneBoxAndPolylineBand) {
  ZoneSpec spec;
  spec.kind = ZoneSpec::Kind::HalfPlane;  // x < 8 m
  spec.point = {8, 0};
  spec.direction = {-3, 0};  // normalised by makeZone
  const Zone left = makeZone(spec);
  EXPECT_TRUE(zoneContains(left, 7.9, 100));
  EXPECT_TRUE(zoneContains(left, 8.0, -3));  // edge included
  EXPECT_FALSE(zoneContains(left, 8.1, 0));

  spec.kind = ZoneSpec::Kind::Box;
  spec.lower_left = {0, 1};
  spec.upper_right = {2, 3};
  const Zone box = makeZone(spec);
  EXPECT_TRUE(zoneContains(box, 1, 2));
  EXPECT_FALSE(zoneContains(box, 1, 0.5));
  EXPECT_FALSE(zoneContains(box, 2.5, 2));

  // polyline (0,0)-(4,0)-(4,3): (2, 1) is 1 m from the first segment; (5, 1.5) 1 m from the
  // second; (6, 5) is sqrt(2^2 + 2^2) = 2.83 m from the end vertex (4, 3)
  spec.kind = ZoneSpec::Kind::PolylineBand;
  spec.vertices = {{0, 0}, {4, 0}, {4, 3}};
  spec.width = 1.0;
  const Zone band = makeZone(spec);
  EXPECT_NEAR(distanceToPolyline(band.vertices, 2, 1), 1.0, 1e-15);
  EXPECT_NEAR(distanceToPolyline(band.vertices, 5, 1.5), 1.0, 1e-15);
  EXPECT_NEAR(distanceToPolyline(band.vertices, 6, 5), std::sqrt(8.0), 1e-14);
  EXPECT_TRUE(zoneContains(band, 2, 1));
  EXPECT_TRUE(zoneContains(band, 3.5, 2));
  EXPECT_FALSE(zoneContains(band, 6, 5));
  EXPECT_FALSE(zoneContains(band, 2, -1.01));
}

// ------------------------------------------------------------------ free boundary

TEST(FreeBoundary, BottomRowOfAQuadMesh) {
  // 3 x 2 quads of 1 m; points only in the bottom row (elements 0, 1, 2). Free sides: 3
  // bottom (mesh edge), left of 0 and right of 2 (mesh edge), 3 tops (empty neighbour): 8.
  // Boundary nodes: the 4 bottom and 4 middle nodes (0-3, 4-7). Top sides: normal (0, 1).
  const Mesh mesh = test::rectangleMesh(3, 2, 3.0, 2.0, ElementType::Quad4);
  const MaterialPoints points = test::seedUniform(mesh, 0, [](int e) { return e < 3; });
  FreeBoundary boundary(mesh);
  boundary.detect(points);
  EXPECT_EQ(boundary.activeElements(), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(boundary.boundaryElements(), (std::vector<int>{0, 1, 2}));
  ASSERT_EQ(boundary.sides().size(), 8u);
  EXPECT_EQ(boundary.nodes(), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  int tops = 0, edges = 0;
  for (const FreeSide& side : boundary.sides()) {
    edges += side.mesh_edge;
    if (side.side == 2) {  // top side of a quad
      ++tops;
      EXPECT_FALSE(side.mesh_edge);
      EXPECT_DOUBLE_EQ(side.normal[0], 0.0);
      EXPECT_DOUBLE_EQ(side.normal[1], 1.0);
      EXPECT_DOUBLE_EQ(side.midpoint(1), 1.0);
      EXPECT_DOUBLE_EQ(side.length, 1.0);
    }
  }
  EXPECT_EQ(tops, 3);
  EXPECT_EQ(edges, 5);
  EXPECT_EQ(boundary.boundaryPoints(points).size(), 12u);  // 4 points in each element

  // All elements full: only the 10 mesh-edge sides; interior nodes 5, 6 are not boundary.
  const MaterialPoints full = test::seedUniform(mesh);
  boundary.detect(full);
  EXPECT_EQ(boundary.sides().size(), 10u);
  EXPECT_EQ(boundary.nodes().size(), 10u);
  EXPECT_FALSE(std::binary_search(boundary.nodes().begin(), boundary.nodes().end(), 5));
}

TEST(FreeBoundary, SlopeOfTrianglesFollowsTheSeededRegion) {
  // 2 x 2 cells of tri3 (each cell: lower-right triangle 2c, upper-left 2c+1). Seeding the
  // lower-right triangles of the diagonal cells and the whole cell (1, 0) gives the region
  // below y = x. Free sides on the diagonal y = x: two hypotenuses (elements 1 and 7 are
  // empty upper-left triangles): outward normal (-1, 1)/sqrt 2, length sqrt 2.
  const Mesh mesh = test::rectangleMesh(2, 2, 2.0, 2.0, ElementType::Tri3);
  // cells: (0,0) -> elements 0,1; (1,0) -> 2,3; (0,1) -> 4,5; (1,1) -> 6,7
  const MaterialPoints points =
      test::seedUniform(mesh, 0, [](int e) { return e == 0 || e == 2 || e == 3 || e == 6; });
  FreeBoundary boundary(mesh);
  boundary.detect(points);
  int diagonal = 0;
  for (const FreeSide& side : boundary.sides()) {
    if (std::fabs(side.midpoint(0) - side.midpoint(1)) > 1e-12) continue;
    ++diagonal;
    EXPECT_NEAR(side.normal[0], -1 / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(side.normal[1], 1 / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(side.length, std::sqrt(2.0), 1e-15);
    EXPECT_FALSE(side.mesh_edge);
  }
  EXPECT_EQ(diagonal, 2);
  // plus bottom (2 sides) and right (2 sides) mesh edges
  EXPECT_EQ(boundary.sides().size(), 6u);
}

// ------------------------------------------------------------------ side integration

TEST(HydraulicAlgebra, HeadToPressure) {
  // H = 0.85 m, y = 0.35 m, rho g = 1000 x 9.81: p = 9810 x 0.5 = 4905 Pa
  EXPECT_NEAR(pressureOfHead(9810, 0.85, 0.35), 4905.0, 1e-9);
  EXPECT_NEAR(pressureOfHead(9810, 0.85, 1.35), -4905.0, 1e-9);  // above: suction
}

TEST(HydraulicAlgebra, UniformAndLinearPressureOnASide) {
  const Real n[kDim] = {0.6, 0.8};
  Real fa[kDim] = {0, 0}, fb[kDim] = {0, 0};
  // uniform p = 100 Pa, L = 2 m: -p n L / 2 = -100 n each
  pressureSideForces(100, 100, 2.0, n, fa, fb);
  EXPECT_NEAR(fa[0], -60, 1e-12);
  EXPECT_NEAR(fa[1], -80, 1e-12);
  EXPECT_NEAR(fb[0], -60, 1e-12);
  // linear 0 -> 300 Pa, L = 1: f_a = -n (2 0 + 300)/6 = -50 n, f_b = -n (0 + 600)/6 = -100 n
  Real ga[kDim] = {0, 0}, gb[kDim] = {0, 0};
  pressureSideForces(0, 300, 1.0, n, ga, gb);
  EXPECT_NEAR(ga[1], -40, 1e-12);
  EXPECT_NEAR(gb[1], -80, 1e-12);
}

TEST(HydraulicAlgebra, HeadOnASideCutByTheLevel) {
  // Vertical side from (0, 0) to (0, 2), outward normal (-1, 0), H = 1 m, rho g = 1e4.
  // s along the side, y = 2 s, p = 1e4 (1 - 2 s) below s = 1/2.
  // f_a = -n L int_0^1/2 (1 - s) p ds = -n 2e4 (1/2 - 3/8 + 1/12) = -n 4166.67
  // f_b = -n 2e4 int_0^1/2 s (1 - 2 s) ds = -n 2e4 (1/8 - 1/12) = -n 833.33
  // (sum 5000 = 1/2 rho g H^2). Normal (-1, 0): forces point +x (into the soil).
  const Real xa[kDim] = {0, 0}, xb[kDim] = {0, 2}, n[kDim] = {-1, 0};
  HeadPressureRule rule;
  rule.rho_g = 1e4;
  rule.head = 1.0;
  Real fa[kDim] = {0, 0}, fb[kDim] = {0, 0};
  headSideForces(xa, xb, 2.0, n, rule, fa, fb);
  EXPECT_NEAR(fa[0], 2e4 * (0.5 - 0.375 + 1.0 / 12), 1e-9);
  EXPECT_NEAR(fb[0], 2e4 * (0.125 - 1.0 / 12), 1e-9);
  EXPECT_NEAR(fa[0] + fb[0], 5000, 1e-9);
  EXPECT_DOUBLE_EQ(fa[1], 0.0);

  // linear suction above: p = 1e4 (1 - 2 s) on the whole side; int_0^2 p dy = 0, so the
  // forces cancel: f_a = -n 2e4 int (1 - s)(1 - 2 s) = -n 2e4 / 6, f_b = +n 2e4 / 6.
  rule.above = AboveLevel::LinearSuction;
  Real sa[kDim] = {0, 0}, sb[kDim] = {0, 0};
  headSideForces(xa, xb, 2.0, n, rule, sa, sb);
  EXPECT_NEAR(sa[0], 2e4 / 6, 1e-9);
  EXPECT_NEAR(sb[0], -2e4 / 6, 1e-9);
  // the mixture's share of it: the suction above the level drops out (mixtureLoadPressure),
  // leaving the hydrostatic part below, the same as with 0 above: fa, fb of the first case
  rule.mixture = true;
  Real ma[kDim] = {0, 0}, mb[kDim] = {0, 0};
  headSideForces(xa, xb, 2.0, n, rule, ma, mb);
  EXPECT_NEAR(ma[0], 2e4 * (0.5 - 0.375 + 1.0 / 12), 1e-9);
  EXPECT_NEAR(mb[0], 2e4 * (0.125 - 1.0 / 12), 1e-9);
  rule.mixture = false;

  // constant 500 Pa above: adds -n 500 int_1/2^1 (1-s) 2 ds = 500 x 2 x 1/8 = 125 to f_a and
  // 500 x 2 x 3/8 = 375 to f_b (in +x)
  rule.above = AboveLevel::ConstantPressure;
  rule.pressure_above = 500;
  Real ca[kDim] = {0, 0}, cb[kDim] = {0, 0};
  headSideForces(xa, xb, 2.0, n, rule, ca, cb);
  EXPECT_NEAR(ca[0] - fa[0], 125, 1e-9);
  EXPECT_NEAR(cb[0] - fb[0], 375, 1e-9);
  // a constant SUCTION of 500 Pa above loads the liquid (-125, -375 relative to fa, fb) but
  // not the mixture (its share is fa, fb)
  rule.pressure_above = -500;
  Real la[kDim] = {0, 0}, lb[kDim] = {0, 0}, xa2[kDim] = {0, 0}, xb2[kDim] = {0, 0};
  headSideForces(xa, xb, 2.0, n, rule, la, lb);
  rule.mixture = true;
  headSideForces(xa, xb, 2.0, n, rule, xa2, xb2);
  EXPECT_NEAR(la[0] - fa[0], -125, 1e-9);
  EXPECT_NEAR(lb[0] - fb[0], -375, 1e-9);
  EXPECT_NEAR(xa2[0], fa[0], 1e-9);
  EXPECT_NEAR(xb2[0], fb[0], 1e-9);
}

// ------------------------------------------------------------------ flux correction

TEST(HydraulicAlgebra, InfiltrationCorrectionConservesMixtureMomentum) {
  // n_L = 0.4, m_L = 2, m_S = 6, n = (0, 1), v_L~ = (0.1, 0.02), v_S~ = (0.1, 0.01):
  // n_L w~ . n = 0.004; rain 1e-3 m/s in: q_out = -1e-3; q_net = 0.005 (4.53).
  // 4.59: dv_L = -0.005 / (0.4 (1 + 1/3)) n = -0.009375 n; 4.58: dv_S = -(2/6) dv_L.
  const Real n[kDim] = {0, 1}, vl[kDim] = {0.1, 0.02}, vs[kDim] = {0.1, 0.01};
  Real dvl[kDim], dvs[kDim];
  const Real q_net = relativeFluxCorrection(0.4, 2, 6, true, n, vl, vs, -1e-3, dvl, dvs);
  EXPECT_NEAR(q_net, 0.005, 1e-15);
  EXPECT_NEAR(dvl[1], -0.009375, 1e-15);
  EXPECT_NEAR(dvs[1], 0.003125, 1e-15);
  EXPECT_DOUBLE_EQ(dvl[0], 0.0);
  // mixture momentum m_L dv_L + m_S dv_S = 0, and the corrected flux is the prescribed one
  EXPECT_NEAR(2 * dvl[1] + 6 * dvs[1], 0.0, 1e-15);
  EXPECT_NEAR(0.4 * ((vl[1] + dvl[1]) - (vs[1] + dvs[1])), -1e-3, 1e-15);
  // fixed skeleton (4.56): dv_S = 0, dv_L = -q_net n / n_L = -0.0125 n
  relativeFluxCorrection(0.4, 2, 6, false, n, vl, vs, -1e-3, dvl, dvs);
  EXPECT_NEAR(dvl[1], -0.0125, 1e-15);
  EXPECT_DOUBLE_EQ(dvs[1], 0.0);
}

TEST(HydraulicAlgebra, PondingAndSeepageFaceSwitches) {
  const int rain = static_cast<int>(FluxCorrection::Infiltration);
  const int ponding = static_cast<int>(FluxCorrection::InfiltrationPonding);
  const int seepage = static_cast<int>(FluxCorrection::SeepageFace);
  // q_net > 0: the zero-pressure surface takes less than the rain (saturated): no ponding
  // -> keep p = 0 (runoff); ponding -> impose the rain anyway.
  EXPECT_FALSE(correctionApplies(rain, 0.005));
  EXPECT_TRUE(correctionApplies(ponding, 0.005));
  // q_net < 0: the dry surface would take more than the rain: impose the rain.
  EXPECT_TRUE(correctionApplies(rain, -0.002));
  // seepage face (q_out = 0): outflow at p = 0 stays; inflow is blocked.
  EXPECT_FALSE(correctionApplies(seepage, 0.004));
  EXPECT_TRUE(correctionApplies(seepage, -0.004));
  const Real n[kDim] = {1, 0}, vl[kDim] = {-0.01, 0}, vs[kDim] = {0, 0};
  Real dvl[kDim], dvs[kDim];
  const Real q_net = relativeFluxCorrection(0.5, 1, 1, true, n, vl, vs, 0.0, dvl, dvs);
  EXPECT_NEAR(q_net, -0.005, 1e-15);  // inflow
  // corrected to zero normal relative velocity: (vl + dvl - vs - dvs) . n = 0
  EXPECT_NEAR((vl[0] + dvl[0]) - (vs[0] + dvs[0]), 0.0, 1e-15);
}

// ------------------------------------------------------------------ the plan

BoundarySpec headCondition(const std::string& name, Real head, ZoneSpec zone) {
  BoundarySpec b;
  b.name = name;
  b.kind = BoundaryKind::TotalHead;
  b.hydraulic.on_zone = true;
  b.hydraulic.zone = zone;
  b.hydraulic.series.value = head;
  return b;
}

TEST(HydraulicConditions, SubmergedBlockFeelsArchimedes) {
  // A 2 m x 2 m block (2 x 2 quads) under a head of 1.5 m, g = 10, rho_L = 1000: rho g = 1e4.
  // Left and right faces: +-int_0^1.5 1e4 (1.5 - y) dy = +-11250 N/m (cancel); base:
  // 1.5e4 Pa x 2 m = 30000 N/m upwards = rho g x submerged volume 2 x 1.5 (Archimedes).
  // The top (y = 2, above the level) gets the constant 0.
  const Mesh mesh = test::rectangleMesh(2, 2, 2.0, 2.0, ElementType::Quad4);
  const MaterialPoints points = test::seedUniform(mesh);
  FreeBoundary boundary(mesh);
  boundary.detect(points);
  StageSpec stage;
  stage.name = "flood";
  stage.boundaries = {headCondition("river", 1.5, ZoneSpec{})};
  HydraulicConditions conditions(mesh, stage);
  conditions.plan(0.0, 10.0, boundary);
  const auto node = test::hostCopy(conditions.loads().node);
  const auto liquid = test::hostCopy(conditions.loads().liquid);
  const auto mixture = test::hostCopy(conditions.loads().mixture);
  Real sum[kDim] = {0, 0}, left_x = 0;
  const auto X = test::hostCopy(mesh.coordinates);
  for (int j = 0; j < conditions.loads().count(); ++j) {
    for (int d = 0; d < kDim; ++d) {
      sum[d] += liquid(j, d);
      EXPECT_DOUBLE_EQ(mixture(j, d), liquid(j, d));  // into both (no suction: p >= 0 here)
    }
    if (X(node(j), 0) == 0.0) left_x += liquid(j, 0);
  }
  EXPECT_NEAR(sum[0], 0.0, 1e-9);
  EXPECT_NEAR(sum[1], 30000.0, 1e-9);
  EXPECT_NEAR(left_x, 11250.0, 1e-9);            // the left face, plus 0 from the base (normal -y)
  EXPECT_EQ(conditions.ownership().count(), 8);  // all boundary nodes belong to "river"
  EXPECT_EQ(conditions.corrections().count(), 0);

  // Half-plane x < 1: sides with midpoints x <= 1: left (2 sides), base and top of the left
  // column of cells. Left face 11250 in +x; base part 1.5e4 x 1 upwards.
  ZoneSpec riverside;
  riverside.kind = ZoneSpec::Kind::HalfPlane;
  riverside.point = {1, 0};
  riverside.direction = {-1, 0};
  stage.boundaries = {headCondition("river", 1.5, riverside)};
  HydraulicConditions left(mesh, stage);
  left.plan(0.0, 10.0, boundary);
  EXPECT_EQ(left.sidesUsed()[0].size(), 4u);
  const auto lliquid = test::hostCopy(left.loads().liquid);
  Real lsum[kDim] = {0, 0};
  for (int j = 0; j < left.loads().count(); ++j)
    for (int d = 0; d < kDim; ++d) lsum[d] += lliquid(j, d);
  EXPECT_NEAR(lsum[0], 11250.0, 1e-9);
  EXPECT_NEAR(lsum[1], 15000.0, 1e-9);
}

TEST(HydraulicConditions, TableTimesCountFromTheStageStartUnlessToldOtherwise) {
  // A drawdown table (0 s, 2.0 m), (1 s, 0.5 m) in a stage that starts at t = 1 s (after a
  // 1 s settling stage). Stage start (default): at t = 1.5 s the stage has run 0.5 s, the
  // head is halfway, (2.0 + 0.5) / 2 = 1.25 m; at t = 1.0 s still 2.0 m. Simulation start:
  // the table's 1 s has passed at t = 1.5 s, the head is 0.5 m.
  const Mesh mesh = test::rectangleMesh(2, 2, 2.0, 2.0, ElementType::Quad4);
  FreeBoundary boundary(mesh);
  boundary.detect(test::seedUniform(mesh));
  BoundarySpec river = headCondition("river", 0.0, ZoneSpec{});
  river.hydraulic.series.source = TimeSeriesSpec::Source::Table;
  river.hydraulic.series.pairs = {0.0, 2.0, 1.0, 0.5};
  StageSpec stage;
  stage.name = "drawdown";
  stage.boundaries = {river};
  HydraulicConditions from_stage(mesh, stage, 1.0);
  from_stage.plan(1.0, 10.0, boundary);
  EXPECT_DOUBLE_EQ(from_stage.currentValues()[0], 2.0);
  from_stage.plan(1.5, 10.0, boundary);
  EXPECT_DOUBLE_EQ(from_stage.currentValues()[0], 1.25);
  stage.boundaries[0].hydraulic.series.origin = TimeOrigin::SimulationStart;
  HydraulicConditions from_simulation(mesh, stage, 1.0);
  from_simulation.plan(1.5, 10.0, boundary);
  EXPECT_DOUBLE_EQ(from_simulation.currentValues()[0], 0.5);
}

TEST(LinearInX, LinearBetweenTheAbscissasConstantBeyond) {
  // v0 = 100 at x0 = 2, v1 = 500 at x1 = 6: slope 100 per m.
  EXPECT_DOUBLE_EQ(linearInX(100, 500, 2, 6, -1), 100);  // before x0: v0
  EXPECT_DOUBLE_EQ(linearInX(100, 500, 2, 6, 2), 100);
  EXPECT_DOUBLE_EQ(linearInX(100, 500, 2, 6, 3), 200);
  EXPECT_DOUBLE_EQ(linearInX(100, 500, 2, 6, 5), 400);
  EXPECT_DOUBLE_EQ(linearInX(100, 500, 2, 6, 6), 500);
  EXPECT_DOUBLE_EQ(linearInX(100, 500, 2, 6, 9), 500);  // after x1: v1
  // A profile whose end series ramps 0 -> 1000 over 10 s: at 5 s, x = 4 is halfway between
  // v0 = 100 and v1 = 500; inactive, the series' value everywhere.
  LinearInX profile;
  profile.x0 = 2;
  profile.x1 = 6;
  profile.end = TimeSeries::fromPairs({0, 0, 10, 1000}, "key");
  EXPECT_DOUBLE_EQ(profile.at(100, 5, 4), 100);
  profile.active = true;
  EXPECT_DOUBLE_EQ(profile.at(100, 5, 4), 300);
}

TEST(HydraulicConditions, PressureLinearInXLoadsTheBaseByItsIntegral) {
  // A 2 m x 2 m block (2 x 2 quads); on its base (y = 0, outward normal -y) p_L linear in x
  // from 1000 Pa at x = 0 to 3000 Pa at x = 2 m: nodes x = 0, 1, 2 hold 1000, 2000, 3000.
  // Linear edge shapes, f_a = (2 pa + pb) L / 6 upwards: x = 0: (2000 + 2000) / 6 = 666.67;
  // x = 1: (1000 + 4000) / 6 + (4000 + 3000) / 6 = 2000; x = 2: (2000 + 6000) / 6 = 1333.33;
  // in all int p dx = 4000 N/m. Positive pressures: the mixture carries the same.
  const Mesh mesh = test::rectangleMesh(2, 2, 2.0, 2.0, ElementType::Quad4);
  FreeBoundary boundary(mesh);
  boundary.detect(test::seedUniform(mesh));
  BoundarySpec base;
  base.name = "base";
  base.kind = BoundaryKind::PressureSeries;
  base.side_set = "bottom";
  base.hydraulic.series.value = 1000;
  base.hydraulic.linear_in_x = true;
  base.hydraulic.x_range = {0.0, 2.0};
  base.hydraulic.end_series.source = TimeSeriesSpec::Source::Table;
  base.hydraulic.end_series.pairs = {0.0, 3000.0, 10.0, 5000.0};  // 3000 Pa at t = 0
  StageSpec stage;
  stage.name = "uplift";
  stage.boundaries = {base};
  HydraulicConditions conditions(mesh, stage);
  conditions.plan(0.0, 10.0, boundary);
  const auto node = test::hostCopy(conditions.loads().node);
  const auto liquid = test::hostCopy(conditions.loads().liquid);
  const auto mixture = test::hostCopy(conditions.loads().mixture);
  const auto X = test::hostCopy(mesh.coordinates);
  std::map<Real, Real> up;  // node x -> upward force
  for (int j = 0; j < conditions.loads().count(); ++j) {
    EXPECT_NEAR(liquid(j, 0), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(mixture(j, 1), liquid(j, 1));
    up[X(node(j), 0)] += liquid(j, 1);
  }
  ASSERT_EQ(up.size(), 3u);
  EXPECT_NEAR(up[0.0], 4000.0 / 6, 1e-9);
  EXPECT_NEAR(up[1.0], 2000.0, 1e-9);
  EXPECT_NEAR(up[2.0], 8000.0 / 6, 1e-9);
  EXPECT_DOUBLE_EQ(conditions.currentValues()[0], 1000);  // the value at x0
  EXPECT_DOUBLE_EQ(conditions.largestCurrentValue(0), 3000);
  // The value at x0 is constant but the end's changes: the plan of t = 0 is not that of 1 s.
  EXPECT_TRUE(conditions.valuesUnchangedAt(0.0));
  EXPECT_FALSE(conditions.valuesUnchangedAt(1.0));
}

TEST(HydraulicConditions, LoadFollowsTheMovingSurface) {
  // 3 x 3 quads of 1 m; soil first in the bottom row; then also in the middle row (the
  // surface rose by 1 m). Head H = 3 m over the whole free boundary, rho g = 1e4.
  // Bottom row only: the top sides at y = 1 carry 2e4 Pa x 3 m = 60000 N/m downwards.
  // Two rows: the tops at y = 2 carry 1e4 x 3 = 30000 N/m downwards. The base (y = 0,
  // 3e4 Pa x 3 m up) and sides (cancel) are the same; net up: 90000 - 60000 = 30000, then
  // 90000 - 30000 = 60000 = rho g x the soil volume (3 and 6 m^2).
  const Mesh mesh = test::rectangleMesh(3, 3, 3.0, 3.0, ElementType::Quad4);
  StageSpec stage;
  stage.name = "flood";
  stage.boundaries = {headCondition("river", 3.0, ZoneSpec{})};
  HydraulicConditions conditions(mesh, stage);
  FreeBoundary boundary(mesh);
  auto netUp = [&]() {
    conditions.plan(0.0, 10.0, boundary);
    const auto liquid = test::hostCopy(conditions.loads().liquid);
    Real up = 0;
    for (int j = 0; j < conditions.loads().count(); ++j) up += liquid(j, 1);
    return up;
  };
  boundary.detect(test::seedUniform(mesh, 0, [](int e) { return e < 3; }));
  EXPECT_NEAR(netUp(), 30000.0, 1e-9);
  boundary.detect(test::seedUniform(mesh, 0, [](int e) { return e < 6; }));
  EXPECT_NEAR(netUp(), 60000.0, 1e-9);
  EXPECT_EQ(boundary.detections(), 2);
}

/// A rain condition named "rain" of `flux` (m/s) on a mesh side set.
BoundarySpec rainOnSideSet(const std::string& side_set, Real flux, bool ponding) {
  BoundarySpec rain;
  rain.name = "rain";
  rain.kind = BoundaryKind::Infiltration;
  rain.side_set = side_set;
  rain.hydraulic.series.value = flux;
  rain.hydraulic.ponding = ponding;
  return rain;
}

TEST(HydraulicConditions, SeepageAboveTheLevelAndInfiltrationNodes) {
  // 2 x 2 block, head 1.0 with a seepage face above: the boundary nodes above y = 1 (the
  // three top nodes at y = 2) get a seepage-face correction; nodes at y <= 1 do not.
  const Mesh mesh = test::rectangleMesh(2, 2, 2.0, 2.0, ElementType::Quad4);
  FreeBoundary boundary(mesh);
  boundary.detect(test::seedUniform(mesh));
  StageSpec stage;
  stage.name = "flood";
  stage.atmosphere_on_free_surfaces = false;  // the conditions' own nodes only
  BoundarySpec head = headCondition("river", 1.0, ZoneSpec{});
  head.hydraulic.above = AboveLevel::SeepageFace;
  BoundarySpec rain = rainOnSideSet("top", 2e-6, true);
  stage.boundaries = {head, rain};
  HydraulicConditions conditions(mesh, stage);
  conditions.plan(0.0, 9.81, boundary);
  const auto node = test::hostCopy(conditions.corrections().node);
  const auto kind = test::hostCopy(conditions.corrections().kind);
  const auto q = test::hostCopy(conditions.corrections().q_out);
  ASSERT_EQ(conditions.corrections().count(), 3);  // nodes 6, 7, 8 (y = 2)
  for (int j = 0; j < 3; ++j) {
    EXPECT_EQ(node(j), 6 + j);
    EXPECT_EQ(kind(j), static_cast<int>(FluxCorrection::SeepageFace));  // first claim wins
    EXPECT_DOUBLE_EQ(q(j), 0.0);
  }
  // without the head condition the top nodes take the rain, q_out = -2e-6
  stage.boundaries = {rain};
  HydraulicConditions only_rain(mesh, stage);
  only_rain.plan(0.0, 9.81, boundary);
  ASSERT_EQ(only_rain.corrections().count(), 3);
  EXPECT_DOUBLE_EQ(test::hostCopy(only_rain.corrections().q_out)(1), -2e-6);
  EXPECT_EQ(test::hostCopy(only_rain.corrections().kind)(1),
            static_cast<int>(FluxCorrection::InfiltrationPonding));
  // a missing side set names the condition
  rain.side_set = "roof";
  stage.boundaries = {rain};
  try {
    HydraulicConditions bad(mesh, stage);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Stages/flood/Boundary Conditions/rain");
  }
}

TEST(HydraulicConditions, TheAtmosphereTakesTheFreeSidesNoConditionCoversUnlessSealed) {
  // 2 x 2 block of 1 m quads (nodes j * 3 + i), rain on the top side set, the left side
  // sealed (its nodes 0, 3, 6 locked along x). With the atmosphere (the default) the free
  // sides no condition covers and no lock seals get seepage-face corrections with the
  // normal of those sides: the bottom (nodes 0, 1, 2; node 0's normal (0, -1), the sealed
  // left side left out) and the right (2, 5; node 2's normal (1, -1) / sqrt 2). The left
  // side's middle node 3 is on sealed sides only: none. The top's nodes keep the rain (the
  // condition claims first). The atmosphere owns no node and conditions none.
  const Mesh mesh = test::rectangleMesh(2, 2, 2.0, 2.0, ElementType::Quad4);
  FreeBoundary boundary(mesh);
  boundary.detect(test::seedUniform(mesh));
  StageSpec stage;
  stage.name = "rain";
  stage.boundaries = {rainOnSideSet("top", 2e-6, false)};
  HydraulicConditions conditions(mesh, stage);
  ASSERT_TRUE(conditions.atmosphere());
  std::vector<unsigned char> rules(static_cast<std::size_t>(mesh.numNodes()), 0);
  rules.at(0) = rules.at(3) = rules.at(6) = HydraulicConditions::kLockedX;
  conditions.setOtherLiquidRules(rules);
  conditions.plan(0.0, 9.81, boundary);
  const auto node = test::hostCopy(conditions.corrections().node);
  const auto kind = test::hostCopy(conditions.corrections().kind);
  const auto normal = test::hostCopy(conditions.corrections().normal);
  const std::map<int, std::array<Real, 2>> atmosphere{
      {0, {0.0, -1.0}}, {1, {0.0, -1.0}}, {2, {M_SQRT1_2, -M_SQRT1_2}}, {5, {1.0, 0.0}}};
  ASSERT_EQ(conditions.corrections().count(), 7);  // 0, 1, 2, 5 and the rain's 6, 7, 8
  for (int j = 0; j < 7; ++j) {
    const auto found = atmosphere.find(node(j));
    if (found == atmosphere.end()) {
      EXPECT_GE(node(j), 6);
      EXPECT_EQ(kind(j), static_cast<int>(FluxCorrection::Infiltration));
      continue;
    }
    EXPECT_EQ(kind(j), static_cast<int>(FluxCorrection::SeepageFace)) << node(j);
    EXPECT_NEAR(normal(j, 0), found->second[0], 1e-15) << node(j);
    EXPECT_NEAR(normal(j, 1), found->second[1], 1e-15) << node(j);
  }
  const auto owned = test::hostCopy(conditions.ownership().node);
  const auto conditioned = test::hostCopy(conditions.conditionedNodes());
  ASSERT_EQ(conditions.ownership().count(), 3);
  ASSERT_EQ(conditioned.extent(0), 3u);
  for (int j = 0; j < 3; ++j) {
    EXPECT_EQ(owned(j), 6 + j);
    EXPECT_EQ(conditioned(j), 6 + j);
  }
  // the bottom's p_L prescribed (`liquid pressure` nodes 0, 1, 2): its sides and nodes are
  // the deck's, and the atmosphere keeps node 5 only (normal (1, 0), the right side)
  for (const std::size_t node : {0u, 1u, 2u})
    rules.at(node) |= HydraulicConditions::kPressurePrescribed;
  conditions.setOtherLiquidRules(rules);
  conditions.plan(0.0, 9.81, boundary);
  ASSERT_EQ(conditions.corrections().count(), 4);  // 5 and the rain's 6, 7, 8
  EXPECT_EQ(test::hostCopy(conditions.corrections().node)(0), 5);
  EXPECT_NEAR(test::hostCopy(conditions.corrections().normal)(0, 0), 1.0, 1e-15);
  // `Surfaces Without Condition: open`: the rain's three nodes only
  stage.atmosphere_on_free_surfaces = false;
  HydraulicConditions open(mesh, stage);
  open.plan(0.0, 9.81, boundary);
  EXPECT_EQ(open.corrections().count(), 3);
}

TEST(HydraulicConditions, LinearSuctionAboveTheLevelLoadsTheLiquidOnly) {
  // The 2 x 2 block of 1 m quads under H = 1 m, linear suction above, rho g = 1e4 (g = 10).
  // The top (y = 2): p = -1e4 over 2 m. Liquid: -p n L / 2 per side end, n = (0, 1): +5e3
  // at the corners, +1e4 at the middle node (up). Mixture: 0 there (air above). The base
  // (y = 0, p = 1e4): both get -1e4 n L/2, i.e. +5e3 / +1e4 upward (free water below).
  const Mesh mesh = test::rectangleMesh(2, 2, 2.0, 2.0, ElementType::Quad4);
  FreeBoundary boundary(mesh);
  boundary.detect(test::seedUniform(mesh));
  StageSpec stage;
  stage.name = "flood";
  BoundarySpec head = headCondition("river", 1.0, ZoneSpec{});
  head.hydraulic.above = AboveLevel::LinearSuction;
  stage.boundaries = {head};
  HydraulicConditions conditions(mesh, stage);
  conditions.plan(0.0, 10.0, boundary);
  const auto node = test::hostCopy(conditions.loads().node);
  const auto liquid = test::hostCopy(conditions.loads().liquid);
  const auto mixture = test::hostCopy(conditions.loads().mixture);
  int checked = 0;
  for (int j = 0; j < conditions.loads().count(); ++j) {
    const int i = node(j);
    if (i == 7) {  // top middle
      EXPECT_NEAR(liquid(j, 1), 1e4, 1e-9);
      EXPECT_NEAR(mixture(j, 1), 0.0, 1e-9);
      ++checked;
    }
    if (i == 1) {  // base middle
      EXPECT_NEAR(liquid(j, 1), 1e4, 1e-9);
      EXPECT_NEAR(mixture(j, 1), 1e4, 1e-9);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2);
}

TEST(FluxWeightCorrection, SetsTheNodeFluxAlongTheFluxWeightByHand) {
  // G = (3, 4), rho_L |S| = 1000 x 0.5: per length 0.002; w~ = v_L - v_S = (0.15, -0.15):
  // measured = (0.45 - 0.6) 0.002 = -3e-4; q_out = 1e-3 -> q_net = -1.3e-3; fraction =
  // |G| 0.002 = 0.01; m_L / m_S = 0.25: scale = 1.3e-3 / 0.0125 = 0.104 along e = (0.6, 0.8).
  const Real weight[kDim] = {3, 4}, vl[kDim] = {0.2, -0.1}, vs[kDim] = {0.05, 0.05};
  Real dvl[kDim], dvs[kDim], q_net = 0;
  ASSERT_TRUE(
      fluxWeightCorrection(weight, 1000, 0.5, 2, 8, true, 0u, vl, vs, 1e-3, dvl, dvs, q_net));
  EXPECT_NEAR(q_net, -1.3e-3, 1e-16);
  EXPECT_NEAR(dvl[0], 0.0624, 1e-15);
  EXPECT_NEAR(dvl[1], 0.0832, 1e-15);
  EXPECT_NEAR(dvs[0], -0.0156, 1e-15);
  EXPECT_NEAR(dvs[1], -0.0208, 1e-15);
  Real flux = 0;  // afterwards the node passes q_out
  for (int d = 0; d < kDim; ++d) flux += (vl[d] + dvl[d] - vs[d] - dvs[d]) * weight[d] * 0.002;
  EXPECT_NEAR(flux, 1e-3, 1e-17);
  // An impermeable lock in x: the correction acts along y alone, fraction 4 x 0.002.
  ASSERT_TRUE(fluxWeightCorrection(weight, 1000, 0.5, 2, 8, true, liquidLockedBit(0), vl, vs, 1e-3,
                                   dvl, dvs, q_net));
  EXPECT_EQ(dvl[0], 0.0);
  EXPECT_NEAR(dvl[1], 0.13, 1e-15);
  EXPECT_NEAR(dvs[1], -0.0325, 1e-15);
  // Locked in both directions, or no weight: the caller's thesis form.
  EXPECT_FALSE(fluxWeightCorrection(weight, 1000, 0.5, 2, 8, true,
                                    liquidLockedBit(0) | liquidLockedBit(1), vl, vs, 1e-3, dvl, dvs,
                                    q_net));
  const Real none[kDim] = {0, 0};
  EXPECT_FALSE(
      fluxWeightCorrection(none, 1000, 0.5, 2, 8, true, 0u, vl, vs, 1e-3, dvl, dvs, q_net));
}

TEST(FluxWeightCorrection, WhereTheSolidIsFixedTheLiquidTakesTheWholeCorrection) {
  // A seepage face on a roller (normal and fixity along x; the river's face on the levee's
  // axis): G = (-5, 0), rho_L |S| = 1000 x 0.1: per length 0.01; v_S~ = 0 (fixed), v_L~ =
  // (0.002, 0): measured = -1e-4, an inflow; q_out = 0 -> q_net = -1e-4; fraction 0.05.
  // m_L / m_S = 0.25. The fixity re-applied after the correction zeroes dv_S,x, so the liquid
  // must take all of dw = 2e-3 (4.56): dv_L,x = -0.002, dv_S,x = 0. Split as in 4.59 (the
  // code up to this test) dv_L,x = -0.0016 and the face passed 0.25 / 1.25 = 20 % of the
  // inflow it is meant to stop.
  const Real weight[kDim] = {-5, 0}, vl[kDim] = {0.002, 0}, vs[kDim] = {0, 0};
  Real dvl[kDim], dvs[kDim], q_net = 0;
  ASSERT_TRUE(fluxWeightCorrection(weight, 1000, 0.1, 2, 8, true, solidFixedBit(0), vl, vs, 0.0,
                                   dvl, dvs, q_net));
  EXPECT_NEAR(q_net, -1e-4, 1e-18);
  EXPECT_NEAR(dvl[0], -0.002, 1e-17);
  EXPECT_EQ(dvs[0], 0.0);
  const Real fixed_vs = 0;  // the fixity: v_S,x = 0 whatever the correction asked
  EXPECT_NEAR((vl[0] + dvl[0] - fixed_vs) * weight[0] * 0.01, 0.0, 1e-18);  // closed
  // A fixity across the correction direction changes nothing (y fixed, G along x): 4.59.
  ASSERT_TRUE(fluxWeightCorrection(weight, 1000, 0.1, 2, 8, true, solidFixedBit(1), vl, vs, 0.0,
                                   dvl, dvs, q_net));
  EXPECT_NEAR(dvl[0], -0.0016, 1e-17);
  EXPECT_NEAR(dvs[0], 0.0004, 1e-17);
  // The thesis form (G = 0) shares it the same way: infiltration 1e-3 m/s into a top face on
  // a node fixed in y, n_L = 0.4: dv_L,y = -q_net / n_L, dv_S,y = 0.
  const Real n[kDim] = {0, 1}, wl[kDim] = {0, -0.01}, ws[kDim] = {0, 0};
  const Real q =
      relativeFluxCorrection(0.4, 2, 8, true, n, wl, ws, -1e-3, dvl, dvs, solidFixedBit(1));
  EXPECT_NEAR(q, -3e-3, 1e-17);
  EXPECT_NEAR(dvl[1], 0.0075, 1e-16);
  EXPECT_EQ(dvs[1], 0.0);
  EXPECT_NEAR(0.4 * (wl[1] + dvl[1]), -1e-3, 1e-17);
}

TEST(FluxWeightCorrection, ASeepageFaceNeverChangesTheRelativeVelocityByMoreThanItself) {
  // q_out = 0: the change of w = v_L - v_S is -(w . e) e, at most |w| whatever the angle
  // between G and the face (the levee drawdown crack: G nearly along the face gave ~1000 m/s
  // with the correction along the side normal).
  for (const Real angle : {0.0, 0.7, 1.5707, 1.570796, 2.5}) {
    const Real weight[kDim] = {std::cos(angle), std::sin(angle)};
    const Real vl[kDim] = {0.3, -0.2}, vs[kDim] = {0.01, 0.02};
    Real dvl[kDim], dvs[kDim], q_net = 0;
    ASSERT_TRUE(
        fluxWeightCorrection(weight, 1000, 0.1, 5, 20, true, 0u, vl, vs, 0.0, dvl, dvs, q_net));
    const Real w[kDim] = {vl[0] - vs[0], vl[1] - vs[1]};
    const Real dw[kDim] = {dvl[0] - dvs[0], dvl[1] - dvs[1]};
    EXPECT_LE(std::hypot(dw[0], dw[1]), std::hypot(w[0], w[1]) * (1 + 1e-15)) << angle;
    EXPECT_NEAR((w[0] + dw[0]) * weight[0] + (w[1] + dw[1]) * weight[1], 0, 1e-16) << angle;
  }
}

}  // namespace
}  // namespace argine
