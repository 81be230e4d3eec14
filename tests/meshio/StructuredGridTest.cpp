// The structured-grid description (Mesh::structured) of generated rectangles: the numbering
// it claims, and only where it holds.
#include <gtest/gtest.h>

#include <string>

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
  return spec;
}

TEST(StructuredGrid, QuadRectangleDescribesItsNumbering) {
  const Mesh mesh = generateMesh(rectangleSpec(ElementType::Quad4));
  const StructuredGrid& grid = mesh.structured;
  ASSERT_TRUE(grid.valid());
  EXPECT_EQ(grid.cells[0], 7);
  EXPECT_EQ(grid.cells[1], 4);
  EXPECT_EQ(grid.origin[0], -1.0);
  EXPECT_EQ(grid.origin[1], 2.0);
  EXPECT_NEAR(grid.spacing[0], 2.0 / 7, 1e-15);
  EXPECT_NEAR(grid.spacing[1], 0.25, 1e-15);
  const int nx = grid.cells[0], ny = grid.cells[1];
  ASSERT_EQ(mesh.numNodes(), (nx + 1) * (ny + 1));
  ASSERT_EQ(mesh.numElements(), nx * ny);
  // node (i, j) = i + j (nx + 1) at origin + (i, j) spacing
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const int node = i + j * (nx + 1);
      EXPECT_NEAR(mesh.coordinates(node, 0), grid.origin[0] + i * grid.spacing[0], 1e-14);
      EXPECT_NEAR(mesh.coordinates(node, 1), grid.origin[1] + j * grid.spacing[1], 1e-14);
    }
  // element (i, j) = i + j nx joins nodes (i, j), (i+1, j), (i+1, j+1), (i, j+1)
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int e = i + j * nx;
      const auto node = [&](int a, int b) { return a + b * (nx + 1); };
      EXPECT_EQ(mesh.connectivity(e, 0), node(i, j));
      EXPECT_EQ(mesh.connectivity(e, 1), node(i + 1, j));
      EXPECT_EQ(mesh.connectivity(e, 2), node(i + 1, j + 1));
      EXPECT_EQ(mesh.connectivity(e, 3), node(i, j + 1));
    }
}

TEST(StructuredGrid, OnlyQuadRectanglesAreStructured) {
  EXPECT_FALSE(generateMesh(rectangleSpec(ElementType::Tri3)).structured.valid());
  GeneratorSpec polygon = rectangleSpec(ElementType::Quad4);
  polygon.kind = GeneratorSpec::Kind::Polygon;
  polygon.regions = {{"soil", {{-1.0, 2.0}, {1.0, 2.0}, {0.0, 2.5}}}};
  EXPECT_FALSE(generateMesh(polygon).structured.valid());
  // An Exodus file of the structured grid reads back unstructured (no metadata in the file).
  const Mesh mesh = generateMesh(rectangleSpec(ElementType::Quad4));
  const std::string path = std::string(ARGINE_BINARY_DIR) + "/tests/meshio_structured.e";
  writeExodusMesh(path, mesh);
  EXPECT_FALSE(readExodusMesh(path).structured.valid());
}

}  // namespace
}  // namespace argine
