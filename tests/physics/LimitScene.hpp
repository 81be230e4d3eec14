#pragma once
// The scene of the donor-limit tests (LiquidOutflowLimit.hpp): on one rank
// (LiquidOutflowLimitTest) and with the donor and the gaining points on different ranks
// (tests/parallel/OutflowLimitRanksTest).

#include <gtest/gtest.h>

#include "Harness.hpp"
#include "argine/physics/LiquidOutflowLimit.hpp"

namespace argine::test {

/// A 1 x 3 column of unit quads, 4 points each, n = 0.5, V = 0.25 m^2, rho_L = 1000,
/// S_min = 0.1: residual n S_min rho_L V = 0.5 * 0.1 * 1000 * 0.25 = 12.5 kg per point.
struct LimitScene {
  Mesh mesh = test::rectangleMesh(1, 3, 1.0, 3.0, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh);
  MaterialTable table;
  PointShapes shapes;
  PointRates rates;
  LimitScene() {
    const MaterialSpec soil = test::withVanGenuchten(
        test::elasticMaterial("soil", PhaseModel::Unsaturated, 1e7, 0.2, 0.5), 1e5, 0.5, 0.1, 1);
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

/// The totals of the donor case of both tests (masses 15, 100, 100 kg, outflows 4, -5, 0 kg
/// per point, bottom to top): 4 donors, 6 kg excess, all of it withdrawn.
inline void expectDonorCaseTotals(const OutflowLimitTotals& totals) {
  EXPECT_EQ(totals.limited_points, 4);
  EXPECT_NEAR(totals.excess, 6.0, 1e-12);
  EXPECT_NEAR(totals.withdrawn, 6.0, 1e-12);
}

}  // namespace argine::test
