// The implicit seepage solver on columns: hydrostatic steadiness, 1D diffusion against the
// series solution with the observed order in dt, mass balance of the Picard scheme, the
// ponding and seepage-face switches, the hand-over to the points, 1 vs 2 ranks.
#include <gtest/gtest.h>
#include <mpi.h>

#include <Teuchos_DefaultMpiComm.hpp>
#include <cmath>
#include <cstdio>

#include "SeepageScenes.hpp"
#include "argine/physics/LiquidState.hpp"

namespace argine {
namespace {

using test::SeepageColumn;

constexpr Real kPi = 3.14159265358979323846;

ImplicitSeepageSpec fixedSteps(Real dt, Real theta) {
  ImplicitSeepageSpec spec;
  spec.theta = theta;
  spec.initial_step = dt;
  spec.adaptive = false;
  return spec;
}

Real maxAbs(const std::vector<Real>& v) {
  Real m = 0;
  for (const Real x : v)
    if (!std::isnan(x)) m = std::max(m, std::fabs(x));
  return m;
}

TEST(ImplicitSeepage, HydrostaticStateStaysSteady) {
  // Water table at y = 0.5 in a 1 m column: p = rho g (0.5 - y), suction above it (van
  // Genuchten). K_L = 1e15 Pa makes rho_L constant to 1e-11, so the linear nodal p is the
  // discrete equilibrium: w = 0 at every point, whatever k(S_L). A wrong gravity sign would
  // drive 2 rho g of gradient and move p by kPa.
  MaterialSpec soil = test::infiltrationSoil();
  soil.liquid.bulk_modulus = 1e15;
  SeepageColumn column(10, 0.1, 1.0, soil);
  ImplicitSeepageSolver solver(column.mesh, column.points, column.materials);
  solver.setSettings(fixedSteps(100.0, 1.0));
  solver.setGravity(9.81);
  const auto hydrostatic = [](Real, Real y) { return 1000 * 9.81 * (0.5 - y); };
  solver.setNodalPressure(hydrostatic);
  const std::vector<Real> before = solver.nodalPressure();
  for (int k = 0; k < 10; ++k) ASSERT_TRUE(solver.step(100.0).converged);
  const std::vector<Real> after = solver.nodalPressure();
  Real change = 0;
  for (std::size_t i = 0; i < after.size(); ++i)
    change = std::max(change, std::fabs(after[i] - before[i]));
  EXPECT_LT(change, 1e-6);  // Pa, after 1000 s
}

TEST(ImplicitSeepage, ProjectionFromPointsIsExactForLinearPressure) {
  SeepageColumn column(8, 0.2, 1.0, test::saturatedSoil(1e-5, 2.2e9), 0);
  {
    auto p =
        Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), column.points.pressure_liquid);
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), column.points.position);
    for (int i = 0; i < column.points.count; ++i) p(i) = 100 + 3 * x(i, 0) - 9810 * x(i, 1);
    Kokkos::deep_copy(column.points.pressure_liquid, p);
  }
  ImplicitSeepageSolver solver(column.mesh, column.points, column.materials);
  const std::vector<Real> nodal = solver.nodalPressure();
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), column.mesh.coordinates);
  for (int n = 0; n < column.mesh.numNodes(); ++n)
    EXPECT_NEAR(nodal[n], 100 + 3 * X(n, 0) - 9810 * X(n, 1), 1e-7);
}

/// p_L at every node after diffusing the first mode of the saturated column for T with
/// fixed steps dt. D = k K_L / (n rho0 g) = 1 m^2/s (no gravity), H = 1, top p = 0, base
/// impermeable: p = A cos(pi y / 2H) exp(-pi^2 D t / 4H^2) (the series solution's first term;
/// starting from it keeps Crank-Nicolson free of the stiff modes an incompatible initial
/// condition would excite).
std::vector<Real> diffuse(Real dt, Real theta, Real end, int rows) {
  const Real K = 2.2e9, n = 0.4, k = n * 1000 * 9.81 / K;  // D = 1
  SeepageColumn column(rows, 0.05, 1.0, test::saturatedSoil(k, K, n));
  ImplicitSeepageSolver solver(column.mesh, column.points, column.materials);
  solver.setSettings(fixedSteps(dt, theta));
  solver.setGravity(0);
  SeepageBoundaryConditions conditions;
  const std::vector<int> top = test::sideNodes(column.mesh, "top");
  conditions.addPressures(top, std::vector<Real>(top.size(), 0.0));
  solver.setBoundaryConditions(conditions);
  solver.setNodalPressure([](Real, Real y) { return 1000 * std::cos(kPi * y / 2); });
  solver.advanceTo(end);
  return solver.nodalPressure();
}

Real seriesSolution(Real y, Real t) {
  return 1000 * std::cos(kPi * y / 2) * std::exp(-kPi * kPi * t / 4);
}

void checkOrderInTime(Real theta, Real low, Real high) {
  const Real end = 0.2;
  const int rows = 40;
  const SeepageColumn geometry(rows, 0.05, 1.0, test::saturatedSoil(1e-6, 2.2e9));
  const auto X =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geometry.mesh.coordinates);
  std::vector<std::vector<Real>> runs;
  std::vector<Real> steps{end / 5, end / 10, end / 20, end / 40};
  for (const Real dt : steps) runs.push_back(diffuse(dt, theta, end, rows));
  // Error against the series solution, and successive differences (pure time error).
  std::vector<Real> analytic_error, difference;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    Real e = 0;
    for (std::size_t i = 0; i < runs[r].size(); ++i)
      e = std::max(e, std::fabs(runs[r][i] - seriesSolution(X(i, 1), end)));
    analytic_error.push_back(e / 1000);
    if (r > 0) {
      Real d = 0;
      for (std::size_t i = 0; i < runs[r].size(); ++i)
        d = std::max(d, std::fabs(runs[r][i] - runs[r - 1][i]));
      difference.push_back(d / 1000);
    }
  }
  for (std::size_t r = 0; r < runs.size(); ++r)
    std::printf("theta %.1f dt %.4f s: max error vs series %.3e (relative to 1 kPa)\n", theta,
                steps[r], analytic_error[r]);
  for (std::size_t r = 1; r < difference.size(); ++r) {
    const Real order = std::log2(difference[r - 1] / difference[r]);
    std::printf("theta %.1f observed order in dt %.3f\n", theta, order);
    EXPECT_GT(order, low);
    EXPECT_LT(order, high);
  }
  // Converges to the series solution (spatial error of 40 rows ~1e-5).
  EXPECT_LT(analytic_error.back(), theta == 1.0 ? 2e-2 : 1e-4);
  EXPECT_LT(analytic_error.back(), analytic_error.front());
}

TEST(ImplicitSeepage, BackwardEulerDiffusionIsFirstOrderInTime) {
  checkOrderInTime(1.0, 0.9, 1.1);
}

TEST(ImplicitSeepage, CrankNicolsonDiffusionIsSecondOrderInTime) {
  checkOrderInTime(0.5, 1.9, 2.1);
}

/// V3-like column (20 rows of 0.05 m), initial suction 2 kPa, top inflow q (m/s).
struct Infiltration {
  SeepageColumn column;
  ImplicitSeepageSolver solver;
  Infiltration(Real q, Real theta, Teuchos::RCP<const Teuchos::Comm<int>> comm = Teuchos::null)
      : column(20, 0.05, 1.0, test::infiltrationSoil(), -2000),
        solver(column.mesh, column.points, column.materials, comm) {
    ImplicitSeepageSpec spec;
    spec.theta = theta;
    spec.initial_step = 1;
    spec.max_step = 20;
    solver.setSettings(spec);
    solver.setGravity(9.81);
    solver.setBoundaryConditions(test::topInflow(column.mesh, q));
  }
};

TEST(ImplicitSeepage, PicardConservesMassWithPondingSwitch) {
  for (const Real theta : {1.0, 0.5}) {
    Infiltration run(1e-4, theta);
    const Real initial = run.solver.liquidMass();
    run.solver.advanceTo(600);
    const Real stored = run.solver.liquidMass() - initial;
    const SeepageTotals& totals = run.solver.totals();
    std::printf(
        "theta %.1f: %lld steps (%lld rejected), %lld Picard, stored %.9e kg/m, inflow "
        "%.9e kg/m, held top nodes %zu\n",
        theta, totals.steps, totals.rejected_steps, totals.picard_iterations, stored, totals.inflow,
        run.solver.heldNodes().size());
    EXPECT_NEAR(totals.storage_change, stored, 1e-10 * std::fabs(stored));
    EXPECT_NEAR(totals.inflow, stored, 1e-10 * std::fabs(stored));
    // The column takes at most the supply: 1e-4 m/s x 0.05 m x 1000 kg/m3 x 600 s = 3 kg/m.
    EXPECT_LE(stored, 3.0 * (1 + 1e-12));
    EXPECT_GT(stored, 0.5);
  }
}

TEST(ImplicitSeepage, PondingHoldsTheSaturatedSurfaceAtZeroPressure) {
  // A supply far above what the soil can take (10 x k_sat) saturates the top at once: the top
  // nodes are held at p = 0 and take less than the supply.
  Infiltration run(1e-3, 1.0);
  run.solver.advanceTo(100);
  const std::vector<int> held = run.solver.heldNodes();
  const std::vector<int> top = test::sideNodes(run.column.mesh, "top");
  ASSERT_EQ(held, top);
  const std::vector<Real> p = run.solver.nodalPressure();
  for (const int node : top) EXPECT_EQ(p[node], 0.0);
  EXPECT_LT(run.solver.totals().inflow, 1e-3 * 0.05 * 1000 * 100);
  EXPECT_LE(maxAbs(p), 1e4);
}

TEST(ImplicitSeepage, SeepageFaceOpensOnlyWhereWaterFlowsOut) {
  // Saturated column, base pressure prescribed; top a potential seepage face. Artesian base
  // (head above the top): the face holds p = 0 and water flows out. Low base (water table
  // at 0.5 m): the face stays closed, the column drains nowhere and p_top = -rho g 0.5.
  for (const bool artesian : {true, false}) {
    MaterialSpec soil = test::infiltrationSoil();
    SeepageColumn column(10, 0.1, 1.0, soil, 0);
    ImplicitSeepageSolver solver(column.mesh, column.points, column.materials);
    ImplicitSeepageSpec spec;
    spec.initial_step = 10;
    spec.max_step = 1e4;
    solver.setSettings(spec);
    solver.setGravity(9.81);
    const Real base = artesian ? 1000 * 9.81 * 1.5 : 1000 * 9.81 * 0.5;
    const std::vector<int> bottom = test::sideNodes(column.mesh, "bottom");
    const std::vector<int> top = test::sideNodes(column.mesh, "top");
    solver.setBoundaryConditions(test::prescribedBaseOpenTop(column.mesh, base));
    solver.setNodalPressure([&](Real, Real y) { return base - 1000 * 9.81 * y; });
    solver.advanceTo(2e4);
    const std::vector<Real> p = solver.nodalPressure();
    if (artesian) {
      EXPECT_EQ(solver.heldNodes(), top);
      for (const int node : top) EXPECT_EQ(p[node], 0.0);
      // Steady flow through a saturated column: p linear from base to 0 at the top.
      for (const int node : bottom) EXPECT_NEAR(p[node], base, 1e-9);
    } else {
      EXPECT_TRUE(solver.heldNodes().empty());
      for (const int node : top) EXPECT_NEAR(p[node], -1000 * 9.81 * 0.5, 1e-3);
    }
  }
}

TEST(ImplicitSeepage, HandOverGivesThePointsTheSolversLiquidMass) {
  Infiltration run(1e-4, 1.0);
  run.solver.advanceTo(200);
  run.solver.handOver();
  const auto mass = test::hostCopy(run.column.points.mass_liquid);
  const auto s = test::hostCopy(run.column.points.saturation);
  const auto p = test::hostCopy(run.column.points.pressure_liquid);
  Real total = 0;
  for (int i = 0; i < run.column.points.count; ++i) {
    total += mass(i);
    EXPECT_NEAR(s(i), saturation(run.column.materials[0].retention, suctionOfPressure(p(i))),
                1e-15);
  }
  EXPECT_NEAR(total, run.solver.liquidMass(), 1e-10 * total);
}

TEST(ImplicitSeepage, OneAndAllRanksGiveTheSameAnswer) {
  // On one rank this compares the solver with itself; `mpirun -np 2` (test
  // seepage_two_ranks) compares a 1-rank run (MPI_COMM_SELF) with a run over both ranks.
  auto self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  auto world = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_WORLD));
  Infiltration one(1e-4, 1.0, self), all(1e-4, 1.0, world);
  one.solver.advanceTo(300);
  all.solver.advanceTo(300);
  const auto [difference, range] =
      test::nodalDifference(one.solver.nodalPressure(), all.solver.nodalPressure());
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  std::printf("ranks %d: max |p_1 - p_all| = %.3e Pa (range %.3e Pa), steps %lld vs %lld\n", ranks,
              difference, range, one.solver.totals().steps, all.solver.totals().steps);
  EXPECT_EQ(one.solver.totals().steps, all.solver.totals().steps);
  EXPECT_LE(difference, 1e-10 * range);
}

}  // namespace
}  // namespace argine
