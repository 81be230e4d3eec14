// The donor limit (LiquidOutflowLimit.hpp) with the donor and the gaining points on
// different ranks: the hand values of LiquidOutflowLimit.CapsTheDonorAtItsResidual... on one
// rank. Partition weights 2, 1, 1 put the donor element (bottom) alone on rank 0 under
// `mpiexec -n 2` (parallel_two_ranks); on one rank the test is the one-rank case again. On
// the grid families a point reaches the nodes of the neighbouring cells too: there the
// distributed limit must give the one-rank values.
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

TEST(OutflowLimitRanks, GridFamiliesDonorAndGainersOnDifferentRanksAsOnOneRank) {
  // The same column and case on GIMP and B-spline shapes, where every point of the donor
  // cell reaches the gainers' nodes three rows up: each point's outflow and the totals as on
  // one rank (computed first on every rank alone).
  for (const ShapeFamily family : {ShapeFamily::Gimp, ShapeFamily::BSpline}) {
    auto onGrid = [family](test::LimitScene& scene) {
      scene.mesh.structured.cells[0] = 1, scene.mesh.structured.cells[1] = 3;
      scene.mesh.structured.spacing[0] = scene.mesh.structured.spacing[1] = 1.0;
      scene.mesh.shape_functions = family;
    };
    const Real mass[3] = {15, 100, 100}, outflow[3] = {4, -5, 0};
    test::LimitScene one;
    onGrid(one);
    evaluatePointShapes(one.mesh, one.points, one.shapes);
    one.set(mass, outflow);
    const OutflowLimitTotals one_totals =
        LiquidOutflowLimit().apply(one.table, one.points, one.shapes, one.rates);
    Real one_mass = 0;
    const std::vector<Real> one_out = one.outflows(one_mass);
    EXPECT_GT(one_totals.withdrawn, 0.0);

    test::LimitScene scene;
    onGrid(scene);
    const RankDecomposition ranks(MPI_COMM_WORLD, scene.mesh, {2.0, 1.0, 1.0});
    keepOwnedPoints(ranks, scene.points);
    evaluatePointShapes(scene.mesh, scene.points, scene.shapes);
    scene.rates.allocate(scene.points.count);
    scene.set(mass, outflow);
    NodalExchange exchange(ranks);
    LiquidOutflowLimit limit;
    limit.distribute(&exchange, ranks.comm(), scene.mesh.numNodes());
    const OutflowLimitTotals totals =
        limit.apply(scene.table, scene.points, scene.shapes, scene.rates);
    EXPECT_EQ(totals.limited_points, one_totals.limited_points);
    EXPECT_NEAR(totals.excess, one_totals.excess, 1e-12);
    EXPECT_NEAR(totals.withdrawn, one_totals.withdrawn, 1e-12);
    Real mass_after = 0;
    const std::vector<Real> out = scene.outflows(mass_after);
    MPI_Allreduce(MPI_IN_PLACE, &mass_after, 1, MPI_DOUBLE, MPI_SUM, ranks.comm());
    EXPECT_NEAR(mass_after, one_mass, 1e-10);
    const auto id = hostCopy(scene.points.id);
    for (int p = 0; p < scene.points.count; ++p)
      EXPECT_NEAR(out[p], one_out[id(p)], 1e-12) << "point " << id(p);
  }
}

}  // namespace
}  // namespace argine
