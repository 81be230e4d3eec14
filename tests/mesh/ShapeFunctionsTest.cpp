// Shape functions and reference <-> physical maps, against hand-computed values.
#include "argine/mesh/ShapeFunctions.hpp"

#include <gtest/gtest.h>

namespace argine {
namespace {

constexpr Real kTight = 1e-14;

// Triangle used below: X0 = (1,1), X1 = (4,2), X2 = (2,5).
// J = [X1-X0, X2-X0] = [[3, 1], [1, 4]], det J = 12 - 1 = 11, area = 11/2 = 5.5.
const Real kTriangle[3][kDim] = {{1.0, 1.0}, {4.0, 2.0}, {2.0, 5.0}};
// Distorted quad: (0,0), (2,0), (3,2), (0,1); shoelace area = (0 + 4 + 3 + 0)/2 = 3.5.
const Real kQuad[4][kDim] = {{0.0, 0.0}, {2.0, 0.0}, {3.0, 2.0}, {0.0, 1.0}};

// Linear field f = 2 + 3x - 5y, whose gradient (3, -5) linear elements reproduce exactly.
Real linearField(const Real x[kDim]) {
  return 2.0 + 3.0 * x[0] - 5.0 * x[1];
}

template <class Shape>
void expectKroneckerAtNodes() {
  for (int a = 0; a < Shape::kNodes; ++a) {
    Real xi[kDim], N[Shape::kNodes];
    Shape::node(a, xi);
    Shape::values(xi, N);
    for (int b = 0; b < Shape::kNodes; ++b) EXPECT_EQ(N[b], a == b ? 1.0 : 0.0) << a << b;
  }
}

template <class Shape>
void expectPartitionOfUnity(const Real xi[kDim]) {
  Real N[Shape::kNodes], dN[Shape::kNodes][kDim];
  Shape::values(xi, N);
  Shape::localGradients(xi, dN);
  Real sum = 0.0, dsum[kDim] = {0.0, 0.0};
  for (int a = 0; a < Shape::kNodes; ++a) {
    sum += N[a];
    dsum[0] += dN[a][0];
    dsum[1] += dN[a][1];
  }
  EXPECT_NEAR(sum, 1.0, kTight);
  EXPECT_NEAR(dsum[0], 0.0, kTight);
  EXPECT_NEAR(dsum[1], 0.0, kTight);
}

TEST(Tri3, KroneckerAndPartitionOfUnity) {
  expectKroneckerAtNodes<Tri3>();
  const Real points[3][kDim] = {{0.2, 0.3}, {1.0 / 3.0, 1.0 / 3.0}, {0.9, 0.05}};
  for (const auto& xi : points) expectPartitionOfUnity<Tri3>(xi);
  // N at (0.2, 0.3) = (1 - 0.2 - 0.3, 0.2, 0.3) = (0.5, 0.2, 0.3).
  const Real xi[kDim] = {0.2, 0.3};
  Real N[3];
  Tri3::values(xi, N);
  EXPECT_NEAR(N[0], 0.5, kTight);
  EXPECT_NEAR(N[1], 0.2, kTight);
  EXPECT_NEAR(N[2], 0.3, kTight);
}

TEST(Tri3, PhysicalGradientsHandComputed) {
  // J^-1 = [[4, -1], [-1, 3]] / 11; dN/dx = dN/dxi J^-1:
  // dN1 = (1,0) -> (4, -1)/11, dN2 = (0,1) -> (-1, 3)/11, dN0 = -(dN1 + dN2) = (-3, -2)/11.
  const Real xi[kDim] = {0.25, 0.25};
  Real dNdx[3][kDim];
  EXPECT_NEAR(physicalGradients<Tri3>(kTriangle, xi, dNdx), 11.0, kTight);
  const Real expected[3][kDim] = {
      {-3.0 / 11, -2.0 / 11}, {4.0 / 11, -1.0 / 11}, {-1.0 / 11, 3.0 / 11}};
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < kDim; ++i) EXPECT_NEAR(dNdx[a][i], expected[a][i], kTight);
  // f at the nodes = 0, 4, -17: grad f = (16 + 17, -4 - 51)/11 = (3, -5).
  Real gradient[kDim] = {0.0, 0.0};
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < kDim; ++i) gradient[i] += dNdx[a][i] * linearField(kTriangle[a]);
  EXPECT_NEAR(gradient[0], 3.0, 1e-13);
  EXPECT_NEAR(gradient[1], -5.0, 1e-13);
  EXPECT_NEAR(elementArea<Tri3>(kTriangle), 5.5, kTight);
}

TEST(Tri3, MapsBothWays) {
  // x = X0 + 0.2 (3,1) + 0.3 (1,4) = (1.9, 2.4).
  const Real xi[kDim] = {0.2, 0.3};
  Real x[kDim], back[kDim];
  mapToPhysical<Tri3>(kTriangle, xi, x);
  EXPECT_NEAR(x[0], 1.9, kTight);
  EXPECT_NEAR(x[1], 2.4, kTight);
  ASSERT_TRUE(mapToLocal<Tri3>(kTriangle, x, back));
  EXPECT_NEAR(back[0], 0.2, kTight);
  EXPECT_NEAR(back[1], 0.3, kTight);
  EXPECT_TRUE(Tri3::inside(back, 0.0));
  // (0,0): x - X0 = (-1,-1), xi = J^-1 (-1,-1) = (-3, -2)/11, outside by 3/11.
  const Real origin[kDim] = {0.0, 0.0};
  ASSERT_TRUE(mapToLocal<Tri3>(kTriangle, origin, back));
  EXPECT_NEAR(back[0], -3.0 / 11, kTight);
  EXPECT_NEAR(back[1], -2.0 / 11, kTight);
  EXPECT_FALSE(Tri3::inside(back, 1e-12));
  EXPECT_NEAR(Tri3::margin(back), -3.0 / 11, kTight);
}

TEST(Tri3, InsideOnEdgesAndVertices) {
  const Real vertex[kDim] = {1.0, 0.0}, edge[kDim] = {0.5, 0.5}, out[kDim] = {0.5, 0.5 + 1e-9};
  EXPECT_TRUE(Tri3::inside(vertex, 0.0));
  EXPECT_TRUE(Tri3::inside(edge, 0.0));
  EXPECT_FALSE(Tri3::inside(out, 1e-12));
  EXPECT_TRUE(Tri3::inside(out, 1e-8));
  Real c[kDim];
  Tri3::centroid(c);
  EXPECT_NEAR(Tri3::margin(c), 1.0 / 3.0, kTight);
}

TEST(Tri3, DegenerateTriangleCannotBeInverted) {
  const Real flat[3][kDim] = {{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}};
  const Real x[kDim] = {0.5, 0.5};
  Real xi[kDim];
  EXPECT_FALSE(mapToLocal<Tri3>(flat, x, xi));
}

TEST(Quad4, KroneckerAndPartitionOfUnity) {
  expectKroneckerAtNodes<Quad4>();
  const Real points[3][kDim] = {{0.5, -0.5}, {0.0, 0.0}, {-0.9, 0.3}};
  for (const auto& xi : points) expectPartitionOfUnity<Quad4>(xi);
  // At (0.5, -0.5): (1-xi)(1-eta)/4 = 0.5*1.5/4 = 0.1875, (1+xi)(1-eta)/4 = 0.5625,
  // (1+xi)(1+eta)/4 = 0.1875, (1-xi)(1+eta)/4 = 0.0625.
  Real N[4];
  Quad4::values(points[0], N);
  EXPECT_NEAR(N[0], 0.1875, kTight);
  EXPECT_NEAR(N[1], 0.5625, kTight);
  EXPECT_NEAR(N[2], 0.1875, kTight);
  EXPECT_NEAR(N[3], 0.0625, kTight);
}

TEST(Quad4, DistortedQuadJacobianAndGradients) {
  // At (0,0): dx/dxi = (2+3)/4 = 1.25, dy/dxi = (2-1)/4 = 0.25, dx/deta = (-2+3)/4 = 0.25,
  // dy/deta = (2+1)/4 = 0.75; det = 0.9375 - 0.0625 = 0.875 (x 4 = area 3.5, det J linear).
  // At (0.5,-0.5): dN0 = (-.375,-.125), dN1 = (.375,-.375), dN2 = (.125,.375),
  // dN3 = (-.125,.125): J = [[1.125, .375], [.125, .875]], det = 0.984375 - 0.046875 = 0.9375.
  const Real centre[kDim] = {0.0, 0.0}, xi[kDim] = {0.5, -0.5};
  Real J[kDim][kDim];
  EXPECT_NEAR(jacobian<Quad4>(kQuad, centre, J), 0.875, kTight);
  EXPECT_NEAR(J[0][0], 1.25, kTight);
  EXPECT_NEAR(J[0][1], 0.25, kTight);
  EXPECT_NEAR(J[1][0], 0.25, kTight);
  EXPECT_NEAR(J[1][1], 0.75, kTight);
  Real dNdx[4][kDim];
  EXPECT_NEAR(physicalGradients<Quad4>(kQuad, xi, dNdx), 0.9375, kTight);
  Real gradient[kDim] = {0.0, 0.0};
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < kDim; ++i) gradient[i] += dNdx[a][i] * linearField(kQuad[a]);
  EXPECT_NEAR(gradient[0], 3.0, 1e-13);
  EXPECT_NEAR(gradient[1], -5.0, 1e-13);
  EXPECT_NEAR(elementArea<Quad4>(kQuad), 3.5, kTight);
}

TEST(Quad4, KnownInverseMapsOnDistortedQuads) {
  // kQuad at (0.5,-0.5): x = 0.5625*(2,0) + 0.1875*(3,2) + 0.0625*(0,1) = (1.6875, 0.4375).
  Real x[kDim], xi[kDim];
  const Real a[kDim] = {0.5, -0.5};
  mapToPhysical<Quad4>(kQuad, a, x);
  EXPECT_NEAR(x[0], 1.6875, kTight);
  EXPECT_NEAR(x[1], 0.4375, kTight);
  const Real xa[kDim] = {1.6875, 0.4375};
  ASSERT_TRUE(mapToLocal<Quad4>(kQuad, xa, xi));
  EXPECT_NEAR(xi[0], 0.5, 1e-13);
  EXPECT_NEAR(xi[1], -0.5, 1e-13);

  // Strongly distorted (0,0), (4,0), (3,3), (1,2) at (-0.3, 0.7):
  // N = (1.3*0.3, 0.7*0.3, 0.7*1.7, 1.3*1.7)/4 = (0.0975, 0.0525, 0.2975, 0.5525),
  // x = 4*0.0525 + 3*0.2975 + 0.5525 = 1.655, y = 3*0.2975 + 2*0.5525 = 1.9975.
  const Real kite[4][kDim] = {{0.0, 0.0}, {4.0, 0.0}, {3.0, 3.0}, {1.0, 2.0}};
  const Real xb[kDim] = {1.655, 1.9975};
  ASSERT_TRUE(mapToLocal<Quad4>(kite, xb, xi));
  EXPECT_NEAR(xi[0], -0.3, 1e-13);
  EXPECT_NEAR(xi[1], 0.7, 1e-13);
  EXPECT_TRUE(Quad4::inside(xi, 0.0));

  // Nodes and the centre (mean of the nodes (1.25, 0.75) for kQuad).
  for (int n = 0; n < 4; ++n) {
    Real expected[kDim];
    Quad4::node(n, expected);
    ASSERT_TRUE(mapToLocal<Quad4>(kQuad, kQuad[n], xi));
    EXPECT_NEAR(xi[0], expected[0], 1e-13);
    EXPECT_NEAR(xi[1], expected[1], 1e-13);
  }
  const Real middle[kDim] = {1.25, 0.75};
  ASSERT_TRUE(mapToLocal<Quad4>(kQuad, middle, xi));
  EXPECT_NEAR(xi[0], 0.0, 1e-13);
  EXPECT_NEAR(xi[1], 0.0, 1e-13);
}

TEST(Quad4, NewtonInvertsStronglyDistortedQuadsEverywhere) {
  // Round trip xi -> x -> xi on a 21 x 21 grid of local points including the boundary, on
  // convex quads far from parallelograms: a kite and a trapezoid with a 0.2 m top side.
  const Real shapes[2][4][kDim] = {{{0.0, 0.0}, {4.0, 0.0}, {3.0, 3.0}, {1.0, 2.0}},
                                   {{0.0, 0.0}, {10.0, 0.0}, {5.1, 1.0}, {4.9, 1.0}}};
  for (const auto& X : shapes)
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        const Real xi[kDim] = {-1.0 + 0.1 * i, -1.0 + 0.1 * j};
        Real x[kDim], back[kDim];
        mapToPhysical<Quad4>(X, xi, x);
        ASSERT_TRUE(mapToLocal<Quad4>(X, x, back)) << i << " " << j;
        EXPECT_NEAR(back[0], xi[0], 1e-12);
        EXPECT_NEAR(back[1], xi[1], 1e-12);
      }
}

TEST(Quad4, LargeOffsetCoordinatesKeepAccuracy) {
  // The kite shifted by (5e5, 5e6) m (UTM-like): same local coordinates to ~1e-10.
  const Real ox = 5e5, oy = 5e6;
  const Real kite[4][kDim] = {{ox, oy}, {ox + 4.0, oy}, {ox + 3.0, oy + 3.0}, {ox + 1.0, oy + 2.0}};
  const Real x[kDim] = {ox + 1.655, oy + 1.9975};
  Real xi[kDim];
  ASSERT_TRUE(mapToLocal<Quad4>(kite, x, xi));
  EXPECT_NEAR(xi[0], -0.3, 1e-9);
  EXPECT_NEAR(xi[1], 0.7, 1e-9);
}

TEST(Quad4, PointsOutside) {
  // Left of the left side x = 0: local xi < -1.
  const Real left[kDim] = {-0.5, 0.5};
  Real xi[kDim];
  ASSERT_TRUE(mapToLocal<Quad4>(kQuad, left, xi));
  EXPECT_LT(xi[0], -1.0);
  EXPECT_FALSE(Quad4::inside(xi, 1e-12));
  EXPECT_LT(Quad4::margin(xi), 0.0);
  // Far away: either no inverse or one outside the reference square.
  const Real far[kDim] = {50.0, -40.0};
  EXPECT_FALSE(mapToLocal<Quad4>(kQuad, far, xi) && Quad4::inside(xi, 1e-12));
}

TEST(ShapeFunctions, UsableInsideKernels) {
  // 100 x det J of kQuad at (0.5, -0.5) (0.9375, above) computed in a kernel: 93.75.
  Real total = 0.0;
  Kokkos::parallel_reduce(
      "areas", Kokkos::RangePolicy<ExecSpace>(0, 100),
      KOKKOS_LAMBDA(const int, Real& sum) {
        const Real X[4][kDim] = {{0.0, 0.0}, {2.0, 0.0}, {3.0, 2.0}, {0.0, 1.0}};
        const Real xi[kDim] = {0.5, -0.5};
        Real dNdx[4][kDim];
        sum += physicalGradients<Quad4>(X, xi, dNdx);
      },
      total);
  EXPECT_NEAR(total, 93.75, 1e-12);
  EXPECT_EQ(withShape(ElementType::Tri3, [](auto shape) { return decltype(shape)::kNodes; }), 3);
  EXPECT_EQ(withShape(ElementType::Quad4, [](auto shape) { return decltype(shape)::kNodes; }), 4);
}

TEST(ShapeFunctions, ClockwiseAreaIsNegative) {
  const Real clockwise[3][kDim] = {{1.0, 1.0}, {2.0, 5.0}, {4.0, 2.0}};
  EXPECT_NEAR(elementArea<Tri3>(clockwise), -5.5, kTight);
}

}  // namespace
}  // namespace argine
