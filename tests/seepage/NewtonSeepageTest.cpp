// The Newton iteration of the implicit seepage path (ImplicitSeepageSolver.hpp,
// SeepagePointTerms.hpp N1-N6): its Jacobian against finite differences of the residual,
// the same answer as Picard in fewer iterations on a strongly non-linear infiltration,
// quadratic convergence, and the mass balance.
#include <gtest/gtest.h>
#include <mpi.h>

#include <Teuchos_DefaultMpiComm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "SeepageScenes.hpp"
#include "argine/core/Error.hpp"

namespace argine {
namespace {

using test::SeepageColumn;

/// Van Genuchten soil (p_ref 3 kPa, lambda 0.7, S_min 0.125) with the Mualem HCC (lambda*
/// 0.7) on S_e: k_r falls by orders of magnitude over a few kPa of suction, the strong
/// non-linearity Picard handles slowly.
MaterialSpec mualemSoil() {
  MaterialSpec soil = test::infiltrationSoil();
  soil.conductivity.model = ConductivityModel::Mualem;
  soil.conductivity.mualem_lambda = 0.7;
  soil.conductivity.use_effective_saturation = true;
  return soil;
}

ImplicitSeepageSpec settings(SeepageIteration iteration, Real dt, Real theta = 1) {
  ImplicitSeepageSpec spec;
  spec.iteration = iteration;
  spec.theta = theta;
  spec.initial_step = dt;
  spec.adaptive = false;
  spec.max_picard_iterations = 60;
  return spec;
}

TEST(NewtonSeepage, JacobianMatchesFiniteDifferencesOfTheResidual) {
  // 2 x 1 Quad4 column (6 unknowns, 8 points), gravity on, theta 1/2 (both time levels in
  // R). Old level and trial field unsaturated everywhere: suctions 1.2-4.8 kPa, above the
  // regularisation's s_reg = 30 Pa, where the storage slope is exact. Non-uniform in x and
  // y, so every point has a flux gradient in both directions.
  SeepageColumn column(2, 0.1, 0.2, mualemSoil(), -2000);
  ImplicitSeepageSolver solver(column.mesh, column.points, column.materials);
  const Real dt = 5;
  solver.setSettings(settings(SeepageIteration::Newton, dt, 0.5));
  solver.setGravity(9.81);
  solver.setNodalPressure([](Real x, Real y) { return -2000 - 4000 * y + 3000 * x; });
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), column.mesh.coordinates);
  std::vector<Real> trial(column.mesh.numNodes());
  for (int n = 0; n < column.mesh.numNodes(); ++n)
    trial[n] = -3000 - 9000 * X(n, 1) + 8000 * X(n, 0) * X(n, 1);
  // trial: -3000 at the base, -4800 ... -4640 at the top (x = 0 / 0.1), varying in x.
  const SeepageLinearisation at = solver.linearise(dt, trial);
  const int n = at.unknowns;
  ASSERT_EQ(n, 6);
  // Central differences with h = 1e-2 Pa: the truncation error h^2 R''' / 6 is ~1e-12
  // relative (R varies on the scale of p_ref = 3 kPa: R''' / R' ~ 1 / p_ref^2); round-off
  // eps |R| / h ~ 1e-11 relative (|R| / (J h) ~ |p - p_old| / h ~ 1e5).
  const Real h = 1e-2;
  Real worst = 0, worst_picard = 0;
  int compared = 0;
  solver.setSettings(settings(SeepageIteration::Picard, dt, 0.5));
  const SeepageLinearisation picard = solver.linearise(dt, trial);
  for (int b = 0; b < n; ++b) {
    std::vector<Real> plus = trial, minus = trial;
    plus[at.node[b]] += h;
    minus[at.node[b]] -= h;
    const std::vector<Real> r_plus = solver.linearise(dt, plus).residual;
    const std::vector<Real> r_minus = solver.linearise(dt, minus).residual;
    for (int a = 0; a < n; ++a) {
      const Real fd = (r_plus[a] - r_minus[a]) / (2 * h);
      const Real jacobian = at.matrix[a * n + b];
      // The base and top rows share no element: no coupling, both exactly 0.
      if (fd == 0) {
        EXPECT_EQ(jacobian, 0.0) << "entry (" << a << ", " << b << ")";
        continue;
      }
      ++compared;
      const Real error = std::fabs(jacobian - fd) / std::fabs(fd);
      worst = std::max(worst, error);
      worst_picard =
          std::max(worst_picard, std::fabs(picard.matrix[a * n + b] - fd) / std::fabs(fd));
      EXPECT_LT(error, 1e-5) << "entry (" << a << ", " << b << "): Jacobian " << jacobian
                             << ", finite differences " << fd;
    }
  }
  std::printf("Jacobian vs finite differences: worst relative error %.3e (Picard matrix %.3e)\n",
              worst, worst_picard);
  EXPECT_EQ(compared, 6 * 6 - 8);  // 2 x 2 pairs (base, top) x 2 orders uncoupled
  // The test can tell: Picard's matrix (no dK/dp) misses the bound by 10x or more.
  EXPECT_GT(worst_picard, 1e-4);
  // Non-symmetric.
  Real asymmetry = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      asymmetry = std::max(asymmetry, std::fabs(at.matrix[a * n + b] - at.matrix[b * n + a]));
  EXPECT_GT(asymmetry, 1e-3 * std::fabs(at.matrix[0]));
}

TEST(NewtonSeepage, CgIsRefusedForNewton) {
  SeepageColumn column(2, 0.1, 0.2, mualemSoil(), -2000);
  ImplicitSeepageSolver solver(column.mesh, column.points, column.materials);
  ImplicitSeepageSpec spec = settings(SeepageIteration::Newton, 1);
  spec.linear.solver = "CG";
  EXPECT_THROW(solver.setSettings(spec), InputError);
}

/// Dry Mualem column (20 rows of 0.05 m, initial suction 8 kPa, S_L ~ 0.3), top inflow q.
struct DryInfiltration {
  SeepageColumn column;
  ImplicitSeepageSolver solver;
  DryInfiltration(const ImplicitSeepageSpec& spec, Real q,
                  Teuchos::RCP<const Teuchos::Comm<int>> comm = Teuchos::null)
      : column(20, 0.05, 1.0, mualemSoil(), -8000),
        solver(column.mesh, column.points, column.materials, comm) {
    solver.setSettings(spec);
    solver.setGravity(9.81);
    solver.setBoundaryConditions(test::topInflow(column.mesh, q));
  }
};

TEST(NewtonSeepage, SameAnswerAsPicardInFewerIterationsConvergingQuadratically) {
  const Real dt = 10, q = 5e-5;
  const int steps = 12;
  DryInfiltration picard(settings(SeepageIteration::Picard, dt), q);
  DryInfiltration newton(settings(SeepageIteration::Newton, dt), q);
  const Real initial = newton.solver.liquidMass();
  int quadratic_checks = 0;
  for (int k = 0; k < steps; ++k) {
    const SeepageStepResult a = picard.solver.step(dt);
    const SeepageStepResult b = newton.solver.step(dt);
    ASSERT_TRUE(a.converged && b.converged) << "step " << k;
    // Quadratic convergence: r_{k+1} <= C r_k^2 / r_0 on the iterates before the residual
    // reaches round-off (1e-9 r_0: the free residual sums terms of size ~r_0 with eps 2e-16
    // over 42 unknowns and the step's storage terms ~1e3 r_0). C = 10 leaves room for the
    // constant of the Newton bound (|J^-1| |J'| / 2 in these units): a linear rate 0.5
    // (Picard-like) fails it as soon as r_k < 0.05 r_0.
    const std::vector<Real>& r = b.residual_norms;
    std::printf("step %2d: Picard %2d iterations, Newton %d:", k, a.picard_iterations,
                b.picard_iterations);
    for (const Real value : r) std::printf(" %.2e", value / r.front());
    std::printf("\n");
    for (std::size_t i = 1; i + 1 < r.size(); ++i) {
      if (r[i + 1] < 1e-9 * r.front() || r[i] > 1e-2 * r.front()) continue;
      ++quadratic_checks;
      EXPECT_LE(r[i + 1] / r.front(), 10 * std::pow(r[i] / r.front(), 2))
          << "step " << k << " iteration " << i;
    }
  }
  EXPECT_GT(quadratic_checks, 0);  // the check ran
  const SeepageTotals& tp = picard.solver.totals();
  const SeepageTotals& tn = newton.solver.totals();
  std::printf("%d steps of %.0f s: Picard %lld iterations, Newton %lld\n", steps, dt,
              tp.picard_iterations, tn.picard_iterations);
  EXPECT_LT(tn.picard_iterations, tp.picard_iterations);
  // Both stop when the last update moved no p_L by more than 1e-6 Pa; Picard's linear rate
  // (~0.5-0.9 here) leaves it up to ~1e-5 Pa from its fixed point per step, and the 12 steps
  // carry that on: 1e-3 Pa is 1e-7 of the 8 kPa range.
  const std::vector<Real> pa = picard.solver.nodalPressure(), pb = newton.solver.nodalPressure();
  Real difference = 0;
  for (std::size_t i = 0; i < pa.size(); ++i)
    difference = std::max(difference, std::fabs(pa[i] - pb[i]));
  std::printf("max |p_Picard - p_Newton| = %.3e Pa\n", difference);
  EXPECT_LT(difference, 1e-3);
  // Mass balance: the storage change equals the inflow (the supply; the top does not pond at
  // q = k_sat / 2) to round-off, as with Picard.
  for (const auto* run : {&picard, &newton}) {
    const Real stored = run->solver.liquidMass() - initial;
    const SeepageTotals& totals = run->solver.totals();
    std::printf("stored %.12e kg/m, inflow %.12e kg/m, supply %.12e kg/m\n", stored, totals.inflow,
                q * 0.05 * 1000 * steps * dt);
    EXPECT_NEAR(totals.inflow, stored, 1e-10 * stored);
    EXPECT_NEAR(totals.storage_change, stored, 1e-10 * stored);
  }
}

TEST(NewtonSeepage, DirectAndGmresSolveTheNonSymmetricSystemAlike) {
  // KLU2 (LU) and GMRES + RILUK on the non-symmetric Jacobian: the same iterates to the
  // linear tolerance 1e-12, so the same converged p after 5 steps within 1e-6 Pa (the
  // pressure tolerance) and the same iteration counts.
  ImplicitSeepageSpec gmres = settings(SeepageIteration::Newton, 10);
  ImplicitSeepageSpec direct = gmres;
  direct.linear.solver = "DIRECT";
  DryInfiltration a(gmres, 5e-5), b(direct, 5e-5);
  for (int k = 0; k < 5; ++k) {
    ASSERT_TRUE(a.solver.step(10).converged);
    ASSERT_TRUE(b.solver.step(10).converged);
  }
  EXPECT_EQ(a.solver.totals().picard_iterations, b.solver.totals().picard_iterations);
  const std::vector<Real> pa = a.solver.nodalPressure(), pb = b.solver.nodalPressure();
  for (std::size_t i = 0; i < pa.size(); ++i) EXPECT_NEAR(pa[i], pb[i], 1e-6);
}

TEST(NewtonSeepage, SeepageFaceOverPrescribedBaseAsPicard) {
  // Saturated Mualem column, base p prescribed (artesian: head 1.5 m over a 1 m column), top a
  // potential seepage face: both iterations hold the top at p = 0, keep the base value, and
  // reach the same steady p (linear from the base to 0) within 1e-6 Pa (the pressure
  // tolerance).
  std::vector<std::vector<Real>> answers;
  for (const SeepageIteration iteration : {SeepageIteration::Picard, SeepageIteration::Newton}) {
    SeepageColumn column(10, 0.1, 1.0, mualemSoil(), 0);
    ImplicitSeepageSolver solver(column.mesh, column.points, column.materials);
    ImplicitSeepageSpec spec = settings(iteration, 10);
    spec.adaptive = true;
    spec.max_step = 1e4;
    solver.setSettings(spec);
    solver.setGravity(9.81);
    const Real base = 1000 * 9.81 * 1.5;
    const std::vector<int> bottom = test::sideNodes(column.mesh, "bottom");
    const std::vector<int> top = test::sideNodes(column.mesh, "top");
    solver.setBoundaryConditions(test::prescribedBaseOpenTop(column.mesh, base));
    solver.setNodalPressure([&](Real, Real y) { return base - 1000 * 9.81 * y; });
    solver.advanceTo(2e4);
    EXPECT_EQ(solver.heldNodes(), top);
    const std::vector<Real> p = solver.nodalPressure();
    for (const int node : top) EXPECT_EQ(p[node], 0.0);
    for (const int node : bottom) EXPECT_EQ(p[node], base);
    answers.push_back(p);
  }
  for (std::size_t i = 0; i < answers[0].size(); ++i)
    EXPECT_NEAR(answers[0][i], answers[1][i], 1e-6);
}

TEST(NewtonSeepage, PondingAndReuseMatrixConserveMass) {
  // Supply 10 x k_sat: the top saturates and is held at p = 0 (the active set around the
  // Newton loop), with the chord variant (Reuse Matrix) too; adaptive steps.
  for (const bool reuse : {false, true}) {
    ImplicitSeepageSpec spec = settings(SeepageIteration::Newton, 1);
    spec.adaptive = true;
    spec.max_step = 20;
    spec.reuse_matrix = reuse;
    DryInfiltration run(spec, 1e-3);
    const Real initial = run.solver.liquidMass();
    run.solver.advanceTo(200);
    const Real stored = run.solver.liquidMass() - initial;
    const SeepageTotals& totals = run.solver.totals();
    std::printf("reuse %d: %lld steps (%lld rejected), %lld Newton iterations, stored %.9e\n",
                reuse, totals.steps, totals.rejected_steps, totals.picard_iterations, stored);
    EXPECT_EQ(run.solver.heldNodes(), test::sideNodes(run.column.mesh, "top"));
    EXPECT_NEAR(totals.inflow, stored, 1e-10 * stored);
    EXPECT_LT(totals.inflow, 1e-3 * 0.05 * 1000 * 200);
  }
}

TEST(NewtonSeepage, OneAndAllRanksGiveTheSameAnswer) {
  // Newton's non-symmetric Jacobian over the ranks' owned and ghost nodes (test
  // seepage_two_ranks runs this under `mpiexec -n 2`): the strongly non-linear dry Mualem
  // infiltration with adaptive steps, so a rank-dependent Jacobian entry would change the
  // iteration counts, the accepted steps and the pressures.
  auto self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  auto world = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_WORLD));
  ImplicitSeepageSpec spec = settings(SeepageIteration::Newton, 5);
  spec.adaptive = true;
  spec.max_step = 50;
  DryInfiltration one(spec, 5e-5, self), all(spec, 5e-5, world);
  one.solver.advanceTo(400);
  all.solver.advanceTo(400);
  const auto [difference, range] =
      test::nodalDifference(one.solver.nodalPressure(), all.solver.nodalPressure());
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const SeepageTotals &ta = one.solver.totals(), &tb = all.solver.totals();
  std::printf(
      "ranks %d: max |p_1 - p_all| = %.3e Pa (range %.3e Pa), steps %lld vs %lld, Newton "
      "iterations %lld vs %lld\n",
      ranks, difference, range, ta.steps, tb.steps, ta.picard_iterations, tb.picard_iterations);
  EXPECT_EQ(ta.steps, tb.steps);
  EXPECT_EQ(ta.picard_iterations, tb.picard_iterations);
  EXPECT_LE(difference, 1e-9 * range);
  EXPECT_NEAR(one.solver.liquidMass(), all.solver.liquidMass(), 1e-12 * one.solver.liquidMass());
}

}  // namespace
}  // namespace argine
