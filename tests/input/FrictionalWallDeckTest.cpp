// [Input] The keys of a frictional wall: coefficient, set, normal, impermeability, errors.
#include <gtest/gtest.h>

#include "DeckTestSupport.hpp"
#include "argine/input/Deck.hpp"

namespace argine {
namespace {

using test::expectDeckError;
using test::kBaseDeck;
using test::parseText;

/// The base deck with `conditions` (YAML lines under Boundary Conditions) added.
std::string withConditions(const std::string& conditions) {
  return kBaseDeck + conditions;
}

TEST(FrictionalWallDeck, SideSetAndNodeSetWalls) {
  const Deck deck = parseText(withConditions(
      R"(        slope: {Type: frictional wall, Side Set: bottom, Friction Coefficient (-): 0.3}
        wall:
          Type: frictional wall
          Node Set: left
          Friction Coefficient (-): 0
          Normal: [-3, 4]
          Impermeable: false
)"));
  const auto& b = deck.stages[0].boundaries;
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[1].kind, BoundaryKind::FrictionalWall);
  EXPECT_EQ(b[1].side_set, "bottom");
  EXPECT_TRUE(b[1].node_set.empty());
  EXPECT_DOUBLE_EQ(b[1].friction_coefficient, 0.3);
  EXPECT_TRUE(b[1].wall_impermeable);  // default: the wall holds the pore liquid
  EXPECT_FALSE(b[1].has_normal);
  EXPECT_EQ(b[2].node_set, "left");
  EXPECT_EQ(b[2].friction_coefficient, 0.0);  // a smooth wall
  EXPECT_FALSE(b[2].wall_impermeable);
  EXPECT_TRUE(b[2].has_normal);
  EXPECT_DOUBLE_EQ(b[2].normal[0], -0.6);  // normalised
  EXPECT_DOUBLE_EQ(b[2].normal[1], 0.8);
}

TEST(FrictionalWallDeck, BadInputNamesTheKey) {
  const std::string path = "Stages/load/Boundary Conditions/slope";
  expectDeckError(withConditions("        slope: {Type: frictional wall, Side Set: bottom, "
                                 "Friction Coefficient (-): -0.1}\n"),
                  path + "/Friction Coefficient (-)", "must be >= 0, got -0.1");
  expectDeckError(withConditions("        slope: {Type: frictional wall, Side Set: bottom}\n"),
                  path + "/Friction Coefficient (-)", "missing required key");
  expectDeckError(withConditions("        slope: {Type: frictional wall, "
                                 "Friction Coefficient (-): 0.3}\n"),
                  path,
                  "give exactly one of 'Node Set' or 'Side Set' when Type is impermeable or "
                  "frictional wall");
  expectDeckError(withConditions("        slope: {Type: frictional wall, Side Set: bottom, "
                                 "Friction Coefficient (-): 0.3, Normal: [0, -1]}\n"),
                  path + "/Normal", "Normal is for a Node Set");
  expectDeckError(withConditions("        slope: {Type: frictional wall, Node Set: bottom, "
                                 "Friction Coefficient (-): 0.3, Normal: [0, 0]}\n"),
                  path + "/Normal", "expected a non-zero finite vector");
  expectDeckError(withConditions("        slope: {Type: traction, Side Set: top, Traction (Pa): "
                                 "[0, 1], Friction Coefficient (-): 0.3}\n"),
                  path + "/Friction Coefficient (-)", "applies only when Type is frictional wall");
}

}  // namespace
}  // namespace argine
