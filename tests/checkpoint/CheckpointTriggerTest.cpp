// [Checkpoint] When a run writes checkpoints: Every Steps (whenever the step count passes a
// multiple) and Wall Interval (min); none by default.
#include <gtest/gtest.h>

#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <filesystem>

#include "argine/input/DeckReader.hpp"
#include "argine/simulation/Checkpoint.hpp"
#include "argine/simulation/Simulation.hpp"

namespace argine {
namespace {

namespace fs = std::filesystem;

// A 0.1 m x 0.5 m saturated column (5 quads), one explicit stage of a fixed 1 us step, 23 steps.
std::string deckWith(const std::string& checkpoint) {
  return R"(argine:
  Mesh:
    Generate: {Type: rectangle, Element: quad4, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], Upper Right (m): [0.1, 0.5]}
  Materials:
    soil:
      Block: soil
      Points Per Element: 4
      Porosity: 0.4
      Solid Density (kg/m3): 2700
      Solid: {Model: linear elastic, Young's Modulus (Pa): 1.0e7, Poisson's Ratio: 0.0}
      Conductivity: {Saturated Conductivity (m/s): 1.0e-5}
  Stages:
    settle:
      Solver: explicit
      Duration (s): 2.3e-5
      Time Step: {Mode: fixed, Fixed Step (s): 1.0e-6}
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
  Output:
    Name: trigger
)" + checkpoint;
}

RunSummary runDeck(const std::string& text, const fs::path& dir) {
  fs::remove_all(dir);
  const Deck deck = parseDeck(*Teuchos::getParametersFromYamlString(text), "");
  RunOptions options;
  options.output_directory = dir.string();
  options.quiet = true;
  Simulation simulation(deck, options);
  return simulation.run();
}

TEST(CheckpointTrigger, EveryStepsWallIntervalAndNone) {
  const fs::path base = fs::path(::testing::TempDir()) / "argine_checkpoint_trigger";
  // 23 steps, every 7: after steps 7, 14, 21.
  const RunSummary steps = runDeck(deckWith("    Checkpoint: {Every Steps: 7}\n"), base / "steps");
  EXPECT_EQ(steps.steps, 23);
  EXPECT_EQ(steps.checkpoints, 3);
  EXPECT_TRUE(fs::exists(checkpointPath((base / "steps").string(), "trigger")));
  EXPECT_GT(steps.checkpoint_bytes, 0u);
  // A wall interval shorter than any step: after every step.
  const RunSummary wall =
      runDeck(deckWith("    Checkpoint: {Wall Interval (min): 1.0e-12}\n"), base / "wall");
  EXPECT_EQ(wall.checkpoints, 23);
  // Default: none, and no file.
  const RunSummary none = runDeck(deckWith(""), base / "none");
  EXPECT_EQ(none.checkpoints, 0);
  EXPECT_FALSE(fs::exists(checkpointPath((base / "none").string(), "trigger")));
}

}  // namespace
}  // namespace argine
