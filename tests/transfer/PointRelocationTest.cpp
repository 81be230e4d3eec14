// Relocating points after they moved: the element, local coordinates and shapes found in
// one pass (relocateAndEvaluateShapes) agree with locating from scratch, and do not depend
// on whether the point stayed in its element or was found by the locator.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "TestScenes.hpp"
#include "argine/mesh/PointLocator.hpp"
#include "argine/transfer/AffineElementMaps.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {
namespace {

using test::hostCopy;

class RelocationOnShape : public ::testing::TestWithParam<ElementType> {};

/// Points seeded uniformly in the 6 x 5 mesh of 3 m x 2.5 m, located, then each moved by up
/// to `reach` cell widths in each direction (seeded) but kept inside the mesh, so most stay in
/// their element and some cross.
MaterialPoints movedPoints(const Mesh& mesh, Real reach, unsigned seed) {
  const Real extent[kDim] = {3.0, 2.5};
  MaterialPoints points = test::seedUniform(mesh);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-reach, reach);
  auto position = Kokkos::create_mirror_view(points.position);
  Kokkos::deep_copy(position, points.position);
  for (int p = 0; p < points.count; ++p)
    for (int d = 0; d < kDim; ++d)  // cells are 0.5 m wide
      position(p, d) = std::clamp(position(p, d) + 0.5 * u(rng), 1e-3, extent[d] - 1e-3);
  Kokkos::deep_copy(points.position, position);
  return points;
}

/// The points of `points` (position, element, local coordinates) in the order `from` gives.
MaterialPoints rearranged(const MaterialPoints& points, const std::vector<int>& from) {
  MaterialPoints out;
  out.allocate(static_cast<int>(from.size()));
  const auto position = hostCopy(points.position), local = hostCopy(points.local);
  const auto element = hostCopy(points.element);
  auto position_out = Kokkos::create_mirror_view(out.position);
  auto local_out = Kokkos::create_mirror_view(out.local);
  auto element_out = Kokkos::create_mirror_view(out.element);
  for (std::size_t r = 0; r < from.size(); ++r) {
    const int q = from[r];
    element_out(r) = element(q);
    for (int d = 0; d < kDim; ++d) {
      position_out(r, d) = position(q, d);
      local_out(r, d) = local(q, d);
    }
  }
  Kokkos::deep_copy(out.position, position_out);
  Kokkos::deep_copy(out.local, local_out);
  Kokkos::deep_copy(out.element, element_out);
  return out;
}

TEST_P(RelocationOnShape, AgreesWithLocatingFromScratch) {
  const Mesh mesh = test::rectangleMesh(6, 5, 3.0, 2.5, GetParam());
  const PointLocator locator(mesh);
  const AffineElementMaps maps(mesh);
  MaterialPoints points = movedPoints(mesh, 0.3, 3);
  MaterialPoints fresh = movedPoints(mesh, 0.3, 3);
  PointShapes relocated, reference;
  const RelocationCounts counts = relocateAndEvaluateShapes(mesh, locator, maps, points, relocated);
  Kokkos::deep_copy(fresh.element, -1);
  ASSERT_EQ(locator.locateAll(fresh), 0);
  evaluatePointShapes(mesh, fresh, reference);

  EXPECT_EQ(counts.lost, 0);
  EXPECT_GT(counts.changed_element, 0);                 // the moves cross element sides...
  EXPECT_LT(counts.changed_element, points.count / 2);  // ...but most stay
  const auto e = hostCopy(points.element), e_ref = hostCopy(fresh.element);
  const auto a = hostCopy(everyPointShape(relocated, points)),
             b = hostCopy(everyPointShape(reference, fresh));
  const int per = GetParam() == ElementType::Quad4 ? 4 : 3;
  for (int p = 0; p < points.count; ++p) {
    ASSERT_EQ(e(p), e_ref(p)) << "point " << p;
    for (int n = 0; n < per; ++n) {
      EXPECT_EQ(a(p).node[n], b(p).node[n]);
      EXPECT_NEAR(a(p).value[n], b(p).value[n], 1e-14) << "point " << p << " node " << n;
      for (int d = 0; d < kDim; ++d)  // gradients are O(1/0.5 m)
        EXPECT_NEAR(a(p).gradient[n][d], b(p).gradient[n][d], 1e-13);
    }
  }
}

TEST_P(RelocationOnShape, SameBitsWhicheverPathFindsTheElement) {
  // In an affine element xi = J^-1 (x - x_0) whether the point was still inside its old
  // element (fast path) or found by the locator, so relocating again from unchanged
  // positions (e.g. after a sort) gives the same shapes bit for bit. Run A: every point
  // keeps its element. Run B: the same points, every other one without an element (the
  // locator finds it).
  const Mesh mesh = test::rectangleMesh(6, 5, 3.0, 2.5, GetParam());
  const PointLocator locator(mesh);
  const AffineElementMaps maps(mesh);
  MaterialPoints a = movedPoints(mesh, 0.3, 5);
  PointShapes shapes_a, shapes_b;
  relocateAndEvaluateShapes(mesh, locator, maps, a, shapes_a);  // now every element is right
  std::vector<int> same(a.count);
  for (int p = 0; p < a.count; ++p) same[p] = p;
  MaterialPoints b = rearranged(a, same);
  auto element_b = hostCopy(b.element);
  for (int p = 0; p < b.count; p += 2) element_b(p) = -1;
  Kokkos::deep_copy(b.element, element_b);
  // Perturb the stored local coordinates of both: they must be recomputed, not reused.
  Kokkos::deep_copy(a.local, 0.0);
  Kokkos::deep_copy(b.local, 0.0);
  const RelocationCounts counts_a = relocateAndEvaluateShapes(mesh, locator, maps, a, shapes_a);
  const RelocationCounts counts_b = relocateAndEvaluateShapes(mesh, locator, maps, b, shapes_b);
  EXPECT_EQ(counts_a.changed_element, 0);
  EXPECT_EQ(counts_b.changed_element, (b.count + 1) / 2);

  const auto element_a = hostCopy(a.element);
  const auto local_a = hostCopy(a.local);
  const auto local_b = hostCopy(b.local);
  element_b = hostCopy(b.element);
  const auto sa = hostCopy(everyPointShape(shapes_a, a)),
             sb = hostCopy(everyPointShape(shapes_b, b));
  for (int p = 0; p < a.count; ++p) {
    ASSERT_EQ(element_a(p), element_b(p)) << "point " << p;
    for (int d = 0; d < kDim; ++d) EXPECT_EQ(local_a(p, d), local_b(p, d)) << "point " << p;
    for (int n = 0; n < kMaxElementNodes; ++n) {
      EXPECT_EQ(sa(p).node[n], sb(p).node[n]);
      EXPECT_EQ(sa(p).value[n], sb(p).value[n]) << "point " << p << " node " << n;
      for (int d = 0; d < kDim; ++d) EXPECT_EQ(sa(p).gradient[n][d], sb(p).gradient[n][d]);
    }
  }
}

TEST_P(RelocationOnShape, WritesNoRecordsForAChunkComputedInOneAffineElement) {
  // A chunk of kLanes points (p / kLanes) that the relocation finds in one affine element,
  // having been in one before, has its shapes computed where they are read
  // (PointShapes::computed_c) and no records written; every other chunk (points in several
  // elements, a point outside the mesh, the short last chunk) gets its records. Both give
  // the bits of the one formula (affineShapes). The records start as NaN, so a written one
  // shows. The points: four an element (Tri3: an element's last point twice), each moved a
  // little, so that most chunks stay in their element and some do not.
  const Mesh mesh = test::rectangleMesh(6, 5, 3.0, 2.5, GetParam());
  const PointLocator locator(mesh);
  const AffineElementMaps maps(mesh);
  const MaterialPoints moved = movedPoints(mesh, 0.3, 7);
  const int per = GetParam() == ElementType::Quad4 ? 4 : 3;
  std::vector<int> from;
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int k = 0; k < kLanes; ++k) from.push_back(e * per + std::min(k, per - 1));
  from.pop_back();  // a short last chunk
  MaterialPoints points = rearranged(moved, from);
  auto position = hostCopy(points.position);
  position(5, 0) = -1.0;  // outside the mesh: its chunk is written
  Kokkos::deep_copy(points.position, position);
  PointShapes shapes;
  shapes.allocate(points.count);
  {
    auto stored = hostCopy(shapes.stored_p);
    for (int p = 0; p < points.count; ++p) stored(p).value[0] = std::nan("");
    Kokkos::deep_copy(shapes.stored_p, stored);
  }
  const RelocationCounts counts = relocateAndEvaluateShapes(mesh, locator, maps, points, shapes);
  ASSERT_EQ(counts.lost, 1);
  ASSERT_TRUE(shapes.fromAffineMaps());

  const auto element = hostCopy(points.element);
  const auto local = hostCopy(points.local);
  const auto stored = hostCopy(shapes.stored_p);
  const auto of = hostCopy(everyPointShape(shapes, points));
  const auto inverse_e = hostCopy(maps.inverse_jacobian_e);
  const auto connectivity = hostCopy(mesh.connectivity);
  // The one formula both paths use, here on the host: every element of the mesh is affine.
  auto reference = [&](int p) {
    PointShape shape;
    const int e = element(p);
    const Real xi[kDim] = {local(p, 0), local(p, 1)};
    const Real inverse[4] = {inverse_e(e, 0), inverse_e(e, 1), inverse_e(e, 2), inverse_e(e, 3)};
    withShape(mesh.type, [&](auto element_shape) {
      using Shape = decltype(element_shape);
      Real N[Shape::kNodes], dNdx[Shape::kNodes][kDim];
      affineShapes<Shape>(xi, inverse, N, dNdx);
      setPointShape<Shape>(connectivity, e, N, dNdx, shape);
    });
    return shape;
  };
  auto expectSame = [](const PointShape& a, const PointShape& b, int p) {
    for (int n = 0; n < kMaxElementNodes; ++n) {
      EXPECT_EQ(a.node[n], b.node[n]) << "point " << p;
      EXPECT_EQ(a.value[n], b.value[n]) << "point " << p << " node " << n;
      for (int d = 0; d < kDim; ++d) EXPECT_EQ(a.gradient[n][d], b.gradient[n][d]) << p;
    }
  };
  const auto computed_c = hostCopy(shapes.computed_c);
  int computed_chunks = 0, stored_chunks = 0;
  for (int first = 0; first < points.count; first += kLanes) {
    const bool computed = computed_c(first / kLanes) != 0;
    (computed ? computed_chunks : stored_chunks) += 1;
    for (int p = first; p < first + kLanes && p < points.count; ++p) {
      if (computed) {
        ASSERT_LE(first + kLanes, points.count);
        EXPECT_EQ(element(p), element(first)) << "point " << p << " in another element";
        EXPECT_GE(element(p), 0);
        EXPECT_TRUE(std::isnan(stored(p).value[0])) << "point " << p << ": record written";
      }
      if (element(p) < 0) {
        EXPECT_EQ(stored(p).node[0], -1);
        EXPECT_EQ(stored(p).value[0], 0.0);
        continue;
      }
      const PointShape expected = reference(p);
      expectSame(of(p), expected, p);
      if (!computed) expectSame(stored(p), expected, p);
    }
  }
  EXPECT_GT(computed_chunks, 2);
  EXPECT_GT(stored_chunks, 2);
}

INSTANTIATE_TEST_SUITE_P(Shapes, RelocationOnShape,
                         ::testing::Values(ElementType::Quad4, ElementType::Tri3));

}  // namespace
}  // namespace argine
