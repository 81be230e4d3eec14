// [2Phase][Explicit] The explicit two-phase step against hand-computed states.
#include <gtest/gtest.h>

#include <cmath>

#include "Harness.hpp"
#include "argine/core/Error.hpp"
#include "argine/materials/LinearElastic.hpp"

namespace argine {
namespace {

using test::hostCopy;
using test::makeStage;
using test::runUntil;

TEST(ExplicitTwoPhase, RigidTranslationOfAFreeBodyKeepsStressesZero) {
  // A saturated 1 m x 1 m body in the middle of a 3 m x 3 m grid moves at v0 = (0.3, -0.2)
  // m/s, both phases, no gravity, no boundary conditions. A uniform nodal velocity has zero
  // gradient, so no strain, stress or pressure may appear, the velocity stays v0 and every
  // point moves by v0 t (0.15, -0.1 m in 0.5 s), across element boundaries (0.5 m elements,
  // points 0.125 m from their edges).
  const Mesh mesh = test::rectangleMesh(6, 6, 3.0, 3.0, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh, 0, [](int e) {
    const int i = e % 6, j = e / 6;
    return i >= 2 && i < 4 && j >= 2 && j < 4;
  });
  std::vector<MaterialSpec> materials{
      test::elasticMaterial("sand", PhaseModel::Saturated, 1e7, 0.3, 0.4)};
  initialisePointState(materials, points);
  Kokkos::deep_copy(Kokkos::subview(points.velocity_solid, Kokkos::ALL, 0), 0.3);
  Kokkos::deep_copy(Kokkos::subview(points.velocity_solid, Kokkos::ALL, 1), -0.2);
  Kokkos::deep_copy(Kokkos::subview(points.velocity_liquid, Kokkos::ALL, 0), 0.3);
  Kokkos::deep_copy(Kokkos::subview(points.velocity_liquid, Kokkos::ALL, 1), -0.2);
  const auto x0 = hostCopy(points.position);

  ExplicitTwoPhaseSolver solver(mesh, points, materials);
  solver.beginStage(makeStage("move", SolverKind::Explicit, 0.0, 0.0, {}));
  runUntil(solver, 0.5);

  const auto x = hostCopy(points.position);
  const auto vs = hostCopy(points.velocity_solid), vl = hostCopy(points.velocity_liquid);
  const auto stress = hostCopy(points.stress_effective);
  const auto pressure = hostCopy(points.pressure_liquid);
  for (int p = 0; p < points.count; ++p) {
    // ~3300 steps of dt v0 added to x: round-off accumulates to ~1e-12 m
    EXPECT_NEAR(x(p, 0), x0(p, 0) + 0.15, 1e-10);
    EXPECT_NEAR(x(p, 1), x0(p, 1) - 0.1, 1e-10);
    EXPECT_NEAR(vs(p, 0), 0.3, 1e-12);
    EXPECT_NEAR(vl(p, 1), -0.2, 1e-12);
    for (int c = 0; c < kStressComponents; ++c) EXPECT_NEAR(stress(p, c), 0.0, 1e-6);
    EXPECT_NEAR(pressure(p), 0.0, 1e-4);
  }
  EXPECT_EQ(solver.diagnostics().lost_points, 0);
  // Kinetic energy 1/2 (M_S + M_L) |v0|^2 with M = (1-n) 2650 + n 1000 kg/m^3 over 1 m^2.
  const Real mass = 0.6 * 2650 + 0.4 * 1000;
  EXPECT_NEAR(
      solver.diagnostics().kinetic_energy_solid + solver.diagnostics().kinetic_energy_liquid,
      0.5 * mass * (0.09 + 0.04), 1e-6 * mass);
}

TEST(ExplicitTwoPhase, DryColumnUnderGravityReachesGeostaticStress) {
  // Dry column H = 1 m, 10 elements, fixed base, rollers; rho_dry = (1 - 0.4) 2650 = 1590.
  // Equilibrium: sigma'_yy = -rho_dry g (H - y); with rollers and elasticity
  // sigma'_xx = nu / (1 - nu) sigma'_yy. Local damping brings it to rest.
  const MaterialSpec sand = test::elasticMaterial("sand", PhaseModel::Dry, 1e6, 0.3, 0.4);
  test::Column column(10, 0.1, 1.0, sand);
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  solver.beginStage(makeStage("gravity", SolverKind::QuasiStatic, 9.81, 0.3,
                              {test::solidFixity("base", "bottom", true, true),
                               test::solidFixity("sides", "left", true, false),
                               test::solidFixity("sides2", "right", true, false)},
                              {CriterionKind::CflDry}));
  runUntil(solver, 3.0);

  const Real rho_g_h = 1590 * 9.81 * 1.0;
  const auto y0 = hostCopy(column.points.initial_position);
  const auto stress = hostCopy(column.points.stress_effective);
  const Real k0 = 0.3 / 0.7;
  for (int p = 0; p < column.points.count; ++p) {
    // Points of an element share the element's (constant) strain, so compare with the exact
    // stress at the element's mid-height (elements are 0.1 m tall).
    const Real y_mid = (std::floor(y0(p, 1) / 0.1) + 0.5) * 0.1;
    const Real exact = -1590 * 9.81 * (1.0 - y_mid);
    EXPECT_NEAR(stress(p, YY), exact, 0.02 * rho_g_h) << "point at y = " << y0(p, 1);
    EXPECT_NEAR(stress(p, XX), k0 * exact, 0.02 * rho_g_h);
    // And with the point's own height, within a few % of rho g H.
    EXPECT_NEAR(stress(p, YY), -1590 * 9.81 * (1.0 - y0(p, 1)), 0.04 * rho_g_h);
  }
  // At rest: kinetic energy a tiny fraction of the potential energy scale m g H = 1560 J/m.
  EXPECT_LT(solver.diagnostics().kinetic_energy_solid, 1e-8 * 1590 * 0.1 * 9.81 * 1.0);
  EXPECT_EQ(solver.diagnostics().liquid_mass, 0.0);
}

TEST(ExplicitTwoPhase, AutomaticStepIsSafetyTimesDryCflOfTheSmallestElement) {
  // Dry column of 0.1 m x 0.1 m elements: L_i = 0.1 m; E_c = E (1-nu)/((1+nu)(1-2nu)) =
  // 1e6 * 0.7 / (1.3 * 0.4) = 1.34615e6 Pa; rho_dry = 1590 kg/m^3;
  // dt_c = L_i sqrt(rho / E_c) = 0.1 * sqrt(1590 / 1.34615e6) = 3.43675e-3 s.
  const MaterialSpec sand = test::elasticMaterial("sand", PhaseModel::Dry, 1e6, 0.3, 0.4);
  test::Column column(10, 0.1, 1.0, sand);
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  // A saturated-only criterion is ignored for dry points: they use the dry CFL.
  solver.beginStage(
      makeStage("s", SolverKind::Explicit, 9.81, 0.0, {}, {CriterionKind::CflUndrained}, 0, 0.8));
  const TimeStepChoice& choice = solver.chooseTimeStep();
  EXPECT_TRUE(choice.automatic);
  EXPECT_EQ(choice.governing, CriterionKind::CflDry);
  EXPECT_NEAR(choice.critical_step, 0.1 * std::sqrt(1590 / 1.346153846e6), 1e-9);
  EXPECT_NEAR(choice.time_step, 0.8 * choice.critical_step, 1e-15);
  ASSERT_GE(choice.point, 0);
  ASSERT_LT(choice.point, column.points.count);

  // Saturated: the undrained CFL with rho_sat = 0.6*2650 + 0.4*1000 = 1990 and
  // E_c + K_L/n = 1.34615e6 + 2.2e9/0.4: dt = 0.1 sqrt(1990 / 5.50135e9) = 6.0145e-5 s.
  const MaterialSpec wet = test::elasticMaterial("wet", PhaseModel::Saturated, 1e6, 0.3, 0.4);
  test::Column wet_column(10, 0.1, 1.0, wet);
  ExplicitTwoPhaseSolver wet_solver(wet_column.mesh, wet_column.points, wet_column.materials);
  wet_solver.beginStage(
      makeStage("s", SolverKind::Explicit, 9.81, 0.0, {}, {CriterionKind::CflUndrained}, 0, 1.0));
  // rho_L at p = 0 is 1000 exactly (4.13).
  EXPECT_NEAR(wet_solver.chooseTimeStep().critical_step,
              0.1 * std::sqrt(1990 / (1.346153846e6 + 2.2e9 / 0.4)), 1e-10);
  EXPECT_EQ(wet_solver.chooseTimeStep().governing, CriterionKind::CflUndrained);
}

TEST(ExplicitTwoPhase, UndrainedLoadGivesSkemptonPorePressure) {
  // Saturated column closed on all sides (impermeable top too), q = 10 kPa on top, no
  // gravity. Undrained 1D compression: the load splits between skeleton and liquid with
  //   p0 = q m_v / (m_v + n / K_L)   (Terzaghi's B; thesis 2.19 with eps_vol = -m_v sigma'),
  // m_v = 1 / E_c. E = 1e7, nu = 0 -> E_c = 1e7, m_v = 1e-7 1/Pa; n = 0.4, K_L = 2e7 Pa:
  //   p0 = 1e4 * 1e-7 / (1e-7 + 2e-8) = 8333.33 Pa, sigma'_yy = -(q - p0) = -1666.67 Pa.
  // (k only sets how fast the closed column's internal flow settles; 1e-2 m/s keeps the
  // drag from limiting the step.)
  MaterialSpec clay =
      test::elasticMaterial("clay", PhaseModel::Saturated, 1e7, 0.0, 0.4, 1e-2, 2e7);
  test::Column column(5, 0.2, 1.0, clay);
  auto boundaries = test::columnBoundaries();
  boundaries.push_back(test::impermeable("top seal", "top"));
  boundaries.push_back(test::traction("load", "top", 0.0, -1e4));
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  solver.beginStage(makeStage("load", SolverKind::QuasiStatic, 0.0, 0.3, boundaries));
  const Real liquid_mass_0 = [&] {
    const auto m = hostCopy(column.points.mass_liquid);
    Real sum = 0;
    for (int p = 0; p < column.points.count; ++p) sum += m(p);
    return sum;
  }();
  runUntil(solver, 0.3);

  const auto pressure = hostCopy(column.points.pressure_liquid);
  const auto stress = hostCopy(column.points.stress_effective);
  const Real p0 = 1e4 * 1e-7 / (1e-7 + 2e-8);
  for (int p = 0; p < column.points.count; ++p) {
    EXPECT_NEAR(pressure(p), p0, 0.01 * p0);
    EXPECT_NEAR(stress(p, YY), -(1e4 - p0), 0.01 * 1e4);
  }
  // Closed column: no liquid leaves. The point masses change only by the relative flux, whose
  // divergence is evaluated at the (slightly moved) points, so the total is kept to the
  // quadrature error of that divergence, not exactly (see ClosedColumnKeepsLiquidMass).
  EXPECT_NEAR(solver.diagnostics().liquid_mass, liquid_mass_0, 1e-7 * liquid_mass_0);
}

TEST(ExplicitTwoPhase, NonFiniteStateStopsTheRunNamingThePoint) {
  const MaterialSpec sand = test::elasticMaterial("sand", PhaseModel::Saturated, 1e6, 0.3, 0.4);
  test::Column column(4, 0.1, 0.4, sand);
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  solver.beginStage(makeStage("s", SolverKind::Explicit, 9.81, 0.0, test::columnBoundaries()));
  solver.step(solver.chooseTimeStep().time_step);
  // Poison the liquid pressure of point 0 (id 0): the next step must stop and name it.
  Kokkos::deep_copy(Kokkos::subview(column.points.pressure_liquid, std::make_pair(0, 1)),
                    std::nan(""));
  const std::string message =
      test::runErrorMessage([&] { solver.step(solver.chooseTimeStep().time_step); });
  EXPECT_NE(message.find("unstable at t = "), std::string::npos) << message;
  EXPECT_NE(message.find("step 2"), std::string::npos) << message;
  EXPECT_NE(message.find("point 0 (index 0) at ("), std::string::npos) << message;
  EXPECT_NE(message.find("nan"), std::string::npos) << message;
}

TEST(ExplicitTwoPhase, TooLargeStepBlowsUpIntoRunError) {
  // Ten times the undrained CFL step: the explicit scheme diverges, and the run must stop
  // with a RunError (kinetic energy bound or non-finite values), not run on silently.
  const MaterialSpec sand = test::elasticMaterial("sand", PhaseModel::Saturated, 1e7, 0.3, 0.4);
  test::Column column(10, 0.1, 1.0, sand);
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  solver.beginStage(
      makeStage("s", SolverKind::Explicit, 9.81, 0.0, test::columnBoundaries(), {}, 6e-4));
  EXPECT_THROW(runUntil(solver, 10.0), RunError);
}

TEST(ExplicitTwoPhase, LocalDampingOpposesTheVelocityWithAFractionOfTheForce) {
  // f_damp = -alpha |f| sign(v): alpha = 0.2, |f| = 10 N.
  EXPECT_DOUBLE_EQ(localDampingForce(0.2, -10.0, 3.0), -2.0);
  EXPECT_DOUBLE_EQ(localDampingForce(0.2, -10.0, -3.0), 2.0);
  EXPECT_DOUBLE_EQ(localDampingForce(0.2, 10.0, 0.0), 0.0);  // at rest: nothing to oppose
}

TEST(ExplicitTwoPhase, MassScalingLengthensTheStepAndDampingSlowsTheFall) {
  // Mass scaling f multiplies the inertia: the dry CFL step grows by sqrt(f) = 2 for f = 4.
  const MaterialSpec sand = test::elasticMaterial("sand", PhaseModel::Dry, 1e6, 0.3, 0.4);
  test::Column column(10, 0.1, 1.0, sand);
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  StageSpec stage = makeStage("s", SolverKind::Explicit, 9.81, 0.0, {}, {CriterionKind::CflDry});
  solver.beginStage(stage);
  const Real plain = solver.chooseTimeStep().critical_step;
  stage.mass_scaling = 4;
  solver.beginStage(stage);
  EXPECT_NEAR(solver.chooseTimeStep().critical_step, 2 * plain, 1e-12);
  // A free-falling body (no supports): with mass scaling f the acceleration is g / f, so
  // after t the velocity is -g t / f (gravity loads the unscaled mass).
  solver.step(1e-3);
  const auto v = hostCopy(column.points.velocity_solid);
  for (int p = 0; p < column.points.count; ++p) EXPECT_NEAR(v(p, 1), -9.81e-3 / 4, 1e-12);
}

TEST(ExplicitTwoPhase, ImplicitSeepageStageIsRefused) {
  const MaterialSpec sand = test::elasticMaterial("sand", PhaseModel::Saturated, 1e6, 0.3, 0.4);
  test::Column column(2, 0.1, 0.2, sand);
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  StageSpec stage = makeStage("flood", SolverKind::ImplicitSeepage, 9.81, 0.0, {});
  try {
    solver.beginStage(stage);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Stages/flood/Solver");
  }
}

}  // namespace
}  // namespace argine
