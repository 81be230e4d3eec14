// The example decks of tests/input/decks are valid and fit the generator's set names.
#include "DeckTestSupport.hpp"

namespace argine::test {

namespace {

std::string exampleDeck(const std::string& name) {
  return std::string(ARGINE_SOURCE_DIR) + "/tests/input/decks/" + name;
}

/// The names the rectangle generator gives: one block, sets left/right/bottom/top.
Mesh rectangleNames(const std::string& block) {
  Mesh mesh;
  mesh.blocks = {ElementBlock{block, 1, {}}};
  int id = 1;
  for (const char* side : {"left", "right", "bottom", "top"}) {
    mesh.node_sets.push_back(NodeSet{side, id, {}});
    mesh.side_sets.push_back(SideSet{side, id, {}, {}});
    ++id;
  }
  return mesh;
}

}  // namespace

TEST(ExampleDecks, SaturatedColumn) {
  const Deck deck = readDeck(exampleDeck("saturated_column.yaml"));
  ASSERT_EQ(deck.materials.size(), 1u);
  const MaterialSpec& soil = deck.materials[0];
  EXPECT_EQ(soil.phase, PhaseModel::Saturated);
  // kappa = k_sat mu_L / (rho_L g) = 1e-5 * 1e-3 / 9810 = 1.019367991845056e-12 m2
  EXPECT_NEAR(soil.conductivity.intrinsic_permeability, 1.019367991845056e-12, 1e-26);
  ASSERT_EQ(deck.stages.size(), 1u);
  EXPECT_EQ(deck.stages[0].gravity, 0.0);
  EXPECT_EQ(deck.stages[0].boundaries.size(), 8u);
  EXPECT_EQ(deck.stages[0].boundaries[6].traction, (std::array<Real, 2>{0.0, -10000.0}));
  EXPECT_NO_THROW(checkDeckAgainstMesh(deck, rectangleNames("soil")));
}

TEST(ExampleDecks, UnsaturatedColumn) {
  const Deck deck = readDeck(exampleDeck("unsaturated_column.yaml"));
  const MaterialSpec& sand = deck.materials.at(0);
  EXPECT_EQ(sand.phase, PhaseModel::Unsaturated);
  EXPECT_EQ(sand.retention.model, RetentionModel::VanGenuchten);
  EXPECT_EQ(sand.solid.model, SolidModel::SuctionMohrCoulomb);
  // k_sat = kappa rho_L g / mu_L = 1e-11 * 1000 * 9.81 / 1e-3 = 9.81e-5 m/s
  EXPECT_NEAR(sand.conductivity.saturated_conductivity, 9.81e-5, 1e-18);
  EXPECT_EQ(sand.initial.liquid_pressure, -2000.0);
  ASSERT_EQ(deck.stages.size(), 2u);
  EXPECT_EQ(deck.stages[0].name, "wetting");
  EXPECT_EQ(deck.stages[0].solver, SolverKind::FixedSkeleton);
  const std::vector<CriterionKind> criteria{CriterionKind::Infiltration,
                                            CriterionKind::UnsaturatedLiquid};
  EXPECT_EQ(deck.stages[0].time_step.criteria, criteria);
  EXPECT_EQ(deck.stages[1].name, "loading");
  EXPECT_FALSE(deck.stages[1].time_step.automatic);
  EXPECT_TRUE(deck.stages[1].reset_displacements);
  EXPECT_NO_THROW(checkDeckAgainstMesh(deck, rectangleNames("sand")));
}

}  // namespace argine::test
