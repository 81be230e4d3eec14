// [2Phase][Boundary] A submerged ground at rest stays at rest under a river and its drawdown
// (verification/submerged_ground, doc/verification.md "A submerged ground at rest swells at
// its top cell").
//
// The foreland of the grid levee alone: a flat ground 0.5 m deep on a 0.1 m uGIMP grid, its
// surface on the cell edges, under a 2 m head (quasi-static settle, 1 s) then drawn down to
// 0.5 m in 1 s and held (explicit, 3 s). The K0 state under the river is the continuum's
// equilibrium, so the top cell should neither swell nor fall below the river's pressure. The
// river's load passed through the boundary points puts part of it a cell deep, opens the top
// cell at the tension cut-off and swells it by +3.9e-3; the head's field over the points'
// volume (`through the soil`, physics/HeadLoadsThroughSoil.hpp) keeps it to the elastic
// response of the drawdown.
#include <gtest/gtest.h>

#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "QuietRun.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/simulation/Simulation.hpp"

namespace argine {
namespace {

constexpr double kCell = 0.1;            // m, the deck's element size
constexpr double kFinalHead = 0.5;       // m, after the drawdown
constexpr double kRhoG = 1000.0 * 9.81;  // the deck's liquid (N/m^3)

struct TopCell {
  double swelling = 0;          ///< mean V / V0 - 1 of the top cell's points
  double pressure_deficit = 0;  ///< largest |p_L - rho_L g (H - y)| among them (Pa)
};

TopCell runGround(const std::string& loads) {
  std::ifstream file(std::string(ARGINE_SOURCE_DIR) +
                     "/verification/submerged_ground/submerged_ground.yaml");
  std::stringstream text;
  text << file.rdbuf();
  std::string yaml = text.str();
  const std::string deck_loads = "Hydraulic Loads: through the soil";
  for (std::size_t at = yaml.find(deck_loads); at != std::string::npos;
       at = yaml.find(deck_loads, at + 1))
    yaml.replace(at, deck_loads.size(), "Hydraulic Loads: " + loads);
  const Deck deck = parseDeck(*Teuchos::getParametersFromYamlString(yaml), "");
  const auto dir = std::filesystem::path(::testing::TempDir()) /
                   (loads == "through the soil" ? "argine_ground_soil" : "argine_ground_points");
  const RunOptions options = test::quietRunIn(dir);
  Simulation simulation(deck, options);
  simulation.run();
  const MaterialPoints& points = simulation.points();
  const auto position = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
  const auto volume = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.volume);
  const auto pressure =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.pressure_liquid);
  const double initial_volume = kCell * kCell / 4;  // four points a cell
  TopCell top;
  int count = 0;
  for (int p = 0; p < points.count; ++p) {
    const double y = position(p, 1);
    if (y < -kCell) continue;
    top.swelling += volume(p) / initial_volume - 1;
    top.pressure_deficit =
        std::max(top.pressure_deficit, std::abs(pressure(p) - kRhoG * (kFinalHead - y)));
    ++count;
  }
  EXPECT_EQ(count, 80);  // two rows of 40 points
  top.swelling /= count;
  std::printf("%s: top cell V/V0 - 1 %.3g, largest |p_L - hydrostatic| %.3g Pa\n", loads.c_str(),
              top.swelling, top.pressure_deficit);
  return top;
}

TEST(SubmergedGround, BoundaryPointsSwellTheTopCell) {
  const TopCell top = runGround("at boundary points");
  EXPECT_GT(top.swelling, 1e-3);           // measured 3.9e-3
  EXPECT_GT(top.pressure_deficit, 500.0);  // measured 1.7 kPa
}

TEST(SubmergedGround, ThroughTheSoilKeepsItAtRest) {
  const TopCell top = runGround("through the soil");
  EXPECT_LT(std::abs(top.swelling), 1e-5);  // measured 1.0e-6 (5.0e-7 on 0.05 m, 1.3e-7 on 0.025 m)
  EXPECT_LT(top.pressure_deficit, 10.0);    // measured 0.03 Pa
}

}  // namespace
}  // namespace argine
