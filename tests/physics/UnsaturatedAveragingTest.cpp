// [2Phase][Unsaturated] Liquid-pressure averaging at unsaturated points (VolumetricAveraging,
// `Liquid Pressure Averaging`): the storage weight and the mass it moves (hand values), and
// a Tri3 column draining under gravity, where without the averaging the three points of a
// triangle share one flux divergence and so carry one p_L (the V3 explicit error).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "Harness.hpp"
#include "argine/physics/VolumetricAveraging.hpp"

namespace argine {
namespace {

using test::hostCopy;

MaterialSpec linearSoil(Real bulk_modulus) {
  MaterialSpec soil =
      test::elasticMaterial("soil", PhaseModel::Unsaturated, 1e7, 0.0, 0.4, 1e-4, bulk_modulus);
  soil.retention.model = RetentionModel::Linear;
  soil.retention.linear_slope = 1e-6;  // S_L = 1 - 1e-6 s (1/Pa)
  soil.retention.saturation_max = 1;
  soil.retention.saturation_min = 0;
  return soil;
}

PointMaterial pointMaterial(const MaterialSpec& spec) {
  return MaterialTable(std::vector<MaterialSpec>{spec}).host(0);
}

TEST(UnsaturatedAveraging, StorageWeightIsTheSecantOfTheLiquidContent) {
  // K_L = 1e30 Pa: rho_L = 1000 exactly in double. n V = 0.4 * 2 = 0.8 m^3.
  const PointMaterial soil = pointMaterial(linearSoil(1e30));
  // p_L -1e5 -> -5e4 Pa: S_L 0.90 -> 0.95; 0.8 * (950 - 900) / 5e4 = 8e-4 kg/Pa.
  EXPECT_NEAR(pressureAveragingWeight(soil, 0.4, 2.0, -1e5, -5e4), 8e-4, 1e-15);
  // The tangent (increment below 1e-6 Pa): 0.8 * 1000 * (S_L/K_L + 1e-6) = 8e-4 kg/Pa.
  EXPECT_NEAR(pressureAveragingWeight(soil, 0.4, 2.0, -1e5, -1e5), 8e-4, 1e-15);
  // Across the kink, -5e4 -> +1e4 Pa: S_L 0.95 -> 1; 0.8 * (1000 - 950) / 6e4 = 6.6667e-4.
  EXPECT_NEAR(pressureAveragingWeight(soil, 0.4, 2.0, -5e4, 1e4), 0.8 * 50 / 6e4, 1e-15);
  // Saturated material: n V rho_L / K_L; K_L = 1e8: 0.8 * 1000 / 1e8 = 8e-6 kg/Pa.
  MaterialSpec clay = linearSoil(1e8);
  clay.phase = PhaseModel::Saturated;
  EXPECT_NEAR(pressureAveragingWeight(pointMaterial(clay), 0.4, 2.0, 0, 0), 8e-6, 1e-18);
  // The mass follows the increment it is given: 10 + 2 (1 - 3) = 6 kg.
  EXPECT_DOUBLE_EQ(averagedLiquidMass(10, 2, 3, 1), 6);
}

struct DrainResult {
  Real largest_spread = 0;     ///< max over triangles of max - min p_L of its points (Pa)
  Real mass_change = 0;        ///< |sum M_L(end) - sum M_L(0)| / sum M_L(0)
  Real hydrostatic_error = 0;  ///< max |p_L(y) - p_L(y') - rho_L g (y' - y)| over point pairs
};

/// A closed Tri3 column (0.05 m x 0.5 m, 10 rows, van Genuchten sand, constant k = 1e-4 m/s),
/// fixed skeleton, gravity, from a uniform -2 kPa: the liquid drains to the impervious base
/// and collects at rest above the base (dp_L/dy = -rho_L g there).
DrainResult drainColumn(IncrementAveraging averaging) {
  MaterialSpec sand = linearSoil(8e7);
  sand.retention.model = RetentionModel::VanGenuchten;
  sand.retention.reference_pressure = 3000;
  sand.retention.lambda = 0.7;
  sand.retention.saturation_min = 0.125;
  sand.retention.saturation_max = 1;
  sand.initial.liquid_pressure = -2000;
  sand.locking.liquid_pressure = averaging;
  const Mesh mesh = test::rectangleMesh(1, 10, 0.05, 0.5, ElementType::Tri3);
  MaterialPoints points = test::seedUniform(mesh);
  std::vector<MaterialSpec> materials{sand};
  initialisePointState(materials, points);
  auto boundaries = test::columnBoundaries();
  boundaries.push_back(test::impermeable("top seal", "top"));
  ExplicitTwoPhaseSolver solver(mesh, points, materials);
  StageSpec stage = test::makeStage("drain", SolverKind::FixedSkeleton, 9.81, 0.0, boundaries,
                                    {CriterionKind::Mieremet});
  stage.mass_scaling = 1e4;
  solver.beginStage(stage);
  const auto m0 = hostCopy(points.mass_liquid);
  test::runUntil(solver, 100.0);
  const auto m1 = hostCopy(points.mass_liquid);
  const auto p = hostCopy(points.pressure_liquid);
  const auto x = hostCopy(points.position);
  const auto element = hostCopy(points.element);
  DrainResult result;
  Real before = 0, after = 0;
  std::map<int, std::pair<Real, Real>> range;
  for (int q = 0; q < points.count; ++q) {
    before += m0(q), after += m1(q);
    auto [it, fresh] = range.try_emplace(element(q), p(q), p(q));
    it->second.first = std::min(it->second.first, p(q));
    it->second.second = std::max(it->second.second, p(q));
    // The wet base rows (y < 0.1 m), where the drained water collects at rest: hydrostatic
    // between any two of their points (as the V3 column's base).
    for (int r = 0; r < points.count; ++r)
      if (x(q, 1) < 0.1 && x(r, 1) < 0.1)
        result.hydrostatic_error = std::max(
            result.hydrostatic_error, std::fabs(p(q) - p(r) - 1000 * 9.81 * (x(r, 1) - x(q, 1))));
  }
  for (const auto& [e, low_high] : range)
    result.largest_spread = std::max(result.largest_spread, low_high.second - low_high.first);
  result.mass_change = std::fabs(after - before) / before;
  std::printf(
      "[ averaging ] %s: spread in a triangle %.1f Pa, hydrostatic error %.1f Pa, "
      "mass change %.2e (%ld steps)\n",
      averaging == IncrementAveraging::None ? "none " : "nodal", result.largest_spread,
      result.hydrostatic_error, result.mass_change, solver.diagnostics().step);
  return result;
}

TEST(UnsaturatedAveraging, NodalAveragingGivesTheTri3PointsAHydrostaticProfile) {
  const DrainResult plain = drainColumn(IncrementAveraging::None);
  const DrainResult nodal = drainColumn(IncrementAveraging::Nodal);
  // Without averaging the points of a triangle keep one p_L (same flux divergence), so the
  // profile is a staircase: off hydrostatic by rho_L g x (the points' height spread in a
  // triangle, h/2 = 0.025 m) = 245 Pa, plus what still flows. With it they follow the gradient.
  EXPECT_LT(plain.largest_spread, 1e-6);
  EXPECT_GT(plain.hydrostatic_error, 100);
  EXPECT_GT(nodal.largest_spread, 50);
  EXPECT_LT(nodal.hydrostatic_error, 0.5 * plain.hydrostatic_error);
  // The liquid mass moves with the averaged increments: the total is kept to round-off.
  EXPECT_LT(nodal.mass_change, 1e-12);
  EXPECT_LT(plain.mass_change, 1e-12);
}

}  // namespace
}  // namespace argine
