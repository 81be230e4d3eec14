// Donor limit of the liquid mass balance at dry points (LiquidOutflowLimit.hpp): the capped
// outflow against hand values, and the exact conservation of the step's liquid mass.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "LimitScene.hpp"
#include "argine/physics/LiquidOutflowLimit.hpp"

namespace argine {
namespace {

using test::hostCopy;
using test::LimitScene;

TEST(LiquidOutflowLimit, ExcessOutflowIsWhatExceedsTheMobileContent) {
  // mass 5 kg, residual 1 kg -> mobile 4 kg
  EXPECT_DOUBLE_EQ(excessOutflow(3.0, 5.0, 1.0), 0.0);   // 3 <= 4: has it
  EXPECT_DOUBLE_EQ(excessOutflow(4.0, 5.0, 1.0), 0.0);   // exactly the mobile content
  EXPECT_DOUBLE_EQ(excessOutflow(6.0, 5.0, 1.0), 2.0);   // 6 - 4
  EXPECT_DOUBLE_EQ(excessOutflow(-3.0, 5.0, 1.0), 0.0);  // inflow
  EXPECT_DOUBLE_EQ(excessOutflow(2.0, 0.5, 1.0), 2.0);   // below residual: nothing mobile
  EXPECT_DOUBLE_EQ(excessOutflow(2.0, 7.0, 0.0), 0.0);   // saturated: all mobile
}

TEST(LiquidOutflowLimit, CapsTheDonorAtItsResidualAndConservesTheLiquidMass) {
  LimitScene scene;
  // Bottom element: M_L 15 kg (mobile 2.5 kg) asked for 4 kg -> excess 1.5 kg per point, 6 kg
  // in all. Middle: gains 5 kg per point (20 kg). Top: nothing moves.
  // Sum of M_L - outflow before: 4 (15 - 4) + 4 (100 + 5) + 4 * 100 = 864 kg.
  const Real mass[3] = {15, 100, 100}, outflow[3] = {4, -5, 0};
  scene.set(mass, outflow);
  LiquidOutflowLimit limit;
  const OutflowLimitTotals totals =
      limit.apply(scene.table, scene.points, scene.shapes, scene.rates);
  test::expectDonorCaseTotals(totals);
  Real mass_after = 0;
  const std::vector<Real> out = scene.outflows(mass_after);
  EXPECT_NEAR(mass_after, 864.0, 1e-10);  // exact conservation (round-off)
  const auto element = hostCopy(scene.points.element);
  std::vector<Real> middle;
  for (int p = 0; p < scene.points.count; ++p) {
    if (element(p) == 0) {
      EXPECT_NEAR(out[p], 2.5, 1e-12);  // left with the residual 12.5 kg
    } else if (element(p) == 2) {
      EXPECT_EQ(out[p], 0.0);
    } else {
      middle.push_back(-out[p]);
    }
  }
  // Middle points (rows at y = 1.25 and 1.75): their shape functions on the shared nodes
  // (y = 1) sum to 0.75 and 0.25. Node deficit there: 1.5 (0.25 + 0.75) per side = 1.5 kg
  // per node, 3 kg in all; node gain 5 (0.75 + 0.25) = 5 kg per node: each gives back 0.3 of
  // its gain through those nodes: 5 * 0.75 * 0.3 = 1.125 and 5 * 0.25 * 0.3 = 0.375 kg.
  // The rest, 3 kg (the deficit on the base nodes, no gaining neighbour there), comes from
  // the remaining gains 3.875, 3.875, 4.625, 4.625 (sum 17) in proportion, fraction 3/17:
  // gains after 3.875 * 14/17 = 3.19118 and 4.625 * 14/17 = 3.80882 kg; total 14 = 20 - 6.
  ASSERT_EQ(middle.size(), 4u);
  std::sort(middle.begin(), middle.end());
  EXPECT_NEAR(middle[0], 3.875 * 14 / 17, 1e-12);
  EXPECT_NEAR(middle[1], 3.875 * 14 / 17, 1e-12);
  EXPECT_NEAR(middle[2], 4.625 * 14 / 17, 1e-12);
  EXPECT_NEAR(middle[3], 4.625 * 14 / 17, 1e-12);
}

TEST(LiquidOutflowLimit, LeavesTheFluxUntouchedWhenEveryPointHasTheLiquid) {
  LimitScene scene;
  const Real mass[3] = {15, 100, 100}, outflow[3] = {2.5, -3, 0.5};
  scene.set(mass, outflow);
  const auto before = hostCopy(scene.rates.content_flux_divergence_increment_p);
  LiquidOutflowLimit limit;
  EXPECT_EQ(limit.apply(scene.table, scene.points, scene.shapes, scene.rates).limited_points, 0);
  const auto after = hostCopy(scene.rates.content_flux_divergence_increment_p);
  for (int p = 0; p < scene.points.count; ++p) EXPECT_EQ(after(p), before(p));  // bit for bit
}

}  // namespace
}  // namespace argine
