// Issue P11 item 2: the physical range of p_L (PhysicalPressureRange.hpp) against values
// computed by hand, and the count of the points outside it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "argine/simulation/PhysicalPressureRange.hpp"

namespace argine {
namespace {

/// Three located points of material 0 stacked in y, squares of side 0.5 m (V = 0.25 m^2),
/// n = 0.4, rho_S = 2700, rho_L = 1000 (saturated): mixture 0.6 x 2700 + 0.4 x 1000 = 2020
/// kg/m^3, i.e. M_S = 0.6 x 2700 x 0.25 = 405 kg, M_L = 0.4 x 1000 x 0.25 = 100 kg.
MaterialPoints column(const std::vector<Real>& pressures) {
  MaterialPoints points;
  points.allocate(static_cast<int>(pressures.size()));
  auto h = [](const auto& view) { return Kokkos::create_mirror_view(view); };
  auto id = h(points.id), element = h(points.element), material = h(points.material);
  auto position = h(points.position);
  auto volume = h(points.volume), solid = h(points.mass_solid), liquid = h(points.mass_liquid);
  auto pressure = h(points.pressure_liquid);
  for (int p = 0; p < points.count; ++p) {
    id(p) = 10 + p;
    element(p) = 0;
    material(p) = 0;
    position(p, 0) = 1.0 + p;
    position(p, 1) = 0.25 + 0.5 * p;  // centres 0.25, 0.75, 1.25: from y = 0 to 1.5 m
    volume(p) = 0.25;
    solid(p) = 405;
    liquid(p) = 100;
    pressure(p) = pressures[p];
  }
  Kokkos::deep_copy(points.id, id);
  Kokkos::deep_copy(points.element, element);
  Kokkos::deep_copy(points.material, material);
  Kokkos::deep_copy(points.position, position);
  Kokkos::deep_copy(points.volume, volume);
  Kokkos::deep_copy(points.mass_solid, solid);
  Kokkos::deep_copy(points.mass_liquid, liquid);
  Kokkos::deep_copy(points.pressure_liquid, pressure);
  return points;
}

MaterialSpec soil(PhaseModel phase) {
  MaterialSpec material;
  material.phase = phase;
  material.retention.model = RetentionModel::Linear;
  material.retention.linear_slope = 4e-7;  // S_L = 1 - 4e-7 s: S_L = 0 at s = 2.5 MPa
  return material;
}

TEST(PhysicalPressureRange, OverburdenOfTheColumn) {
  const MaterialPoints points = column({0, 0, 0});
  // g rho_max (y_top - y_bottom) = 10 x 2020 x 1.5 = 30300 Pa
  EXPECT_NEAR(largestTotalVerticalStress(points, 10.0, StageSurcharge{}), 30300.0, 1e-9);
  // water standing 0.5 m above the top (h_w = 2 m) adds 10 x 1000 x 0.5 = 5000 Pa; a 2 kPa
  // surface pressure adds itself
  StageSurcharge surcharge;
  surcharge.water_level = 2.0;
  surcharge.surface_pressure = 2000;
  EXPECT_NEAR(largestTotalVerticalStress(points, 10.0, surcharge), 37300.0, 1e-9);
  // a level below the top adds nothing
  surcharge.water_level = 1.0;
  EXPECT_NEAR(largestTotalVerticalStress(points, 10.0, surcharge), 32300.0, 1e-9);
}

TEST(PhysicalPressureRange, StageSurchargeTakesTheLargestValues) {
  StageSpec stage;
  BoundarySpec head;
  head.kind = BoundaryKind::TotalHead;
  head.hydraulic.series.source = TimeSeriesSpec::Source::Table;
  head.hydraulic.series.pairs = {0.0, 2.0, 1.0, 0.5};  // the levee drawdown: 2 m to 0.5 m
  BoundarySpec traction;
  traction.kind = BoundaryKind::Traction;
  traction.traction = {3000.0, -4000.0};  // |t| = 5 kPa
  BoundarySpec pressure;
  pressure.kind = BoundaryKind::LiquidPressure;
  pressure.pressure = 1000.0;
  stage.boundaries = {head, traction, pressure};
  const StageSurcharge surcharge = stageSurcharge(stage);
  EXPECT_DOUBLE_EQ(surcharge.water_level, 2.0);
  EXPECT_DOUBLE_EQ(surcharge.surface_pressure, 5000.0);
}

TEST(PhysicalPressureRange, LowestPressureFromInitialStateDrainageAndRetention) {
  // g = 10: drained to the bottom of the 1.5 m column, -1000 x 10 x 1.5 = -15 kPa at the top
  const Real g = 10;
  const MaterialPoints initial = column({-9810, 5000, 20000});
  // saturated: the drained -15 kPa, below the initial state's -9.81 kPa
  EXPECT_DOUBLE_EQ(lowestPhysicalPressures(initial, {soil(PhaseModel::Saturated)}, g)[0], -15000.0);
  // an initial state below that: its own lowest
  EXPECT_DOUBLE_EQ(
      lowestPhysicalPressures(column({-20000, 6000, 7000}), {soil(PhaseModel::Saturated)}, g)[0],
      -20000.0);
  // no gravity, positive initial pressures: 0 (drainage to the atmosphere)
  EXPECT_DOUBLE_EQ(
      lowestPhysicalPressures(column({5000, 6000, 7000}), {soil(PhaseModel::Saturated)}, 0)[0],
      0.0);
  // linear retention reaching S_min = 0 at s = 1 / 4e-7 = 2.5 MPa: not binding, -15 kPa
  EXPECT_DOUBLE_EQ(lowestPhysicalPressures(initial, {soil(PhaseModel::Unsaturated)}, g)[0],
                   -15000.0);
  // a steeper one, S_min at s = 1 / 1e-4 = 10 kPa: no liquid left to drain beyond, -10 kPa
  MaterialSpec steep = soil(PhaseModel::Unsaturated);
  steep.retention.linear_slope = 1e-4;
  EXPECT_DOUBLE_EQ(lowestPhysicalPressures(initial, {steep}, g)[0], -10000.0);
  // van Genuchten has no largest suction: the drained -15 kPa
  MaterialSpec vg = soil(PhaseModel::Unsaturated);
  vg.retention.model = RetentionModel::VanGenuchten;
  vg.retention.reference_pressure = 1e4;
  EXPECT_DOUBLE_EQ(lowestPhysicalPressures(initial, {vg}, g)[0], -15000.0);
  // dry: not checked
  EXPECT_EQ(lowestPhysicalPressures(initial, {soil(PhaseModel::Dry)}, g)[0],
            -std::numeric_limits<Real>::infinity());
}

TEST(PhysicalPressureRange, CountsAboveAndBelowAndNamesTheWorst) {
  // bound above 30.3 kPa (OverburdenOfTheColumn), below -9.81 kPa (saturated)
  const MaterialPoints points = column({45000, -12000, 30000});
  const std::vector<MaterialSpec> materials{soil(PhaseModel::Saturated)};
  const PressureRangeCount count =
      countPressuresOutsideRange(points, materials, {-9810.0}, 30300.0);
  EXPECT_EQ(count.outside, 2);  // 45 kPa above, -12 kPa below; 30 kPa inside
  EXPECT_EQ(count.above, 1);
  // the worst: 45 - 30.3 = 14.7 kPa outside against -9.81 - (-12) = 2.19 kPa
  EXPECT_EQ(count.worst_id, 10);
  EXPECT_DOUBLE_EQ(count.worst_pressure, 45000.0);
  EXPECT_DOUBLE_EQ(count.worst_bound, 30300.0);
  EXPECT_DOUBLE_EQ(count.worst_position[0], 1.0);
  EXPECT_DOUBLE_EQ(count.worst_position[1], 0.25);
  const std::string line = describePressureRange(count, 21.0);
  EXPECT_NE(line.find("2 point(s) with p_L outside the physical range at t = 21 s (1 above "
                      "sigma_v,max = 30.3 kPa, 1 below"),
            std::string::npos)
      << line;
  EXPECT_NE(line.find("worst: point 10 at (1, 0.25) m, p_L = 45 kPa (bound 30.3 kPa)"),
            std::string::npos)
      << line;
  // inside the range, dry, or outside the mesh: none counted
  EXPECT_EQ(
      countPressuresOutsideRange(column({30000, -9000, 0}), materials, {-9810.0}, 30300.0).outside,
      0);
  EXPECT_EQ(countPressuresOutsideRange(points, {soil(PhaseModel::Dry)}, {-9810.0}, 30300.0).outside,
            0);
  MaterialPoints lost = column({45000, 0, 0});
  Kokkos::deep_copy(Kokkos::subview(lost.element, std::make_pair(0, 1)), -1);
  EXPECT_EQ(countPressuresOutsideRange(lost, materials, {-9810.0}, 30300.0).outside, 0);
}

}  // namespace
}  // namespace argine
