// Point location on tri3/quad4 meshes, checked against a brute-force search, on edges and
// vertices (lowest containing index, from connectivity alone), outside and in non-convex
// domains; plus a throughput printout.
#include "argine/mesh/PointLocator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <limits>
#include <random>
#include <vector>

#include "TestMeshes.hpp"
#include "argine/mesh/MeshGeometry.hpp"

namespace argine {
namespace {

struct Located {
  int element;
  Real xi[kDim];
};

/// Brute force: lowest-index element containing x within `tolerance` (local units).
template <class Shape>
Located bruteForce(const Mesh& mesh, const Real x[kDim], Real tolerance) {
  const auto coordinates =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  for (int e = 0; e < mesh.numElements(); ++e) {
    Real X[Shape::kNodes][kDim], xi[kDim];
    gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
    if (mapToLocal<Shape>(X, x, xi) && Shape::inside(xi, tolerance)) return {e, {xi[0], xi[1]}};
  }
  return {-1, {0.0, 0.0}};
}

Located locateOnHost(const PointLocator& locator, const Real x[kDim], int hint) {
  Located result{-1, {-7.0, -7.0}};
  result.element = locator.locate(x, result.xi, hint);
  return result;
}

/// Random points in [lo, hi]^2 located with a random hint agree with brute force.
template <class Shape>
void expectAgreesWithBruteForce(const Mesh& mesh, Real lo_x, Real hi_x, Real lo_y, Real hi_y,
                                int samples, unsigned seed) {
  const PointLocator locator(mesh);
  std::mt19937 random(seed);
  std::uniform_real_distribution<Real> ux(lo_x, hi_x), uy(lo_y, hi_y);
  std::uniform_int_distribution<int> hint(-1, mesh.numElements() - 1);
  int inside = 0;
  for (int k = 0; k < samples; ++k) {
    const Real x[kDim] = {ux(random), uy(random)};
    const Located expected = bruteForce<Shape>(mesh, x, 1e-12);
    const Located got = locateOnHost(locator, x, hint(random));
    ASSERT_EQ(got.element, expected.element) << "x = " << x[0] << ", " << x[1];
    if (expected.element < 0) continue;
    ++inside;
    EXPECT_NEAR(got.xi[0], expected.xi[0], 1e-12);
    EXPECT_NEAR(got.xi[1], expected.xi[1], 1e-12);
  }
  EXPECT_GT(inside, samples / 8);  // the test exercised both inside and outside points
}

/// Points made from random (element, xi) pairs are found in that element at that xi
/// (independent of the brute force, which shares mapToLocal with the locator).
template <class Shape>
void expectFindsMappedPoints(const Mesh& mesh, int samples, unsigned seed) {
  const PointLocator locator(mesh);
  const auto coordinates =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> pick(0, mesh.numElements() - 1);
  std::uniform_real_distribution<Real> u(0.001, 0.999);
  for (int k = 0; k < samples; ++k) {
    const int e = pick(random);
    Real xi[kDim] = {u(random), u(random)};
    if (Shape::kAffine) {
      while (xi[0] + xi[1] > 0.999) {  // inside the triangle by at least 0.001
        xi[0] = u(random);
        xi[1] = u(random);
      }
    } else {
      xi[0] = 2.0 * xi[0] - 1.0;
      xi[1] = 2.0 * xi[1] - 1.0;
    }
    Real X[Shape::kNodes][kDim], x[kDim];
    gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
    mapToPhysical<Shape>(X, xi, x);
    const Located got = locateOnHost(locator, x, k % 2 == 0 ? -1 : pick(random));
    ASSERT_EQ(got.element, e);
    EXPECT_NEAR(got.xi[0], xi[0], 1e-12);
    EXPECT_NEAR(got.xi[1], xi[1], 1e-12);
  }
}

TEST(PointLocator, FindsPointsMappedFromKnownElements) {
  test::GridOptions options;
  options.nx = 10;
  options.ny = 10;
  options.perturbation = 0.3;
  expectFindsMappedPoints<Tri3>(test::structuredMesh(ElementType::Tri3, options), 2000, 21);
  expectFindsMappedPoints<Quad4>(test::structuredMesh(ElementType::Quad4, options), 2000, 22);
  expectFindsMappedPoints<Tri3>(test::starFanMesh(), 500, 23);
}

TEST(PointLocator, PerturbedTriangleGridAgreesWithBruteForce) {
  test::GridOptions options;
  options.nx = 12;
  options.ny = 9;
  options.lx = 3.0;
  options.ly = 2.0;
  options.perturbation = 0.3;
  const Mesh mesh = test::structuredMesh(ElementType::Tri3, options);
  checkMeshQuality(mesh, "grid");
  expectAgreesWithBruteForce<Tri3>(mesh, -0.2, 3.2, -0.2, 2.2, 3000, 7);
}

TEST(PointLocator, PerturbedQuadGridAgreesWithBruteForce) {
  test::GridOptions options;
  options.nx = 10;
  options.ny = 7;
  options.x0 = -5.0;
  options.lx = 4.0;
  options.ly = 3.0;
  options.perturbation = 0.25;
  const Mesh mesh = test::structuredMesh(ElementType::Quad4, options);
  checkMeshQuality(mesh, "grid");
  expectAgreesWithBruteForce<Quad4>(mesh, -5.5, -0.5, -0.5, 3.5, 3000, 11);
}

TEST(PointLocator, StarFanAgreesWithBruteForce) {
  // Non-convex star: many points in the bounding box fall between its arms.
  expectAgreesWithBruteForce<Tri3>(test::starFanMesh(), -1.1, 1.1, -1.1, 1.1, 3000, 3);
}

TEST(PointLocator, LShapeAndLeveeWithHoles) {
  // L-shape: [0,2]^2 minus [1,2]^2 (nodes moved at most 0.05).
  const Mesh l_tri = test::structuredMesh(ElementType::Tri3, test::lShapeOptions());
  const Mesh l_quad = test::structuredMesh(ElementType::Quad4, test::lShapeOptions());
  expectAgreesWithBruteForce<Tri3>(l_tri, -0.1, 2.1, -0.1, 2.1, 2000, 5);
  expectAgreesWithBruteForce<Quad4>(l_quad, -0.1, 2.1, -0.1, 2.1, 2000, 6);
  const PointLocator locator(l_tri);
  for (int hint : {-1, 0, 100}) {  // 100: out of range, ignored
    const Real notch[kDim] = {1.5, 1.5}, leg[kDim] = {0.5, 1.5}, foot[kDim] = {1.5, 0.5};
    EXPECT_EQ(locateOnHost(locator, notch, hint).element, -1);
    EXPECT_GE(locateOnHost(locator, leg, hint).element, 0);
    EXPECT_GE(locateOnHost(locator, foot, hint).element, 0);
  }

  // Levee-like grid with two empty regions (a trapezoid crest cut away and a hole).
  test::GridOptions levee;
  levee.nx = 20;
  levee.ny = 6;
  levee.lx = 20.0;
  levee.ly = 6.0;
  levee.perturbation = 0.2;
  levee.keep = [](int i, int j) {
    const bool above_slopes = j >= 2 && (i < j || i >= 20 - j);
    const bool hole = (i == 9 || i == 10) && j == 1;
    return !above_slopes && !hole;
  };
  const Mesh levee_mesh = test::structuredMesh(ElementType::Tri3, levee);
  checkMeshQuality(levee_mesh, "levee");
  expectAgreesWithBruteForce<Tri3>(levee_mesh, -1.0, 21.0, -1.0, 7.0, 3000, 9);
  const PointLocator levee_locator(levee_mesh);
  const Real in_hole[kDim] = {10.0, 1.5}, above[kDim] = {0.5, 5.5};
  EXPECT_EQ(locateOnHost(levee_locator, in_hole, -1).element, -1);
  EXPECT_EQ(locateOnHost(levee_locator, above, -1).element, -1);
}

/// Every node and every edge midpoint must be found, and in the lowest-index element that
/// has that node / that edge (computed from connectivity alone), whatever the hint.
template <class Shape>
void expectVerticesAndEdgesInLowestElement(const Mesh& mesh) {
  const PointLocator locator(mesh);
  const auto coordinates =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const int elements = mesh.numElements(), per = Shape::kNodes;
  std::vector<int> lowest_with_node(mesh.numNodes(), -1);
  for (int e = elements - 1; e >= 0; --e)
    for (int a = 0; a < per; ++a) lowest_with_node[connectivity(e, a)] = e;
  for (int n = 0; n < mesh.numNodes(); ++n) {
    if (lowest_with_node[n] < 0) continue;  // unused node of a masked grid
    const Real x[kDim] = {coordinates(n, 0), coordinates(n, 1)};
    for (int hint : {-1, elements - 1, lowest_with_node[n]}) {
      const Located got = locateOnHost(locator, x, hint);
      ASSERT_EQ(got.element, lowest_with_node[n]) << "node " << n << " hint " << hint;
    }
  }
  for (int e = 0; e < elements; ++e)
    for (int s = 0; s < per; ++s) {
      const int a = connectivity(e, s), b = connectivity(e, (s + 1) % per);
      int lowest = e;
      for (int f = 0; f < e; ++f)
        for (int t = 0; t < per; ++t) {
          const int c = connectivity(f, t), d = connectivity(f, (t + 1) % per);
          if ((c == a && d == b) || (c == b && d == a)) lowest = std::min(lowest, f);
        }
      const Real x[kDim] = {0.5 * (coordinates(a, 0) + coordinates(b, 0)),
                            0.5 * (coordinates(a, 1) + coordinates(b, 1))};
      for (int hint : {-1, e, elements - 1}) {
        const Located got = locateOnHost(locator, x, hint);
        ASSERT_EQ(got.element, lowest) << "element " << e << " side " << s << " hint " << hint;
        // On the side: the margin is zero up to round-off.
        EXPECT_NEAR(Shape::margin(got.xi), 0.0, 1e-12);
      }
    }
}

TEST(PointLocator, VerticesAndEdgesGoToLowestContainingElement) {
  test::GridOptions options;
  options.nx = 6;
  options.ny = 5;
  options.perturbation = 0.25;
  expectVerticesAndEdgesInLowestElement<Tri3>(test::structuredMesh(ElementType::Tri3, options));
  expectVerticesAndEdgesInLowestElement<Quad4>(test::structuredMesh(ElementType::Quad4, options));
  expectVerticesAndEdgesInLowestElement<Tri3>(test::starFanMesh());
  expectVerticesAndEdgesInLowestElement<Tri3>(
      test::structuredMesh(ElementType::Tri3, test::lShapeOptions()));
}

TEST(PointLocator, OutsidePointsAndNaN) {
  const Mesh mesh = test::structuredMesh(ElementType::Tri3, test::GridOptions{});
  const PointLocator locator(mesh);
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const Real points[4][kDim] = {{-0.5, 0.5}, {0.5, 1.0 + 1e-9}, {1e30, 0.0}, {nan, 0.5}};
  for (const auto& x : points)
    for (int hint : {-1, 0, 31}) EXPECT_EQ(locateOnHost(locator, x, hint).element, -1);
  // A corner of the unit square: node 0 at (0,0) is in element 0 only.
  const Real corner[kDim] = {0.0, 0.0};
  EXPECT_EQ(locateOnHost(locator, corner, 17).element, 0);
}

TEST(PointLocator, LargeOffsetCoordinates) {
  // The same perturbed grid shifted to UTM-like coordinates keeps agreeing with brute force.
  test::GridOptions options;
  options.nx = 8;
  options.ny = 8;
  options.x0 = 6.5e5;
  options.y0 = 5.7e6;
  options.lx = 8.0;
  options.ly = 8.0;
  options.perturbation = 0.25;
  const Mesh mesh = test::structuredMesh(ElementType::Quad4, options);
  const PointLocator locator(mesh);
  // Round-off of x - X0 is ~eps |x| = 2.2e-16 * 5.7e6 = 1.3e-9 m over elements >= 0.5 m:
  // tolerance 16 eps |x| / h <= 4e-8, well above 1e-12 and far below a point spacing.
  EXPECT_GT(locator.tolerance(), 1e-12);
  EXPECT_LT(locator.tolerance(), 1e-7);
  expectAgreesWithBruteForce<Quad4>(mesh, 6.5e5 - 0.5, 6.5e5 + 8.5, 5.7e6 - 0.5, 5.7e6 + 8.5, 1500,
                                    13);
}

TEST(PointLocator, NeighboursViewIsExposed) {
  const Mesh mesh =
      test::makeMesh(ElementType::Tri3, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}});
  const PointLocator locator(mesh);
  const auto n =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), locator.elementNeighbours());
  EXPECT_EQ(n(0, 2), 1);
  EXPECT_EQ(n(1, 0), 0);
  EXPECT_EQ(n(0, 0), -1);
}

TEST(PointLocator, LocateAllInAKernelAndThroughput) {
  // 200 x 200 cells -> 80,000 perturbed triangles over [0,100]^2; 1e6 random points in a
  // slightly larger box. Checks counts against a hand count of points outside [0,100]^2
  // (the grid boundary is straight), then prints queries per second (not asserted).
  test::GridOptions options;
  options.nx = 200;
  options.ny = 200;
  options.lx = 100.0;
  options.ly = 100.0;
  options.perturbation = 0.25;
  const Mesh mesh = test::structuredMesh(ElementType::Tri3, options);
  const auto start_build = std::chrono::steady_clock::now();
  const PointLocator locator(mesh);
  const double build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_build).count();

  const int n = 1000000;
  Kokkos::View<Real*[kDim], MemSpace> positions("x", n), local("xi", n);
  Kokkos::View<int*, MemSpace> elements("e", n);
  auto x = Kokkos::create_mirror_view(positions);
  std::mt19937 random(42);
  std::uniform_real_distribution<Real> u(-2.0, 102.0);
  int expected_outside = 0;
  for (int p = 0; p < n; ++p) {
    x(p, 0) = u(random);
    x(p, 1) = u(random);
    if (x(p, 0) < 0.0 || x(p, 0) > 100.0 || x(p, 1) < 0.0 || x(p, 1) > 100.0) ++expected_outside;
  }
  Kokkos::deep_copy(positions, x);
  Kokkos::deep_copy(elements, -1);

  // Process CPU time, not wall time: the test machine is shared, so wall time would
  // measure the other jobs as well.
  auto seconds = [](auto&& f) {
    const std::clock_t start = std::clock();
    f();
    return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  };
  int outside = -1;
  const double cold = seconds([&] { outside = locator.locateAll(positions, elements, local); });
  EXPECT_EQ(outside, expected_outside);

  // Small moves (a tenth of a cell): the hint or a neighbour holds most points.
  std::uniform_real_distribution<Real> small(-0.05, 0.05);
  for (int p = 0; p < n; ++p) {
    x(p, 0) = std::clamp(x(p, 0) + small(random), 0.0, 100.0);
    x(p, 1) = std::clamp(x(p, 1) + small(random), 0.0, 100.0);
  }
  Kokkos::deep_copy(positions, x);
  const double warm = seconds([&] { outside = locator.locateAll(positions, elements, local); });
  EXPECT_EQ(outside, 0);

  // Spot-check the kernel result against brute force.
  auto e_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), elements);
  for (int p = 0; p < n; p += 50000) {
    const Real xp[kDim] = {x(p, 0), x(p, 1)};
    EXPECT_EQ(e_host(p), bruteForce<Tri3>(mesh, xp, 1e-12).element);
  }

  // As in a run: points sorted by element (sortPointsByElement), then small moves again.
  std::vector<int> order(n);
  for (int p = 0; p < n; ++p) order[p] = p;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return e_host(a) < e_host(b); });
  auto sorted_x = Kokkos::create_mirror_view(positions);
  auto sorted_e = Kokkos::create_mirror_view(elements);
  for (int p = 0; p < n; ++p) {
    sorted_e(p) = e_host(order[p]);
    for (int d = 0; d < kDim; ++d)
      sorted_x(p, d) = std::clamp(x(order[p], d) + small(random), 0.0, 100.0);
  }
  Kokkos::deep_copy(positions, sorted_x);
  Kokkos::deep_copy(elements, sorted_e);
  const double sorted = seconds([&] { outside = locator.locateAll(positions, elements, local); });
  EXPECT_EQ(outside, 0);
  e_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), elements);
  for (int p = 7; p < n; p += 50000) {
    const Real xp[kDim] = {sorted_x(p, 0), sorted_x(p, 1)};
    EXPECT_EQ(e_host(p), bruteForce<Tri3>(mesh, xp, 1e-12).element);
  }

  std::printf(
      "[ locate   ] 80k tri3, bins %d x %d, build %.3f s; 1e6 points, queries per CPU second: "
      "no hint %.3g, hint after small moves %.3g (unsorted) %.3g (sorted by element)\n",
      locator.binCount(0), locator.binCount(1), build_seconds, n / cold, n / warm, n / sorted);
}

}  // namespace
}  // namespace argine
