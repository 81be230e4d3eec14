// Element partition, nodal exchange and point migration over the ranks of MPI_COMM_WORLD
// (any number of ranks, 1 included; the suite runs them on 1 and on 2 ranks).
#include <gtest/gtest.h>
#include <mpi.h>

#include <stdexcept>
#include <vector>

#include "../transfer/TestScenes.hpp"
#include "argine/parallel/NodalExchange.hpp"
#include "argine/parallel/PointMigration.hpp"
#include "argine/parallel/RankDecomposition.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/CompensatedSum.hpp"

namespace argine {
namespace {

int worldSize() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

TEST(ElementBisection, SplitsARowByWeight) {
  // Four elements in a row at x = 0, 1, 2, 3. Equal weights, two parts: the first half of
  // the weight (2 of 4) goes to part 0. Weights 3, 1, 1, 1 (total 6, target 3): element 0
  // alone reaches half the weight.
  const std::vector<Real> x{0, 1, 2, 3}, y{0, 0, 0, 0};
  EXPECT_EQ(bisectElements(x, y, {1, 1, 1, 1}, 2), (std::vector<int>{0, 0, 1, 1}));
  EXPECT_EQ(bisectElements(x, y, {3, 1, 1, 1}, 2), (std::vector<int>{0, 1, 1, 1}));
  // Four parts of four equal elements: one each, in order along x.
  EXPECT_EQ(bisectElements(x, y, {1, 1, 1, 1}, 4), (std::vector<int>{0, 1, 2, 3}));
  // A column (taller than wide) is cut across y.
  EXPECT_EQ(bisectElements(y, x, {1, 1, 1, 1}, 2), (std::vector<int>{0, 0, 1, 1}));
}

/// For every node, the ranks whose elements touch it (each once).
std::vector<std::vector<int>> ranksTouchingNodes(const Mesh& mesh, const RankDecomposition& ranks) {
  const auto& owner = ranks.elementOwners();
  const auto C = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  std::vector<std::vector<int>> touching(mesh.numNodes());
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int a = 0; a < 4; ++a) {
      auto& list = touching[C(e, a)];
      if (std::find(list.begin(), list.end(), owner[e]) == list.end()) list.push_back(owner[e]);
    }
  return touching;
}

TEST(RankDecomposition, SharedNodesSumOverRanks) {
  // 8 x 2 quads of 1 m: with equal weights each rank owns a block of columns. Every rank
  // adds (rank + 1) at each node of its elements; after the exchange a node's value is the
  // sum of (r + 1) over the ranks r whose elements touch it, counted from the partition.
  const Mesh mesh = test::rectangleMesh(8, 2, 8.0, 2.0, ElementType::Quad4);
  const RankDecomposition ranks(MPI_COMM_WORLD, mesh, std::vector<Real>(mesh.numElements(), 1));
  const std::vector<std::vector<int>> touching = ranksTouchingNodes(mesh, ranks);
  Kokkos::View<Real*, MemSpace> scalar("scalar", mesh.numNodes());
  Kokkos::View<Real* [2], MemSpace> vector("vector", mesh.numNodes());
  for (int i = 0; i < mesh.numNodes(); ++i)
    if (std::find(touching[i].begin(), touching[i].end(), ranks.rank()) != touching[i].end()) {
      scalar(i) = ranks.rank() + 1;
      vector(i, 0) = 10 * (ranks.rank() + 1);
      vector(i, 1) = -(ranks.rank() + 1);
    }
  NodalExchange exchange(ranks);
  exchange.sum({nodalField(scalar), nodalField(vector)});
  int shared = 0;
  for (int i = 0; i < mesh.numNodes(); ++i) {
    if (std::find(touching[i].begin(), touching[i].end(), ranks.rank()) == touching[i].end())
      continue;
    Real expected = 0;
    for (const int r : touching[i]) expected += r + 1;
    shared += touching[i].size() > 1 ? 1 : 0;
    EXPECT_EQ(scalar(i), expected) << "node " << i;
    EXPECT_EQ(vector(i, 0), 10 * expected);
    EXPECT_EQ(vector(i, 1), -expected);
  }
  EXPECT_EQ(shared, static_cast<int>(ranks.sharedNodes().size()));
  if (worldSize() == 2) {
    EXPECT_EQ(ranks.sharedNodes().size(), 3u);  // one vertical cut line
  }
  // Every node is owned by exactly one rank.
  Kokkos::View<Real*, MemSpace> owned("owned", mesh.numNodes());
  const auto mask = ranks.nodeOwnedView();
  for (int i = 0; i < mesh.numNodes(); ++i) owned(i) = mask(i);
  MPI_Allreduce(MPI_IN_PLACE, owned.data(), mesh.numNodes(), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  for (int i = 0; i < mesh.numNodes(); ++i) EXPECT_EQ(owned(i), 1.0) << "node " << i;
}

TEST(RankDecomposition, GridFamiliesShareEveryNodeBothRanksPointsReach) {
  // The 8 x 2 grid of 1 m cells on B-splines: a point reaches the nodes of its cell's
  // neighbours (ElementFootprint). Cut between cell columns 3 and 4 on 2 ranks, rank 0's
  // points reach node columns up to 5 and rank 1's down to 3: three node columns of 3 nodes
  // are shared (one on linear shapes), owned by rank 0; the other nodes by the rank alone.
  Mesh mesh = test::rectangleMesh(8, 2, 8.0, 2.0, ElementType::Quad4);
  mesh.structured.cells[0] = 8, mesh.structured.cells[1] = 2;
  mesh.structured.spacing[0] = mesh.structured.spacing[1] = 1.0;
  mesh.shape_functions = ShapeFamily::BSpline;
  const RankDecomposition ranks(MPI_COMM_WORLD, mesh, std::vector<Real>(mesh.numElements(), 1));
  const auto owned = ranks.nodeOwnedView();
  if (worldSize() == 2) {
    std::vector<int> expected;
    for (int i = 0; i < mesh.numNodes(); ++i)
      if (i % 9 >= 3 && i % 9 <= 5) expected.push_back(i);
    EXPECT_EQ(ranks.sharedNodes(), expected);
    ASSERT_EQ(ranks.neighbours().size(), 1u);
    EXPECT_EQ(ranks.neighbours()[0].nodes, expected);
    for (int i = 0; i < mesh.numNodes(); ++i)
      EXPECT_EQ(owned(i), (i % 9 <= 5) == (ranks.rank() == 0) ? 1 : 0) << "node " << i;
  }
  if (worldSize() == 1) {
    EXPECT_TRUE(ranks.sharedNodes().empty());
  }
  Kokkos::View<Real*, MemSpace> count("owners", mesh.numNodes());
  for (int i = 0; i < mesh.numNodes(); ++i) count(i) = owned(i);
  MPI_Allreduce(MPI_IN_PLACE, count.data(), mesh.numNodes(), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  for (int i = 0; i < mesh.numNodes(); ++i) EXPECT_EQ(count(i), 1.0) << "node " << i;
}

TEST(RankDecomposition, CompensatedSumsAtSharedNodesKeepWhatPlainSumsLose) {
  // Each rank holds the reproducible (binned) sum of its partial terms at the shared nodes:
  // rank r adds 1e16 (r even) or -1e16 (r odd) and then 1 + r. The exact total is
  // sum (1 + r) (+ 1e16 if the count of ranks touching the node is odd); plain partial sums
  // have lost the small terms already, the merged binned sums keep them.
  const Mesh mesh = test::rectangleMesh(8, 2, 8.0, 2.0, ElementType::Quad4);
  const RankDecomposition ranks(MPI_COMM_WORLD, mesh, std::vector<Real>(mesh.numElements(), 1));
  const std::vector<std::vector<int>> touching = ranksTouchingNodes(mesh, ranks);
  Kokkos::View<Real*, MemSpace> hi("hi", mesh.numNodes());
  const auto lo = allocateLowParts(hi);
  const int me = ranks.rank();
  for (int i = 0; i < mesh.numNodes(); ++i)
    if (std::find(touching[i].begin(), touching[i].end(), me) != touching[i].end()) {
      Real* parts[kSumParts];
      partsAt(hi, lo, i, parts);
      addToSum(parts, me % 2 == 0 ? 1e16 : -1e16);
      addToSum(parts, 1.0 + me);
    }
  NodalExchange exchange(ranks);
  std::vector<NodalFieldRef> lo_refs;
  for (int k = 0; k < kLowParts; ++k) lo_refs.push_back(nodalField(lo[k]));
  exchange.sumCompensated({nodalField(hi)}, lo_refs);
  for (int i = 0; i < mesh.numNodes(); ++i) {
    if (std::find(touching[i].begin(), touching[i].end(), me) == touching[i].end()) continue;
    std::vector<int> around = touching[i];
    std::sort(around.begin(), around.end());
    Real big = 0, small = 0;
    for (const int r : around) {
      big += r % 2 == 0 ? 1e16 : -1e16;
      small += 1.0 + r;
    }
    Real parts[kSumParts] = {hi(i)};
    for (int k = 0; k < kLowParts; ++k) parts[k + 1] = lo[k](i);
    EXPECT_EQ(foldSum(parts), big + small) << "node " << i;  // exact in doubles here
  }
}

TEST(PointMigration, PointsGoToTheOwnerOfTheirElementWithAllFields) {
  const Mesh mesh = test::rectangleMesh(8, 2, 8.0, 2.0, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh);
  const int total = points.count;
  for (int p = 0; p < points.count; ++p) {  // recognisable values in every field kind
    points.pressure_liquid(p) = 1000.0 + points.id(p);
    points.stress_effective(p, XY) = -0.5 * points.id(p);
    points.plastic_state(p) = points.id(p) % 3;
  }
  const RankDecomposition ranks(MPI_COMM_WORLD, mesh, std::vector<Real>(mesh.numElements(), 1));
  keepOwnedPoints(ranks, points);
  // Move every point one element to the right (the last column wraps to the first): a point
  // of a border column enters the next rank's elements.
  for (int p = 0; p < points.count; ++p) {
    const int e = points.element(p);
    points.element(p) = (e % 8 == 7) ? e - 7 : e + 1;
  }
  const MigrationCounts moved = migratePoints(ranks, points);
  long long count = points.count;
  MPI_Allreduce(MPI_IN_PLACE, &count, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(count, total);
  if (worldSize() > 1) {
    EXPECT_GT(moved.total, 0);
  }
  for (int p = 0; p < points.count; ++p) {
    EXPECT_EQ(ranks.elementOwners()[points.element(p)], ranks.rank());
    EXPECT_EQ(points.pressure_liquid(p), 1000.0 + points.id(p));
    EXPECT_EQ(points.stress_effective(p, XY), -0.5 * points.id(p));
    EXPECT_EQ(points.plastic_state(p), points.id(p) % 3);
  }
}

TEST(PointMigration, GatherByRankAndRangeGiveEachRankItsPointsBackInOrder) {
  // What a checkpoint of a decomposed run stores (gatherPointsByRank on rank 0) and what a
  // restart hands each rank (pointRange of its slice): the same points in the same order.
  const Mesh mesh = test::rectangleMesh(8, 2, 8.0, 2.0, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh);
  const RankDecomposition ranks(MPI_COMM_WORLD, mesh, std::vector<Real>(mesh.numElements(), 1));
  keepOwnedPoints(ranks, points);
  // A rank's memory order that is not the id order (as after a migration).
  std::vector<int> reversed(points.count);
  for (int p = 0; p < points.count; ++p) reversed[p] = points.count - 1 - p;
  MaterialPoints mine;
  mine.allocate(points.count);
  for (int p = 0; p < points.count; ++p) {
    mine.id(p) = points.id(reversed[p]);
    mine.element(p) = points.element(reversed[p]);
    mine.pressure_liquid(p) = 1000.0 + mine.id(p);
    mine.stress_effective(p, XY) = -0.5 * mine.id(p);
  }
  std::vector<long long> counts;
  const MaterialPoints stored = gatherPointsByRank(MPI_COMM_WORLD, mine, counts);
  // Every rank reads the stored points (here: broadcast from rank 0) and takes its slice.
  long long total = stored.count;
  MPI_Bcast(&total, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  counts.resize(worldSize());
  MPI_Bcast(counts.data(), worldSize(), MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  std::vector<int> ids(total);
  std::vector<Real> pressures(total);
  for (int p = 0; p < stored.count; ++p) {
    ids[p] = stored.id(p);
    pressures[p] = stored.pressure_liquid(p);
  }
  MPI_Bcast(ids.data(), static_cast<int>(total), MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Bcast(pressures.data(), static_cast<int>(total), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  MaterialPoints everything;
  everything.allocate(static_cast<int>(total));
  for (int p = 0; p < total; ++p) {
    everything.id(p) = ids[p];
    everything.pressure_liquid(p) = pressures[p];
  }
  long long first = 0;
  for (int r = 0; r < ranks.rank(); ++r) first += counts[r];
  ASSERT_EQ(counts[ranks.rank()], mine.count);
  const MaterialPoints back =
      pointRange(everything, static_cast<int>(first), static_cast<int>(counts[ranks.rank()]));
  ASSERT_EQ(back.count, mine.count);
  for (int p = 0; p < mine.count; ++p) {
    EXPECT_EQ(back.id(p), mine.id(p)) << p;
    EXPECT_EQ(back.pressure_liquid(p), mine.pressure_liquid(p)) << p;
  }
  if (ranks.rank() == 0) {  // the stored copy carries every field, not only the two sent here
    for (int p = 0; p < stored.count; ++p)
      EXPECT_EQ(stored.stress_effective(p, XY), -0.5 * stored.id(p)) << p;
  }
  EXPECT_THROW(pointRange(everything, static_cast<int>(total), 1), std::out_of_range);
}

}  // namespace
}  // namespace argine
