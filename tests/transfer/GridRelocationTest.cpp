// The grid families' relocation by index arithmetic (GridRelocation.hpp) against the element
// route it replaces (locator, element shapes, then the tensor shapes): the same elements and
// tensor shapes, the local coordinates to round-off, the same counts; and the cell map only
// where the elements are the grid's cells.
#include <gtest/gtest.h>

#include <random>

#include "TestScenes.hpp"
#include "argine/mesh/PointLocator.hpp"
#include "argine/transfer/AffineElementMaps.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {
namespace {

using test::hostCopy;

/// The 6 x 5 quads of 0.5 m as a StructuredGrid with `family`'s shape functions.
Mesh gridMesh(ShapeFamily family) {
  Mesh mesh = test::rectangleMesh(6, 5, 3.0, 2.5, ElementType::Quad4);
  mesh.structured.cells[0] = 6;
  mesh.structured.cells[1] = 5;
  mesh.structured.spacing[0] = mesh.structured.spacing[1] = 0.5;
  mesh.shape_functions = family;
  return mesh;
}

/// Four points an element with their shapes, then moved: each by up to 0.3 cells (seeded),
/// and a few onto the lines between cells, the grid's edges and corner, and outside it.
MaterialPoints movedPoints(const Mesh& mesh, PointShapes& shapes) {
  MaterialPoints points = test::seedUniform(mesh);
  Kokkos::deep_copy(points.initial_volume, points.volume);  // uGIMP's half-width
  evaluatePointShapes(mesh, points, shapes);
  auto position = hostCopy(points.position);
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(-0.15, 0.15);
  for (int p = 0; p < points.count; ++p)
    for (int d = 0; d < kDim; ++d) position(p, d) += u(rng);
  const Real special[][kDim] = {{1.0, 1.2}, {1.3, 2.0},   {1.5, 1.0},  {3.0, 0.7},  {0.0, 0.0},
                                {3.0, 2.5}, {-0.01, 1.0}, {1.0, 2.51}, {0.5, 1e-14}};
  int p = 0;
  for (const auto& x : special) {
    position(p, 0) = x[0];
    position(p, 1) = x[1];
    p += 7;
  }
  Kokkos::deep_copy(points.position, position);
  return points;
}

class GridRelocation : public ::testing::TestWithParam<ShapeFamily> {};

TEST_P(GridRelocation, FindsTheElementRoutesElementsAndStencils) {
  const Mesh mesh = gridMesh(GetParam());
  const PointLocator locator(mesh);
  const AffineElementMaps maps(mesh);
  ASSERT_EQ(maps.cell_element.extent(0), 30u);
  PointShapes on_grid, by_element;
  MaterialPoints a = movedPoints(mesh, on_grid), b = movedPoints(mesh, by_element);
  const RelocationCounts counts_a = relocateAndEvaluateShapes(mesh, locator, maps, a, on_grid);
  const RelocationCounts counts_b =  // without the cell map: the element route
      relocateAndEvaluateShapes(mesh, locator, AffineElementMaps{}, b, by_element);
  EXPECT_GE(counts_a.lost, 2);  // (-0.01, 1.0), (1.0, 2.51) and some moved across the edges
  EXPECT_EQ(counts_a.lost, counts_b.lost);
  EXPECT_EQ(counts_a.changed_element, counts_b.changed_element);
  EXPECT_GT(counts_a.changed_element, 0);

  const auto element_a = hostCopy(a.element), element_b = hostCopy(b.element);
  const auto local_a = hostCopy(a.local), local_b = hostCopy(b.local);
  const auto grid_a = hostCopy(on_grid.grid_p), grid_b = hostCopy(by_element.grid_p);
  for (int p = 0; p < a.count; ++p) {
    ASSERT_EQ(element_a(p), element_b(p)) << "point " << p;
    if (element_a(p) >= 0) {
      for (int d = 0; d < kDim; ++d) EXPECT_NEAR(local_a(p, d), local_b(p, d), 1e-13) << p;
    }
    for (int d = 0; d < kDim; ++d)
      for (int k = 0; k < kGridStencil; ++k) {
        EXPECT_EQ(grid_a(p).line[d][k], grid_b(p).line[d][k]) << "point " << p;
        EXPECT_EQ(grid_a(p).value[d][k], grid_b(p).value[d][k]) << "point " << p;
        EXPECT_EQ(grid_a(p).gradient[d][k], grid_b(p).gradient[d][k]) << "point " << p;
      }
  }
}

TEST_P(GridRelocation, NoCellMapWhereTheElementsAreNotTheCellsInGridOrder) {
  Mesh rotated = gridMesh(GetParam());  // element 0's nodes start at another corner
  auto connectivity = hostCopy(rotated.connectivity);
  const int first = connectivity(0, 0);
  for (int k = 0; k < 3; ++k) connectivity(0, k) = connectivity(0, k + 1);
  connectivity(0, 3) = first;
  Kokkos::deep_copy(rotated.connectivity, connectivity);
  EXPECT_EQ(AffineElementMaps(rotated).cell_element.extent(0), 0u);

  Mesh shifted = gridMesh(GetParam());  // the grid does not describe the nodes
  shifted.structured.origin[0] = 0.1;
  EXPECT_EQ(AffineElementMaps(shifted).cell_element.extent(0), 0u);

  EXPECT_EQ(AffineElementMaps(test::rectangleMesh(6, 5, 3.0, 2.5, ElementType::Quad4))
                .cell_element.extent(0),
            0u);  // no StructuredGrid
}

INSTANTIATE_TEST_SUITE_P(Families, GridRelocation,
                         ::testing::Values(ShapeFamily::Gimp, ShapeFamily::BSpline),
                         [](const ::testing::TestParamInfo<ShapeFamily>& info) {
                           return std::string(info.param == ShapeFamily::Gimp ? "Gimp" : "BSpline");
                         });

}  // namespace
}  // namespace argine
