// [Seepage] The adaptive step of the implicit path (P10, SeepageStepControl.hpp): the time
// error estimate by hand and on a quadratic history (where it is exact), the factors, and a
// wetting column whose step now grows past `Initial Step` towards `Maximum Step` (with the
// old rule, growth only after <= 4 Picard iterations, it stayed at the initial step for the
// first minutes) while the column's answer stays within 1 % of its pressure range of a run
// with small fixed steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "SeepageScenes.hpp"
#include "argine/input/Deck.hpp"
#include "argine/seepage/SeepageStepControl.hpp"

namespace argine {
namespace {

TEST(SeepageStepControl, TimeErrorByHand) {
  // rates 4/2 = 2 and 1/1 = 1 Pa/s at the first node, 0 at the second: e = 2^2/3 x 1.
  EXPECT_DOUBLE_EQ(seepageTimeError(2, {4, 0}, 1, {1, 0}), 4.0 / 3.0);
  // The largest change of rate counts, whatever its sign.
  EXPECT_DOUBLE_EQ(seepageTimeError(1, {0, -3}, 1, {0, 1}), 0.5 * 4);
}

TEST(SeepageStepControl, TimeErrorIsBackwardEulersLocalErrorOnAQuadraticHistory) {
  // p(t) = a t^2: backward Euler's local error over a step dt is dt^2 p''/2 = a dt^2.
  const Real a = 3, t0 = 1, dt_prev = 2, dt = 0.5;
  const auto p = [&](Real t) { return a * t * t; };
  const Real previous = p(t0 + dt_prev) - p(t0);
  const Real increment = p(t0 + dt_prev + dt) - p(t0 + dt_prev);
  EXPECT_NEAR(seepageTimeError(dt, {increment}, dt_prev, {previous}), a * dt * dt, 1e-14);
}

TEST(SeepageStepControl, TheStepGrowsWhenAccurateWhateverTheModerateIterationCount) {
  ImplicitSeepageSpec settings;  // step error 100 Pa, dS 0.05, 30 iterations, no maximum
  SeepageStepOutcome outcome{10, 5, 0.001, 25};
  // 5 iterations (the old rule grew only at <= 4): e = 25 Pa allows 0.9 sqrt(4) = 1.8.
  EXPECT_DOUBLE_EQ(nextSeepageStep(outcome, settings), 18);
  outcome.time_error = -1;  // no estimate yet (the stage's first step): doubles
  EXPECT_DOUBLE_EQ(nextSeepageStep(outcome, settings), 20);
  outcome.time_error = 400;  // 4 x the target: 0.9 x 0.5
  EXPECT_DOUBLE_EQ(nextSeepageStep(outcome, settings), 4.5);
  outcome.time_error = 1e6;  // clamped at 0.3
  EXPECT_DOUBLE_EQ(nextSeepageStep(outcome, settings), 3);
  outcome.time_error = 25;
  outcome.max_saturation_change = 0.1;  // twice the target change
  EXPECT_DOUBLE_EQ(nextSeepageStep(outcome, settings), 5);
  outcome.max_saturation_change = 0.001;
  outcome.iterations = 10;  // slow convergence shrinks it
  EXPECT_DOUBLE_EQ(nextSeepageStep(outcome, settings), 6);
  settings.max_picard_iterations = 12;
  outcome.iterations = 6;  // half the allowed iterations: no growth
  EXPECT_DOUBLE_EQ(nextSeepageStep(outcome, settings), 10);
  settings.max_step = 12;
  outcome.iterations = 2;
  EXPECT_DOUBLE_EQ(nextSeepageStep(outcome, settings), 12);
}

/// A V3-like wetting column (20 rows of 0.05 m, suction 2 kPa, 5e-5 m/s on top) for 600 s.
struct WettingRun {
  test::SeepageColumn column;
  ImplicitSeepageSolver solver;
  explicit WettingRun(const ImplicitSeepageSpec& spec)
      : column(20, 0.05, 1.0, test::infiltrationSoil(), -2000),
        solver(column.mesh, column.points, column.materials) {
    solver.setSettings(spec);
    solver.setGravity(9.81);
    solver.setBoundaryConditions(test::topInflow(column.mesh, 5e-5));
    solver.advanceTo(600);
  }
};

TEST(SeepageStepControl, AWettingColumnTakesLargerStepsAndKeepsItsAnswer) {
  ImplicitSeepageSpec adaptive;
  adaptive.initial_step = 1;
  adaptive.max_step = 60;
  adaptive.pressure_tolerance = 10;  // the levee_flood_72h tolerances (about 5 Picard per step)
  adaptive.mass_tolerance = 1e-2;
  const WettingRun run(adaptive);
  ImplicitSeepageSpec fixed = adaptive;
  fixed.adaptive = false;
  fixed.initial_step = 0.5;
  const WettingRun reference(fixed);
  const std::vector<Real> p = run.solver.nodalPressure(), q = reference.solver.nodalPressure();
  Real range = 0, largest = 0, low = q[0], high = q[0];
  for (std::size_t i = 0; i < p.size(); ++i) {
    low = std::min(low, q[i]);
    high = std::max(high, q[i]);
    largest = std::max(largest, std::fabs(p[i] - q[i]));
  }
  range = high - low;
  const long long steps = run.solver.totals().steps;
  std::printf(
      "adaptive: %lld steps (%lld Picard); fixed 0.5 s: %lld steps; max |dp| %.3g Pa of "
      "a %.4g Pa range (%.3g %%)\n",
      steps, run.solver.totals().picard_iterations, reference.solver.totals().steps, largest, range,
      100 * largest / range);
  EXPECT_LT(steps, 150);  // 600 steps at the initial 1 s; the old rule took about 600
  EXPECT_LT(largest, 0.01 * range);
}

}  // namespace
}  // namespace argine
