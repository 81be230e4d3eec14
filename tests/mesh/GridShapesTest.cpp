// [Mesh][GridShapes] uGIMP and quadratic B-spline shape functions on a structured grid,
// against hand-computed values, with the edge folding.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "argine/mesh/GridShapes.hpp"

namespace argine {
namespace {

TEST(GridShapes, QuadraticBSplineHandValues) {
  Real v, s;
  quadraticBSpline(0.0, v, s);
  EXPECT_DOUBLE_EQ(v, 0.75);
  EXPECT_DOUBLE_EQ(s, 0.0);
  quadraticBSpline(0.5, v, s);  // 3/4 - 1/4 = (3/2 - 1/2)^2 / 2 = 1/2
  EXPECT_DOUBLE_EQ(v, 0.5);
  EXPECT_DOUBLE_EQ(s, -1.0);
  quadraticBSpline(-1.0, v, s);  // (1/2)^2 / 2
  EXPECT_DOUBLE_EQ(v, 0.125);
  EXPECT_DOUBLE_EQ(s, 0.5);
  quadraticBSpline(1.25, v, s);  // (1/4)^2 / 2, slope -(3/2 - 5/4)
  EXPECT_DOUBLE_EQ(v, 0.03125);
  EXPECT_DOUBLE_EQ(s, -0.25);
  quadraticBSpline(1.5, v, s);
  EXPECT_EQ(v, 0.0);
  EXPECT_EQ(s, 0.0);
}

TEST(GridShapes, GimpHandValues) {
  const Real l = 0.25;
  Real v, s;
  gimp(0.0, l, v, s);  // 1 - l / 2
  EXPECT_DOUBLE_EQ(v, 0.875);
  EXPECT_DOUBLE_EQ(s, 0.0);
  gimp(0.125, l, v, s);  // 1 - (1/64 + 1/16) / (1/2) = 0.84375; slope -r / l = -1/2
  EXPECT_DOUBLE_EQ(v, 0.84375);
  EXPECT_DOUBLE_EQ(s, -0.5);
  gimp(-0.5, l, v, s);  // the hat: 1 - |r|
  EXPECT_DOUBLE_EQ(v, 0.5);
  EXPECT_DOUBLE_EQ(s, 1.0);
  gimp(1.0, l, v, s);  // l^2 / (4 l) = l / 4; slope -l / (2 l) = -1/2
  EXPECT_DOUBLE_EQ(v, 0.0625);
  EXPECT_DOUBLE_EQ(s, -0.5);
  gimp(1.25, l, v, s);
  EXPECT_EQ(v, 0.0);
  // continuity where the pieces meet (|r| = l and 1 - l)
  Real a, b, sa, sb;
  gimp(l - 1e-12, l, a, sa);
  gimp(l + 1e-12, l, b, sb);
  EXPECT_NEAR(a, b, 1e-11);
  EXPECT_NEAR(sa, sb, 1e-10);
  gimp(1 - l - 1e-12, l, a, sa);
  gimp(1 - l + 1e-12, l, b, sb);
  EXPECT_NEAR(a, b, 1e-11);
  EXPECT_NEAR(sa, sb, 1e-10);
}

/// The same bits (sign of zero included).
bool sameBits(Real a, Real b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(GridShapes, LaneFunctionsGiveTheScalarFunctionsBits) {
  // gimpLanes / quadraticBSplineLanes (selects, the stencil's path) against gimp /
  // quadraticBSpline (branches) at random distances and on every piece's ends, +-0 included.
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(-2.0, 2.0);
  for (const Real l : {0.5, 0.25, 0.125, 0.1}) {
    std::vector<Real> r = {0.0, -0.0, l, -l, 1 - l, l - 1, 1 + l, -1 - l, 0.5, -0.5, 1.5, -1.5};
    for (const Real x : std::vector<Real>(r)) {
      r.push_back(std::nextafter(x, 3.0));
      r.push_back(std::nextafter(x, -3.0));
    }
    for (int trial = 0; trial < 4000; ++trial) r.push_back(u(rng));
    for (std::size_t i = 0; i < r.size(); i += kLanes) {
      Lanes distances;
      for (int k = 0; k < kLanes; ++k) distances[k] = r[(i + k) % r.size()];
      Lanes gv, gs, bv, bs;
      gimpLanes(distances, l, gv, gs);
      quadraticBSplineLanes(distances, bv, bs);
      for (int k = 0; k < kLanes; ++k) {
        Real value, slope;
        gimp(distances[k], l, value, slope);
        EXPECT_TRUE(sameBits(gv[k], value) && sameBits(gs[k], slope)) << distances[k] << " " << l;
        quadraticBSpline(distances[k], value, slope);
        EXPECT_TRUE(sameBits(bv[k], value) && sameBits(bs[k], slope)) << distances[k];
      }
    }
  }
}

/// Sums of a 1D stencil: sum N, sum N x_k, sum dN/dx, sum dN/dx x_k (x_k = k h).
struct Moments {
  Real unity = 0, first = 0, slope = 0, slope_first = 0;
};

Moments momentsOf(const GridStencil1D& s, Real h) {
  Moments m;
  for (int k = 0; k < kGridStencil; ++k) {
    m.unity += s.value[k];
    m.first += s.value[k] * s.line[k] * h;
    m.slope += s.gradient[k];
    m.slope_first += s.gradient[k] * s.line[k] * h;
  }
  return m;
}

TEST(GridShapes, PartitionOfUnityAndLinearReproductionEverywhereIncludingTheEdges) {
  // Sum N = 1, sum N x_k = x, sum dN/dx = 0, sum dN/dx x_k = 1 at random positions on grids
  // of 1, 2 and 5 cells (the folding at both edges, and a one-cell grid folded on each
  // side), for both families; every line within the grid.
  std::mt19937 rng(5);
  const Real h = 0.2;
  for (const ShapeFamily family : {ShapeFamily::BSpline, ShapeFamily::Gimp})
    for (const int cells : {1, 2, 5})
      for (const Real l : {0.5, 0.25, 0.125}) {
        std::uniform_real_distribution<Real> u(0.0, cells);
        for (int trial = 0; trial < 2000; ++trial) {
          const Real xi = trial == 0 ? 0.0 : trial == 1 ? Real(cells) : u(rng);
          GridStencil1D s;
          gridStencil1D(family, xi, cells, h, l, s);
          const Moments m = momentsOf(s, h);
          EXPECT_NEAR(m.unity, 1.0, 1e-14) << xi;
          EXPECT_NEAR(m.first, xi * h, 1e-14) << xi;
          EXPECT_NEAR(m.slope, 0.0, 1e-12) << xi;
          EXPECT_NEAR(m.slope_first, 1.0, 1e-13) << xi;
          for (int k = 0; k < kGridStencil; ++k) {
            EXPECT_GE(s.line[k], 0);
            EXPECT_LE(s.line[k], cells);
            EXPECT_GE(s.value[k], -1e-15);  // the folded functions stay non-negative
          }
        }
      }
}

TEST(GridShapes, FoldedBSplineIsTheLinearHatInTheOuterHalfCellAndInterpolatesAtTheEdge) {
  const Real h = 0.5;
  for (const Real xi : {0.0, 0.1, 0.3, 0.5}) {
    GridStencil1D s;
    gridStencil1D(ShapeFamily::BSpline, xi, 4, h, 0, s);
    Real on0 = 0, on1 = 0, slope0 = 0;
    for (int k = 0; k < kGridStencil; ++k) {
      if (s.line[k] == 0) on0 += s.value[k], slope0 += s.gradient[k];
      if (s.line[k] == 1) on1 += s.value[k];
    }
    EXPECT_NEAR(on0, 1 - xi, 1e-15);
    EXPECT_NEAR(on1, xi, 1e-15);
    EXPECT_NEAR(slope0, -1 / h, 1e-14);
  }
  // the same at the far edge (4 cells: lines 3 and 4)
  GridStencil1D s;
  gridStencil1D(ShapeFamily::BSpline, 4.0, 4, h, 0, s);
  for (int k = 0; k < kGridStencil; ++k)
    EXPECT_NEAR(s.value[k], s.line[k] == 4 && s.value[k] != 0 ? 1.0 : 0.0, 1e-15);
}

TEST(GridShapes, FoldedBSplineIsContinuouslyDifferentiableWhereTheFoldingEnds) {
  // At xi = 1/2 the stencil moves from lines (-1 folded, 0, 1) to (0, 1, 2): the values and
  // the slopes of every line agree on both sides.
  const Real h = 1.0;
  GridStencil1D below, above;
  gridStencil1D(ShapeFamily::BSpline, 0.5 - 1e-12, 3, h, 0, below);
  gridStencil1D(ShapeFamily::BSpline, 0.5 + 1e-12, 3, h, 0, above);
  for (int line = 0; line <= 2; ++line) {
    Real v[2] = {0, 0}, g[2] = {0, 0};
    for (int k = 0; k < kGridStencil; ++k) {
      if (below.line[k] == line) v[0] += below.value[k], g[0] += below.gradient[k];
      if (above.line[k] == line) v[1] += above.value[k], g[1] += above.gradient[k];
    }
    EXPECT_NEAR(v[0], v[1], 1e-11) << "line " << line;
    EXPECT_NEAR(g[0], g[1], 1e-10) << "line " << line;
  }
}

TEST(GridShapes, GimpOfAPointWhoseDomainLiesInsideNeedsNoFolding) {
  // A point whose domain lies inside the grid (xi >= l) has no weight on a ghost line: its
  // stencil is the plain uGIMP one.
  const Real l = 0.25, h = 1.0;
  GridStencil1D s;
  gridStencil1D(ShapeFamily::Gimp, 0.3, 4, h, l, s);  // lines -1, 0, 1 -> -1 has no weight
  Real v, slope;
  gimp(0.3, l, v, slope);
  for (int k = 0; k < kGridStencil; ++k)
    if (s.line[k] == 0 && s.value[k] != 0) {
      EXPECT_DOUBLE_EQ(s.value[k], v);
    }
  gimp(0.3 - 1.0, l, v, slope);
  for (int k = 0; k < kGridStencil; ++k)
    if (s.line[k] == 1) {
      EXPECT_DOUBLE_EQ(s.value[k], v);
    }
}

TEST(GridShapes, PointsKeepHalfTheirHalfWidthFromTheGridsEdges) {
  // l = 0.25 cells: the centre stays 0.125 cells from either edge of a 4-cell axis; inside
  // that it moves nothing, and a centre outside the grid is left to leave it.
  EXPECT_EQ(clearOfGridEdges(0.0, 4, 0.25), 0.125);
  EXPECT_EQ(clearOfGridEdges(0.05, 4, 0.25), 0.125);
  EXPECT_EQ(clearOfGridEdges(0.125, 4, 0.25), 0.125);
  EXPECT_EQ(clearOfGridEdges(0.2, 4, 0.25), 0.2);
  EXPECT_EQ(clearOfGridEdges(2.0, 4, 0.25), 2.0);
  EXPECT_EQ(clearOfGridEdges(3.95, 4, 0.25), 3.875);
  EXPECT_EQ(clearOfGridEdges(4.0, 4, 0.25), 3.875);
  EXPECT_EQ(clearOfGridEdges(-0.01, 4, 0.25), -0.01);
  EXPECT_EQ(clearOfGridEdges(4.01, 4, 0.25), 4.01);
  // Why: at the kept centre the folded uGIMP weight of line 1 is l / 2 (the linear hat's
  // xi there), its gradient 1 / h: |dN|^2 / N = 8 / h^2 instead of growing without bound.
  GridStencil1D s;
  gridStencil1D(ShapeFamily::Gimp, 0.125, 4, 1.0, 0.25, s);
  for (int k = 0; k < kGridStencil; ++k)
    if (s.line[k] == 1) {
      EXPECT_DOUBLE_EQ(s.value[k], 0.125);
      EXPECT_DOUBLE_EQ(s.gradient[k], 1.0);
    }
}

TEST(GridShapes, TensorShapeOfAPointOnTheGrid) {
  // 4 x 3 cells of 0.5 x 0.25 m from (1, 2); a point at (2.3, 2.4) is at xi = (2.6, 1.6):
  // B-spline base lines floor(2.1) = 2 and floor(1.1) = 1.
  StructuredGrid grid;
  grid.cells[0] = 4;
  grid.cells[1] = 3;
  grid.origin[0] = 1;
  grid.origin[1] = 2;
  grid.spacing[0] = 0.5;
  grid.spacing[1] = 0.25;
  const Real x[kDim] = {2.3, 2.4};
  TensorShape t;
  tensorShape(ShapeFamily::BSpline, grid, x, 0, t);
  EXPECT_EQ(t.line[0][0], 2);
  EXPECT_EQ(t.line[1][0], 1);
  Real v, s;
  quadraticBSpline(2.6 - 3, v, s);
  EXPECT_NEAR(t.value[0][1], v, 1e-14);
  EXPECT_NEAR(t.gradient[0][1], s / 0.5, 1e-13);
  quadraticBSpline(1.6 - 3, v, s);
  EXPECT_NEAR(t.value[1][2], v, 1e-14);
  EXPECT_NEAR(t.gradient[1][2], s / 0.25, 1e-12);
  // uGIMP half-width of a point seeded 2 x 2 a cell: 1/4 of a cell
  EXPECT_DOUBLE_EQ(gimpHalfWidth(0.5 * 0.25 / 4, grid), 0.25);
  EXPECT_DOUBLE_EQ(gimpHalfWidth(1.0, grid), 0.5);  // at most half a cell
}

TEST(GridShapes, CellCentreWeightsAreOneHalfOnTheCellsTwoLinesIncludingTheEdgeCells) {
  // Hand values on 5 cells of 1 m (and on one cell): the cell of xi, its two lines 1/2 each;
  // a folded ghost slot repeats its neighbour's line and gets nothing.
  struct Case {
    int cells;
    Real xi;
    Real expected[kGridStencil];
  };
  const Case cases[] = {
      {5, 2.3, {0, 0.5, 0.5}},  // base floor(1.8) = 1: lines 1 2 3, cell 2
      {5, 2.7, {0.5, 0.5, 0}},  // base 2: lines 2 3 4, cell 2
      {5, 0.2, {0, 0.5, 0.5}},  // base -1: lines [0] 0 1 (ghost folded), cell 0
      {5, 4.8, {0.5, 0.5, 0}},  // base 4: lines 4 5 [5], cell 4
      {1, 0.7, {0.5, 0.5, 0}},  // one cell: lines 0 1 [1]
      {1, 0.3, {0, 0.5, 0.5}},  // one cell: lines [0] 0 1
  };
  for (const ShapeFamily family : {ShapeFamily::BSpline, ShapeFamily::Gimp})
    for (const Case& c : cases) {
      StructuredGrid grid;
      grid.cells[0] = grid.cells[1] = c.cells;
      grid.spacing[0] = grid.spacing[1] = 1;
      const Real x[kDim] = {c.xi, c.xi};
      TensorShape t;
      tensorShape(family, grid, x, 0.25, t);
      for (int d = 0; d < kDim; ++d) {
        Real w[kGridStencil];
        cellCentreWeights1D(t, d, w);
        for (int k = 0; k < kGridStencil; ++k)
          EXPECT_EQ(w[k], c.expected[k]) << "xi " << c.xi << " cells " << c.cells << " slot " << k;
      }
      // and they are the family's own values at the cell centre (the ghost has none there)
      const Real centre[kDim] = {std::floor(c.xi) + 0.5, std::floor(c.xi) + 0.5};
      TensorShape at_centre;
      tensorShape(family, grid, centre, 0.25, at_centre);
      Real w[kGridStencil];
      cellCentreWeights1D(t, 0, w);
      for (int k = 0; k < kGridStencil; ++k)
        for (int j = 0; j < kGridStencil; ++j)
          if (at_centre.line[0][j] == t.line[0][k] && at_centre.value[0][j] > 0 && w[k] > 0) {
            EXPECT_NEAR(at_centre.value[0][j], w[k], 1e-14);
          }
    }
}

}  // namespace
}  // namespace argine
