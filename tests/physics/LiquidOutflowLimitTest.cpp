// Donor limit of the liquid mass balance at dry points (LiquidOutflowLimit.hpp): the capped
// outflow against hand values, and the exact conservation of the step's liquid mass.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "Harness.hpp"
#include "argine/physics/LiquidOutflowLimit.hpp"

namespace argine {
namespace {

using test::hostCopy;

TEST(LiquidOutflowLimit, ExcessOutflowIsWhatExceedsTheMobileContent) {
  // mass 5 kg, residual 1 kg -> mobile 4 kg
  EXPECT_DOUBLE_EQ(excessOutflow(3.0, 5.0, 1.0), 0.0);   // 3 <= 4: has it
  EXPECT_DOUBLE_EQ(excessOutflow(4.0, 5.0, 1.0), 0.0);   // exactly the mobile content
  EXPECT_DOUBLE_EQ(excessOutflow(6.0, 5.0, 1.0), 2.0);   // 6 - 4
  EXPECT_DOUBLE_EQ(excessOutflow(-3.0, 5.0, 1.0), 0.0);  // inflow
  EXPECT_DOUBLE_EQ(excessOutflow(2.0, 0.5, 1.0), 2.0);   // below residual: nothing mobile
  EXPECT_DOUBLE_EQ(excessOutflow(2.0, 7.0, 0.0), 0.0);   // saturated: all mobile
}

/// A 1 x 3 column of unit quads, 4 points each, n = 0.5, V = 0.25 m^2, rho_L = 1000,
/// S_min = 0.1: residual n S_min rho_L V = 0.5 * 0.1 * 1000 * 0.25 = 12.5 kg per point.
struct LimitScene {
  Mesh mesh = test::rectangleMesh(1, 3, 1.0, 3.0, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh);
  MaterialTable table;
  PointShapes shapes;
  PointRates rates;
  LimitScene() {
    MaterialSpec soil = test::elasticMaterial("soil", PhaseModel::Unsaturated, 1e7, 0.2, 0.5);
    soil.retention.model = RetentionModel::VanGenuchten;
    soil.retention.reference_pressure = 1e5;
    soil.retention.lambda = 0.5;
    soil.retention.saturation_min = 0.1;
    soil.retention.saturation_max = 1;
    table = MaterialTable({soil});
    evaluatePointShapes(mesh, points, shapes);
    rates.allocate(points.count);
  }
  /// Per element (bottom to top): M_L (kg) and outflow V dt div(c w) (kg) of its points.
  void set(const Real mass[3], const Real outflow[3]) {
    auto porosity = hostCopy(points.porosity);
    auto volume = hostCopy(points.volume);
    auto density = hostCopy(points.density_liquid);
    auto m = hostCopy(points.mass_liquid);
    auto flux = hostCopy(rates.content_flux_divergence_increment_p);
    const auto element = hostCopy(points.element);
    for (int p = 0; p < points.count; ++p) {
      porosity(p) = 0.5;
      volume(p) = 0.25;
      density(p) = 1000;
      m(p) = mass[element(p)];
      flux(p) = outflow[element(p)] / 0.25;
    }
    Kokkos::deep_copy(points.porosity, porosity);
    Kokkos::deep_copy(points.volume, volume);
    Kokkos::deep_copy(points.density_liquid, density);
    Kokkos::deep_copy(points.mass_liquid, m);
    Kokkos::deep_copy(rates.content_flux_divergence_increment_p, flux);
  }
  /// The outflow V dt div(c w) of every point (kg), and the sum of M_L - outflow.
  std::vector<Real> outflows(Real& mass_after) const {
    const auto flux = hostCopy(rates.content_flux_divergence_increment_p);
    const auto m = hostCopy(points.mass_liquid);
    std::vector<Real> out(points.count);
    mass_after = 0;
    for (int p = 0; p < points.count; ++p) {
      out[p] = 0.25 * flux(p);
      mass_after += m(p) - out[p];
    }
    return out;
  }
};

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
  EXPECT_EQ(totals.limited_points, 4);
  EXPECT_NEAR(totals.excess, 6.0, 1e-12);
  EXPECT_NEAR(totals.withdrawn, 6.0, 1e-12);
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
