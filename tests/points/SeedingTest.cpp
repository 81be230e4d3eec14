// Seeding patterns, seeded volumes and positions, sorting by element, and locating points.
#include "argine/points/Seeding.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>
#include <type_traits>
#include <utility>

#include "TestMeshes.hpp"
#include "argine/core/Error.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/mesh/PointLocator.hpp"
#include "argine/points/PointFields.hpp"

namespace argine {
namespace {

template <class View>
auto onHost(const View& view) {
  return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
}

/// Mean of the pattern points and mean of xi^2.
std::pair<std::array<Real, 2>, Real> moments(const std::vector<Real>& pattern) {
  const int n = static_cast<int>(pattern.size()) / 2;
  std::array<Real, 2> mean{0.0, 0.0};
  Real xi2 = 0.0;
  for (int k = 0; k < n; ++k) {
    mean[0] += pattern[2 * k] / n;
    mean[1] += pattern[2 * k + 1] / n;
    xi2 += pattern[2 * k] * pattern[2 * k] / n;
  }
  return {mean, xi2};
}

TEST(SeedingPattern, TrianglePatternsHandValues) {
  const auto three = seedingPattern(ElementType::Tri3, 3, "k");
  const std::vector<Real> gauss{1.0 / 6, 1.0 / 6, 2.0 / 3, 1.0 / 6, 1.0 / 6, 2.0 / 3};
  ASSERT_EQ(three.size(), 6u);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(three[i], gauss[i], 1e-15);
  // 4: the three corner sub-triangle centroids and the middle one (1/3, 1/3).
  const auto four = seedingPattern(ElementType::Tri3, 4, "k");
  EXPECT_NEAR(four[6], 1.0 / 3, 1e-15);
  EXPECT_NEAR(four[7], 1.0 / 3, 1e-15);
  // 6: first point has barycentric (11, 5, 2)/18 -> local (5/18, 2/18).
  const auto six = seedingPattern(ElementType::Tri3, 6, "k");
  EXPECT_NEAR(six[0], 5.0 / 18, 1e-15);
  EXPECT_NEAR(six[1], 2.0 / 18, 1e-15);
  // 12: first point = 2/3 (0,0) + 1/6 (1/2,0) + 1/6 (0,1/2) = (1/12, 1/12).
  const auto twelve = seedingPattern(ElementType::Tri3, 12, "k");
  EXPECT_NEAR(twelve[0], 1.0 / 12, 1e-15);
  EXPECT_NEAR(twelve[1], 1.0 / 12, 1e-15);

  for (int n : {1, 3, 4, 6, 12}) {
    const auto pattern = seedingPattern(ElementType::Tri3, n, "k");
    ASSERT_EQ(static_cast<int>(pattern.size()), 2 * n);
    // Equal weights reproduce the centroid (1/3, 1/3) exactly (first moments).
    const auto [mean, xi2] = moments(pattern);
    EXPECT_NEAR(mean[0], 1.0 / 3, 1e-15) << n;
    EXPECT_NEAR(mean[1], 1.0 / 3, 1e-15) << n;
    // The 3- and 12-point patterns are exact for quadratics:
    // mean of xi^2 over the triangle = (1/12) / (1/2) = 1/6.
    if (n == 3 || n == 12) {
      EXPECT_NEAR(xi2, 1.0 / 6, 1e-15) << n;
    }
    std::set<std::pair<Real, Real>> distinct;
    for (int k = 0; k < n; ++k) {
      const Real xi[kDim] = {pattern[2 * k], pattern[2 * k + 1]};
      EXPECT_GT(Tri3::margin(xi), 0.05) << n << " " << k;
      distinct.insert({xi[0], xi[1]});
    }
    EXPECT_EQ(static_cast<int>(distinct.size()), n);
  }
}

TEST(SeedingPattern, QuadPatternsHandValues) {
  const auto four = seedingPattern(ElementType::Quad4, 4, "k");
  const std::vector<Real> expected{-0.5, -0.5, 0.5, -0.5, -0.5, 0.5, 0.5, 0.5};
  ASSERT_EQ(four.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(four[i], expected[i]);
  const auto nine = seedingPattern(ElementType::Quad4, 9, "k");
  EXPECT_NEAR(nine[0], -2.0 / 3, 1e-15);  // centre of [-1, -1/3]
  EXPECT_NEAR(nine[8], 0.0, 1e-15);       // point 5 is the element centre
  EXPECT_NEAR(nine[9], 0.0, 1e-15);
  const auto one = seedingPattern(ElementType::Quad4, 1, "k");
  EXPECT_EQ(one, (std::vector<Real>{0.0, 0.0}));
}

TEST(SeedingPattern, UnsupportedCountsAreInputErrors) {
  try {
    seedingPattern(ElementType::Quad4, 3, "Materials/clay/Points Per Element");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Materials/clay/Points Per Element");
    EXPECT_NE(std::string(error.what()).find("1, 4, 9, 16"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("found 3"), std::string::npos) << error.what();
  }
  EXPECT_THROW(seedingPattern(ElementType::Tri3, 5, "k"), InputError);
  EXPECT_THROW(seedingPattern(ElementType::Tri3, 0, "k"), InputError);
  EXPECT_THROW(seedingPattern(ElementType::Quad4, 12, "k"), InputError);
  EXPECT_THROW(seedingPattern(ElementType::Quad4, 25, "k"), InputError);
}

/// 3 m x 2 m perturbed grid, two blocks: foundation (rows 0-1) and embankment (rows 2-3).
test::GridOptions twoBlockGrid() {
  test::GridOptions o;
  o.nx = 6;
  o.ny = 4;
  o.lx = 3.0;
  o.ly = 2.0;
  o.perturbation = 0.25;
  o.block = [](int, int j) { return j < 2 ? 0 : 1; };
  o.block_names = {"foundation", "embankment"};
  return o;
}

template <class Shape>
void expectSeededCorrectly(const Mesh& mesh, const std::vector<SeedRequest>& requests,
                           Real total_area) {
  const MaterialPoints points = seedMaterialPoints(mesh, requests);
  const auto areas = onHost(elementAreas(mesh));
  int expected_count = 0;
  std::vector<Real> block_area(mesh.blocks.size(), 0.0), block_volume(mesh.blocks.size(), 0.0);
  for (const auto& r : requests) {
    expected_count += r.points_per_element * static_cast<int>(mesh.blocks[r.block].elements.size());
    for (int e : mesh.blocks[r.block].elements) block_area[r.block] += areas(e);
  }
  ASSERT_EQ(points.count, expected_count);

  const auto id = onHost(points.id);
  const auto element = onHost(points.element);
  const auto material = onHost(points.material);
  const auto local = onHost(points.local);
  const auto position = onHost(points.position);
  const auto initial_position = onHost(points.initial_position);
  const auto volume = onHost(points.volume);
  const auto initial_volume = onHost(points.initial_volume);
  const auto stress = onHost(points.stress_effective);
  const auto mass = onHost(points.mass_solid);
  const auto blocks = onHost(mesh.element_block);
  const PointLocator locator(mesh);
  std::vector<Real> element_volume(mesh.numElements(), 0.0);
  Real total = 0.0;
  for (int p = 0; p < points.count; ++p) {
    EXPECT_EQ(id(p), p);
    if (p > 0) {
      EXPECT_GE(element(p), element(p - 1));  // sorted by element
    }
    const int block = blocks(element(p));
    const SeedRequest* request = nullptr;
    for (const auto& r : requests)
      if (r.block == block) request = &r;
    ASSERT_NE(request, nullptr);
    EXPECT_EQ(material(p), request->material);
    // Inside its element, at the stored local coordinates.
    const Real x[kDim] = {position(p, 0), position(p, 1)};
    Real xi[kDim];
    EXPECT_EQ(locator.locate(x, xi, -1), element(p));
    EXPECT_NEAR(xi[0], local(p, 0), 1e-12);
    EXPECT_NEAR(xi[1], local(p, 1), 1e-12);
    EXPECT_EQ(initial_position(p, 0), x[0]);
    EXPECT_EQ(initial_position(p, 1), x[1]);
    EXPECT_GT(volume(p), 0.0);
    EXPECT_EQ(initial_volume(p), volume(p));
    if (Shape::kAffine) {
      EXPECT_NEAR(volume(p), areas(element(p)) / request->points_per_element, 1e-14);
    }
    EXPECT_EQ(stress(p, 0), 0.0);
    EXPECT_EQ(mass(p), 0.0);
    element_volume[element(p)] += volume(p);
    block_volume[block] += volume(p);
    total += volume(p);
  }
  for (const auto& r : requests) {
    for (int e : mesh.blocks[r.block].elements) EXPECT_NEAR(element_volume[e], areas(e), 1e-13);
    EXPECT_NEAR(block_volume[r.block], block_area[r.block], 1e-12);
  }
  EXPECT_NEAR(total, total_area, 1e-12);
}

TEST(Seeding, TrianglesTwoBlocksVolumesAndPositions) {
  const Mesh mesh = test::structuredMesh(ElementType::Tri3, twoBlockGrid());
  // Both blocks: the whole 3 m x 2 m rectangle (boundary nodes are not perturbed).
  for (auto [n0, n1] : {std::pair{3, 12}, std::pair{1, 6}, std::pair{4, 3}})
    expectSeededCorrectly<Tri3>(mesh, {{0, 0, n0, ""}, {1, 1, n1, ""}}, 6.0);
}

TEST(Seeding, DistortedQuadsVolumesSumToElementAreas) {
  const Mesh mesh = test::structuredMesh(ElementType::Quad4, twoBlockGrid());
  for (auto [n0, n1] : {std::pair{4, 9}, std::pair{1, 16}})
    expectSeededCorrectly<Quad4>(mesh, {{0, 0, n0, ""}, {1, 1, n1, ""}}, 6.0);
  // Only one block: the embankment, area = sum of its element areas (checked inside).
  const MaterialPoints points = seedMaterialPoints(mesh, {{1, 3, 4, ""}});
  EXPECT_EQ(points.count, 4 * 12);
}

TEST(Seeding, ParallelogramQuadPointsHaveEqualVolumes) {
  // Parallelogram (0,0),(2,0),(3,1),(1,1): area 2, so 9 points of 2/9 m^2 each.
  const Mesh mesh =
      test::makeMesh(ElementType::Quad4, {{0, 0}, {2, 0}, {3, 1}, {1, 1}}, {{0, 1, 2, 3}});
  const MaterialPoints points = seedMaterialPoints(mesh, {{0, 0, 9, ""}});
  const auto volume = onHost(points.volume);
  const auto position = onHost(points.position);
  for (int p = 0; p < 9; ++p) EXPECT_NEAR(volume(p), 2.0 / 9, 1e-15);
  // Point 5 (local (0,0)) sits at the mean of the nodes (1.5, 0.5).
  EXPECT_NEAR(position(4, 0), 1.5, 1e-15);
  EXPECT_NEAR(position(4, 1), 0.5, 1e-15);
}

TEST(Seeding, BadRequestsAreInputErrors) {
  const Mesh mesh = test::structuredMesh(ElementType::Tri3, twoBlockGrid());
  try {
    seedMaterialPoints(mesh, {{0, 0, 3, ""}, {0, 1, 3, "Materials/sand/Block"}});
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Materials/sand/Block");
    EXPECT_NE(std::string(error.what()).find("'foundation'"), std::string::npos);
  }
  try {
    seedMaterialPoints(mesh, {{1, 0, 5, ""}});
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Points Per Element (block 'embankment')");
  }
  EXPECT_THROW(seedMaterialPoints(mesh, {{2, 0, 3, ""}}), InputError);
  EXPECT_EQ(seedMaterialPoints(mesh, {}).count, 0);
}

/// Value stored in component c of a field for point `id`, different for every field.
Real tag(int field, int id, int c) {
  return 1000.0 * id + 10.0 * field + c;
}

TEST(Seeding, SortByElementPermutesEveryField) {
  const Mesh mesh = test::structuredMesh(ElementType::Tri3, twoBlockGrid());
  MaterialPoints points = seedMaterialPoints(mesh, {{0, 0, 3, ""}, {1, 1, 6, ""}});
  const int n = points.count;  // seeded ids are 0..n-1 in order

  // Original element of each point id; every 17th point leaves the mesh (element -1).
  std::vector<int> element_of = [&] {
    const auto e = onHost(points.element);
    std::vector<int> out(n);
    for (int q = 0; q < n; ++q) out[q] = q % 17 == 0 ? -1 : e(q);
    return out;
  }();
  // Scramble: slot p holds point id order[p]; every other field holds a value tagged with
  // the point id and the field, so a field left unpermuted shows up below.
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(3));
  auto fill = [&](int field, const std::string& name, auto& target, int p, int c) {
    const int q = order[p];
    using T = typename std::decay_t<decltype(target)>::non_const_value_type;
    const T value = name == "id"        ? static_cast<T>(q)
                    : name == "element" ? static_cast<T>(element_of[q])
                                        : static_cast<T>(tag(field, q, c));
    if constexpr (std::decay_t<decltype(target)>::rank == 1)
      target(p) = value;
    else
      target(p, c) = value;
  };
  int field = 0;
  forEachPointField(points, [&](const char* name, auto& view) {
    auto host = Kokkos::create_mirror_view(Kokkos::HostSpace(), view);
    for (int p = 0; p < n; ++p)
      for (int c = 0; c < static_cast<int>(view.extent(1)); ++c) fill(field, name, host, p, c);
    Kokkos::deep_copy(view, host);
    ++field;
  });
  ASSERT_GE(field, 23);  // every field of MaterialPoints was visited

  sortPointsByElement(points);

  const auto id = onHost(points.id);
  const auto element = onHost(points.element);
  std::vector<int> seen(n, 0);
  for (int p = 0; p < n; ++p) ++seen[id(p)];
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), n);  // a permutation of the ids
  auto key = [&](int p) { return element(p) < 0 ? 1 << 30 : element(p); };
  for (int p = 1; p < n; ++p) {
    ASSERT_LE(key(p - 1), key(p)) << p;
    if (key(p - 1) == key(p)) {
      EXPECT_LT(id(p - 1), id(p));  // id order within an element
    }
  }
  EXPECT_EQ(element(n - 1), -1);
  field = 0;
  int mismatches = 0;
  forEachPointField(points, [&](const char* name, auto& view) {
    const auto host = onHost(view);
    const std::string field_name = name;
    for (int p = 0; p < n; ++p)
      for (int c = 0; c < static_cast<int>(view.extent(1)); ++c) {
        Real value;
        if constexpr (std::decay_t<decltype(host)>::rank == 1)
          value = host(p);
        else
          value = host(p, c);
        const Real expected = field_name == "id"        ? id(p)
                              : field_name == "element" ? element_of[id(p)]
                                                        : tag(field, id(p), c);
        if (value != expected) ++mismatches;
      }
    ++field;
  });
  EXPECT_EQ(mismatches, 0);
}

TEST(Seeding, LocateAllMaterialPoints) {
  // Move seeded points by a tenth of a cell and relocate them with their element as hint;
  // then push two points out of the rectangle.
  const Mesh mesh = test::structuredMesh(ElementType::Tri3, twoBlockGrid());
  MaterialPoints points = seedMaterialPoints(mesh, {{0, 0, 3, ""}, {1, 1, 12, ""}});
  const PointLocator locator(mesh);
  auto position = onHost(points.position);
  std::mt19937 random(5);
  std::uniform_real_distribution<Real> shift(-0.05, 0.05);
  for (int p = 0; p < points.count; ++p)
    for (int d = 0; d < kDim; ++d)
      position(p, d) = std::clamp(position(p, d) + shift(random), 0.0, d == 0 ? 3.0 : 2.0);
  position(0, 0) = -1.0;
  position(5, 1) = 2.5;
  Kokkos::deep_copy(points.position, position);
  EXPECT_EQ(locator.locateAll(points), 2);
  const auto element = onHost(points.element);
  const auto local = onHost(points.local);
  EXPECT_EQ(element(0), -1);
  EXPECT_EQ(element(5), -1);
  for (int p = 1; p < points.count; ++p) {
    if (p == 5) continue;
    const Real x[kDim] = {position(p, 0), position(p, 1)};
    Real xi[kDim];
    ASSERT_EQ(locator.locate(x, xi, -1), element(p));
    EXPECT_NEAR(local(p, 0), xi[0], 1e-12);
    EXPECT_NEAR(local(p, 1), xi[1], 1e-12);
  }
}

}  // namespace
}  // namespace argine
