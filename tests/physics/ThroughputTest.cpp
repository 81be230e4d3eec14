// [2Phase][Explicit][benchmark] Material-point updates per second of the two-phase step on a
// 2D scene with > 1e5 points. Printed, not asserted (the machine is shared).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>

#include "Harness.hpp"

namespace argine {
namespace {

/// Runs `steps` steps (automatic dt, criteria every `update_interval` steps) and prints the
/// rate by wall time and by this process's CPU time (what an idle core would give when other
/// jobs share the machine).
/// `empty_factor` = 1: 160 x 160 quads of 0.1 m, 4 points each = 102400 points, saturated,
/// gravity, fixed base, rollers, impermeable sides and base. `empty_factor` = 2: the same
/// body in the lower-left quarter of a 320 x 320 mesh (3/4 of the elements empty).
void measure(int update_interval, int steps, int empty_factor = 1) {
  const int n = 160 * empty_factor;
  const Mesh mesh = test::rectangleMesh(n, n, 0.1 * n, 0.1 * n, ElementType::Quad4);
  MaterialPoints points =
      test::seedUniform(mesh, 0, [n](int e) { return e % n < 160 && e / n < 160; });
  std::vector<MaterialSpec> materials{
      test::elasticMaterial("sand", PhaseModel::Saturated, 1e7, 0.3, 0.4, 1e-3)};
  initialisePointState(materials, points);
  ExplicitTwoPhaseSolver solver(mesh, points, materials);
  StageSpec stage =
      test::makeStage("bench", SolverKind::Explicit, 9.81, 0.05, test::columnBoundaries());
  stage.time_step.update_interval = update_interval;
  solver.beginStage(stage);
  for (int k = 0; k < 2; ++k) solver.step(solver.chooseTimeStep().time_step);  // warm-up
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  for (int k = 0; k < steps; ++k) solver.step(solver.chooseTimeStep().time_step);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const double updates = static_cast<double>(points.count) * steps;
  std::printf(
      "[ throughput ] two-phase explicit step, %d points in %d elements, %d steps, "
      "criteria every %d step(s): wall %.3f s = %.3g point-updates/s; CPU %.3f s = "
      "%.3g per core\n",
      points.count, mesh.numElements(), steps, update_interval, seconds, updates / seconds,
      cpu_seconds, updates / cpu_seconds);
  EXPECT_EQ(solver.diagnostics().lost_points, 0);
  EXPECT_GT(solver.diagnostics().kinetic_energy_solid, 0.0);  // it did move (gravity)
}

TEST(ExplicitTwoPhaseThroughput, SaturatedSceneWithOver1e5Points) {
  const char* requested = std::getenv("ARGINE_BENCH_STEPS");  // longer runs for profiling
  const int steps = requested ? std::atoi(requested) : 10;
  measure(1, steps);
  measure(10, steps);
  measure(10, steps, 2);  // empty elements must cost (almost) nothing
}

}  // namespace
}  // namespace argine
