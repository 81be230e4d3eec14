#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "argine/meshio/Delaunay.hpp"
#include "argine/meshio/Geometry2D.hpp"

namespace argine {
namespace {

TEST(Geometry2D, AreaInsideDistanceCrossing) {
  const std::vector<Point2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_DOUBLE_EQ(signedArea(square), 1.0);
  const std::vector<Point2> clockwise{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  EXPECT_DOUBLE_EQ(signedArea(clockwise), -1.0);
  // L-shape: unit square minus its upper-right quarter; area 0.75.
  const std::vector<Point2> ell{{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}};
  EXPECT_DOUBLE_EQ(signedArea(ell), 0.75);
  EXPECT_TRUE(isInsidePolygon({0.25, 0.75}, ell));
  EXPECT_FALSE(isInsidePolygon({0.75, 0.75}, ell));
  EXPECT_FALSE(isInsidePolygon({1.5, 0.25}, ell));
  EXPECT_DOUBLE_EQ(distanceToSegment({0.5, 2}, {0, 0}, {1, 0}), 2.0);
  EXPECT_DOUBLE_EQ(distanceToSegment({4, 4}, {0, 0}, {1, 0}), 5.0);  // 3-4-5 to the end
  Point2 where{};
  EXPECT_TRUE(segmentsCross({0, 0}, {2, 2}, {0, 2}, {2, 0}, 1e-9, &where));
  EXPECT_DOUBLE_EQ(where[0], 1.0);
  EXPECT_DOUBLE_EQ(where[1], 1.0);
  EXPECT_FALSE(segmentsCross({0, 0}, {2, 0}, {1, 0}, {1, 1}, 1e-9, nullptr));  // T touch
  EXPECT_FALSE(segmentsCross({0, 0}, {2, 0}, {1, 0}, {3, 0}, 1e-9, nullptr));  // collinear
  EXPECT_NEAR(minimumAngleDegrees({0, 0}, {1, 0}, {0.5, std::sqrt(0.75)}), 60.0, 1e-12);
  EXPECT_NEAR(minimumAngleDegrees({0, 0}, {2, 0}, {0, 1}), std::atan(0.5) * 180 / M_PI, 1e-12);
}

TEST(Delaunay, SquareGridWithCocircularAndCollinearPointsIsComplete) {
  // 11 x 11 grid on the unit square: every cell's 4 corners are cocircular and the
  // boundary points collinear. Exact predicates must give 2 triangles per cell.
  DelaunayTriangulation dt({0, 0}, {1, 1});
  for (int j = 0; j <= 10; ++j)
    for (int i = 0; i <= 10; ++i) dt.insert({0.1 * i, 0.1 * j});
  EXPECT_EQ(dt.numVertices(), 121);
  const auto triangles = dt.innerTriangles();
  EXPECT_EQ(triangles.size(), 200u);
  double area = 0;
  for (const auto& t : triangles) {
    const double twice = orientation(dt.point(t[0]), dt.point(t[1]), dt.point(t[2]));
    EXPECT_GT(twice, 0);
    area += 0.5 * twice;
  }
  EXPECT_NEAR(area, 1.0, 1e-12);
  EXPECT_TRUE(dt.hasEdge(0, 1));         // (0,0)-(0.1,0)
  EXPECT_TRUE(dt.hasEdge(0, 11));        // (0,0)-(0,0.1)
  EXPECT_FALSE(dt.hasEdge(0, 2));        // (0,0)-(0.2,0) passes through a vertex
  EXPECT_EQ(dt.insert({0.5, 0.5}), 60);  // an existing point returns its index
  EXPECT_EQ(dt.numVertices(), 121);
}

TEST(Delaunay, RandomPointsHaveEmptyCircumcircles) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  DelaunayTriangulation dt({0, 0}, {2, 1});
  for (int i = 0; i < 400; ++i) dt.insert({2 * uniform(random), uniform(random)});
  const auto triangles = dt.innerTriangles();
  ASSERT_GT(triangles.size(), 700u);
  for (const auto& t : triangles) {
    const Point2 &a = dt.point(t[0]), &b = dt.point(t[1]), &c = dt.point(t[2]);
    ASSERT_GT(orientation(a, b, c), 0);
    // Circumcentre and radius, then no other point strictly inside (small tolerance).
    const double d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
    const double ux =
        ((a[0] * a[0] + a[1] * a[1]) * (b[1] - c[1]) + (b[0] * b[0] + b[1] * b[1]) * (c[1] - a[1]) +
         (c[0] * c[0] + c[1] * c[1]) * (a[1] - b[1])) /
        d;
    const double uy =
        ((a[0] * a[0] + a[1] * a[1]) * (c[0] - b[0]) + (b[0] * b[0] + b[1] * b[1]) * (a[0] - c[0]) +
         (c[0] * c[0] + c[1] * c[1]) * (b[0] - a[0])) /
        d;
    const double radius = std::hypot(a[0] - ux, a[1] - uy);
    for (int v = 0; v < dt.numVertices(); ++v)
      EXPECT_GE(std::hypot(dt.point(v)[0] - ux, dt.point(v)[1] - uy), radius * (1 - 1e-9));
  }
}

}  // namespace
}  // namespace argine
