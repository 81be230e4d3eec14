// The end-of-step reduction (physics/DistributedStep.hpp): the step's sums over all ranks of
// MPI_COMM_WORLD and the next time step (the smallest, ties to the lowest rank, the point
// named on its rank only), in one Allreduce. Registered on 2 ranks (parallel_two_ranks) and
// on 1.
#include <gtest/gtest.h>
#include <mpi.h>

#include <vector>

#include "argine/physics/DistributedStep.hpp"

namespace argine {
namespace {

struct World {
  int rank = 0, size = 1;
  World() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
  }
};

/// Rank r's candidate: step `step`, criterion Mieremet, point 10 + r with id 100 + r.
TimeStepCandidate candidateOf(int rank, Real step, bool ready = true) {
  TimeStepCandidate next;
  next.choice.time_step = step;
  next.choice.critical_step = 2 * step;
  next.choice.automatic = true;
  next.choice.governing = CriterionKind::Mieremet;
  next.choice.point = 10 + rank;
  next.choice.point_id = 100 + rank;
  next.choice.position[0] = rank + 0.25;
  next.choice.position[1] = -rank - 0.5;
  next.ready = ready;
  return next;
}

TEST(EndOfStepReduction, SumsOverTheRanksAndTheSmallestStepWithItsPointInOneCall) {
  const World world;
  EndOfStepSums sums;
  sums.kinetic_solid = world.rank + 1.0;
  sums.lost = 1;
  sums.emigrants = world.rank;
  std::vector<Real> also{0.5, static_cast<Real>(world.rank)}, scratch;
  // the last rank offers the smallest step
  TimeStepCandidate next = candidateOf(world.rank, world.rank == world.size - 1 ? 1e-4 : 3e-4);
  sumOverRanks(MPI_COMM_WORLD, sums, also, &next, scratch);
  const int n = world.size, last = n - 1;
  EXPECT_EQ(sums.kinetic_solid, n * (n + 1) / 2.0);
  EXPECT_EQ(sums.lost, n);
  EXPECT_EQ(sums.emigrants, n * (n - 1) / 2.0);
  EXPECT_EQ(also, (std::vector<Real>{0.5 * n, n * (n - 1) / 2.0}));
  EXPECT_TRUE(next.ready);
  EXPECT_EQ(next.choice.time_step, 1e-4);
  EXPECT_EQ(next.choice.critical_step, 2e-4);
  EXPECT_TRUE(next.choice.automatic);
  EXPECT_EQ(next.choice.governing, CriterionKind::Mieremet);
  EXPECT_EQ(next.choice.point_id, 100 + last);
  EXPECT_EQ(next.choice.point, world.rank == last ? 10 + last : -1);
  EXPECT_EQ(next.choice.position[0], last + 0.25);
  EXPECT_EQ(next.choice.position[1], -last - 0.5);
}

TEST(EndOfStepReduction, EqualStepsGoToTheLowestRankAndOneUnreadyRankMakesAllUnready) {
  const World world;
  EndOfStepSums sums;
  std::vector<Real> also, scratch;
  TimeStepCandidate next = candidateOf(world.rank, 2e-4);
  sumOverRanks(MPI_COMM_WORLD, sums, also, &next, scratch);
  EXPECT_EQ(next.choice.point_id, 100);
  EXPECT_EQ(next.choice.point, world.rank == 0 ? 10 : -1);
  EXPECT_TRUE(next.ready);
  // as globalTimeStep chooses
  const TimeStepChoice gathered =
      globalTimeStep(MPI_COMM_WORLD, candidateOf(world.rank, 2e-4).choice);
  EXPECT_EQ(gathered.point_id, next.choice.point_id);

  next = candidateOf(world.rank, 1e-4, world.rank != world.size - 1);
  sumOverRanks(MPI_COMM_WORLD, sums, also, &next, scratch);
  EXPECT_FALSE(next.ready);
  // without a candidate: the sums alone
  sums = EndOfStepSums{};
  sums.liquid_mass = 2;
  sumOverRanks(MPI_COMM_WORLD, sums, also, nullptr, scratch);
  EXPECT_EQ(sums.liquid_mass, 2.0 * world.size);
}

}  // namespace
}  // namespace argine
