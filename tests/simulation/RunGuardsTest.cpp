// Issue P8: the physical guards of a run. The liquid balance and kinetic energy warnings
// (once, with value, bound, time and step), and points leaving the mesh: stop (RunError
// naming time, step, point id and position; the output so far is kept) or remove (counted
// in the log, the run goes on).
#include <gtest/gtest.h>

#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/simulation/RunGuards.hpp"
#include "argine/simulation/Simulation.hpp"

namespace argine {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(RunGuards, MassBalanceWarnsOnceWithItsNumbers) {
  GuardsSpec spec;  // default bound 1e-3
  RunGuards guards(spec);
  // Stage starts with 10 m3/m stored, 2 m3/m net inflow so far, initial volume 100 m3/m.
  guards.beginStage(10.0, 2.0, 100.0);
  // storage +0.05, inflow +0.0: error 0.05 / 100 = 5e-4 <= 1e-3
  EXPECT_EQ(guards.checkMassBalance(10.05, 2.0, {1.0, 10, "flood"}), "");
  // storage +0.20, inflow +0.05: error 0.15 / 100 = 1.5e-3 > 1e-3
  const std::string warning = guards.checkMassBalance(10.2, 2.05, {2.5, 17, "flood"});
  EXPECT_TRUE(contains(warning, "liquid mass balance error 0.0015")) << warning;
  EXPECT_TRUE(contains(warning, "Guards/Mass Balance Bound 0.001")) << warning;
  EXPECT_TRUE(contains(warning, "at t = 2.5 s (step 17, stage 'flood')")) << warning;
  EXPECT_TRUE(contains(warning, "storage change 0.2")) << warning;
  // once per run, even when worse or in a later stage
  EXPECT_EQ(guards.checkMassBalance(20.0, 2.0, {3.0, 20, "flood"}), "");
  guards.beginStage(20.0, 2.0, 100.0);
  EXPECT_EQ(guards.checkMassBalance(30.0, 2.0, {4.0, 30, "later"}), "");
}

TEST(RunGuards, KineticEnergyWarnsOnceAboveTheFractionOfTheScale) {
  GuardsSpec spec;
  spec.kinetic_energy_bound = 0.2;
  RunGuards guards(spec);
  // scale 50 J/m: bound 0.2 x 50 = 10 J/m
  EXPECT_EQ(guards.checkKineticEnergy(10.0, 50.0, {0.1, 3, "s"}), "");
  const std::string warning = guards.checkKineticEnergy(12.5, 50.0, {0.2, 4, "s"});
  EXPECT_TRUE(contains(warning, "kinetic energy 12.5 J/m exceeds Guards/Kinetic Energy Bound 0.2"))
      << warning;
  EXPECT_TRUE(contains(warning, "energy scale 50 J/m = 10 J/m at t = 0.2 s (step 4")) << warning;
  EXPECT_EQ(guards.checkKineticEnergy(40.0, 50.0, {0.3, 5, "s"}), "");
}

TEST(RunGuards, KineticEnergyPeakIsTheStagesLargestRatioToTheScale) {
  GuardsSpec spec;  // default bound 0.1
  RunGuards guards(spec);
  guards.beginStage(0, 0, 0);
  EXPECT_EQ(guards.kineticEnergyPeak("s"), "");  // no step checked yet
  // ratios 0.02, 0.05 (the peak: 3 J/m of a scale of 60 J/m grown from 50), 0.04
  guards.checkKineticEnergy(1.0, 50.0, {0.1, 1, "s"});
  guards.checkKineticEnergy(3.0, 60.0, {0.2, 2, "s"});
  guards.checkKineticEnergy(2.4, 60.0, {0.3, 3, "s"});
  const std::string line = guards.kineticEnergyPeak("s");
  EXPECT_TRUE(contains(line, "stage 's': largest kinetic energy 3 J/m at t = 0.2 s (step 2"))
      << line;
  EXPECT_TRUE(contains(line, "= 0.05 x the energy scale 60 J/m")) << line;
  EXPECT_TRUE(contains(line, "warns above 0.1 x, the run stops above 1 x")) << line;
  guards.beginStage(0, 0, 0);  // a new stage starts its own peak
  EXPECT_EQ(guards.kineticEnergyPeak("t"), "");
}

// A saturated column 0.1 m x 1 m with no support: it falls under gravity and its lowest
// points leave the mesh through the bottom after about sqrt(2 x 0.021 / 9.81) = 0.066 s.
const std::string kFallingColumn = R"(argine:
  Mesh:
    Generate: {Type: rectangle, Element: quad4, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], Upper Right (m): [0.1, 1.0]}
  Materials:
    soil:
      Block: soil
      Points Per Element: 4
      Porosity: 0.4
      Solid Density (kg/m3): 2700
      Solid: {Model: linear elastic, Young's Modulus (Pa): 1.0e7, Poisson's Ratio: 0.0}
      Conductivity: {Saturated Conductivity (m/s): 1.0e-3}
  Stages:
    fall:
      Solver: explicit
      Duration (s): 0.2
      Output Interval (s): 0.02
  Output: {Name: fall}
)";

std::filesystem::path freshDirectory(const std::string& name) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / ("argine_guards_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

Deck fallingColumn(const std::string& guards) {
  return parseDeck(*Teuchos::getParametersFromYamlString(kFallingColumn + guards), "");
}

// A column wetted from below on the implicit path between two explicit fixed-skeleton
// stages. The run's liquid bookkeeping (<name>_boundary_flux.csv, the mass-balance guard)
// goes on through the implicit stage, and the hand-overs both ways keep the liquid mass: the
// projection of the points' p_L onto the implicit solver's nodes is not exact after the
// explicit stage (4.6e-7 m3/m of 7.8e-4 m3/m inflow before the first implicit step started
// from the points' own state).
const std::string kWettedColumn = R"(argine:
  Mesh:
    Generate: {Type: rectangle, Element: tri3, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], Upper Right (m): [0.1, 1.0]}
  Materials:
    soil:
      Block: soil
      Phase Model: unsaturated
      Porosity: 0.4
      Solid Density (kg/m3): 2700
      Solid: {Model: linear elastic, Young's Modulus (Pa): 1.0e7, Poisson's Ratio: 0.3}
      Liquid: {Density (kg/m3): 1000, Bulk Modulus (Pa): 8.0e7, Viscosity (Pa s): 1.0e-3}
      Retention: {Model: van Genuchten, Reference Pressure (Pa): 3000, Lambda: 0.7, Minimum Saturation: 0.125, Maximum Saturation: 1.0}
      Conductivity: {Model: constant, Saturated Conductivity (m/s): 1.0e-4}
  Initialisation:
    Method: K0 procedure
    Ground Surface (m): [0.0, 1.0, 0.1, 1.0]
    Phreatic Surface (m): [0.0, 0.5, 0.1, 0.5]
  Stages:
    before:
      Solver: fixed skeleton
      Duration (s): 0.01
      Output Interval (s): 0.005
      Boundary Conditions:
        base: {Type: total head, Side Set: bottom, Total Head (m): 0.5}
    wetting:
      Solver: implicit seepage
      Duration (s): 200
      Output Interval (s): 50
      Implicit Seepage: {Initial Step (s): 1, Maximum Step (s): 10}
      Boundary Conditions:
        base: {Type: total head, Side Set: bottom, Total Head (m): 0.8}
    after:
      Solver: fixed skeleton
      Duration (s): 0.01
      Output Interval (s): 0.005
      Boundary Conditions:
        base: {Type: total head, Side Set: bottom, Total Head (m): 0.8}
  Output: {Name: wetted}
)";

TEST(RunGuards, LiquidBookkeepingRunsThroughAnImplicitStage) {
  RunOptions options;
  options.output_directory = freshDirectory("wetted").string();
  options.quiet = true;
  Simulation simulation(parseDeck(*Teuchos::getParametersFromYamlString(kWettedColumn), ""),
                        options);
  simulation.run();
  for (const auto& line : simulation.stageLog())
    EXPECT_FALSE(contains(line, "mass balance")) << line;  // the guard's baseline is right
  // <name>_boundary_flux.csv: time, storage_change, net_inflow_all_nodes,
  // net_inflow_interior_nodes, base_step, base_cumulative
  std::ifstream csv(options.output_directory + "/wetted_boundary_flux.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line,
            "time,storage_change,net_inflow_all_nodes,net_inflow_interior_nodes,base_step,"
            "base_cumulative");
  std::vector<std::array<Real, 6>> rows;
  while (std::getline(csv, line)) {
    std::stringstream cells(line);
    std::array<Real, 6> row{};
    std::string cell;
    for (Real& value : row) {
      std::getline(cells, cell, ',');
      value = std::stod(cell);
    }
    rows.push_back(row);
  }
  ASSERT_GE(rows.size(), 8u);
  Real largest = 0;
  for (const auto& row : rows) largest = std::max(largest, std::fabs(row[2]));
  EXPECT_GT(largest, 5e-4);  // m3/m (7.8e-4 measured): the implicit inflow is counted
  for (const auto& row : rows) {
    EXPECT_NEAR(row[1], row[2], 1e-8 * largest) << "t = " << row[0];
    // a column of full elements that does not deform makes no liquid inside
    EXPECT_NEAR(row[3], 0.0, 1e-9 * largest) << "t = " << row[0];
  }
  // (P10) The per-condition columns are filled on the implicit path too: there all the
  // water enters through `base`, so between the wetting stage's outputs its cumulative
  // volume grows as the net inflow does, and each output reports the last implicit step's
  // inflow through it. (They were 0 on the implicit path.)
  int implicit_rows = 0;
  for (std::size_t r = 1; r < rows.size(); ++r)
    if (rows[r][0] > 0.0101 && rows[r][0] < 200.0101) {
      ++implicit_rows;
      EXPECT_GT(rows[r][4], 0.0) << "t = " << rows[r][0];
      EXPECT_NEAR(rows[r][5] - rows[r - 1][5], rows[r][2] - rows[r - 1][2], 1e-9 * largest)
          << "t = " << rows[r][0];
    }
  EXPECT_EQ(implicit_rows, 4);  // 50, 100, 150, 200 s after the first stage
}

TEST(RunGuards, PointsLeavingTheMeshStopTheRunByDefault) {
  RunOptions options;
  options.output_directory = freshDirectory("stop").string();
  options.quiet = true;
  Simulation simulation(fallingColumn(""), options);
  try {
    simulation.run();
    ADD_FAILURE() << "the run went on with points outside the mesh";
  } catch (const RunError& error) {
    const std::string message = error.what();
    EXPECT_TRUE(contains(message, "material point(s) left the background mesh at t = ")) << message;
    EXPECT_TRUE(contains(message, "(step ")) << message;
    EXPECT_TRUE(contains(message, "stage 'fall'")) << message;
    EXPECT_TRUE(contains(message, "first point id ")) << message;
    EXPECT_TRUE(contains(message, "the last output is kept")) << message;
    // The point named lies below the mesh (y < 0).
    const auto at = message.find("first point id ");
    const auto comma = message.find(", ", message.find(" at (", at));
    EXPECT_LT(std::stod(message.substr(comma + 2)), 0.0) << message;
  }
  // the output written before the stop is there
  EXPECT_TRUE(std::filesystem::exists(simulation.pointsPath())) << simulation.pointsPath();
}

TEST(RunGuards, PointsLeavingTheMeshAreRemovedAndCountedWhenTheDeckSaysSo) {
  RunOptions options;
  options.output_directory = freshDirectory("remove").string();
  options.quiet = true;
  Simulation simulation(
      fallingColumn("  Guards: {Points Leaving Mesh: remove, Kinetic Energy Bound: 0.01}\n"),
      options);
  ASSERT_NO_THROW(simulation.run());
  const auto& log = simulation.stageLog();
  const auto removed = std::count_if(log.begin(), log.end(), [](const std::string& line) {
    return contains(line, "left the background mesh") &&
           contains(line, "removed from the computation");
  });
  EXPECT_GE(removed, 1);
  const auto energy = std::count_if(log.begin(), log.end(), [](const std::string& line) {
    return contains(line, "warning: kinetic energy");
  });
  EXPECT_EQ(energy, 1);  // a free fall: far above 1 % of the scale, warned once
  // The points outside are out of the computation: no velocity.
  const MaterialPoints& points = simulation.points();
  const auto element = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.element);
  const auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.velocity_solid);
  int outside = 0;
  for (int p = 0; p < points.count; ++p)
    if (element(p) < 0) {
      ++outside;
      EXPECT_EQ(v(p, 1), 0.0);
    }
  EXPECT_GT(outside, 0);
}

}  // namespace
}  // namespace argine
