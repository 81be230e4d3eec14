// The donor limit (LiquidOutflowLimit.hpp) with the donor and the gaining points on
// different ranks: the hand values of LiquidOutflowLimit.CapsTheDonorAtItsResidual... on one
// rank. Partition weights 2, 1, 1 put the donor element (bottom) alone on rank 0 under
// `mpiexec -n 2` (parallel_two_ranks); on one rank the test is the one-rank case again.
#include <gtest/gtest.h>
#include <mpi.h>

#include "../physics/LimitScene.hpp"
#include "argine/parallel/NodalExchange.hpp"
#include "argine/parallel/PointMigration.hpp"
#include "argine/parallel/RankDecomposition.hpp"

namespace argine {
namespace {

using test::hostCopy;

TEST(OutflowLimitRanks, DonorAndGainersOnDifferentRanksAsOnOneRank) {
  test::LimitScene scene;
  const RankDecomposition ranks(MPI_COMM_WORLD, scene.mesh, {2.0, 1.0, 1.0});
  if (ranks.size() == 2) {
    ASSERT_NE(ranks.elementOwners()[0], ranks.elementOwners()[1]);  // donor | gainers
  }
  keepOwnedPoints(ranks, scene.points);
  evaluatePointShapes(scene.mesh, scene.points, scene.shapes);
  scene.rates.allocate(scene.points.count);
  const Real mass[3] = {15, 100, 100}, outflow[3] = {4, -5, 0};
  scene.set(mass, outflow);
  NodalExchange exchange(ranks);
  LiquidOutflowLimit limit;
  limit.distribute(&exchange, ranks.comm(), scene.mesh.numNodes());
  const OutflowLimitTotals totals =
      limit.apply(scene.table, scene.points, scene.shapes, scene.rates);
  // The totals are those of the whole column.
  test::expectDonorCaseTotals(totals);
  Real mass_after = 0;
  const std::vector<Real> out = scene.outflows(mass_after);
  MPI_Allreduce(MPI_IN_PLACE, &mass_after, 1, MPI_DOUBLE, MPI_SUM, ranks.comm());
  EXPECT_NEAR(mass_after, 864.0, 1e-10);
  // Per point, the hand values of the one-rank test: the donors keep their residual, the
  // middle row at y = 1.25 (shape sum 0.75 on the shared nodes) gains 3.875 * 14 / 17, the
  // row at y = 1.75 gains 4.625 * 14 / 17, the top moves nothing.
  const auto element = hostCopy(scene.points.element);
  const auto y = hostCopy(scene.points.position);
  for (int p = 0; p < scene.points.count; ++p) {
    if (element(p) == 0) {
      EXPECT_NEAR(out[p], 2.5, 1e-12);
    } else if (element(p) == 2) {
      EXPECT_EQ(out[p], 0.0);
    } else {
      EXPECT_NEAR(-out[p], (y(p, 1) < 1.5 ? 3.875 : 4.625) * 14 / 17, 1e-12) << "y " << y(p, 1);
    }
  }
}

}  // namespace
}  // namespace argine
