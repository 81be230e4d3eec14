// The implicit seepage path's cheaper linear-algebra options give the same converged answer:
// the direct solver (Amesos2 KLU2) and the chord iteration (Reuse Matrix) against the default
// GMRES + RILUK with a fresh matrix every Picard iteration. The residual that Picard drives to
// zero is the same in all three, so the answers may differ only by the convergence tolerances.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "SeepageScenes.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {
namespace {

using test::SeepageColumn;

/// The V3-like column of ImplicitSeepageTest (20 rows of 0.05 m, initial suction 2 kPa) with
/// a ponding supply of 2e-4 m/s on top (above k_sat = 1e-4 m/s: the top saturates and the
/// switch acts), fixed steps of 5 s to t = 200 s.
std::vector<Real> infiltrate(const LinearSolverSpec& linear, bool reuse_matrix,
                             SeepageTotals* totals, Real* stored) {
  SeepageColumn column(20, 0.05, 1.0, test::infiltrationSoil(), -2000);
  ImplicitSeepageSolver solver(column.mesh, column.points, column.materials);
  ImplicitSeepageSpec spec;
  spec.initial_step = 5;
  spec.adaptive = false;
  spec.reuse_matrix = reuse_matrix;
  spec.linear = linear;
  solver.setSettings(spec);
  solver.setGravity(9.81);
  solver.setBoundaryConditions(test::topInflow(column.mesh, 2e-4));
  const Real initial = solver.liquidMass();
  solver.advanceTo(200);
  *totals = solver.totals();
  *stored = solver.liquidMass() - initial;
  return solver.nodalPressure();
}

TEST(SeepageLinearSolverOptions, DirectAndChordIterationGiveTheKrylovAnswer) {
  SeepageTotals krylov_totals, direct_totals, chord_totals;
  Real krylov_stored = 0, direct_stored = 0, chord_stored = 0;
  LinearSolverSpec direct;
  direct.solver = "DIRECT";
  const std::vector<Real> krylov =
      infiltrate(LinearSolverSpec{}, false, &krylov_totals, &krylov_stored);
  const std::vector<Real> exact = infiltrate(direct, false, &direct_totals, &direct_stored);
  const std::vector<Real> chord = infiltrate(direct, true, &chord_totals, &chord_stored);
  Real direct_diff = 0, chord_diff = 0, range = 0;
  for (std::size_t i = 0; i < krylov.size(); ++i) {
    direct_diff = std::max(direct_diff, std::fabs(exact[i] - krylov[i]));
    chord_diff = std::max(chord_diff, std::fabs(chord[i] - krylov[i]));
    range = std::max(range, std::fabs(krylov[i]));
  }
  std::printf(
      "Picard iterations: GMRES %lld, direct %lld, direct + reuse %lld; max |dp| %.3g / "
      "%.3g Pa of %.4g Pa\n",
      krylov_totals.picard_iterations, direct_totals.picard_iterations,
      chord_totals.picard_iterations, direct_diff, chord_diff, range);
  ASSERT_GT(range, 1000.0);  // the front moved: a real non-linear problem
  // Picard stops when its last update is below 1e-6 Pa (the default pressure tolerance);
  // linear convergence of the chord iteration leaves at most a few such updates unresolved.
  EXPECT_LT(direct_diff, 1e-5);
  EXPECT_LT(chord_diff, 1e-5);
  // Each run conserves mass to the mass tolerance (1e-12 of the step's terms).
  EXPECT_NEAR(direct_totals.inflow, direct_stored, 1e-9 * std::fabs(direct_stored));
  EXPECT_NEAR(chord_totals.inflow, chord_stored, 1e-9 * std::fabs(chord_stored));
  // The chord iteration needs at least as many iterations as full Picard.
  EXPECT_GE(chord_totals.picard_iterations, direct_totals.picard_iterations);
}

}  // namespace
}  // namespace argine
