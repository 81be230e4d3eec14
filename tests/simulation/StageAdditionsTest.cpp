// Issue P4 in the Simulation: the relaxation monitor, material changes (applied at the stage
// start and logged), the meaningful t = 0 diagnostics row, probes in a run, K0 initialisation
// chosen by the deck.
#include <gtest/gtest.h>

#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "CsvRows.hpp"
#include "QuietRun.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/simulation/MaterialChanges.hpp"
#include "argine/simulation/RelaxationMonitor.hpp"
#include "argine/simulation/Simulation.hpp"

namespace argine {
namespace {

TEST(RelaxationMonitor, WindowKeepsATurningPointFromPassingForRest) {
  RelaxationSpec spec;
  spec.enabled = true;
  spec.kinetic_energy_ratio = 0.01;
  spec.window = 1.0;
  RelaxationMonitor monitor(spec, 10.0);  // stage starts at t = 10 s
  // Stored energy 100 J/m throughout. An oscillation: E_k 50 at t = 10.2, then 0 (turning
  // point) at t = 10.6: the window still holds 50, R = 50/100 = 0.5.
  EXPECT_FALSE(monitor.add(10.2, 50, 100));
  EXPECT_FALSE(monitor.add(10.6, 0, 100));
  EXPECT_DOUBLE_EQ(monitor.ratio(), 0.5);
  // t = 11.0: one window has passed, but 50 (t = 10.2 >= 11.0 - 1) is still in it.
  EXPECT_FALSE(monitor.add(11.0, 0.5, 100));
  EXPECT_DOUBLE_EQ(monitor.ratio(), 0.5);
  // t = 11.3: 50 (t = 10.2 < 10.3) has left the window; max of {0 (10.6), 0.5 (11.0), 0.2}
  // is 0.5: R = 0.005 <= 0.01.
  EXPECT_TRUE(monitor.add(11.3, 0.2, 100));
  EXPECT_DOUBLE_EQ(monitor.ratio(), 0.005);
  EXPECT_DOUBLE_EQ(monitor.peak(), 50);
  EXPECT_EQ(monitor.steps(), 4);
}

TEST(RelaxationMonitor, NoStoredEnergyWhileMovingIsNotRest) {
  RelaxationSpec spec;
  spec.window = 0.1;
  RelaxationMonitor monitor(spec, 0);
  EXPECT_FALSE(monitor.add(0.2, 1, 0));
  EXPECT_EQ(monitor.ratio(), std::numeric_limits<Real>::infinity());
  RelaxationMonitor still(spec, 0);
  EXPECT_TRUE(still.add(0.2, 0, 0));  // nothing moves: at rest
}

TEST(MaterialChanges, AppliesAndLogsEachValue) {
  std::vector<MaterialSpec> materials(2);
  materials[0].name = "clay";
  materials[1].name = "sand";
  materials[1].solid.cohesion = 20000;
  materials[1].solid.friction_angle = 0.5;
  MaterialChangeSpec change;
  change.material = "sand";
  change.cohesion = 2000;
  change.friction_angle = 20 * 3.14159265358979323846 / 180;
  change.intrinsic_permeability = 1e-12;
  const auto log = applyMaterialChanges("soften", {change}, materials);
  EXPECT_EQ(materials[1].solid.cohesion, 2000);
  EXPECT_EQ(materials[1].solid.friction_angle, *change.friction_angle);
  // k_sat = kappa rho_L g / mu_L = 1e-12 * 1000 * 9.81 / 1e-3 = 9.81e-6 m/s
  EXPECT_NEAR(materials[1].conductivity.saturated_conductivity, 9.81e-6, 1e-18);
  EXPECT_EQ(materials[0].solid.cohesion, MaterialSpec().solid.cohesion);  // untouched
  ASSERT_EQ(log.size(), 3u);
  EXPECT_EQ(log[0], "material 'sand': cohesion 20000 -> 2000 Pa");
  EXPECT_EQ(log[1], "material 'sand': friction angle 28.6479 -> 20 deg");  // 0.5 rad
  change.material = "silt";
  EXPECT_THROW(applyMaterialChanges("soften", {change}, materials), InputError);
}

// A saturated column 0.1 m x 1 m (10 quads), two short stages; the second changes the
// permeability. Probes: the point nearest (0.05, 0.5) and a profile along the axis.
const std::string kDeck = R"(argine:
  Mesh:
    Generate: {Type: rectangle, Element: quad4, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], Upper Right (m): [0.1, 1.0]}
  Materials:
    soil:
      Block: soil
      Points Per Element: 4
      Porosity: 0.4
      Solid Density (kg/m3): 2700
      Solid: {Model: linear elastic, Young's Modulus (Pa): 1.0e7, Poisson's Ratio: 0.0}
      Liquid: {Bulk Modulus (Pa): 1.0e8}
      Conductivity: {Saturated Conductivity (m/s): 1.0e-3}
      Initial State: {K0: 0.5}
  Initialisation: {Method: K0 procedure, Ground Surface (m): [0.0, 1.0], Phreatic Surface (m): [0.0, 1.0]}
  Stages:
    settle:
      Solver: quasi-static
      Duration (s): 0.002
      Local Damping: 0.5
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        sides: {Type: solid fixity, Node Set: left, Direction: x}
        other side: {Type: solid fixity, Node Set: right, Direction: x}
    tighten:
      Solver: quasi-static
      Duration (s): 0.001
      Local Damping: 0.5
      Material Changes:
        soil: {Saturated Conductivity (m/s): 2.0e-4}
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
  Probes:
    Points:
      middle: {Position (m): [0.05, 0.5], Tolerance (m): 0.05}
    Sections:
      axis: {Type: profile, From (m): [0.05, 0.0], To (m): [0.05, 1.0], Width (m): 0.1, Samples: 5}
  Output: {Name: column}
)";

TEST(SimulationStages, K0StateMaterialChangeProbesAndInitialDiagnostics) {
  const Deck deck = parseDeck(*Teuchos::getParametersFromYamlString(kDeck), "");
  const auto dir = std::filesystem::path(::testing::TempDir()) / "argine_simulation_stages";
  const RunOptions options = test::quietRunIn(dir);
  Simulation simulation(deck, options);

  // K0 state at t = 0: p_L = 9810 (1 - y), sigma'_yy = -(0.6*2700 + 0.4*1000 - 1000) 9.81 (1-y)
  // = -1020 * 9.81 (1 - y) = -10006.2 (1 - y) (rho_L0 in both; compressibility is O(1e-4) of p_L,
  // not in sigma).
  {
    const MaterialPoints& points = simulation.points();
    auto y = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
    auto p = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.pressure_liquid);
    auto s = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.stress_effective);
    for (int i = 0; i < points.count; ++i) {
      const double depth = 1 - y(i, 1);
      EXPECT_NEAR(p(i), 9810 * depth, 1e-8);
      EXPECT_NEAR(s(i, YY), -10006.2 * depth, 1e-8);
      EXPECT_NEAR(s(i, XX), -5003.1 * depth, 1e-8);
    }
  }
  simulation.run();

  // The change reached the points: saturated, so k = k_sat = 2e-4 m/s everywhere.
  auto k =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), simulation.points().conductivity);
  for (int i = 0; i < simulation.points().count; ++i) EXPECT_DOUBLE_EQ(k(i), 2.0e-4);
  EXPECT_EQ(simulation.currentMaterials()[0].conductivity.saturated_conductivity, 2.0e-4);
  bool logged = false;
  for (const auto& line : simulation.stageLog())
    logged = logged || line ==
                           "stage 'tighten': material 'soil': saturated conductivity 0.001 "
                           "-> 0.0002 m/s";
  EXPECT_TRUE(logged);

  // t = 0 diagnostics row: the liquid mass of the points, sum n rho_L V over the 0.1 m3 column
  // = 0.4 * 0.1 * rho_L0 * mean exp(p_L/K_L), with p_L/K_L <= 9810/1e8 ~ 1e-4: 40.0 kg/m to
  // 1e-4 (40 * (1 + 4.9e-5) = 40.00196); a positive step; no kinetic energy at rest.
  const auto diagnostics = readCsvRows((dir / "column_diagnostics.csv").string());
  ASSERT_GE(diagnostics.size(), 3u);
  EXPECT_EQ(diagnostics[0][0], 0);
  EXPECT_GT(diagnostics[0][1], 0);
  EXPECT_EQ(diagnostics[0][2], 0);
  EXPECT_NEAR(diagnostics[0][4], 40.00196, 2e-4);

  // Probes: one row per output (t = 0 and the end of each stage), the same point id.
  const auto middle = readCsvRows((dir / "column_probe_middle.csv").string());
  ASSERT_EQ(middle.size(), 3u);
  EXPECT_EQ(middle[0][1], middle[2][1]);
  EXPECT_NEAR(middle[0][3], 0.5, 0.05);
  const auto axis = readCsvRows((dir / "column_section_axis.csv").string());
  EXPECT_EQ(axis.size(), 15u);  // 5 samples x 3 outputs
}

}  // namespace
}  // namespace argine
