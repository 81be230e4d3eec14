// The liquid head stabilisation (LiquidHeadStabilisation.hpp) with the two triangles of a
// square on different ranks: the node averages on the shared diagonal need both ranks' sums,
// and each rank must find the one-rank hand values of
// LiquidHeadStabilisation.TwoTrianglesByHand. Under `mpiexec -n 2` (parallel_two_ranks) each
// rank holds one triangle; on one rank the test is the one-rank case again.
#include <gtest/gtest.h>
#include <mpi.h>

#include "../physics/HeadScene.hpp"
#include "argine/parallel/NodalExchange.hpp"
#include "argine/parallel/PointMigration.hpp"
#include "argine/parallel/RankDecomposition.hpp"

namespace argine {
namespace {

using test::hostCopy;

TEST(HeadStabilisationRanks, TwoTrianglesOnTwoRanksAsOnOneRank) {
  test::HeadScene scene(1, 1, 1.0, 0.1);
  const RankDecomposition ranks(MPI_COMM_WORLD, scene.mesh, {1.0, 1.0});
  if (ranks.size() == 2) {
    ASSERT_NE(ranks.elementOwners()[0], ranks.elementOwners()[1]);
  }
  keepOwnedPoints(ranks, scene.points);
  evaluatePointShapes(scene.mesh, scene.points, scene.shapes);
  scene.rates.allocate(scene.points.count);
  scene.active.rebuild(scene.mesh, scene.points, ranks.sharedNodeView());
  const auto id = hostCopy(scene.points.id);
  int q = 0;
  scene.setPressure([&](Real, Real) { return id(q++) == 0 ? 4000.0 : 1000.0; });
  NodalExchange exchange(ranks);
  const Real dt = 1e-3, conductance = 0.1 * test::kConductivity / 9.81;
  const std::vector<Real> change = scene.massChanges(dt, 0.0, &exchange);
  Real total = 0;
  for (int p = 0; p < scene.points.count; ++p) {
    // Uncapped, equal conductances: dM = -+ dt g (4000 - 1000) / 3 (the one-rank test).
    const Real expected = (id(p) == 0 ? -1 : 1) * dt * conductance * 3000.0 / 3;
    EXPECT_NEAR(change[p], expected, 1e-18) << "point " << id(p);
    total += change[p];
  }
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_DOUBLE, MPI_SUM, ranks.comm());
  EXPECT_NEAR(total, 0.0, 1e-20);
}

}  // namespace
}  // namespace argine
