// [Input] The keys of the side walls of a quasi-2D channel: width, coefficient, errors.
#include <gtest/gtest.h>

#include "DeckTestSupport.hpp"
#include "argine/input/Deck.hpp"

namespace argine {
namespace {

using test::expectDeckError;
using test::kBaseDeck;
using test::parseText;

TEST(SideWallsDeck, WidthAndCoefficient) {
  const Deck deck = parseText(kBaseDeck + R"(        channel:
          Type: side walls
          Channel Width (m): 0.1
          Friction Coefficient (-): 0.46
)");
  const auto& b = deck.stages[0].boundaries;
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[1].kind, BoundaryKind::SideWalls);
  EXPECT_DOUBLE_EQ(b[1].channel_width, 0.1);
  EXPECT_DOUBLE_EQ(b[1].friction_coefficient, 0.46);
  EXPECT_TRUE(b[1].node_set.empty());
  EXPECT_TRUE(b[1].side_set.empty());
}

TEST(SideWallsDeck, BadInputNamesTheKey) {
  const std::string path = "Stages/load/Boundary Conditions/channel";
  expectDeckError(kBaseDeck +
                      "        channel: {Type: side walls, Channel Width (m): 0, "
                      "Friction Coefficient (-): 0.4}\n",
                  path + "/Channel Width (m)", "must be > 0 m, got 0");
  expectDeckError(
      kBaseDeck + "        channel: {Type: side walls, Friction Coefficient (-): 0.4}\n",
      path + "/Channel Width (m)", "missing required key");
  expectDeckError(kBaseDeck + "        channel: {Type: side walls, Channel Width (m): 0.1}\n",
                  path + "/Friction Coefficient (-)", "missing required key");
  expectDeckError(kBaseDeck +
                      "        channel: {Type: side walls, Channel Width (m): 0.1, "
                      "Friction Coefficient (-): -1}\n",
                  path + "/Friction Coefficient (-)", "must be >= 0, got -1");
  // the walls are out of the plane: no set
  expectDeckError(kBaseDeck +
                      "        channel: {Type: side walls, Channel Width (m): 0.1, "
                      "Friction Coefficient (-): 0.4, Side Set: bottom}\n",
                  path + "/Side Set", "applies only when Type is");
  expectDeckError(kBaseDeck +
                      "        slope: {Type: frictional wall, Side Set: bottom, "
                      "Friction Coefficient (-): 0.3, Channel Width (m): 0.1}\n",
                  "Stages/load/Boundary Conditions/slope/Channel Width (m)",
                  "applies only when Type is side walls");
}

}  // namespace
}  // namespace argine
