#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "argine/core/Error.hpp"
#include "argine/meshio/MeshGenerators.hpp"
#include "argine/meshio/SectionGraph.hpp"

namespace argine {
namespace {

GeneratorSpec boxSpec() {
  GeneratorSpec spec;
  spec.kind = GeneratorSpec::Kind::Polygon;
  spec.element = ElementType::Tri3;
  spec.element_size = 0.25;
  spec.lower_left = {0.0, 0.0};
  spec.upper_right = {4.0, 2.0};
  return spec;
}

bool hasSegment(const SectionGraph& graph, Point2 p, Point2 q) {
  for (const auto& s : graph.segments) {
    const Point2& a = graph.vertices[s[0]];
    const Point2& b = graph.vertices[s[1]];
    if ((a == p && b == q) || (a == q && b == p)) return true;
  }
  return false;
}

/// Runs f and returns the InputError message ("" when nothing was thrown).
template <class F>
std::string inputErrorOf(F f) {
  try {
    f();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(SectionGraph, SharedCornersMergeAndSharedEdgesAreStoredOnce) {
  GeneratorSpec spec = boxSpec();
  // A levee on the box bottom: its base is the box bottom, its toes are box corners.
  spec.regions = {{"levee", {{0, 0}, {4, 0}, {2.5, 1}, {1.5, 1}}}};
  const SectionGraph graph = buildSectionGraph(spec);
  EXPECT_EQ(graph.vertices.size(), 6u);  // 4 box corners + 2 crest points
  EXPECT_EQ(graph.segments.size(), 7u);  // 4 box sides + 2 slopes + crest
}

TEST(SectionGraph, EdgesAreSplitAtVerticesOnThem) {
  GeneratorSpec spec = boxSpec();
  // Layer up to y = 1; a levee standing on it whose toes (1,1), (3,1) lie on the layer top,
  // and a layer vertex (2.5, 0) on the box bottom.
  spec.regions = {{"layer", {{0, 0}, {2.5, 0}, {4, 0}, {4, 1}, {0, 1}}},
                  {"levee", {{1, 1}, {3, 1}, {2, 1.5}}}};
  const SectionGraph graph = buildSectionGraph(spec);
  EXPECT_TRUE(hasSegment(graph, {0, 1}, {1, 1}));
  EXPECT_TRUE(hasSegment(graph, {1, 1}, {3, 1}));
  EXPECT_TRUE(hasSegment(graph, {3, 1}, {4, 1}));
  EXPECT_FALSE(hasSegment(graph, {0, 1}, {4, 1}));
  EXPECT_TRUE(hasSegment(graph, {0, 0}, {2.5, 0}));
  EXPECT_FALSE(hasSegment(graph, {0, 0}, {4, 0}));
  // Segments: box bottom (2) + right (2: split at (4,1)) + top + left (2) = 7; layer top 3;
  // levee slopes 2.
  EXPECT_EQ(graph.segments.size(), 12u);
}

TEST(SectionGraph, ClockwiseRegionIsAcceptedAndReversed) {
  GeneratorSpec spec = boxSpec();
  spec.regions = {{"block", {{1, 0.5}, {1, 1.5}, {3, 1.5}, {3, 0.5}}}};
  const SectionGraph graph = buildSectionGraph(spec);
  EXPECT_DOUBLE_EQ(signedArea(graph.regions[0]), 2.0);
}

TEST(SectionGraph, BadRegionsAreInputErrors) {
  GeneratorSpec spec = boxSpec();
  spec.regions = {{"levee", {{0, 0}, {4.5, 0}, {2, 1}}}};  // (4.5, 0) is outside the box
  std::string message = inputErrorOf([&] { buildSectionGraph(spec); });
  EXPECT_NE(message.find("Mesh/Generate/Regions/levee"), std::string::npos) << message;
  EXPECT_NE(message.find("outside the box"), std::string::npos) << message;

  spec.regions = {{"a", {{0, 0}, {2, 0}, {2, 1}, {0, 1}}}, {"b", {{1, 0.5}, {3, 0.5}, {3, 1.5}}}};
  message = inputErrorOf([&] { buildSectionGraph(spec); });
  EXPECT_NE(message.find("region a and region b overlap"), std::string::npos) << message;

  spec.regions = {{"bowtie", {{1, 0.5}, {3, 1.5}, {3, 0.5}, {1, 1.8}}}};  // edges 1-2, 3-4 cross
  message = inputErrorOf([&] { buildSectionGraph(spec); });
  EXPECT_NE(message.find("intersects itself"), std::string::npos) << message;

  spec.regions = {{"line", {{1, 1}, {2, 1}, {3, 1}}}};
  message = inputErrorOf([&] { buildSectionGraph(spec); });
  EXPECT_NE(message.find("zero area"), std::string::npos) << message;

  spec.regions = {{"two", {{1, 1}, {2, 1}, {1, 1}}}};
  EXPECT_NE(inputErrorOf([&] { buildSectionGraph(spec); }), "");
}

TEST(SectionGraph, RegionInsideAnotherIsAnOverlapError) {
  // No edges cross, so only the element classification can see it.
  GeneratorSpec spec = boxSpec();
  spec.regions = {{"outer", {{0.5, 0.5}, {3.5, 0.5}, {3.5, 1.5}, {0.5, 1.5}}},
                  {"inner", {{1, 0.8}, {2, 0.8}, {2, 1.2}}}};
  const std::string message = inputErrorOf([&] { generateMesh(spec); });
  EXPECT_NE(message.find("regions outer and inner overlap"), std::string::npos) << message;
}

TEST(SectionGraph, RegionsFillingTheBoxLeaveNoEmptyBlock) {
  GeneratorSpec spec = boxSpec();
  spec.regions = {{"lower", {{0, 0}, {4, 0}, {4, 1}, {0, 1}}},
                  {"upper", {{0, 1}, {4, 1}, {4, 2}, {0, 2}}}};
  const Mesh mesh = generateMesh(spec);
  ASSERT_EQ(mesh.blocks.size(), 2u);
  EXPECT_EQ(mesh.blocks[0].name, "lower");
  EXPECT_EQ(mesh.blocks[1].name, "upper");
  EXPECT_EQ(mesh.findBlock("empty"), nullptr);
}

TEST(SectionGraph, TwoPolygonsMayShareABlockName) {
  GeneratorSpec spec = boxSpec();
  spec.regions = {{"sand", {{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}}},
                  {"sand", {{2.5, 0.5}, {3.5, 0.5}, {3.5, 1.5}}}};
  const Mesh mesh = generateMesh(spec);
  ASSERT_EQ(mesh.blocks.size(), 2u);  // sand, empty
  EXPECT_EQ(mesh.blocks[0].name, "sand");
  EXPECT_EQ(mesh.blocks[1].name, "empty");
}

}  // namespace
}  // namespace argine
