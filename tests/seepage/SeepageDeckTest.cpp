// The implicit stage's deck block and the boundary node lists resolved from it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/seepage/SeepageBoundary.hpp"
#include "argine/simulation/Setup.hpp"

namespace argine {
namespace {

TEST(SeepageDeck, V3DeckGivesTheImplicitSettingsAndBoundaryNodes) {
  const Deck deck =
      readDeck(ARGINE_SOURCE_DIR "/verification/infiltration_column/infiltration_column.yaml");
  const StageSpec& stage = deck.stages.at(0);
  EXPECT_EQ(stage.solver, SolverKind::ImplicitSeepage);
  EXPECT_EQ(stage.seepage.theta, 1.0);
  EXPECT_EQ(stage.seepage.max_step, 2.0);
  EXPECT_EQ(stage.seepage.initial_step, 0.5);
  EXPECT_EQ(stage.seepage.linear.solver, "GMRES");
  EXPECT_EQ(stage.seepage.linear.preconditioner, "RILUK");
  EXPECT_EQ(stage.seepage.linear.tolerance, 1e-12);
  ASSERT_EQ(stage.boundaries.at(0).kind, BoundaryKind::Infiltration);
  EXPECT_EQ(stage.boundaries.at(0).hydraulic.series.value, 1e-4);
  EXPECT_FALSE(stage.boundaries.at(0).hydraulic.ponding);  // runs off at p_L = 0 (switchable)

  // The top of the 0.05 m wide column: two nodes, each with L/2 = 0.025 m, q L/2 = 2.5e-6 m2/s.
  const Mesh mesh = loadMesh(deck);
  const MaterialPoints points = seedPoints(deck, mesh);
  const SeepageBoundaryConditions conditions =
      seepageBoundaryPlan(mesh, points, stage).at(0.0, 1.0);
  ASSERT_EQ(conditions.supply_nodes.size(), 2u);
  for (std::size_t j = 0; j < 2; ++j) {
    EXPECT_NEAR(conditions.supplies[j], 2.5e-6, 1e-18);
    EXPECT_EQ(conditions.switchable[j], 1);
  }
  EXPECT_TRUE(conditions.pressure_nodes.empty());  // impermeable base: natural
}

TEST(SeepageDeck, MissingSideSetNamesTheCondition) {
  Deck deck =
      readDeck(ARGINE_SOURCE_DIR "/verification/infiltration_column/infiltration_column.yaml");
  StageSpec stage = deck.stages.at(0);
  stage.boundaries.at(0).side_set = "crest";
  const Mesh mesh = loadMesh(deck);
  const MaterialPoints points = seedPoints(deck, mesh);
  try {
    seepageBoundaryPlan(mesh, points, stage);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Stages/infiltration/Boundary Conditions/rain/Side Set");
  }
}

TEST(SeepageDeck, NonlinearSolverKeyDefaultsToPicardAndNewtonRefusesCg) {
  const std::string dir = ARGINE_SOURCE_DIR "/verification/infiltration_column/";
  EXPECT_EQ(readDeck(dir + "infiltration_column.yaml").stages.at(0).seepage.iteration,
            SeepageIteration::Picard);
  const std::string newton = dir + "infiltration_column_newton.yaml";
  EXPECT_EQ(readDeck(newton).stages.at(0).seepage.iteration, SeepageIteration::Newton);
  // The same deck with the cg linear solver: refused, naming the linear solver's key.
  std::ifstream in(newton);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string gmres = "Solver: gmres";
  ASSERT_NE(text.find(gmres), std::string::npos);
  text.replace(text.find(gmres), gmres.size(), "Solver: cg");
  const auto path = std::filesystem::path(ARGINE_BINARY_DIR) / "seepage_newton_cg.yaml";
  std::ofstream(path) << text;
  try {
    readDeck(path.string());
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Stages/infiltration/Implicit Seepage/Linear Solver/Solver");
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace argine
