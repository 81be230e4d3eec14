// The patches of `Averaging Length (m)` (physics/AveragingPatches.hpp) and the element averages
// over them (physics/PointValueAveraging.hpp): the patches of a grid by hand, the averages over
// a patch by hand, and patches of one cell equal to the element averages bit for bit.

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "../transfer/TestScenes.hpp"
#include "argine/physics/AveragingPatches.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {
namespace {

/// Four by two quads of 0.5 m from (1, -1), 4 points each.
struct PatchScene {
  Mesh mesh = test::rectangleMesh(4, 2, 2.0, 1.0, ElementType::Quad4, 1.0, -1.0);
  MaterialPoints points = test::seedUniform(mesh);
  PointShapes shapes;
  ActiveNodes active{mesh.numNodes()};
  PatchScene() {
    evaluatePointShapes(mesh, points, shapes);
    active.rebuild(mesh, points);
  }
  Real weight(int p) const { return 0.2 + 0.05 * p; }
  Real value(int p) const { return std::sin(1.0 + p) + points.position(p, 0); }
};

std::vector<int> patchesOf(const AveragingPatches& patches) {
  const auto patch_e = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), patches.patch_e);
  return std::vector<int>(patch_e.data(), patch_e.data() + patch_e.extent(0));
}

/// Element averages of the scene's values, over `patches` if given.
std::vector<Real> elementAverages(const PatchScene& scene, const AveragingPatches* patches) {
  AveragingScratch scratch;
  if (patches) scratch.usePatches(patches->patch_e, MPI_COMM_NULL);
  scratch.allocateSums(1, patches ? patches->count : scene.mesh.numElements(), 0);
  scratch.fitPoints(scene.points.count);
  for (int p = 0; p < scene.points.count; ++p) {
    scratch.weight_p(p) = scene.weight(p);
    scratch.mode_pc(p, 0) = kAverageElement;
    scratch.value_pc(p, 0) = scene.value(p);
  }
  averagePointValues(scene.points, scene.shapes, scene.active, scratch, nullptr);
  std::vector<Real> out(scene.points.count);
  for (int p = 0; p < scene.points.count; ++p) out[p] = scratch.value_pc(p, 0);
  return out;
}

TEST(AveragingPatches, SquaresOfTheLengthFromTheLowerLeftCorner) {
  const PatchScene scene;
  // L = 1 m: 2 x 1 patches of 2 x 2 cells; the element centres (1.25 + 0.5 i, -0.75 + 0.5 j)
  const AveragingPatches patches = buildAveragingPatches(scene.mesh, 1.0);
  EXPECT_EQ(patches.count, 2);
  const auto host_nodes =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), scene.mesh.connectivity);
  const auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), scene.mesh.coordinates);
  const std::vector<int> patch = patchesOf(patches);
  for (int e = 0; e < scene.mesh.numElements(); ++e) {
    Real centre = 0;
    for (int a = 0; a < 4; ++a) centre += x(host_nodes(e, a), 0) / 4;
    EXPECT_EQ(patch[e], centre < 2.0 ? 0 : 1) << "element " << e;
  }
  // L = 0.75 m: columns from x = 1, 1.75, 2.5 and rows from y = -1, -0.25: 3 x 2 patches
  const AveragingPatches uneven = buildAveragingPatches(scene.mesh, 0.75);
  EXPECT_EQ(uneven.count, 6);
  // L = the cell: one element a patch
  const std::vector<int> own = patchesOf(buildAveragingPatches(scene.mesh, 0.5));
  EXPECT_EQ(std::set<int>(own.begin(), own.end()).size(), own.size());
  EXPECT_THROW(buildAveragingPatches(scene.mesh, 0.0), std::invalid_argument);
}

TEST(AveragingPatches, AveragesOverAPatchByHand) {
  const PatchScene scene;
  const AveragingPatches patches = buildAveragingPatches(scene.mesh, 1.0);
  const std::vector<int> patch = patchesOf(patches);
  const std::vector<Real> averaged = elementAverages(scene, &patches);
  for (int p = 0; p < scene.points.count; ++p) {
    const int mine = patch[scene.points.element(p)];
    Real wq = 0, w = 0;
    for (int q = 0; q < scene.points.count; ++q)
      if (patch[scene.points.element(q)] == mine) {
        wq += scene.weight(q) * scene.value(q);
        w += scene.weight(q);
      }
    EXPECT_NEAR(averaged[p], wq / w, 1e-15 * std::fabs(wq / w)) << "point " << p;
  }
}

TEST(AveragingPatches, PatchesOfOneCellAreTheElementAveragesBitForBit) {
  const PatchScene scene;
  const AveragingPatches patches = buildAveragingPatches(scene.mesh, 0.5);
  const std::vector<Real> by_patch = elementAverages(scene, &patches);
  const std::vector<Real> by_element = elementAverages(scene, nullptr);
  for (int p = 0; p < scene.points.count; ++p) EXPECT_EQ(by_patch[p], by_element[p]) << p;
}

}  // namespace
}  // namespace argine
