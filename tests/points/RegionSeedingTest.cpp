// Seeding the soil regions of a rectangle (Mesh::regions): points at the pattern positions
// inside each polygon only, in every element it touches; shared edges seeded once; the
// body's volume against the polygon's area.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "TestMeshes.hpp"
#include "argine/core/Error.hpp"
#include "argine/mesh/PointLocator.hpp"
#include "argine/points/Seeding.hpp"

namespace argine {
namespace {

using Polygon = std::vector<std::array<Real, kDim>>;

template <class View>
auto onHost(const View& view) {
  return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
}

/// An nx x ny grid over [0, lx] x [0, ly] whose blocks are the given regions (blocks 0..)
/// and `empty` (last, holding every element: seeding of a region block does not look at
/// the block's elements, only at the polygons).
Mesh regionMesh(ElementType type, int nx, int ny, Real lx, Real ly,
                const std::vector<std::pair<std::string, Polygon>>& regions) {
  test::GridOptions options;
  options.nx = nx;
  options.ny = ny;
  options.lx = lx;
  options.ly = ly;
  options.block_names.clear();
  for (const auto& region : regions) options.block_names.push_back(region.first);
  options.block_names.push_back("empty");
  const int empty = static_cast<int>(regions.size());
  options.block = [empty](int, int) { return empty; };
  Mesh mesh = test::structuredMesh(type, options);
  for (std::size_t r = 0; r < regions.size(); ++r)
    mesh.regions.push_back({static_cast<int>(r), regions[r].second});
  return mesh;
}

/// Positions of all points, and checks every point: inside its element at its local
/// coordinates, sorted by element, ids in order, volume the pattern share `share`.
std::vector<std::array<Real, kDim>> checkedPositions(const Mesh& mesh, const MaterialPoints& points,
                                                     Real share) {
  const auto id = onHost(points.id);
  const auto element = onHost(points.element);
  const auto local = onHost(points.local);
  const auto position = onHost(points.position);
  const auto volume = onHost(points.volume);
  const PointLocator locator(mesh);
  std::vector<std::array<Real, kDim>> positions;
  for (int p = 0; p < points.count; ++p) {
    EXPECT_EQ(id(p), p);
    if (p > 0) {
      EXPECT_GE(element(p), element(p - 1));
    }
    const Real x[kDim] = {position(p, 0), position(p, 1)};
    Real xi[kDim];
    EXPECT_EQ(locator.locate(x, xi, element(p)), element(p));
    EXPECT_NEAR(xi[0], local(p, 0), 1e-12);
    EXPECT_NEAR(xi[1], local(p, 1), 1e-12);
    EXPECT_NEAR(volume(p), share, 1e-15);
    positions.push_back({x[0], x[1]});
  }
  return positions;
}

TEST(RegionSeeding, SlopePointsLieInsideThePolygonOnly) {
  // Triangle (0, 0), (0.9, 0), (0, 0.9) in 4 x 4 cells of 0.25 m. An m x m pattern puts
  // points at ((i + 1/2) s, (j + 1/2) s), s = 0.25 / m, i, j = 0 .. 4m - 1; inside when
  // (i + j + 1) s <= 0.9. m = 2 (s = 1/8): i + j <= 6, 1 + 2 + ... + 7 = 28 points.
  // m = 4 (s = 1/16): i + j <= 13, 1 + 2 + ... + 14 = 105 points.
  const Polygon triangle{{0.0, 0.0}, {0.9, 0.0}, {0.0, 0.9}};
  const Mesh mesh = regionMesh(ElementType::Quad4, 4, 4, 1.0, 1.0, {{"slope", triangle}});
  for (const auto& [m, expected] : {std::pair{2, 28}, std::pair{4, 105}}) {
    const MaterialPoints points = seedMaterialPoints(mesh, {{0, 0, m * m, ""}});
    ASSERT_EQ(points.count, expected) << m;
    const auto positions = checkedPositions(mesh, points, 0.0625 / (m * m));
    for (const auto& x : positions) EXPECT_LE(x[0] + x[1], 0.9) << m;
    // The cells the hypotenuse crosses hold some points, not all: (0.5, 0.25)-(0.75, 0.5)
    // is cell 6, centroid (0.625, 0.375) outside the triangle.
    const auto element = onHost(points.element);
    int in_cell_6 = 0;
    for (int p = 0; p < points.count; ++p) in_cell_6 += element(p) == 6;
    EXPECT_GT(in_cell_6, 0) << m;
    EXPECT_LT(in_cell_6, m * m) << m;
  }
}

TEST(RegionSeeding, PositionsOnTheOutlineAreInside) {
  // Triangle (0, 0), (1, 0), (0, 1): the hypotenuse x + y = 1 runs through cell corners,
  // and with 2 x 2 points per cell the 8 positions with i + j = 7 lie on it. Closed
  // polygons: they are soil. i + j <= 7: 1 + 2 + ... + 8 = 36 points.
  const Mesh mesh =
      regionMesh(ElementType::Quad4, 4, 4, 1.0, 1.0, {{"slope", {{0, 0}, {1, 0}, {0, 1}}}});
  const MaterialPoints points = seedMaterialPoints(mesh, {{0, 0, 4, ""}});
  ASSERT_EQ(points.count, 36);
  int on_edge = 0;
  for (const auto& x : checkedPositions(mesh, points, 0.0625 / 4)) {
    EXPECT_LE(x[0] + x[1], 1.0 + 1e-12);
    on_edge += std::abs(x[0] + x[1] - 1.0) < 1e-12;
  }
  EXPECT_EQ(on_edge, 8);
}

TEST(RegionSeeding, PositionsOnASharedEdgeGoToExactlyOneRegion) {
  // Two triangles sharing the diagonal x + y = 1 fill the square: all 64 positions are
  // seeded once; the 8 on the diagonal go to the region listed first.
  const Polygon lower{{0, 0}, {1, 0}, {0, 1}}, upper{{1, 0}, {1, 1}, {0, 1}};
  for (const bool lower_first : {true, false}) {
    const Mesh mesh =
        lower_first
            ? regionMesh(ElementType::Quad4, 4, 4, 1.0, 1.0, {{"lower", lower}, {"upper", upper}})
            : regionMesh(ElementType::Quad4, 4, 4, 1.0, 1.0, {{"upper", upper}, {"lower", lower}});
    const MaterialPoints points = seedMaterialPoints(mesh, {{0, 0, 4, ""}, {1, 1, 4, ""}});
    ASSERT_EQ(points.count, 64);
    const auto positions = checkedPositions(mesh, points, 0.0625 / 4);
    std::set<std::pair<Real, Real>> distinct;
    for (const auto& x : positions) distinct.insert({x[0], x[1]});
    EXPECT_EQ(distinct.size(), 64u);
    const auto material = onHost(points.material);
    int first = 0;
    for (int p = 0; p < points.count; ++p) first += material(p) == 0;
    EXPECT_EQ(first, 36);  // 28 strictly inside the first region + 8 on the diagonal
  }
}

TEST(RegionSeeding, BodyVolumeApproachesThePolygonArea) {
  // A levee cross-section with slopes of no special angle: base 0.05-0.95 m, crest
  // 0.38-0.61 m at 0.43 m, in 10 x 5 cells of 0.1 m. Area (0.9 + 0.23) / 2 x 0.43.
  const Polygon levee{{0.05, 0.0}, {0.95, 0.0}, {0.61, 0.43}, {0.38, 0.43}};
  const Real area = (0.9 + 0.23) / 2 * 0.43;
  const Real perimeter = 0.9 + 0.23 + std::hypot(0.34, 0.43) + std::hypot(0.33, 0.43);
  const Mesh mesh = regionMesh(ElementType::Quad4, 10, 5, 1.0, 0.5, {{"levee", levee}});
  Real previous_error = INFINITY;
  for (const int m : {1, 2, 3, 4}) {
    const MaterialPoints points = seedMaterialPoints(mesh, {{0, 0, m * m, ""}});
    const auto positions = checkedPositions(mesh, points, 0.01 / (m * m));
    const Real volume = points.count * 0.01 / (m * m);
    // Tolerance: the points are the lattice of sub-square centres (spacing s = h / m) in the
    // closed polygon, each with volume s^2. For a convex region the lattice-point count N
    // differs from area / s^2 by less than perimeter / (2 s) + 1 (Nosarzewska 1948; Bokowski,
    // Hadwiger and Wills 1972), so |V - A| < P s / 2 + s^2: first order in s.
    const Real s = 0.1 / m;
    const Real error = std::abs(volume - area);
    EXPECT_LT(error, perimeter * s / 2 + s * s) << m;
    // Measured: 1.2, 1.9, 0.6 and 0.44 % of the area for m = 1 .. 4 (errors along straight
    // edges cancel); at 16 points per cell the volume is within 0.5 % and closer than before.
    if (m == 4) {
      EXPECT_LT(error, 0.005 * area);
      EXPECT_LT(error, previous_error);
    }
    previous_error = std::min(previous_error, error);
  }
}

TEST(RegionSeeding, TrianglesSeedInsideThePolygonToo) {
  const Polygon triangle{{0.0, 0.0}, {0.9, 0.0}, {0.0, 0.9}};
  const Mesh mesh = regionMesh(ElementType::Tri3, 4, 4, 1.0, 1.0, {{"slope", triangle}});
  for (const int n : {1, 3, 4, 6, 12}) {
    const MaterialPoints points = seedMaterialPoints(mesh, {{0, 0, n, ""}});
    const auto positions = checkedPositions(mesh, points, 0.03125 / n);
    EXPECT_GT(points.count, 0) << n;
    for (const auto& x : positions) EXPECT_LE(x[0] + x[1], 0.9) << n;
    // Far fewer than all 32 n positions: the triangle covers 0.405 of the square.
    EXPECT_LT(points.count, 32 * n * 0.6) << n;
    EXPECT_GT(points.count, 32 * n * 0.25) << n;
  }
}

TEST(RegionSeeding, ConflictingRequestsAreInputErrors) {
  const Mesh mesh =
      regionMesh(ElementType::Quad4, 4, 4, 1.0, 1.0, {{"slope", {{0, 0}, {1, 0}, {0, 1}}}});
  // The rest of the box, seeded whole, would share elements with the region's points.
  try {
    seedMaterialPoints(mesh, {{0, 0, 4, ""}, {1, 1, 4, "Materials/air/Points Per Element"}});
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Materials/air/Points Per Element");
    EXPECT_NE(std::string(error.what()).find("also holds points of region 'slope'"),
              std::string::npos)
        << error.what();
  }
  // A region block with two materials.
  try {
    seedMaterialPoints(mesh, {{0, 0, 4, ""}, {0, 1, 4, "Materials/sand/Block"}});
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Materials/sand/Block");
    EXPECT_NE(std::string(error.what()).find("'slope' is already seeded"), std::string::npos)
        << error.what();
  }
  // A pattern the element type lacks is refused as without regions.
  EXPECT_THROW(seedMaterialPoints(mesh, {{0, 0, 3, ""}}), InputError);
}

}  // namespace
}  // namespace argine
