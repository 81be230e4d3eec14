// The volume-weighted averaging of point values (physics/PointValueAveraging.hpp): element
// averages by hand, the weighted sum kept by nodal averages, points without a mode left
// alone, and several channels in one call equal to one call per channel, bit for bit.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../transfer/TestScenes.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {
namespace {

/// Three quads in a row, 4 points each, the point volumes made unequal.
struct AveragingScene {
  Mesh mesh = test::rectangleMesh(3, 1, 3.0, 1.0, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh);
  PointShapes shapes;
  ActiveNodes active{mesh.numNodes()};
  AveragingScene() {
    evaluatePointShapes(mesh, points, shapes);
    active.rebuild(mesh, points);
  }
  int count() const { return points.count; }
  Real weight(int p) const { return 0.2 + 0.05 * p; }
  Real x(int p) const { return points.position(p, 0); }
};

/// Channel c's mode and value of point p in the test below.
int modeOf(int c, int p) {
  if (c == 0) return kAverageNodal;
  if (c == 1) return kAverageElement;
  return p % 3 == 0 ? kAverageNone : kAverageNodal;  // some points take no part
}
Real valueOf(const AveragingScene& scene, int c, int p) {
  if (c == 0) return std::sin(1.0 + p);
  if (c == 1) return scene.x(p) * scene.x(p);
  return 1.0 + 3.0 * p;
}

/// Averages `channels` (indices into modeOf/valueOf) in ONE call; the values after it.
std::vector<std::vector<Real>> average(const AveragingScene& scene,
                                       const std::vector<int>& channels) {
  AveragingScratch scratch;
  const int k = static_cast<int>(channels.size());
  scratch.allocateSums(k, scene.mesh.numElements(), scene.mesh.numNodes());
  scratch.fitPoints(scene.count());
  for (int p = 0; p < scene.count(); ++p) {
    scratch.weight_p(p) = scene.weight(p);
    for (int j = 0; j < k; ++j) {
      scratch.mode_pc(p, j) = modeOf(channels[j], p);
      scratch.value_pc(p, j) = valueOf(scene, channels[j], p);
    }
  }
  averagePointValues(scene.points, scene.shapes, scene.active, scratch, nullptr);
  std::vector<std::vector<Real>> out(k, std::vector<Real>(scene.count()));
  for (int j = 0; j < k; ++j)
    for (int p = 0; p < scene.count(); ++p) out[j][p] = scratch.value_pc(p, j);
  return out;
}

TEST(PointValueAveraging, ElementAveragesByHandAndNodalAveragesKeepTheWeightedSum) {
  const AveragingScene scene;
  const auto values = average(scene, {0, 1, 2});
  // Element: the weighted mean of the element's four points, at each of them.
  for (int p = 0; p < scene.count(); ++p) {
    const int e = scene.points.element(p);
    Real wq = 0, w = 0;
    for (int q = 0; q < scene.count(); ++q)
      if (scene.points.element(q) == e) {
        wq += scene.weight(q) * valueOf(scene, 1, q);
        w += scene.weight(q);
      }
    EXPECT_NEAR(values[1][p], wq / w, 1e-15 * std::fabs(wq / w)) << "point " << p;
  }
  // Nodal: sum_p w_p q_p over the body is kept (channel 0: all points; channel 2: those in
  // it), and the values do change.
  for (const int c : {0, 2}) {
    Real before = 0, after = 0, changed = 0;
    for (int p = 0; p < scene.count(); ++p) {
      if (modeOf(c, p) == kAverageNone) continue;
      before += scene.weight(p) * valueOf(scene, c, p);
      after += scene.weight(p) * values[c][p];
      changed = std::max(changed, std::fabs(values[c][p] - valueOf(scene, c, p)));
    }
    EXPECT_NEAR(after, before, 1e-14 * std::fabs(before)) << "channel " << c;
    EXPECT_GT(changed, 0.01) << "channel " << c;
  }
  // A point without a mode keeps its value.
  for (int p = 0; p < scene.count(); p += 3) EXPECT_EQ(values[2][p], valueOf(scene, 2, p));
}

TEST(PointValueAveraging, ChannelsAveragedTogetherEqualOneCallEachBitForBit) {
  const AveragingScene scene;
  const auto together = average(scene, {0, 1, 2});
  for (int c = 0; c < 3; ++c) {
    const auto alone = average(scene, {c});
    for (int p = 0; p < scene.count(); ++p)
      ASSERT_EQ(together[c][p], alone[0][p]) << "channel " << c << ", point " << p;
  }
}

}  // namespace
}  // namespace argine
