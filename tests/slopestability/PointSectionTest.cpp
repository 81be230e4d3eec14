// A limit-equilibrium section from material points (slopestability/PointSection.hpp): the
// raster's weights, envelope and interpolation on lattices where the answer is known, and
// ACADS 1(a) filled with points against the same search on the polygon section.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "AcadsSlope.hpp"
#include "argine/slopestability/CircleSearch.hpp"
#include "argine/slopestability/PointSection.hpp"

namespace argine {
namespace {

using acads::kCohesion;
using acads::kFriction;
using acads::latticeBelow;

TEST(PointRaster, BlockWeightsEnvelopeAndLinearPressure) {
  // A 2 m x 1 m block, h = 0.1 m, gamma = 20 kN/m3, hydrostatic p_L = 9810 (1 - y).
  const Polyline top({0.0, 2.0}, {1.0, 1.0});
  const SectionPoints pts =
      latticeBelow(top, 0, 2, 0, 0.1, 20e3, [](Real, Real y) { return 9810 * (1 - y); });
  ASSERT_EQ(pts.size(), 200u);
  const PointRaster raster(pts, 0);
  EXPECT_NEAR(raster.cellSize(), 0.2, 1e-12);  // twice the spacing sqrt(V) = 0.1
  // The envelope: highest point 0.95 plus half its spacing: y = 1 from x = 0 to 2.
  const Polyline& g = raster.ground();
  EXPECT_NEAR(g.xFirst(), 0, 1e-12);
  EXPECT_NEAR(g.xLast(), 2, 1e-12);
  for (const Real y : g.y) EXPECT_NEAR(y, 1.0, 1e-12);
  EXPECT_NEAR(raster.bottom(), 0, 1e-12);
  // Weight per area of any column part: gamma times its height.
  EXPECT_NEAR(raster.columnWeightDensity(1.03, 0.0, 1.0), 20e3, 1e-8);
  EXPECT_NEAR(raster.columnWeightDensity(0.31, 0.27, 0.64), 20e3 * 0.37, 1e-8);
  // A linear field is reproduced everywhere, up to the surface and the edges (least-squares
  // planes per cell).
  for (const auto& [x, y] :
       {std::pair<Real, Real>{0.5, 0.5}, {1.37, 0.21}, {0.77, 0.83}, {0.63, 0.99}, {0.01, 0.02}})
    EXPECT_NEAR(raster.porePressure(x, y), 9810 * (1 - y), 1e-8) << x << ", " << y;
  EXPECT_NEAR(raster.surfaceWaterPressure(0.9), 0, 1e-8);  // p_L = 0 at the surface y = 1
  // Under half a metre of standing water, p_L = 9810 (1.5 - y): 4905 Pa on the ground.
  const SectionPoints wet =
      latticeBelow(top, 0, 2, 0, 0.1, 20e3, [](Real, Real y) { return 9810 * (1.5 - y); });
  EXPECT_NEAR(PointRaster(wet, 0).surfaceWaterPressure(1.23), 4905, 1e-8);
  // Beyond the outermost points (x = 1.95) the raster's margin column [2.0, 2.2) is empty:
  // a circle leaving the ground there (x = 2.05) still finds the standing water's pressure,
  // and p_L from the nearest column's plane.
  EXPECT_NEAR(PointRaster(wet, 0).surfaceWaterPressure(2.05), 4905, 1e-8);
  EXPECT_NEAR(PointRaster(wet, 0).porePressure(2.1, 0.5), 9810, 1e-8);
  EXPECT_NEAR(raster.saturation(1, 0.5), 1, 1e-15);
  EXPECT_EQ(raster.material(1, 0.5), 0);
}

TEST(PointSection, AcadsProblem1aFromPointsAsFromItsPolygon) {
  // ACADS 1(a) (AcadsBenchmarkTest.cpp): c' = 3 kPa, phi' = 19.6 deg, gamma = 20 kN/m3, dry.
  const Polyline ground = acads::problem1aGround();
  const CircleSearchGrid grid = acads::problem1aGrid();
  const CriticalCircle exact = searchCriticalCircle(acads::problem1a(), grid);
  ASSERT_TRUE(exact.found);

  const Real h = 0.1;  // spacing: 1 % of the slope height
  const SectionPoints pts =
      latticeBelow(ground, 20, 70, 20, h, acads::kUnitWeight, [](Real, Real) { return 0; });
  const SlopeSection section = sectionFromPoints(pts, [](int, Real, Real) {
    return BaseStrength{0, kCohesion, kFriction, 0};
  });
  const CriticalCircle points = searchCriticalCircle(section, grid);
  ASSERT_TRUE(points.found);
  std::cout << "ACADS 1(a) Bishop F: polygon " << exact.bishop.value << ", from " << pts.size()
            << " points " << points.bishop.value << "\n";
  // The points' envelope lies within a spacing of the face and the masses differ by O(h/H):
  // the factor agrees to 1 % (h / H = 0.01).
  EXPECT_NEAR(points.bishop.value, exact.bishop.value, 0.01 * exact.bishop.value);
  EXPECT_NEAR(points.mass.entry_x, exact.mass.entry_x, 1.0);
  EXPECT_NEAR(points.mass.exit_x, exact.mass.exit_x, 1.0);
}

TEST(PointSection, PorePressureAndSuctionFromThePoints) {
  // The same slope with a phreatic line at y = 24.9 up to the toe (x = 30), rising to y = 31
  // at x = 70, below the ground everywhere (p_L = 9810 (h_w(x) - y), negative above it): the
  // positive pore pressure lowers F, a suction strength added by the strength callable raises it
  // again.
  const Polyline ground = acads::problem1aGround();
  const Polyline phreatic({20, 30, 70}, {24.9, 24.9, 31});
  const auto water = [&phreatic](Real x, Real y) { return 9810 * (phreatic.at(x) - y); };
  const SectionPoints pts = latticeBelow(ground, 20, 70, 20, 0.1, acads::kUnitWeight, water);
  const CircleSearchGrid grid = acads::problem1aGrid();
  const auto plain = [](int, Real, Real) { return BaseStrength{0, kCohesion, kFriction, 0}; };
  const auto suction = [](int, Real p_L, Real S_L) {
    return BaseStrength{0, kCohesion, kFriction,
                        S_L * std::max(-p_L, Real(0)) * std::tan(kFriction)};
  };
  // The polygon section with the phreatic line gives the reference of the wet case.
  SlopeSection polygon = acads::problem1a();
  polygon.phreatic = phreatic;
  const Real wet_exact = searchCriticalCircle(polygon, grid).bishop.value;
  const Real wet = searchCriticalCircle(sectionFromPoints(pts, plain), grid).bishop.value;
  const Real dry_suction = searchCriticalCircle(sectionFromPoints(pts, suction), grid).bishop.value;
  std::cout << "ACADS 1(a) with a phreatic line: polygon " << wet_exact << ", points " << wet
            << ", points with suction strength " << dry_suction << "\n";
  EXPECT_NEAR(wet, wet_exact, 0.01 * wet_exact);
  EXPECT_LT(wet, 0.985);        // below the dry factor
  EXPECT_GT(dry_suction, wet);  // suction above the table adds strength
}

}  // namespace
}  // namespace argine
