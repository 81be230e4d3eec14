// [Mesh][ElementFootprint] The nodes an element's points can reach: the element's nodes on
// linear shapes; on GIMP and B-spline the 4 x 4 block of grid lines around the cell, which
// holds every node of every stencil (GridShapes.hpp) of a point in the cell, and no more.
#include "argine/mesh/ElementFootprint.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "TestMeshes.hpp"

namespace argine {
namespace {

std::vector<int> footprintOf(const ElementFootprint& footprint, int element) {
  int nodes[ElementFootprint::kMaxNodes];
  const int count = footprint.nodes(element, nodes);
  return std::vector<int>(nodes, nodes + count);
}

/// A structured grid of nx x ny cells of hx x hy from (x0, y0), as generateRectangle sets it.
Mesh gridMesh(int nx, int ny, Real x0, Real y0, Real hx, Real hy, ShapeFamily family) {
  test::GridOptions options;
  options.nx = nx, options.ny = ny, options.x0 = x0, options.y0 = y0;
  options.lx = nx * hx, options.ly = ny * hy;
  Mesh mesh = test::structuredMesh(ElementType::Quad4, options);
  mesh.structured.cells[0] = nx, mesh.structured.cells[1] = ny;
  mesh.structured.origin[0] = x0, mesh.structured.origin[1] = y0;
  mesh.structured.spacing[0] = hx, mesh.structured.spacing[1] = hy;
  mesh.shape_functions = family;
  return mesh;
}

TEST(ElementFootprint, LinearShapesReachTheElementsNodes) {
  for (const ElementType type : {ElementType::Tri3, ElementType::Quad4}) {
    test::GridOptions options;
    options.nx = 3, options.ny = 2;
    const Mesh mesh = test::structuredMesh(type, options);
    const ElementFootprint footprint(mesh);
    const auto C = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
    for (int e = 0; e < mesh.numElements(); ++e) {
      std::vector<int> expected;
      for (int a = 0; a < mesh.nodesPerElement(); ++a) expected.push_back(C(e, a));
      EXPECT_EQ(footprintOf(footprint, e), expected) << "element " << e;  // connectivity order
    }
  }
}

TEST(ElementFootprint, GridFamiliesReachTheFourByFourBlockClippedToTheGrid) {
  // 5 x 4 cells, 6 nodes per row: node (i, j) = i + 6 j.
  const Mesh mesh = gridMesh(5, 4, 0, 0, 1, 1, ShapeFamily::BSpline);
  const ElementFootprint footprint(mesh);
  auto block = [](int i0, int i1, int j0, int j1) {
    std::vector<int> nodes;
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) nodes.push_back(i + 6 * j);
    return nodes;
  };
  EXPECT_EQ(footprintOf(footprint, 2 + 5 * 1), block(1, 4, 0, 3));  // interior cell (2, 1)
  EXPECT_EQ(footprintOf(footprint, 0), block(0, 2, 0, 2));          // corner cell (0, 0)
  EXPECT_EQ(footprintOf(footprint, 4 + 5 * 3), block(3, 5, 2, 4));  // corner cell (4, 3)
  EXPECT_EQ(footprintOf(footprint, 4 + 5 * 1), block(3, 5, 0, 3));  // right edge cell (4, 1)
}

TEST(ElementFootprint, HoldsEveryStencilOfAPointInTheCellAndNothingElse) {
  // Points all over each cell, on its edges and corners too, for both families and the GIMP
  // half-widths of 1 to 3 points per cell and axis: every node of every point's stencil is in
  // the footprint of the point's cell, and the stencils together cover the footprint.
  const int nx = 5, ny = 3;
  const Real x0 = -1.3, y0 = 0.7, hx = 0.4, hy = 0.25;
  for (const ShapeFamily family : {ShapeFamily::Gimp, ShapeFamily::BSpline}) {
    const Mesh mesh = gridMesh(nx, ny, x0, y0, hx, hy, family);
    const ElementFootprint footprint(mesh);
    const int row = nx + 1;
    for (const Real half_width : {0.5, 0.25, 1.0 / 6}) {
      for (int e = 0; e < mesh.numElements(); ++e) {
        const std::vector<int> expected = footprintOf(footprint, e);
        const std::set<int> allowed(expected.begin(), expected.end());
        std::set<int> reached;
        const int ci = e % nx, cj = e / nx;
        const int samples = 16;
        for (int s = 0; s <= samples; ++s)
          for (int t = 0; t <= samples; ++t) {
            const Real x[kDim] = {x0 + (ci + Real(s) / samples) * hx,
                                  y0 + (cj + Real(t) / samples) * hy};
            TensorShape shape;
            tensorShape(family, mesh.structured, x, half_width, shape);
            for (int a = 0; a < kGridStencil; ++a)
              for (int b = 0; b < kGridStencil; ++b) {
                const int node = shape.line[0][a] + shape.line[1][b] * row;
                EXPECT_TRUE(allowed.count(node))
                    << "node " << node << " of a point at (" << x[0] << ", " << x[1]
                    << ") outside the footprint of cell " << e;
                reached.insert(node);
              }
          }
        EXPECT_EQ(std::vector<int>(reached.begin(), reached.end()), expected) << "cell " << e;
      }
    }
  }
}

}  // namespace
}  // namespace argine
