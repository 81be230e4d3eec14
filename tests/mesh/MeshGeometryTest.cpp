// Element areas and sizes, edge adjacency and the mesh quality check.
#include "argine/mesh/MeshGeometry.hpp"

#include <gtest/gtest.h>

#include "TestMeshes.hpp"
#include "argine/core/Error.hpp"

namespace argine {
namespace {

using test::makeMesh;

template <class View>
auto onHost(const View& view) {
  return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
}

TEST(MeshGeometry, TriangleAreasAndMinimumHeights) {
  // Right triangle with legs 3 and 4: area 6, shortest altitude 2*6/5 = 2.4.
  // Sliver (0,0),(10,0),(5,0.1): area 0.5, altitude on the longest side 10 = 0.1
  // (sqrt(area) = 0.707 would overstate its thickness sevenfold).
  const Mesh mesh = makeMesh(ElementType::Tri3, {{0, 0}, {3, 0}, {0, 4}, {10, 0}, {5, 0.1}},
                             {{0, 1, 2}, {0, 3, 4}});
  const auto areas = onHost(elementAreas(mesh));
  const auto sizes = onHost(elementCharacteristicSizes(mesh));
  EXPECT_NEAR(areas(0), 6.0, 1e-14);
  EXPECT_NEAR(sizes(0), 2.4, 1e-14);
  EXPECT_NEAR(areas(1), 0.5, 1e-14);
  EXPECT_NEAR(sizes(1), 0.1, 1e-14);
}

TEST(MeshGeometry, QuadAreasAndMinimumHeights) {
  // 2 x 1 rectangle: area 2, size 1. Parallelogram (0,0),(2,0),(3,1),(1,1): area 2,
  // heights 1 (over the horizontal sides) and 2/sqrt(2) = 1.414 (over the slanted ones).
  const Mesh mesh = makeMesh(ElementType::Quad4, {{0, 0}, {2, 0}, {2, 1}, {0, 1}, {3, 1}, {1, 1}},
                             {{0, 1, 2, 3}, {0, 1, 4, 5}});
  const auto areas = onHost(elementAreas(mesh));
  const auto sizes = onHost(elementCharacteristicSizes(mesh));
  EXPECT_NEAR(areas(0), 2.0, 1e-14);
  EXPECT_NEAR(sizes(0), 1.0, 1e-14);
  EXPECT_NEAR(areas(1), 2.0, 1e-14);
  EXPECT_NEAR(sizes(1), 1.0, 1e-14);
}

TEST(MeshGeometry, NeighboursOfASplitSquare) {
  // Square 0(0,0) 1(1,0) 2(1,1) 3(0,1) split along 0-2: e0 = (0,1,2), e1 = (0,2,3).
  // e0 side 2 (nodes 2,0) and e1 side 0 (nodes 0,2) are shared; all other sides boundary.
  const Mesh mesh =
      makeMesh(ElementType::Tri3, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}});
  const auto n = onHost(computeElementNeighbours(mesh));
  EXPECT_EQ(n(0, 0), -1);
  EXPECT_EQ(n(0, 1), -1);
  EXPECT_EQ(n(0, 2), 1);
  EXPECT_EQ(n(1, 0), 0);
  EXPECT_EQ(n(1, 1), -1);
  EXPECT_EQ(n(1, 2), -1);
}

TEST(MeshGeometry, NeighboursAreSymmetricOnAGrid) {
  // 3 x 3 quads: interior cell 4 has neighbours 1 (below), 5 (right), 7 (above), 3 (left).
  test::GridOptions options;
  options.nx = 3;
  options.ny = 3;
  const Mesh mesh = test::structuredMesh(ElementType::Quad4, options);
  const auto n = onHost(computeElementNeighbours(mesh));
  EXPECT_EQ(n(4, 0), 1);
  EXPECT_EQ(n(4, 1), 5);
  EXPECT_EQ(n(4, 2), 7);
  EXPECT_EQ(n(4, 3), 3);
  int boundary = 0;
  for (int e = 0; e < 9; ++e)
    for (int s = 0; s < 4; ++s) {
      if (n(e, s) < 0) {
        ++boundary;
        continue;
      }
      bool back = false;
      for (int t = 0; t < 4; ++t) back = back || n(n(e, s), t) == e;
      EXPECT_TRUE(back) << e << " " << s;
    }
  EXPECT_EQ(boundary, 12);  // perimeter of a 3 x 3 grid
}

TEST(MeshQuality, ValidMeshesPass) {
  test::GridOptions options;
  options.perturbation = 0.2;
  EXPECT_NO_THROW(checkMeshQuality(test::structuredMesh(ElementType::Tri3, options), "t.exo"));
  EXPECT_NO_THROW(checkMeshQuality(test::structuredMesh(ElementType::Quad4, options), "q.exo"));
  EXPECT_NO_THROW(checkMeshQuality(test::starFanMesh(), "fan.exo"));
}

/// Runs checkMeshQuality and returns the InputError message ("" if none was thrown).
std::string qualityError(const Mesh& mesh) {
  try {
    checkMeshQuality(mesh, "levee.exo");
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "levee.exo");
    return error.what();
  }
  return "";
}

TEST(MeshQuality, InvertedElementIsNamedWithItsBlock) {
  // Element 2 (1-based) is clockwise.
  const Mesh mesh = makeMesh(ElementType::Tri3, {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                             {{0, 1, 2}, {0, 3, 2}}, {0, 1}, {"foundation", "dam"});
  const std::string message = qualityError(mesh);
  EXPECT_NE(message.find("element 2 "), std::string::npos) << message;
  EXPECT_NE(message.find("'dam'"), std::string::npos) << message;
  EXPECT_NE(message.find("inverted"), std::string::npos) << message;
}

TEST(MeshQuality, DegenerateElementIsRejected) {
  const Mesh mesh =
      makeMesh(ElementType::Tri3, {{0, 0}, {1, 0}, {2, 0}, {0, 1}}, {{0, 1, 3}, {0, 1, 2}});
  const std::string message = qualityError(mesh);
  EXPECT_NE(message.find("element 2 "), std::string::npos) << message;
  EXPECT_NE(message.find("degenerate"), std::string::npos) << message;
}

TEST(MeshQuality, NonConvexQuadIsRejected) {
  // Arrowhead (0,0),(2,1),(0,2),(0.5,1): positive area 1.5 but folded at node 4:
  // (X1 - X4) x (X3 - X4) = (-0.5,-1) x (-0.5,1) = -0.5 - 0.5 = -1.
  const Mesh mesh =
      makeMesh(ElementType::Quad4, {{0, 0}, {2, 1}, {0, 2}, {0.5, 1}}, {{0, 1, 2, 3}});
  const std::string message = qualityError(mesh);
  EXPECT_NE(message.find("element 1 "), std::string::npos) << message;
  EXPECT_NE(message.find("non-convex"), std::string::npos) << message;
  EXPECT_NE(message.find("node 4"), std::string::npos) << message;
}

TEST(MeshQuality, EdgeSharedByThreeElementsIsRejected) {
  const Mesh mesh = makeMesh(ElementType::Tri3, {{0, 0}, {1, 0}, {0.5, 1}, {0.5, -1}, {0.5, 2}},
                             {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  const std::string message = qualityError(mesh);
  EXPECT_NE(message.find("more than two elements"), std::string::npos) << message;
  EXPECT_THROW(computeElementNeighbours(mesh), InputError);
}

TEST(MeshQuality, ConnectivityOutOfRangeIsRejected) {
  const Mesh mesh = makeMesh(ElementType::Tri3, {{0, 0}, {1, 0}, {0, 1}}, {{0, 1, 7}});
  const std::string message = qualityError(mesh);
  EXPECT_NE(message.find("node 8"), std::string::npos) << message;
}

}  // namespace
}  // namespace argine
