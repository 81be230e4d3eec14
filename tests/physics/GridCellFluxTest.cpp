// [2Phase][GridShapes] On the grid families (GIMP, B-spline) the liquid flux divergence of
// 4.12 / 4.16 is one per cell, as linear elements take it at the element centre: the points of
// a cell must not get different flux divergences, else the saturated zone stores a pressure
// pattern the nodal forces cannot see (doc/theory.md Sec. 3.11; V3 per shape family).
#include <gtest/gtest.h>

#include <cmath>

#include "WetPointsFlux.hpp"

namespace argine {
namespace {

/// Four saturated points (2 x 2, as seeded) in cell (2, 2) of a 5 x 5 grid of 1 m cells on
/// `family`, the liquid velocity a quadratic field v_L = (0, 1e-3 y^2): their flux increments.
PointRates fluxesOfOneCell(ShapeFamily family) {
  return test::wetPointsFlux(
      5, family, 2, 2, {{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}}, [](Real, Real y) {
        return std::array<Real, 2>{0, 1e-3 * y * y};
      });
}

TEST(GridCellFlux, ThePointsOfOneCellShareTheFluxDivergenceOfItsCentre) {
  for (const ShapeFamily family : {ShapeFamily::Gimp, ShapeFamily::BSpline}) {
    const PointRates rates = fluxesOfOneCell(family);
    // c = n rho_L = 400 kg/m3 wherever the nodes see these points only through ratios of the
    // same sums, so div(c w) at the cell centre is c (v(3) - v(2)) / h = 400 x 5e-3 1/s.
    for (int p = 0; p < 4; ++p)
      EXPECT_NEAR(rates.content_flux_divergence_increment_p(p), 1e-3 * 400 * 5e-3, 1e-12)
          << (family == ShapeFamily::Gimp ? "GIMP" : "B-spline") << " point " << p;
  }
  // while div v_L at the points stays the point's own: the B-spline reproduces the quadratic
  // (d/dy 1e-3 y^2 = 2e-3 y), so it differs between the rows of the cell
  const PointRates rates = fluxesOfOneCell(ShapeFamily::BSpline);
  EXPECT_NEAR(rates.liquid_divergence_increment_p(0), 1e-3 * 2e-3 * 2.25, 1e-12);
  EXPECT_NEAR(rates.liquid_divergence_increment_p(2), 1e-3 * 2e-3 * 2.75, 1e-12);
}

}  // namespace
}  // namespace argine
