// A deck with soil regions in a `rectangle` mesh and 9 or 16 points per quad, through the
// setup a run uses (loadMesh, seedPoints): the m x m patterns, the points inside the
// polygon, and the key paths of the errors.
#include <gtest/gtest.h>

#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <functional>
#include <string>
#include <vector>

#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/simulation/Setup.hpp"

namespace argine {
namespace {

/// A 1 m x 1 m box in 4 x 4 quads of 0.25 m; `mesh` is the rest of the Generate line and
/// `points` the material's Points Per Element.
std::string deckText(const std::string& mesh, int points, const std::string& block = "soil") {
  return R"(argine:
  Mesh:
    Generate: {Type: rectangle, Element Size (m): 0.25, Lower Left (m): [0.0, 0.0], Upper Right (m): [1.0, 1.0])" +
         mesh + R"(}
  Materials:
    sand:
      Block: )" +
         block + R"(
      Points Per Element: )" +
         std::to_string(points) + R"(
      Phase Model: dry
      Porosity: 0.4
      Solid Density (kg/m3): 2700
      Solid: {Model: linear elastic, Young's Modulus (Pa): 1.0e7, Poisson's Ratio: 0.3}
  Stages:
    settle: {Solver: explicit, Duration (s): 0.1}
)";
}

/// The deck with triangles instead of quads.
std::string replacedElement(std::string text) {
  const std::string from = "Type: rectangle,";
  return text.replace(text.find(from), from.size(), from + " Element: tri3,");
}

Deck parse(const std::string& text) {
  return parseDeck(*Teuchos::getParametersFromYamlString(text), "");
}

template <class View>
auto onHost(const View& view) {
  return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
}

TEST(RegionDeck, NineAndSixteenPointsPerQuadGiveTheGridPattern) {
  for (const int m : {3, 4}) {
    const Deck deck = parse(deckText("", m * m));
    EXPECT_EQ(deck.materials[0].points_per_element, m * m);
    const Mesh mesh = loadMesh(deck);
    const MaterialPoints points = seedPoints(deck, mesh);
    ASSERT_EQ(points.count, 16 * m * m);
    // In every cell the local coordinates are the centres of m x m equal sub-squares,
    // -1 + (2 i + 1) / m, row by row, and each point has 1/m^2 of the cell.
    const auto local = onHost(points.local);
    const auto volume = onHost(points.volume);
    for (int p = 0; p < points.count; ++p) {
      const int k = p % (m * m), i = k % m, j = k / m;
      EXPECT_NEAR(local(p, 0), -1.0 + (2.0 * i + 1.0) / m, 1e-15);
      EXPECT_NEAR(local(p, 1), -1.0 + (2.0 * j + 1.0) / m, 1e-15);
      EXPECT_NEAR(volume(p), 0.0625 / (m * m), 1e-16);
    }
  }
}

TEST(RegionDeck, TrianglesRefuseNinePointsNamingTheKey) {
  const Deck deck = parse(replacedElement(deckText("", 9)));
  const Mesh mesh = loadMesh(deck);
  try {
    seedPoints(deck, mesh);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Materials/sand/Points Per Element");
    EXPECT_NE(std::string(error.what()).find("1, 3, 4, 6, 12"), std::string::npos);
  }
}

TEST(RegionDeck, RegionPointsLieInsideTheSlope) {
  // The triangle (0, 0), (0.9, 0), (0, 0.9) with 16 points per quad: 105 points
  // (RegionSeeding test), all with x + y <= 0.9.
  const Deck deck = parse(
      deckText(", Regions: {slope: {Vertices (m): [0.0, 0.0, 0.9, 0.0, 0.0, 0.9]}}", 16, "slope"));
  const Mesh mesh = loadMesh(deck);
  EXPECT_EQ(mesh.blockNames(), (std::vector<std::string>{"slope", "empty"}));
  const MaterialPoints points = seedPoints(deck, mesh);
  ASSERT_EQ(points.count, 105);
  const auto position = onHost(points.position);
  for (int p = 0; p < points.count; ++p) EXPECT_LE(position(p, 0) + position(p, 1), 0.9);
}

TEST(RegionDeck, ErrorsNameTheKeyPath) {
  const std::string slope = ", Regions: {slope: {Vertices (m): [0.0, 0.0, 0.9, 0.0, 0.0, 0.9]}";
  const auto expectError = [](const std::function<void()>& action, const std::string& where,
                              const std::string& part) {
    try {
      action();
      ADD_FAILURE() << "no error at " << where;
    } catch (const InputError& error) {
      EXPECT_EQ(error.where(), where);
      EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
    }
  };
  // A material on the rest of the box.
  expectError([&] { loadMesh(parse(deckText(slope + "}", 4, "empty"))); }, "Materials/sand/Block",
              "a material fills a region: slope");
  // Overlapping regions.
  expectError(
      [&] {
        loadMesh(parse(deckText(slope + ", toe: {Vertices (m): [0.1, 0.1, 0.3, 0.1, 0.1, 0.3]}}", 4,
                                "slope")));
      },
      "Mesh/Generate/Regions", "regions slope and toe overlap");
  // A region partly outside the box.
  expectError(
      [&] {
        parse(deckText(", Regions: {slope: {Vertices (m): [0.0, 0.0, 1.5, 0.0, 0.0, 0.9]}}", 4,
                       "slope"));
      },
      "Mesh/Generate/Regions/slope/Vertices (m)", "outside the box");
  // Block beside Regions.
  expectError([&] { parse(deckText(", Block: soil" + slope + "}", 4, "slope")); },
              "Mesh/Generate/Block", "takes its block names from the regions");
}

}  // namespace
}  // namespace argine
