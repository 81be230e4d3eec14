// The explicit solver on all ranks of MPI_COMM_WORLD gives the one-rank answer to round-off:
// each rank first runs the scene alone (no decomposition), then all ranks run it together;
// the point states are gathered by id and compared (RanksHarness.hpp). Registered on 2 ranks
// (parallel_two_ranks) and on 1 (the plain test_parallel run).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <memory>
#include <string>

#include "../physics/Harness.hpp"
#include "RanksHarness.hpp"
#include "argine/parallel/RankDecomposition.hpp"

namespace argine {
namespace {

using test::copyOf;
using test::deckScene;
using test::expectSameAsOneRank;
using test::slumpingSlope;
using Scene = test::RanksScene;

// The relative differences allowed: round-off of sums taken in another order (partial
// sums per rank at the shared nodes), grown over the steps. Measured on 2 ranks (printed):
// 4e-10 (p_L of the seepage case, where the seepage-face switch amplifies), else <= 2e-11.
constexpr Real kRoundOff = 1e-9;

TEST(DistributedSolver, TerzaghiColumnMatchesOneRank) {  // V1
  expectSameAsOneRank(deckScene("verification/terzaghi/terzaghi.yaml", 0, 1, 300), kRoundOff);
}

TEST(DistributedSolver, LeveeSeepageMatchesOneRank) {  // V4 explicit: hydraulic conditions
  expectSameAsOneRank(deckScene("verification/levee_seepage/levee_seepage.yaml", 0, 1, 150),
                      kRoundOff);
}

TEST(DistributedSolver, LeveeDrawdownMatchesOneRank) {
  // The undamped 'drawdown' stage (Mohr-Coulomb, fixities, impermeable sides, total head
  // with a seepage face) from the K0 state. The damped 'settle' stage is not compared: local
  // damping -alpha |f| sign(v) turns a round-off difference of a nodal velocity near zero
  // into an O(alpha |f|) force difference (doc/parallel.md); so does sorting on one rank.
  expectSameAsOneRank(deckScene("inputs/levee_drawdown/levee_drawdown.yaml", 1, 1, 300), kRoundOff);
}

/// The slope on all ranks against one rank (to `tolerance`); points must have migrated.
void expectSlopeAsOneRank(const Scene& scene, Real tolerance) {
  test::expectSameAsOneRankWithMigration(scene, tolerance);
}

TEST(DistributedSolver, CollapsingSlopeMigratesPointsAndMatchesOneRank) {
  expectSlopeAsOneRank(slumpingSlope(0.0), kRoundOff);
}

TEST(DistributedSolver, SlopeSlidingOnFrictionalWallsMatchesOneRank) {
  // The same slope on frictional walls (doc/theory.md Sec. 5.6): an impermeable floor (mu =
  // 0.4) and a permeable left wall (mu = 0.2), a held corner where they meet. The contact is
  // per node on completed sums, so the ranks sharing the cut's nodes agree.
  Scene scene = slumpingSlope(0.0);
  BoundarySpec floor, wall;
  floor.name = "floor";
  floor.kind = wall.kind = BoundaryKind::FrictionalWall;
  floor.side_set = "bottom";
  floor.friction_coefficient = 0.4;
  wall.name = "wall";
  wall.side_set = "left";
  wall.friction_coefficient = 0.2;
  wall.wall_impermeable = false;
  scene.stages[0].boundaries = {floor, wall};
  expectSlopeAsOneRank(scene, kRoundOff);
}

/// The slope between the side walls of a channel (doc/theory.md Sec. 5.7): W = 4 m,
/// mu_w = 0.2 (narrower or rougher walls hold it: no point would cross the rank border), a
/// resistance summed over the ranks as the masses are.
Scene slopeBetweenSideWalls() {
  Scene scene = slumpingSlope(0.0);
  BoundarySpec walls;
  walls.name = "channel";
  walls.kind = BoundaryKind::SideWalls;
  walls.channel_width = 4.0;
  walls.friction_coefficient = 0.2;
  scene.stages[0].boundaries.push_back(walls);
  return scene;
}

TEST(DistributedSolver, SlopeBetweenSideWallsMatchesOneRank) {
  expectSlopeAsOneRank(slopeBetweenSideWalls(), kRoundOff);
}

TEST(DistributedSolver, SlopeBetweenSideWallsWithReproducibleSumsEqualsOneRankBitForBit) {
  Scene scene = slopeBetweenSideWalls();
  scene.reproducible_sums = true;
  expectSameAsOneRank(scene, 0.0);
}

// ---- Reproducible sums (transfer/CompensatedSum.hpp): the same scenes, and the damped
// stage, give the one-rank answer bit for bit.

TEST(DistributedSolver, DampedSettleStageWithReproducibleSumsEqualsOneRankBitForBit) {
  // levee_drawdown's 'settle' stage (local damping 0.7, quasi-static): with plain sums it
  // differs from one rank by ~1 % of the stress range after 300 steps (doc/parallel.md).
  Scene scene = deckScene("inputs/levee_drawdown/levee_drawdown.yaml", 0, 1, 300);
  scene.reproducible_sums = true;
  expectSameAsOneRank(scene, 0.0);
}

TEST(DistributedSolver, SeepageWithReproducibleSumsEqualsOneRankBitForBit) {
  // V4: hydraulic conditions (boundary gradients) and the head stabilisation's node sums.
  Scene scene = deckScene("verification/levee_seepage/levee_seepage.yaml", 0, 1, 150);
  scene.reproducible_sums = true;
  expectSameAsOneRank(scene, 0.0);
}

/// Each step's time step as chosen (dt, critical step, governing criterion), the time-step
/// control's carried state after the step, and the number of ranks that hold the governing
/// point (its index there naming that point's id); the materials stiffened 4x after
/// `change_at` steps.
struct TimeStepRecord {
  std::vector<Real> steps;   ///< dt, critical step, governing criterion, per step
  std::vector<int> carried;  ///< calls since the last evaluation, stale, per step
  std::vector<int> holders;  ///< ranks holding the governing point, per step
  int misnamed = 0;          ///< steps where the index held does not name the point id
};

TimeStepRecord recordTimeSteps(Scene scene, bool distributed, int change_at) {
  MaterialPoints copy = copyOf(scene.points);
  ExplicitTwoPhaseSolver solver(scene.mesh, copy, scene.materials);
  solver.setSortInterval(ExplicitTwoPhaseSolver::kRecommendedSortInterval);
  solver.setReproducibleSums(scene.reproducible_sums);
  std::unique_ptr<RankDecomposition> ranks;
  if (distributed) {
    ranks = std::make_unique<RankDecomposition>(MPI_COMM_WORLD, scene.mesh, scene.weights);
    solver.distribute(*ranks);
  }
  const MPI_Comm comm = distributed ? MPI_COMM_WORLD : MPI_COMM_SELF;
  TimeStepRecord record;
  solver.beginStage(scene.stages.at(0));
  for (int k = 0; k < scene.steps_per_stage; ++k) {
    if (k == change_at) {
      std::vector<MaterialSpec> stiffer = scene.materials;
      for (auto& material : stiffer) material.solid.youngs_modulus *= 4;
      solver.setMaterials(stiffer);
    }
    const TimeStepChoice choice = solver.chooseTimeStep();
    record.steps.insert(record.steps.end(), {choice.time_step, choice.critical_step,
                                             static_cast<Real>(choice.governing)});
    int holds = choice.point >= 0 ? 1 : 0;
    if (choice.point >= 0 && copy.id(choice.point) != choice.point_id) ++record.misnamed;
    MPI_Allreduce(MPI_IN_PLACE, &holds, 1, MPI_INT, MPI_SUM, comm);
    record.holders.push_back(holds);
    solver.step(choice.time_step);
    const TimeStepControl::State state = solver.resumeState().time_step;
    record.carried.insert(record.carried.end(), {state.calls_since_update, state.stale ? 1 : 0});
  }
  return record;
}

TEST(DistributedSolver, TimeStepsAreTheOneRankStepsAcrossMigrationSortingAndMaterialChanges) {
  // On several ranks the next step is chosen at the end of the last one, with its sums; it
  // must be the one-rank step (bit for bit with reproducible sums), follow its point when
  // points are sorted or migrate, be chosen again after setMaterials, and leave the
  // time-step control's carried state (what a checkpoint saves) as one rank leaves it.
  Scene scene = slumpingSlope(0.05);
  scene.reproducible_sums = true;
  scene.stages.at(0).time_step.update_interval = 3;
  const int change_at = 400;
  const TimeStepRecord one = recordTimeSteps(scene, false, change_at);
  const TimeStepRecord all = recordTimeSteps(scene, true, change_at);
  ASSERT_EQ(one.steps.size(), all.steps.size());
  for (std::size_t k = 0; k < one.steps.size(); ++k)
    ASSERT_EQ(one.steps[k], all.steps[k]) << "step " << k / 3 << ", value " << k % 3;
  EXPECT_EQ(one.carried, all.carried);
  // the stiffer material shortened the step at once (CFL ~ 1/sqrt(E)), update interval or not
  const TimeStepRecord unchanged = recordTimeSteps(scene, false, -1);
  EXPECT_LT(one.steps[3 * change_at], 0.8 * unchanged.steps[3 * change_at]);
  for (std::size_t k = 0; k < all.holders.size(); ++k)
    ASSERT_EQ(all.holders[k], 1) << "step " << k << ": ranks holding the governing point";
  EXPECT_EQ(all.misnamed, 0);
}

TEST(DistributedSolver, MigratingPointsWithReproducibleSumsEqualOneRankBitForBit) {
  // Points cross the rank border (migrated, appended in another order) and are sorted, in a
  // damped slump (the damping amplifies any difference): the compensated sums do not depend
  // on the order of the points either.
  Scene scene = slumpingSlope(0.05);
  scene.reproducible_sums = true;
  expectSlopeAsOneRank(scene, 0.0);
}

}  // namespace
}  // namespace argine
