// The checkerboard filter of the element averages (`Checkerboard Filter`,
// AveragingScratch::useCheckerboardFilter in physics/PointValueAveraging.hpp) and the edge
// neighbours it reads (buildRowNeighbours, physics/AveragingPatches.hpp): neighbours of a
// grid by hand, one cell's value shared by hand (also with a part-filled neighbour), sum w q
// kept, a uniform field kept at the grid's edges, in part-filled and next to empty cells, the
// checkerboard pattern removed and a linear field kept where a cell and its neighbours have
// full neighbourhoods.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../transfer/TestScenes.hpp"
#include "argine/physics/AveragingPatches.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {
namespace {

/// n x n quads of 0.5 m from (0, 0), 4 points each (element e = i + n j, cell column i, row j).
struct FilterScene {
  int n;
  Mesh mesh;
  MaterialPoints points;
  PointShapes shapes;
  ActiveNodes active;
  explicit FilterScene(int cells)
      : n(cells),
        mesh(test::rectangleMesh(cells, cells, 0.5 * cells, 0.5 * cells, ElementType::Quad4)),
        points(test::seedUniform(mesh)),
        active(mesh.numNodes()) {
    evaluatePointShapes(mesh, points, shapes);
    active.rebuild(mesh, points);
  }
  /// The cell (column, row) of point p.
  std::array<int, 2> cell(int p) const {
    return {static_cast<int>(std::floor(points.position(p, 0) / 0.5)),
            static_cast<int>(std::floor(points.position(p, 1) / 0.5))};
  }
};

/// The filtered element averages of value(p) with weights weight(p), per point.
template <class Value, class Weight>
std::vector<Real> filtered(const FilterScene& scene, Value value, Weight weight) {
  const RowNeighbours neighbours = buildRowNeighbours(scene.mesh, {}, scene.mesh.numElements());
  AveragingScratch scratch;
  scratch.useCheckerboardFilter(neighbours.start, neighbours.rows, neighbours.most);
  scratch.allocateSums(1, scene.mesh.numElements(), 0);
  scratch.fitPoints(scene.points.count);
  for (int p = 0; p < scene.points.count; ++p) {
    scratch.weight_p(p) = weight(p);
    scratch.mode_pc(p, 0) = kAverageElement;
    scratch.value_pc(p, 0) = value(p);
  }
  averagePointValues(scene.points, scene.shapes, scene.active, scratch, nullptr);
  std::vector<Real> out(scene.points.count);
  for (int p = 0; p < scene.points.count; ++p) out[p] = scratch.value_pc(p, 0);
  return out;
}

TEST(CheckerboardFilter, EdgeNeighboursOfAGridByHand) {
  const FilterScene scene(3);
  const RowNeighbours neighbours = buildRowNeighbours(scene.mesh, {}, 9);
  EXPECT_EQ(neighbours.most, 4);
  const auto start = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), neighbours.start);
  const auto rows = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), neighbours.rows);
  // which element is which cell: from its points
  std::vector<int> element_of_cell(9, -1);
  for (int p = 0; p < scene.points.count; ++p) {
    const auto c = scene.cell(p);
    element_of_cell[c[0] + 3 * c[1]] = scene.points.element(p);
  }
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      std::vector<int> expected;
      const int di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
      for (int k = 0; k < 4; ++k) {
        const int ii = i + di[k], jj = j + dj[k];
        if (ii >= 0 && ii < 3 && jj >= 0 && jj < 3)
          expected.push_back(element_of_cell[ii + 3 * jj]);
      }
      const int e = element_of_cell[i + 3 * j];
      std::vector<int> got(rows.data() + start(e), rows.data() + start(e + 1));
      std::sort(expected.begin(), expected.end());
      std::sort(got.begin(), got.end());
      EXPECT_EQ(got, expected) << "cell " << i << ", " << j;
    }
}

TEST(CheckerboardFilter, OneCellsValueSharedByHand) {
  // 3 x 3 cells of equal weight, 1 in the centre cell, 0 elsewhere: the centre's shared weight
  // W/2 + 4 W/8 = W, so t = 1 there; it keeps 1/2, each edge neighbour gets 1/8, a corner 0.
  const FilterScene scene(3);
  const auto value = [&](int p) {
    const auto c = scene.cell(p);
    return c[0] == 1 && c[1] == 1 ? 1.0 : 0.0;
  };
  const std::vector<Real> q = filtered(scene, value, [](int) { return 0.25; });
  for (int p = 0; p < scene.points.count; ++p) {
    const auto c = scene.cell(p);
    const int distance = std::abs(c[0] - 1) + std::abs(c[1] - 1);
    const Real expected = distance == 0 ? 0.5 : distance == 1 ? 0.125 : 0.0;
    EXPECT_DOUBLE_EQ(q[p], expected) << "cell " << c[0] << ", " << c[1];
  }
}

TEST(CheckerboardFilter, APartFilledNeighbourExchangesByItsOwnWeight) {
  // 3 x 3 cells, 1 in the centre cell, 0 elsewhere; every cell weighs 1 but the centre's right
  // neighbour (2, 1), part-filled, 0.2. Each pair exchanges min(W_r, W_s) (q_s - q_r) / 8:
  // the centre keeps 1 - (1 + 1 + 1 + 0.2) / 8 = 0.6, the full edge neighbours get 1/8, the
  // part-filled one 0.2 / 8 of sum, so 1/8 as its average too; the corners 0 (sum 1 kept).
  const FilterScene scene(3);
  const auto value = [&](int p) {
    const auto c = scene.cell(p);
    return c[0] == 1 && c[1] == 1 ? 1.0 : 0.0;
  };
  const auto weight = [&](int p) {
    const auto c = scene.cell(p);
    return c[0] == 2 && c[1] == 1 ? 0.05 : 0.25;
  };
  const std::vector<Real> q = filtered(scene, value, weight);
  for (int p = 0; p < scene.points.count; ++p) {
    const auto c = scene.cell(p);
    const int distance = std::abs(c[0] - 1) + std::abs(c[1] - 1);
    const Real expected = distance == 0 ? 0.6 : distance == 1 ? 0.125 : 0.0;
    EXPECT_NEAR(q[p], expected, 1e-15) << "cell " << c[0] << ", " << c[1];
  }
}

TEST(CheckerboardFilter, KeepsAUniformFieldAtEdgesInPartFilledAndNextToEmptyCells) {
  // 5 x 5 cells of unequal weights, the top row's left three cells empty (weight 0, as cells
  // a surface leaves): a uniform value stays uniform in every cell that has points, at the
  // grid's edges (3 or 2 neighbours) too. (Sharing each row's sum in proportion to the
  // neighbourhood's weights, the filter's earlier form, gave 0.98 of it to an edge cell of
  // equal cells, 0.95 to a corner and 0.49 to a cell a 45-degree face cuts to a tenth.)
  const FilterScene scene(5);
  const auto empty = [&](int p) {
    const auto c = scene.cell(p);
    return c[1] == 4 && c[0] <= 2;
  };
  const auto weight = [&](int p) { return empty(p) ? 0.0 : 0.1 + 0.07 * ((p * 7) % 11); };
  const std::vector<Real> q = filtered(
      scene, [](int) { return 2.5; }, weight);
  for (int p = 0; p < scene.points.count; ++p) {
    if (empty(p)) continue;
    EXPECT_NEAR(q[p], 2.5, 1e-14) << "point " << p;
  }
}

TEST(CheckerboardFilter, KeepsTheWeightedSumOfUnequalCells) {
  const FilterScene scene(5);
  const auto weight = [&](int p) { return 0.1 + 0.07 * ((p * 7) % 11); };
  const auto value = [&](int p) { return std::sin(0.3 * p) + 2.0 * scene.points.position(p, 1); };
  const std::vector<Real> q = filtered(scene, value, weight);
  Real before = 0, after = 0, scale = 0;
  for (int p = 0; p < scene.points.count; ++p) {
    before += weight(p) * value(p);
    after += weight(p) * q[p];
    scale += weight(p) * std::fabs(value(p));
  }
  EXPECT_NEAR(after, before, 1e-14 * scale);
  // points of one cell share one value
  for (int p = 1; p < scene.points.count; ++p)
    if (scene.points.element(p) == scene.points.element(p - 1)) {
      EXPECT_EQ(q[p], q[p - 1]);
    }
}

TEST(CheckerboardFilter, RemovesTheCheckerboardAndKeepsALinearField) {
  // 7 x 7 cells of equal weight: the cells 2..4 have neighbours whose neighbourhoods are full
  const FilterScene scene(7);
  const auto inner = [&](int p) {
    const auto c = scene.cell(p);
    return c[0] >= 2 && c[0] <= 4 && c[1] >= 2 && c[1] <= 4;
  };
  const auto equal = [](int) { return 0.25; };
  const auto sign = [&](int p) {
    const auto c = scene.cell(p);
    return (c[0] + c[1]) % 2 == 0 ? 1.0 : -1.0;
  };
  const std::vector<Real> checker = filtered(
      scene, [&](int p) { return 3.0 + 2.0 * sign(p); }, equal);
  // a linear field's cell average is its value at the cell centre
  const auto centre_value = [&](int p) {
    const auto c = scene.cell(p);
    return 1.0 + 0.4 * (0.5 * c[0] + 0.25) - 0.9 * (0.5 * c[1] + 0.25);
  };
  const std::vector<Real> linear = filtered(scene, centre_value, equal);
  int checked = 0;
  for (int p = 0; p < scene.points.count; ++p) {
    if (!inner(p)) continue;
    EXPECT_NEAR(checker[p], 3.0, 1e-14) << "point " << p;  // the alternating part gone
    EXPECT_NEAR(linear[p], centre_value(p), 1e-14) << "point " << p;
    ++checked;
  }
  EXPECT_EQ(checked, 9 * 4);
}

}  // namespace
}  // namespace argine
