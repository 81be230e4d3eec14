// Soil regions inside a rectangle: blocks by element centroid on the unchanged grid,
// overlaps and regions outside the box refused, a rectangle without regions unchanged.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "argine/core/Error.hpp"
#include "argine/meshio/ExodusMesh.hpp"
#include "argine/meshio/MeshGenerators.hpp"

namespace argine {
namespace {

/// 2.0 x 1.0 m box from (-1, 2), h = 0.3: 7 x 4 cells of 2/7 x 0.25 m (as RectangleGenerator).
GeneratorSpec rectangleSpec(ElementType type) {
  GeneratorSpec spec;
  spec.kind = GeneratorSpec::Kind::Rectangle;
  spec.element = type;
  spec.element_size = 0.3;
  spec.lower_left = {-1.0, 2.0};
  spec.upper_right = {1.0, 3.0};
  spec.block = "column";
  return spec;
}

/// The unit square in 4 x 4 cells of 0.25 m with the given regions.
GeneratorSpec unitSquare(std::vector<PolygonRegion> regions,
                         ElementType type = ElementType::Quad4) {
  GeneratorSpec spec;
  spec.kind = GeneratorSpec::Kind::Rectangle;
  spec.element = type;
  spec.element_size = 0.25;
  spec.lower_left = {0.0, 0.0};
  spec.upper_right = {1.0, 1.0};
  spec.regions = std::move(regions);
  return spec;
}

/// A foundation under the lower half and a 45-degree slope on it: triangle (0, 0.5),
/// (0.5, 0.5), (0, 1), its hypotenuse x + y = 1 through cell corners.
std::vector<PolygonRegion> foundationAndSlope() {
  return {{"foundation", {{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.5}, {0.0, 0.5}}},
          {"slope", {{0.0, 0.5}, {0.5, 0.5}, {0.0, 1.0}}}};
}

void expectInputError(const GeneratorSpec& spec, const std::string& where,
                      const std::string& part) {
  try {
    generateMesh(spec);
    ADD_FAILURE() << "expected an InputError at " << where;
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), where);
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
  }
}

TEST(RectangleRegions, WithoutRegionsTheRectangleIsAsBefore) {
  // The values of the rectangle before regions existed (RectangleGenerator tests).
  const Mesh mesh = generateMesh(rectangleSpec(ElementType::Quad4));
  EXPECT_EQ(mesh.numNodes(), 40);
  EXPECT_EQ(mesh.numElements(), 28);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].name, "column");
  EXPECT_EQ(mesh.blocks[0].elements.size(), 28u);
  EXPECT_TRUE(mesh.regions.empty());
  EXPECT_EQ(mesh.coordinates(0, 0), -1.0);
  EXPECT_NEAR(mesh.coordinates(8, 1), 2.25, 1e-15);
  EXPECT_EQ(mesh.coordinates(39, 0), 1.0);
  EXPECT_EQ(mesh.coordinates(39, 1), 3.0);
  EXPECT_EQ(mesh.connectivity(0, 2), 9);
  const Mesh triangles = generateMesh(rectangleSpec(ElementType::Tri3));
  EXPECT_EQ(triangles.numElements(), 56);
  EXPECT_TRUE(triangles.regions.empty());
}

TEST(RectangleRegions, BlocksByCentroidOnTheUnchangedGrid) {
  const Mesh plain = generateMesh(unitSquare({}));
  const Mesh mesh = generateMesh(unitSquare(foundationAndSlope()));
  // Same nodes and elements in the same order as without regions.
  ASSERT_EQ(mesh.numNodes(), plain.numNodes());
  ASSERT_EQ(mesh.numElements(), 16);
  EXPECT_TRUE(mesh.structured.valid());
  EXPECT_EQ(mesh.structured.cells[0], 4);
  for (int n = 0; n < mesh.numNodes(); ++n)
    for (int d = 0; d < kDim; ++d) EXPECT_EQ(mesh.coordinates(n, d), plain.coordinates(n, d));
  for (int e = 0; e < 16; ++e)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(mesh.connectivity(e, k), plain.connectivity(e, k));
  // Centroids (0.125 + 0.25 i, 0.125 + 0.25 j): rows 0-1 in the foundation; the slope holds
  // x + y <= 1 above y = 0.5: (0.125, 0.625), (0.375, 0.625) (on the hypotenuse: closed),
  // (0.125, 0.875) (on it too); the other five are empty.
  ASSERT_EQ(mesh.blocks.size(), 3u);
  EXPECT_EQ(mesh.blocks[0].name, "foundation");
  EXPECT_EQ(mesh.blocks[1].name, "slope");
  EXPECT_EQ(mesh.blocks[2].name, "empty");
  EXPECT_EQ(mesh.blocks[2].id, 3);
  EXPECT_EQ(mesh.blocks[0].elements, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(mesh.blocks[1].elements, (std::vector<int>{8, 9, 12}));
  EXPECT_EQ(mesh.blocks[2].elements, (std::vector<int>{10, 11, 13, 14, 15}));
  for (std::size_t b = 0; b < 3; ++b)
    for (int e : mesh.blocks[b].elements) EXPECT_EQ(mesh.element_block(e), static_cast<int>(b));
  // The polygons, counter-clockwise, with their blocks, in deck order.
  ASSERT_EQ(mesh.regions.size(), 2u);
  EXPECT_EQ(mesh.regions[0].block, 0);
  EXPECT_EQ(mesh.regions[1].block, 1);
  EXPECT_EQ(mesh.regions[1].vertices.size(), 3u);
  EXPECT_EQ(mesh.node_sets.size(), 4u);  // the box sides as before
}

TEST(RectangleRegions, TrianglesTakeBlocksByCentroidToo) {
  const Mesh mesh = generateMesh(unitSquare(foundationAndSlope(), ElementType::Tri3));
  EXPECT_EQ(mesh.numElements(), 32);
  EXPECT_FALSE(mesh.structured.valid());
  ASSERT_EQ(mesh.blocks.size(), 3u);
  EXPECT_EQ(mesh.blocks[0].elements.size(), 16u);  // the lower two rows of cells
  std::size_t total = 0;
  for (const auto& block : mesh.blocks) total += block.elements.size();
  EXPECT_EQ(total, 32u);
  EXPECT_EQ(mesh.regions.size(), 2u);
}

TEST(RectangleRegions, RegionsFillingTheBoxLeaveNoEmptyBlock) {
  // Two triangles sharing the diagonal: every centroid is in one of them.
  const Mesh mesh = generateMesh(unitSquare({{"lower", {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}}},
                                             {"upper", {{1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}}}));
  ASSERT_EQ(mesh.blocks.size(), 2u);
  // The four cells on the diagonal have their centroid on the shared edge: the first region.
  EXPECT_EQ(mesh.blocks[0].elements.size(), 10u);
  EXPECT_EQ(mesh.blocks[1].elements.size(), 6u);
}

TEST(RectangleRegions, OverlappingRegionsAreRefused) {
  const std::string where = "Mesh/Generate/Regions";
  const PolygonRegion big{"big", {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}};
  // One inside the other: no edges cross.
  expectInputError(unitSquare({big, {"small", {{0.2, 0.2}, {0.4, 0.2}, {0.3, 0.4}}}}), where,
                   "regions big and small overlap");
  // The same polygon twice.
  expectInputError(unitSquare({big, {"copy", big.vertices}}), where, "overlap");
  // Sharing the bottom and top edges in part, and half the area: no edges cross either.
  expectInputError(unitSquare({{"left", {{0.0, 0.0}, {0.6, 0.0}, {0.6, 0.5}, {0.0, 0.5}}},
                               {"right", {{0.4, 0.0}, {1.0, 0.0}, {1.0, 0.5}, {0.4, 0.5}}}}),
                   where, "regions left and right overlap");
  // Crossing edges.
  expectInputError(unitSquare({{"a", {{0.0, 0.0}, {0.6, 0.0}, {0.6, 0.6}, {0.0, 0.6}}},
                               {"b", {{0.3, 0.3}, {0.9, 0.3}, {0.9, 0.9}, {0.3, 0.9}}}}),
                   where, "overlap");
  // Neighbours sharing an edge do not overlap.
  EXPECT_NO_THROW(generateMesh(unitSquare(foundationAndSlope())));
}

TEST(RectangleRegions, RegionsOutsideTheBoxAreRefused) {
  expectInputError(unitSquare({{"slope", {{0.0, 0.0}, {1.5, 0.0}, {0.0, 1.0}}}}),
                   "Mesh/Generate/Regions/slope/Vertices (m)", "outside the box");
  expectInputError(unitSquare({{"slope", {{0.0, -0.1}, {1.0, 0.0}, {0.0, 1.0}}}}),
                   "Mesh/Generate/Regions/slope/Vertices (m)", "outside the box");
}

TEST(RectangleRegions, ExodusWriterKeepsTheRegionBlocks) {
  const Mesh mesh = generateMesh(unitSquare(foundationAndSlope()));
  const std::string path = std::string(ARGINE_BINARY_DIR) + "/tests/meshio_rectangle_regions.e";
  writeExodusMesh(path, mesh);
  const Mesh read = readExodusMesh(path);
  ASSERT_EQ(read.blockNames(), mesh.blockNames());
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    EXPECT_EQ(read.blocks[b].elements.size(), mesh.blocks[b].elements.size());
  EXPECT_TRUE(read.regions.empty());  // a file holds blocks of whole elements only
}

}  // namespace
}  // namespace argine
