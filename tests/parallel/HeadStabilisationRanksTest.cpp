// The liquid head stabilisation (LiquidHeadStabilisation.hpp) with the eight triangles of four
// squares on two ranks: the node planes on the shared nodes need both ranks' sums, and each
// rank must find the one-rank hand values of
// LiquidHeadStabilisation.CheckerboardOnFourSquaresByHand. Under `mpiexec -n 2`
// (parallel_two_ranks) each rank holds one triangle; on one rank the test is the one-rank case
// again.
#include <gtest/gtest.h>
#include <mpi.h>

#include "../physics/HeadScene.hpp"
#include "argine/parallel/NodalExchange.hpp"
#include "argine/parallel/PointMigration.hpp"
#include "argine/parallel/RankDecomposition.hpp"

namespace argine {
namespace {

using test::hostCopy;

TEST(HeadStabilisationRanks, FourSquaresOnTwoRanksAsOnOneRank) {
  test::HeadScene scene(2, 2, 1.0, 0.1);
  const RankDecomposition ranks(MPI_COMM_WORLD, scene.mesh, std::vector<Real>(8, 1.0));
  if (ranks.size() == 2) {  // both ranks hold triangles
    int first = 0;
    for (const int owner : ranks.elementOwners()) first += owner == 0;
    ASSERT_GT(first, 0);
    ASSERT_LT(first, 8);
  }
  keepOwnedPoints(ranks, scene.points);
  evaluatePointShapes(scene.mesh, scene.points, scene.shapes);
  scene.rates.allocate(scene.points.count);
  scene.active.rebuild(scene.mesh, scene.points, ranks.sharedNodeView());
  scene.setPressure([](Real x, Real y) { return 2500.0 + 1500.0 * test::checkerboardSign(x, y); });
  NodalExchange exchange(ranks);
  const Real dt = 1e-3, conductance = 0.1 * test::kConductivity / 9.81;
  const std::vector<Real> change = scene.massChanges(dt, 0.0, &exchange);
  const auto position = hostCopy(scene.points.position);
  Real total = 0;
  for (int p = 0; p < scene.points.count; ++p) {
    const Real x = position(p, 0), y = position(p, 1);
    const Real expected = test::fourSquaresHandChange(x, y, dt * conductance);
    EXPECT_NEAR(change[p], expected, 1e-6 * dt * conductance * 1500.0)
        << "point at " << x << ", " << y;
    total += change[p];
  }
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_DOUBLE, MPI_SUM, ranks.comm());
  EXPECT_NEAR(total, 0.0, 1e-20);
}

}  // namespace
}  // namespace argine
