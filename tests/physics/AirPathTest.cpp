// [LargeDeformation] Where an air-filled tension crack may open (AirPath.hpp): in elements on
// the soil's free surface (not the mesh edge) and next to an open air-filled crack.
#include <gtest/gtest.h>

#include <vector>

#include "Harness.hpp"
#include "argine/physics/AirPath.hpp"
#include "argine/physics/MaterialTable.hpp"

namespace argine {
namespace {

using test::hostCopy;

MaterialSpec unsaturatedSoil(TensionCracks cracks) {
  MaterialSpec m = test::elasticMaterial("soil", PhaseModel::Unsaturated, 1e6, 0.25, 0.4);
  m.retention.linear_slope = 4e-5;
  m.tension_cracks = cracks;
  return m;
}

std::vector<int> reachedElements(const AirPath& path) {
  const auto reaches = hostCopy(path.reachesElement());
  std::vector<int> list;
  for (int e = 0; e < static_cast<int>(reaches.extent(0)); ++e)
    if (reaches(e)) list.push_back(e);
  return list;
}

TEST(AirPath, FromTheFreeSurfaceAndThroughOpenCracks) {
  // 4 x 4 quads of 1 m (element = 4 row + column), soil in the bottom three rows: the free
  // surface is the top of row 2 (elements 8-11); the sides and the base are the mesh edge.
  const Mesh mesh = test::rectangleMesh(4, 4, 4.0, 4.0, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh, 0, [](int e) { return e < 12; });
  const MaterialTable table({unsaturatedSoil(TensionCracks::AirFilled)});
  FreeBoundary boundary(mesh);
  boundary.detect(points);
  AirPath path(table, mesh.numElements());
  ASSERT_TRUE(path.enabled());
  path.update(boundary, points);
  EXPECT_EQ(reachedElements(path), (std::vector<int>{8, 9, 10, 11}));
  EXPECT_EQ(path.crackedElements(), 0);

  // An open crack in element 5 (row 1, column 1) lets air into it and across its sides:
  // elements 1, 4, 6 and 9.
  auto element = hostCopy(points.element);
  auto separation = Kokkos::create_mirror_view(points.separation);
  Kokkos::deep_copy(separation, 0.0);
  for (int p = 0; p < points.count; ++p)
    if (element(p) == 5) separation(p) = 1e-3;
  Kokkos::deep_copy(points.separation, separation);
  path.update(boundary, points);
  EXPECT_EQ(reachedElements(path), (std::vector<int>{1, 4, 5, 6, 8, 9, 10, 11}));
  EXPECT_EQ(path.crackedElements(), 1);

  // Closed again: only the surface.
  Kokkos::deep_copy(points.separation, 0.0);
  path.update(boundary, points);
  EXPECT_EQ(reachedElements(path), (std::vector<int>{8, 9, 10, 11}));
}

TEST(AirPath, OnlyForMaterialsWithAirFilledCracks) {
  // Pore-space cracks (the default): no map, nothing to do each step.
  const MaterialTable table({unsaturatedSoil(TensionCracks::PoreSpace)});
  const AirPath path(table, 16);
  EXPECT_FALSE(path.enabled());
  EXPECT_EQ(path.reachesElement().extent(0), 0u);
}

}  // namespace
}  // namespace argine
