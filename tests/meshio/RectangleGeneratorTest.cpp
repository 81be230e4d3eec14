#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "argine/core/Error.hpp"
#include "argine/meshio/ExodusMesh.hpp"
#include "argine/meshio/MeshGenerators.hpp"
#include "argine/meshio/MeshQuality.hpp"

namespace argine {
namespace {

GeneratorSpec rectangleSpec(ElementType type) {
  // 2.0 x 1.0 m box from (-1, 2); h = 0.3 -> nx = ceil(2 / 0.3) = 7 (dx = 0.2857),
  // ny = ceil(1 / 0.3) = 4 (dy = 0.25): 28 cells, 8 x 5 = 40 nodes.
  GeneratorSpec spec;
  spec.kind = GeneratorSpec::Kind::Rectangle;
  spec.element = type;
  spec.element_size = 0.3;
  spec.lower_left = {-1.0, 2.0};
  spec.upper_right = {1.0, 3.0};
  spec.block = "column";
  return spec;
}

TEST(Rectangle, QuadCountsAndSizeRoundUp) {
  const Mesh mesh = generateMesh(rectangleSpec(ElementType::Quad4));
  EXPECT_EQ(mesh.type, ElementType::Quad4);
  EXPECT_EQ(mesh.numNodes(), 40);
  EXPECT_EQ(mesh.numElements(), 28);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].name, "column");
  EXPECT_EQ(mesh.blocks[0].id, 1);
  EXPECT_EQ(mesh.blocks[0].elements.size(), 28u);
  // Node 0 at the lower left, node 8 one row up (x fastest); element 0 = (0 1 9 8).
  EXPECT_EQ(mesh.coordinates(0, 0), -1.0);
  EXPECT_EQ(mesh.coordinates(0, 1), 2.0);
  EXPECT_NEAR(mesh.coordinates(8, 1), 2.25, 1e-15);
  EXPECT_EQ(mesh.connectivity(0, 0), 0);
  EXPECT_EQ(mesh.connectivity(0, 1), 1);
  EXPECT_EQ(mesh.connectivity(0, 2), 9);
  EXPECT_EQ(mesh.connectivity(0, 3), 8);
  const MeshQuality quality = measureQuality(mesh);
  EXPECT_NEAR(quality.total_area, 2.0, 1e-14);
  EXPECT_NEAR(quality.min_angle_degrees, 90.0, 1e-9);
  EXPECT_EQ(quality.non_ccw_elements, 0);
  EXPECT_EQ(quality.unmatched_edges, 0);
}

TEST(Rectangle, ExactMultipleDoesNotRoundUpToOneMore) {
  GeneratorSpec spec = rectangleSpec(ElementType::Quad4);
  spec.lower_left = {0.0, 0.0};
  spec.upper_right = {1.0, 0.7};
  spec.element_size = 0.1;  // 1.0 / 0.1 and 0.7 / 0.1 are 10 and 7 up to rounding
  EXPECT_EQ(generateMesh(spec).numElements(), 70);
}

TEST(Rectangle, TrianglesSplitEveryCellInTwo) {
  const Mesh mesh = generateMesh(rectangleSpec(ElementType::Tri3));
  EXPECT_EQ(mesh.type, ElementType::Tri3);
  EXPECT_EQ(mesh.numNodes(), 40);
  EXPECT_EQ(mesh.numElements(), 56);
  const MeshQuality quality = measureQuality(mesh);
  EXPECT_NEAR(quality.total_area, 2.0, 1e-14);
  EXPECT_EQ(quality.non_ccw_elements, 0);
  EXPECT_EQ(quality.unmatched_edges, 0);
  // Right triangles with legs dx = 2/7 and dy = 0.25: angles atan(0.25 / (2/7)) = 41.19 deg,
  // 48.81 deg and 90 deg.
  EXPECT_NEAR(quality.min_angle_degrees, std::atan(0.25 / (2.0 / 7.0)) * 180 / M_PI, 1e-9);
  EXPECT_NEAR(quality.max_angle_degrees, 90.0, 1e-9);
}

TEST(Rectangle, BoxSidesAreNodeSetsAndSideSets) {
  for (ElementType type : {ElementType::Quad4, ElementType::Tri3}) {
    const Mesh mesh = generateMesh(rectangleSpec(type));
    const int nv = mesh.nodesPerElement();
    // name, constant axis, its value, expected nodes (8 along x, 5 along y)
    struct Expect {
      std::string name;
      int axis;
      double value;
      std::size_t nodes;
    };
    const Expect expected[] = {
        {"left", 0, -1.0, 5}, {"right", 0, 1.0, 5}, {"bottom", 1, 2.0, 8}, {"top", 1, 3.0, 8}};
    for (std::size_t s = 0; s < 4; ++s) {
      const auto& e = expected[s];
      const NodeSet* nodes = mesh.findNodeSet(e.name);
      const SideSet* sides = mesh.findSideSet(e.name);
      ASSERT_NE(nodes, nullptr) << e.name;
      ASSERT_NE(sides, nullptr) << e.name;
      EXPECT_EQ(nodes->id, static_cast<int>(s) + 1);
      EXPECT_EQ(sides->id, static_cast<int>(s) + 1);
      ASSERT_EQ(nodes->nodes.size(), e.nodes) << e.name;
      ASSERT_EQ(sides->elements.size(), e.nodes - 1) << e.name;
      for (std::size_t i = 0; i < nodes->nodes.size(); ++i) {
        EXPECT_EQ(mesh.coordinates(nodes->nodes[i], e.axis), e.value);
        if (i > 0) {  // sorted along the side
          EXPECT_LT(mesh.coordinates(nodes->nodes[i - 1], 1 - e.axis),
                    mesh.coordinates(nodes->nodes[i], 1 - e.axis));
        }
      }
      for (std::size_t i = 0; i < sides->elements.size(); ++i) {
        const int el = sides->elements[i], side = sides->sides[i];
        EXPECT_EQ(mesh.coordinates(mesh.connectivity(el, side), e.axis), e.value);
        EXPECT_EQ(mesh.coordinates(mesh.connectivity(el, (side + 1) % nv), e.axis), e.value);
      }
    }
  }
}

TEST(Rectangle, BadBoxOrSizeIsAnInputError) {
  GeneratorSpec spec = rectangleSpec(ElementType::Quad4);
  spec.element_size = 0;
  EXPECT_THROW(generateMesh(spec), InputError);
  spec = rectangleSpec(ElementType::Quad4);
  spec.upper_right = {-2.0, 3.0};
  EXPECT_THROW(generateMesh(spec), InputError);
  spec = rectangleSpec(ElementType::Quad4);
  spec.element_size = 1e-6;  // 2e6 x 1e6 cells: over the limit
  EXPECT_THROW(generateMesh(spec), InputError);
}

TEST(Rectangle, ExodusRoundTripOfGeneratedMesh) {
  const Mesh mesh = generateMesh(rectangleSpec(ElementType::Tri3));
  const std::string path = std::string(ARGINE_BINARY_DIR) + "/tests/meshio_rectangle.e";
  writeExodusMesh(path, mesh);
  const Mesh read = readExodusMesh(path);
  ASSERT_EQ(read.numElements(), mesh.numElements());
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(read.connectivity(e, k), mesh.connectivity(e, k));
  EXPECT_EQ(read.sideSetNames(), mesh.sideSetNames());
  EXPECT_EQ(read.findSideSet("top")->sides, mesh.findSideSet("top")->sides);
}

}  // namespace
}  // namespace argine
