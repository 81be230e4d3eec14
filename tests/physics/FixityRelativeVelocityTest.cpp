// [2Phase][Boundary] The liquid at a solid-fixed, permeable node (Liquid At Solid Fixities).
//
// A saturated column on a fixed base that is drained (p_L = 0 on it, not sealed), sealed on
// its sides and top, moving as a whole at v0 = (0, -0.05) m/s, both phases (the motion a
// sliding body or a point's grid-invisible FLIP velocity maps to a fixed base node). The
// liquid moves with the solid: there is no relative velocity anywhere, so no Darcy flux may
// leave through the base in the first step. The thesis' rule keeps the liquid's remapped
// velocity at the base nodes while the fixity stops the solid, so it makes the body's
// speed a Darcy flux out of the base: about n rho_L |v0| (width) dt of liquid in the step.
// `relative velocity` keeps the remapped relative velocity (zero): no liquid leaves.
#include <gtest/gtest.h>

#include <cmath>

#include "Harness.hpp"
#include "argine/physics/StabilityCheck.hpp"

namespace argine {
namespace {

using test::makeStage;

struct FirstStep {
  Real liquid_lost = 0;  ///< kg per m thickness
  Real dt = 0;           ///< s
};

FirstStep rammedColumnFirstStep(bool keep_relative_velocity) {
  // k = 1e-5 m/s: the Darcy flux any pressure of this step could drive is negligible
  MaterialSpec sand =
      test::elasticMaterial("sand", PhaseModel::Saturated, 1e7, 0.3, 0.4, 1e-5, 2.2e9);
  test::Column column(4, 0.25, 1.0, sand);
  Kokkos::deep_copy(Kokkos::subview(column.points.velocity_solid, Kokkos::ALL, 1), -0.05);
  Kokkos::deep_copy(Kokkos::subview(column.points.velocity_liquid, Kokkos::ALL, 1), -0.05);
  std::vector<BoundarySpec> boundaries{test::solidFixity("base", "bottom", true, true),
                                       test::solidFixity("left roller", "left", true, false),
                                       test::solidFixity("right roller", "right", true, false),
                                       test::impermeable("left seal", "left"),
                                       test::impermeable("right seal", "right"),
                                       test::impermeable("top seal", "top"),
                                       test::liquidPressure("drained base", "bottom", 0.0)};
  StageSpec stage = makeStage("ram", SolverKind::Explicit, 0.0, 0.0, boundaries);
  stage.fixity_keeps_relative_velocity = keep_relative_velocity;
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  solver.beginStage(stage);
  const Real before = sumPointTotals(column.points).liquid_mass;
  FirstStep result;
  result.dt = solver.chooseTimeStep().time_step;
  solver.step(result.dt);
  result.liquid_lost = before - sumPointTotals(column.points).liquid_mass;
  return result;
}

TEST(FixityRelativeVelocity, ThesisRuleMakesTheBodysSpeedADarcyFluxThroughTheFixedBase) {
  const FirstStep step = rammedColumnFirstStep(false);
  // n rho_L |v0| (width 0.25 m) dt, the liquid the base nodes' 5 cm/s carries out in the step
  const Real through_base = 0.4 * 1000 * 0.05 * 0.25 * step.dt;
  EXPECT_GT(step.liquid_lost, 0.5 * through_base);
  EXPECT_LT(step.liquid_lost, 2.0 * through_base);
}

TEST(FixityRelativeVelocity, RelativeVelocityRuleLetsNoLiquidOutWithoutRelativeMotion) {
  const FirstStep step = rammedColumnFirstStep(true);
  const Real through_base = 0.4 * 1000 * 0.05 * 0.25 * step.dt;
  EXPECT_LT(std::fabs(step.liquid_lost), 1e-9 * through_base);
}

}  // namespace
}  // namespace argine
