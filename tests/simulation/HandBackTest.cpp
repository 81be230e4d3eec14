// `Hand Back At Rest` (P12): an explicit stage whose points have stopped moving runs the rest
// of its duration on the implicit seepage path. A wet column under rain settles under gravity
// with local damping; once it is at rest the rain goes on soaking it on the fixed skeleton.
#include <gtest/gtest.h>

#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>

#include "CsvRows.hpp"
#include "PointSums.hpp"
#include "QuietRun.hpp"
#include "WetColumnDeck.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/simulation/RestMonitor.hpp"
#include "argine/simulation/Simulation.hpp"

namespace argine {
namespace {

TEST(RestMonitor, AWindowIsJudgedOnceLongEnoughAgainstTheMeanSpeed) {
  HandBackSpec spec;
  spec.enabled = true;
  spec.largest_speed = 1e-3;  // m/s
  spec.window = 0.05;         // s
  RestMonitor rest(spec);
  rest.startWindow(0.1);
  EXPECT_FALSE(rest.due(0.14));
  EXPECT_TRUE(rest.due(0.15));  // (0.15 - 0.1 in doubles is 0.04999...: within the tolerance)
  EXPECT_TRUE(rest.due(0.16));
  // 0.06 s at 1 mm/s: 6e-5 m
  EXPECT_TRUE(rest.atRest(0.16, 5.9e-5));
  EXPECT_FALSE(rest.atRest(0.16, 6.1e-5));
  EXPECT_FALSE(rest.atRest(0.16, std::nan("")));
  rest.startWindow(0.16);
  EXPECT_EQ(rest.windowStart(), 0.16);
  EXPECT_FALSE(rest.due(0.2));
}

TEST(RestMonitor, LargestMotionOfTheLocatedPointsSinceTheReference) {
  MaterialPoints points;
  points.allocate(3);
  auto u = Kokkos::create_mirror_view(points.displacement);
  auto e = Kokkos::create_mirror_view(points.element);
  for (int p = 0; p < 3; ++p) u(p, 0) = u(p, 1) = 1.0;
  e(0) = 0, e(1) = 1, e(2) = -1;
  Kokkos::deep_copy(points.displacement, u);
  Kokkos::deep_copy(points.element, e);
  markRestReference(points);
  EXPECT_EQ(largestMotionSinceReference(points), 0.0);
  u(0, 0) = 4, u(0, 1) = 5;    // moved (3, 4): 5 m
  u(1, 0) = 1, u(1, 1) = -1;   // moved (0, -2): 2 m
  u(2, 0) = 99, u(2, 1) = 99;  // lost: not counted
  Kokkos::deep_copy(points.displacement, u);
  EXPECT_EQ(largestMotionSinceReference(points), 5.0);
  u(1, 0) = std::nan("");
  Kokkos::deep_copy(points.displacement, u);
  EXPECT_TRUE(std::isinf(largestMotionSinceReference(points)));
}

std::string columnDeck(Real duration, const std::string& stage_extra) {
  return test_decks::wetColumnDeck(std::to_string(duration),
                                   stage_extra.empty() ? "" : stage_extra + "\n");
}

const std::string kHandBack =
    "      Hand Back At Rest: {Largest Speed (m/s): 1.0e-3, Window (s): 0.05}\n"
    "      Implicit Seepage: {Initial Step (s): 0.01}";

Deck parse(const std::string& text) {
  return parseDeck(*Teuchos::getParametersFromYamlString(text), "");
}

void expectInputError(const std::string& text, const std::string& where) {
  try {
    parse(text);
    FAIL() << "no error for " << where;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
  }
}

TEST(HandBackDeck, KeysAndTheirChecks) {
  const Deck deck = parse(columnDeck(0.4, kHandBack));
  EXPECT_TRUE(deck.stages[0].hand_back.enabled);
  EXPECT_EQ(deck.stages[0].hand_back.largest_speed, 1e-3);
  EXPECT_EQ(deck.stages[0].hand_back.window, 0.05);
  EXPECT_EQ(deck.stages[0].seepage.initial_step, 0.01);
  EXPECT_FALSE(parse(columnDeck(0.4, "")).stages[0].hand_back.enabled);
  // the speed is tested at outputs: a window no longer than the output interval is refused
  expectInputError(
      columnDeck(0.4, "      Hand Back At Rest: {Largest Speed (m/s): 1.0e-3, Window (s): 0.02}"),
      "Stages/settle/Hand Back At Rest/Window (s)");
  expectInputError(columnDeck(0.4, "      Hand Back At Rest: {Window (s): 0.05}"),
                   "Largest Speed (m/s)");
  expectInputError(columnDeck(0.4, "      Implicit Seepage: {Initial Step (s): 0.01}"),
                   "Stages/settle/Implicit Seepage");
  std::string quasi_static = columnDeck(0.4, kHandBack);
  quasi_static.replace(quasi_static.find("Solver: explicit"), 16, "Solver: quasi-static");
  expectInputError(quasi_static, "Hand Back At Rest");
}

struct ColumnRun {
  MaterialPoints points;
  std::vector<std::string> log;
  std::filesystem::path dir;  ///< its output folder
};

ColumnRun runColumn(const std::string& text, const std::string& folder) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / folder;
  const RunOptions options = test::quietRunIn(dir);
  Simulation simulation(parseDeck(*Teuchos::getParametersFromYamlString(text), ""), options);
  simulation.run();
  return {simulation.points(), simulation.stageLog(), dir};
}

TEST(HandBackRun, TheRestOfTheStageSoaksTheRestingColumnOnTheFixedSkeleton) {
  const ColumnRun back = runColumn(columnDeck(0.4, kHandBack), "argine_hand_back");
  std::string line;
  for (const auto& l : back.log)
    if (l.find("stage 'settle': at rest at t = ") != std::string::npos) line = l;
  ASSERT_FALSE(line.empty()) << "no hand-back logged";
  std::cout << line << "\n";
  const Real at_rest = std::stod(line.substr(line.find("t = ") + 4));
  EXPECT_GT(at_rest, 0.05);
  EXPECT_LT(at_rest, 0.4 - 0.02);
  // The same deck without the key, cut at that output: the explicit part is the same run.
  const ColumnRun until = runColumn(columnDeck(at_rest, ""), "argine_hand_back_until");
  ASSERT_EQ(back.points.count, until.points.count);
  const auto u_back =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), back.points.displacement);
  const auto u_until =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), until.points.displacement);
  const auto p_back =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), back.points.pressure_liquid);
  const auto p_until =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), until.points.pressure_liquid);
  int pressure_changed = 0;
  for (int p = 0; p < back.points.count; ++p) {
    // the fixed skeleton: no point moves after the hand-back
    EXPECT_EQ(u_back(p, 0), u_until(p, 0)) << p;
    EXPECT_EQ(u_back(p, 1), u_until(p, 1)) << p;
    if (p_back(p) != p_until(p)) ++pressure_changed;
  }
  EXPECT_GT(pressure_changed, 0);  // the rain went on
  // ... and its water is in the points: 1e-4 m/s x 0.1 m x 1000 kg/m3 over the rest of the
  // stage (the top stays unsaturated, so none runs off).
  const Real rain = 1e-4 * 0.1 * 1000 * (0.4 - at_rest);
  EXPECT_NEAR(totalLiquidMass(back.points) - totalLiquidMass(until.points), rain, 1e-9);

  // The diagnostics rows of the implicit rest: its own step (the explicit one is below 1e-3
  // s here), no kinetic energy (fixed skeleton, no inertia), its liquid mass; the explicit
  // rows before carry the explicit step and the settling column's motion.
  // Columns: time, time_step, kinetic_energy_solid, kinetic_energy_liquid, liquid_mass, ...
  const auto rows = readCsvRows((back.dir / "column_diagnostics.csv").string());
  int implicit_rows = 0, moving_rows = 0;
  for (const auto& row : rows) {
    ASSERT_GE(row.size(), 5u);
    if (row[0] <= at_rest + 1e-9) {
      if (row[0] > 0) {
        EXPECT_LT(row[1], 1e-3) << "explicit row at t = " << row[0];
      }
      if (row[2] > 0) ++moving_rows;
      continue;
    }
    ++implicit_rows;
    EXPECT_GE(row[1], 1e-3) << "implicit row at t = " << row[0];
    EXPECT_EQ(row[2], 0.0) << "implicit row at t = " << row[0];
    EXPECT_EQ(row[3], 0.0) << "implicit row at t = " << row[0];
  }
  EXPECT_GT(moving_rows, 3);
  EXPECT_GT(implicit_rows, 3);
  EXPECT_NEAR(rows.back()[4], totalLiquidMass(back.points), 1e-9 * totalLiquidMass(back.points));

  // Without the key the stage stays explicit to its end.
  const ColumnRun explicit_only = runColumn(columnDeck(0.4, ""), "argine_hand_back_none");
  for (const auto& l : explicit_only.log) EXPECT_EQ(l.find("at rest at"), std::string::npos) << l;
}

}  // namespace
}  // namespace argine
