#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>

#include "argine/core/Error.hpp"
#include "argine/meshio/ExodusMesh.hpp"
#include "argine/meshio/Geometry2D.hpp"
#include "argine/meshio/MeshGenerators.hpp"
#include "argine/meshio/MeshQuality.hpp"

namespace argine {
namespace {

/// The V4 levee: trapezoid 4.5 m base, 0.5 m crest, 1 m high, in a 4.5 x 1.2 m box.
/// Area = (4.5 + 0.5) / 2 * 1.0 = 2.5 m^2; the empty rest 5.4 - 2.5 = 2.9 m^2.
GeneratorSpec leveeSpec(ElementType type, Real h) {
  GeneratorSpec spec;
  spec.kind = GeneratorSpec::Kind::Polygon;
  spec.element = type;
  spec.element_size = h;
  spec.lower_left = {0.0, 0.0};
  spec.upper_right = {4.5, 1.2};
  spec.regions = {{"levee", {{0.0, 0.0}, {4.5, 0.0}, {2.5, 1.0}, {2.0, 1.0}}}};
  return spec;
}

/// Three layers in a 12 x 5 m box: a sand foundation with a sloping top (area
/// 12 * (1.2 + 1.8) / 2 = 18), a clay blanket above it up to y = 2 (12 * (0.2 + 0.8) / 2 = 6)
/// and a levee standing on the blanket (bases 8 and 2, height 2: area 10). The levee base
/// lies on the blanket top, which has no vertices at x = 2 and x = 10 (T-junctions).
GeneratorSpec layeredSpec(ElementType type, Real h) {
  GeneratorSpec spec;
  spec.kind = GeneratorSpec::Kind::Polygon;
  spec.element = type;
  spec.element_size = h;
  spec.lower_left = {0.0, 0.0};
  spec.upper_right = {12.0, 5.0};
  spec.regions = {{"sand", {{0.0, 0.0}, {12.0, 0.0}, {12.0, 1.2}, {0.0, 1.8}}},
                  {"clay", {{0.0, 1.8}, {12.0, 1.2}, {12.0, 2.0}, {0.0, 2.0}}},
                  {"levee", {{2.0, 2.0}, {10.0, 2.0}, {7.0, 4.0}, {5.0, 4.0}}}};
  return spec;
}

Real polygonArea(const PolygonRegion& region) {
  return std::abs(signedArea(region.vertices));
}

/// Checks conformity (block areas = polygon areas), validity, shape and size.
void checkSection(const GeneratorSpec& spec, const Mesh& mesh) {
  const Real box_area =
      (spec.upper_right[0] - spec.lower_left[0]) * (spec.upper_right[1] - spec.lower_left[1]);
  const std::vector<Real> areas = blockAreas(mesh);
  Real regions_area = 0;
  for (const auto& region : spec.regions) {
    const ElementBlock* block = mesh.findBlock(region.block);
    ASSERT_NE(block, nullptr) << region.block;
    const Real expected = polygonArea(region);
    regions_area += expected;
    EXPECT_NEAR(areas[block - mesh.blocks.data()], expected, 1e-10 * expected) << region.block;
  }
  const ElementBlock* empty = mesh.findBlock("empty");
  ASSERT_NE(empty, nullptr);
  EXPECT_EQ(empty, &mesh.blocks.back());
  EXPECT_NEAR(areas.back(), box_area - regions_area, 1e-10 * box_area);

  const MeshQuality quality = measureQuality(mesh);
  EXPECT_EQ(quality.non_ccw_elements, 0);
  EXPECT_GT(quality.min_area, 0.0);
  EXPECT_EQ(quality.unmatched_edges, 0);  // no hanging nodes, no overlaps
  EXPECT_NEAR(quality.total_area, box_area, 1e-10 * box_area);
  const Real h = spec.element_size;
  const Real reference = box_area / (h * h * std::sqrt(3.0) / 4);  // equilateral triangles
  if (mesh.type == ElementType::Tri3) {
    EXPECT_GE(quality.min_angle_degrees, 20.0);
    EXPECT_GT(mesh.numElements(), 0.5 * reference);
    EXPECT_LT(mesh.numElements(), 2.0 * reference);
  } else {
    EXPECT_GT(quality.min_angle_degrees, 5.0);
    // Quads: 3 per triangle of size 2h, i.e. 3/4 of `reference`.
    EXPECT_GT(mesh.numElements(), 0.5 * 0.75 * reference);
    EXPECT_LT(mesh.numElements(), 2.0 * 0.75 * reference);
  }
  ::testing::Test::RecordProperty("min_angle_degrees", std::to_string(quality.min_angle_degrees));
  std::printf("    %s h=%g: %d nodes, %d elements (reference %.0f), angles %.2f..%.2f deg\n",
              exodusName(mesh.type), h, mesh.numNodes(), mesh.numElements(), reference,
              quality.min_angle_degrees, quality.max_angle_degrees);

  // Box side sets: every side lies on its box side; side lengths add up to the box side.
  for (const char* name : {"left", "right", "bottom", "top"}) {
    const SideSet* sides = mesh.findSideSet(name);
    const NodeSet* nodes = mesh.findNodeSet(name);
    ASSERT_NE(sides, nullptr);
    ASSERT_NE(nodes, nullptr);
    Real length = 0;
    for (std::size_t i = 0; i < sides->elements.size(); ++i) {
      const int e = sides->elements[i], s = sides->sides[i];
      const int a = mesh.connectivity(e, s),
                b = mesh.connectivity(e, (s + 1) % mesh.nodesPerElement());
      length += std::hypot(mesh.coordinates(b, 0) - mesh.coordinates(a, 0),
                           mesh.coordinates(b, 1) - mesh.coordinates(a, 1));
    }
    const bool vertical = std::string(name) == "left" || std::string(name) == "right";
    const Real side_length = vertical ? spec.upper_right[1] - spec.lower_left[1]
                                      : spec.upper_right[0] - spec.lower_left[0];
    EXPECT_NEAR(length, side_length, 1e-12 * side_length) << name;
    EXPECT_EQ(nodes->nodes.size(), sides->elements.size() + 1) << name;
  }
}

TEST(PolygonSection, V4LeveeTrianglesConformAndAreWellShaped) {
  const GeneratorSpec spec = leveeSpec(ElementType::Tri3, 0.05);
  const Mesh mesh = generateMesh(spec);
  ASSERT_EQ(mesh.blocks.size(), 2u);
  EXPECT_EQ(mesh.blocks[0].name, "levee");
  checkSection(spec, mesh);
}

TEST(PolygonSection, V4LeveeQuads) {
  const GeneratorSpec spec = leveeSpec(ElementType::Quad4, 0.05);
  const Mesh mesh = generateMesh(spec);
  EXPECT_EQ(mesh.type, ElementType::Quad4);
  checkSection(spec, mesh);
}

TEST(PolygonSection, ExodusRoundTripKeepsBlocksAndSets) {
  const Mesh mesh = generateMesh(leveeSpec(ElementType::Quad4, 0.1));
  const std::string path = std::string(ARGINE_BINARY_DIR) + "/tests/meshio_levee.e";
  writeExodusMesh(path, mesh, "V4 levee");
  const Mesh read = readExodusMesh(path);
  ASSERT_EQ(read.numElements(), mesh.numElements());
  ASSERT_EQ(read.numNodes(), mesh.numNodes());
  EXPECT_EQ(read.blockNames(), (std::vector<std::string>{"levee", "empty"}));
  EXPECT_EQ(read.nodeSetNames(), (std::vector<std::string>{"left", "right", "bottom", "top"}));
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    EXPECT_EQ(read.blocks[b].elements, mesh.blocks[b].elements);
  for (std::size_t s = 0; s < mesh.side_sets.size(); ++s) {
    EXPECT_EQ(read.side_sets[s].elements, mesh.side_sets[s].elements);
    EXPECT_EQ(read.side_sets[s].sides, mesh.side_sets[s].sides);
  }
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int k = 0; k < 4; ++k) ASSERT_EQ(read.connectivity(e, k), mesh.connectivity(e, k));
}

TEST(PolygonSection, ThreeLayersTrianglesAndQuads) {
  for (ElementType type : {ElementType::Tri3, ElementType::Quad4}) {
    const GeneratorSpec spec = layeredSpec(type, 0.1);
    const Mesh mesh = generateMesh(spec);
    ASSERT_EQ(mesh.blocks.size(), 4u);
    checkSection(spec, mesh);
  }
}

TEST(PolygonSection, CoarseAndFineSizesStayValid) {
  // Sizes comparable to the thin clay blanket (0.2 m at x = 0) and much finer.
  for (Real h : {0.5, 0.3, 0.17, 0.08})
    checkSection(layeredSpec(ElementType::Tri3, h),
                 generateMesh(layeredSpec(ElementType::Tri3, h)));
  for (Real h : {0.3, 0.07, 0.033})
    checkSection(leveeSpec(ElementType::Tri3, h), generateMesh(leveeSpec(ElementType::Tri3, h)));
}

TEST(PolygonSection, FineLeveeMeshesQuickly) {
  const GeneratorSpec spec = leveeSpec(ElementType::Tri3, 0.02);
  const auto start = std::chrono::steady_clock::now();
  const Mesh mesh = generateMesh(spec);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("    4.5 x 1.2 m at h = 0.02: %d elements in %.3f s\n", mesh.numElements(), seconds);
#ifdef NDEBUG
  EXPECT_LT(seconds, 2.0);
#endif
  checkSection(spec, mesh);
}

}  // namespace
}  // namespace argine
