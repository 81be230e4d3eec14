// The factor of safety of a run (P13 items 1 and 4): the deck section, the CSV at every
// output, the stage hand-over below a threshold, and the factor of the deck's initial state
// against the same search on the polygon the deck's mesh region draws.
#include <gtest/gtest.h>

#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "CsvRows.hpp"
#include "DrySlopeDeck.hpp"
#include "QuietRun.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/simulation/Simulation.hpp"

namespace argine {
namespace {

constexpr Real kDegree = 3.14159265358979323846 / 180;

// The dry slope of DrySlopeDeck.hpp, tri3 of 0.25 m. Two quasi-static stages; the first hands
// over below F = 5 (it is near 1).
std::string deckText(const std::string& extra_stage_key, bool with_section) {
  std::string deck = test_decks::drySlopeDeckHead("0.25") + R"(
  Stages:
    hold:
      Solver: quasi-static
      Duration (s): 0.02
      Output Interval (s): 0.005
      Local Damping: 0.7
)" + extra_stage_key +
                     R"(
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        left: {Type: solid fixity, Node Set: left, Direction: x}
        right: {Type: solid fixity, Node Set: right, Direction: x}
    next:
      Solver: quasi-static
      Duration (s): 0.005
      Local Damping: 0.7
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        left: {Type: solid fixity, Node Set: left, Direction: x}
        right: {Type: solid fixity, Node Set: right, Direction: x}
)";
  if (with_section)
    deck += R"(  Factor Of Safety:
    Centre X (m): [2.0, 14.0]
    Centre Y (m): [9.4, 21.4]
    Tangent Y (m): [0.0, 8.6]
    Suction Strength: none
)";
  deck += "  Output: {Name: slope}\n";
  return deck;
}

Deck parse(const std::string& text) {
  return parseDeck(*Teuchos::getParametersFromYamlString(text), "");
}

TEST(FactorOfSafetyDeck, HandOverNeedsTheSectionAndRangesMustIncrease) {
  const std::string key = "      Hand Over Below Factor Of Safety: 1.0";
  try {
    parse(deckText(key, false));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Stages/hold/Hand Over Below Factor Of Safety"),
              std::string::npos)
        << e.what();
  }
  std::string reversed = deckText("", true);
  reversed.replace(reversed.find("[2.0, 14.0]"), 11, "[14.0, 2.0]");
  try {
    parse(reversed);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Factor Of Safety/Centre X (m)"), std::string::npos)
        << e.what();
  }
  std::string one_vertex = deckText("", true);
  one_vertex.replace(one_vertex.find("    Suction Strength: none"), 0,
                     "    Ground Surface (m): [0.0, 5.0]\n");
  try {
    parse(one_vertex);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Factor Of Safety/Ground Surface (m)"), std::string::npos)
        << e.what();
  }
  const Deck deck = parse(deckText(key, true));
  EXPECT_TRUE(deck.factor_of_safety.enabled);
  EXPECT_EQ(deck.factor_of_safety.suction, SuctionStrength::None);
  EXPECT_EQ(deck.stages[0].hand_over_below_factor_of_safety, 1.0);
  EXPECT_EQ(deck.stages[1].hand_over_below_factor_of_safety, 0);
}

TEST(FactorOfSafetyRun, EveryOutputAndTheHandOver) {
  const Deck deck = parse(deckText("      Hand Over Below Factor Of Safety: 5.0", true));
  const auto dir = std::filesystem::path(::testing::TempDir()) / "argine_factor_of_safety";
  const RunOptions options = test::quietRunIn(dir);
  Simulation simulation(deck, options);
  simulation.run();

  // Rows at t = 0, at the first output of 'hold' (where F < 5 ends it) and at the end of
  // 'next', 0.005 s later.
  const auto rows = readCsvRows((dir / "slope_factor_of_safety.csv").string());
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_NEAR(rows[0][0], 0, 1e-12);
  EXPECT_NEAR(rows[1][0], 0.005, 1e-9);
  EXPECT_NEAR(rows[2][0], 0.010, 1e-9);
  bool logged = false;
  for (const auto& line : simulation.stageLog())
    logged = logged || line.find("stage 'hold': factor of safety") != std::string::npos;
  EXPECT_TRUE(logged);

  // The initial state's factor against the same search on the deck's polygon with the
  // points' unit weight: the points' envelope lies within about one point spacing (0.1 m)
  // of the face, 2.5 % of the height, so the factors agree to that.
  SlopeSection polygon;
  polygon.ground = Polyline({0, 4, 12, 16}, {5, 5, 9, 9});
  polygon.layers.push_back({"soil", polygon.ground, 0.6 * 2650 * 9.81, 1200, 19.6 * kDegree});
  polygon.floor = 0;
  CircleSearchGrid grid;
  grid.centre_x_min = 2;
  grid.centre_x_max = 14;
  grid.centre_y_min = 9.4;
  grid.centre_y_max = 21.4;
  grid.tangent_y_min = 0;
  grid.tangent_y_max = 8.6;
  const CriticalCircle exact = searchCriticalCircle(polygon, grid);
  ASSERT_TRUE(exact.found);
  std::cout << "slope: initial F from the points " << rows[0][1] << ", from the polygon "
            << exact.bishop.value << "\n";
  EXPECT_NEAR(rows[0][1], exact.bishop.value, 0.025 * exact.bishop.value);
  // the slice table: the slices of each of the three evaluations
  const auto slices = readCsvRows((dir / "slope_critical_slices.csv").string());
  EXPECT_GE(slices.size(), 3u * 50u);
  // Bishop's method: the factor is Bishop's column; the ordinary method is lower (phi' > 0).
  EXPECT_EQ(rows[0][1], rows[0][2]);
  EXPECT_LT(rows[0][3], rows[0][2]);
}

TEST(FactorOfSafetyRun, SpencerOnTheSameState) {
  // Method spencer on the same deck: Spencer's F of its own critical circle, within 1 % of
  // Bishop's in a dry homogeneous slope (Bishop's simplified method is known to lie within
  // a few per cent of the rigorous methods on circles; SpencerCircleTest: 1 %).
  std::string text = deckText("", true);
  text.replace(text.find("    Suction Strength: none"), 0,
               "    Method: spencer\n    Search Starts: 1\n");  // one start: a quicker test
  const Deck deck = parse(text);
  ASSERT_TRUE(deck.factor_of_safety.spencer);
  const Simulation initial(deck, RunOptions{});  // the initial state, not run
  const CriticalCircle spencer_circle =
      criticalCircleOf(deck.factor_of_safety, initial.points(), deck.materials, 9.81);
  ASSERT_TRUE(spencer_circle.found);
  std::cout << "slope: Spencer F " << spencer_circle.objective.value << ", Bishop on its circle "
            << spencer_circle.bishop.value << "\n";
  EXPECT_NEAR(spencer_circle.objective.value, spencer_circle.bishop.value,
              0.01 * spencer_circle.bishop.value);
}

}  // namespace
}  // namespace argine
