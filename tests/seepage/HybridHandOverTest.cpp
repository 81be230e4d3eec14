// Hybrid run: an implicit seepage stage (rain through the deck's infiltration kind, resolved
// by seepageBoundaryPlan) followed by an explicit fixed-skeleton stage on the same points.
// The explicit stage must start from the implicit p_L, S_L, M_L, and the liquid mass must be
// the same on both sides of the hand-over (closed box afterwards: no flux).
#include <gtest/gtest.h>

#include <cmath>

#include "PointSums.hpp"
#include "SeepageScenes.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"

namespace argine {
namespace {

BoundarySpec sealed(const std::string& set) {
  BoundarySpec spec;
  spec.name = "sealed " + set;
  spec.kind = BoundaryKind::LiquidFixity;
  spec.side_set = set;
  return spec;
}

TEST(HybridHandOver, ExplicitStageStartsFromTheImplicitStateAndKeepsItsLiquidMass) {
  test::SeepageColumn column(20, 0.05, 1.0, test::infiltrationSoil(), -2000);
  const Real initial_mass = totalLiquidMass(column.points);

  StageSpec rain_stage;
  rain_stage.name = "rain";
  rain_stage.solver = SolverKind::ImplicitSeepage;
  rain_stage.gravity = 9.81;
  rain_stage.seepage.max_step = 20;
  BoundarySpec rain;
  rain.name = "rain";
  rain.kind = BoundaryKind::Infiltration;
  rain.side_set = "top";
  rain.hydraulic.series.value = 1e-4;  // ponding false: runs off once the top saturates
  rain_stage.boundaries = {rain, sealed("bottom")};

  ImplicitSeepageSolver implicit(column.mesh, column.points, column.materials);
  implicit.beginStage(rain_stage);
  implicit.advanceTo(100);
  implicit.handOver();
  const Real handed = implicit.liquidMass();
  // Rain 1e-4 m/s x 0.05 m x 100 s x 1000 kg/m3 = 0.5 kg/m entered (the top does not saturate
  // within 100 s: p_L stays < 0 there), and the points hold exactly the solver's mass.
  EXPECT_TRUE(implicit.heldNodes().empty());
  EXPECT_NEAR(implicit.totals().inflow, 0.5, 1e-12);
  EXPECT_NEAR(handed - initial_mass, 0.5, 1e-10 * handed);
  EXPECT_NEAR(totalLiquidMass(column.points), handed, 1e-10 * handed);
  const auto p_implicit = test::hostCopy(column.points.pressure_liquid);
  const auto s_implicit = test::hostCopy(column.points.saturation);
  const auto m_implicit = test::hostCopy(column.points.mass_liquid);
  Real p_min = 0, p_max = -1e30;
  for (int i = 0; i < column.points.count; ++i) {
    p_min = std::min(p_min, p_implicit(i));
    p_max = std::max(p_max, p_implicit(i));
  }
  EXPECT_LT(p_min, -1900.0);  // still dry at the base
  EXPECT_GT(p_max, -1000.0);  // wetted near the top

  StageSpec closed;
  closed.name = "closed";
  closed.solver = SolverKind::FixedSkeleton;
  closed.gravity = 9.81;
  closed.mass_scaling = 1e4;
  closed.boundaries = {sealed("bottom"), sealed("left"), sealed("right"), sealed("top")};
  ExplicitTwoPhaseSolver explicit_solver(column.mesh, column.points, column.materials);
  explicit_solver.setTime(implicit.time());
  explicit_solver.beginStage(closed);
  {
    const auto p = test::hostCopy(column.points.pressure_liquid);
    const auto s = test::hostCopy(column.points.saturation);
    const auto m = test::hostCopy(column.points.mass_liquid);
    for (int i = 0; i < column.points.count; ++i) {
      EXPECT_EQ(p(i), p_implicit(i));
      EXPECT_EQ(s(i), s_implicit(i));
      EXPECT_EQ(m(i), m_implicit(i));
    }
  }
  for (int k = 0; k < 50; ++k) explicit_solver.step(explicit_solver.chooseTimeStep().time_step);
  EXPECT_GT(explicit_solver.time(), implicit.time());
  EXPECT_NEAR(totalLiquidMass(column.points), handed, 1e-10 * handed);
}

}  // namespace
}  // namespace argine
