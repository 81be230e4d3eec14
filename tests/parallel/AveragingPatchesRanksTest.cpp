// Element averages over patches (physics/AveragingPatches.hpp) on two ranks: a patch holds
// elements of both ranks, so its sums need both ranks' points. Under `mpiexec -n 2`
// (parallel_two_ranks) every rank must find the one-rank averages: to round-off with plain
// sums, bit for bit with reproducible ones. On one rank the test is the one-rank case again.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <vector>

#include "../transfer/TestScenes.hpp"
#include "argine/parallel/PointMigration.hpp"
#include "argine/parallel/RankDecomposition.hpp"
#include "argine/physics/AveragingPatches.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {
namespace {

Real weightAt(Real x, Real y) {
  return 0.3 + 0.1 * x + 0.05 * y * y;
}
Real valueAt(Real x, Real y) {
  return std::sin(3.0 * x) + y;
}

/// The points' element averages over `patches` (their comm: `comm`), by position.
std::vector<Real> averages(const Mesh& mesh, const MaterialPoints& points,
                           const AveragingPatches& patches, MPI_Comm comm, bool compensated) {
  PointShapes shapes;
  evaluatePointShapes(mesh, points, shapes);
  ActiveNodes active{mesh.numNodes()};
  active.rebuild(mesh, points);
  AveragingScratch scratch;
  scratch.usePatches(patches.patch_e, comm);
  scratch.allocateSums(1, patches.count, 0);
  scratch.compensate(compensated);
  scratch.fitPoints(points.count);
  for (int p = 0; p < points.count; ++p) {
    const Real x = points.position(p, 0), y = points.position(p, 1);
    scratch.weight_p(p) = weightAt(x, y);
    scratch.mode_pc(p, 0) = kAverageElement;
    scratch.value_pc(p, 0) = valueAt(x, y);
  }
  averagePointValues(points, shapes, active, scratch, nullptr);
  std::vector<Real> out(points.count);
  for (int p = 0; p < points.count; ++p) out[p] = scratch.value_pc(p, 0);
  return out;
}

TEST(AveragingPatchesRanks, PatchesAcrossTheRankBorderAsOnOneRank) {
  // 8 x 2 quads of 0.25 m, patches of 0.75 m: a border between the halves at x = 1 m cuts
  // through the middle patch (0.75 to 1.5 m)
  const Mesh mesh = test::rectangleMesh(8, 2, 2.0, 0.5, ElementType::Quad4);
  const AveragingPatches patches = buildAveragingPatches(mesh, 0.75);
  ASSERT_EQ(patches.count, 3);
  const MaterialPoints all = test::seedUniform(mesh);
  const RankDecomposition ranks(MPI_COMM_WORLD, mesh, std::vector<Real>(mesh.numElements(), 1.0));
  for (const bool compensated : {false, true}) {
    const std::vector<Real> one = averages(mesh, all, patches, MPI_COMM_NULL, compensated);
    MaterialPoints mine = test::seedUniform(mesh);
    keepOwnedPoints(ranks, mine);
    const std::vector<Real> shared = averages(mesh, mine, patches, ranks.comm(), compensated);
    for (int p = 0; p < mine.count; ++p) {
      int q = 0;  // the same point in the one-rank set
      while (all.position(q, 0) != mine.position(p, 0) || all.position(q, 1) != mine.position(p, 1))
        ++q;
      if (compensated)
        EXPECT_EQ(shared[p], one[q]) << "point " << p;
      else
        EXPECT_NEAR(shared[p], one[q], 1e-14) << "point " << p;
    }
  }
}

}  // namespace
}  // namespace argine
