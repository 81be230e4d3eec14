// The point terms of the implicit seepage path against hand computations.
#include <gtest/gtest.h>

#include <cmath>

#include "SeepageScenes.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/seepage/SeepagePointTerms.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {
namespace {

/// Shape record of a point at the centre of the unit square (0,0),(1,0),(1,1),(0,1):
/// N_a = 1/4; grad N = (-1/2,-1/2), (1/2,-1/2), (1/2,1/2), (-1/2,1/2) (bilinear, at x=y=1/2:
/// N1 = (1-x)(1-y) -> (-(1-y), -(1-x)), ...).
PointShape centreShape() {
  PointShape shape{};
  const Real g[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  for (int a = 0; a < 4; ++a) {
    shape.node[a] = a;
    shape.value[a] = 0.25;
    shape.gradient[a][0] = g[a][0];
    shape.gradient[a][1] = g[a][1];
  }
  return shape;
}

TEST(SeepagePointTerms, CentrePointStorageAndConductivityMatrices) {
  const PointShape shape = centreShape();
  Real storage[4][4] = {}, conductivity[4][4] = {};
  addPointStorageMatrix(shape, 4, 16.0, storage);  // 16 N_a N_b = 1
  addPointConductivityMatrix(shape, 4, 2.0, conductivity);
  // grad N_a . grad N_b: diagonal 1/2; neighbours along an edge (1-2, 1-4) 0; opposite
  // corners (1-3, 2-4) -1/2. Times 2.
  const Real expected[4][4] = {{1, 0, -1, 0}, {0, 1, 0, -1}, {-1, 0, 1, 0}, {0, -1, 0, 1}};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      EXPECT_DOUBLE_EQ(storage[a][b], 1.0);
      EXPECT_DOUBLE_EQ(conductivity[a][b], expected[a][b]);
    }
}

TEST(SeepagePointTerms, FourPointElementStorageMatrix) {
  // Unit square, 4 points at local +-1/2 (x, y in {1/4, 3/4}), V = 1/4 each.
  // N1 = (1-x)(1-y) at the points: 9/16, 3/16, 1/16, 3/16 (order (1/4,1/4), (3/4,1/4),
  // (3/4,3/4), (1/4,3/4)); N2 = x(1-y): 3/16, 9/16, 3/16, 1/16; N3 = xy: 1/16, 3/16, 9/16, 3/16.
  // M11 = 1/4 (81 + 9 + 1 + 9)/256 = 25/256; M12 = 1/4 (27 + 27 + 3 + 3)/256 = 15/256;
  // M13 = 1/4 (9 + 9 + 9 + 9)/256 = 9/256; row sum 64/256 = 1/4 (the element area / 4).
  const Mesh mesh = test::rectangleMesh(1, 1, 1.0, 1.0, ElementType::Quad4);
  const MaterialPoints points = test::seedUniform(mesh);
  PointShapes shapes;
  evaluatePointShapes(mesh, points, shapes);
  const auto shape = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), shapes.stored_p);
  Real m[4][4] = {};
  for (int p = 0; p < 4; ++p) addPointStorageMatrix(shape(p), 4, 0.25, m);
  // Mesh node order of the element: counter-clockwise from (0,0), as the local nodes.
  EXPECT_NEAR(m[0][0], 25.0 / 256, 1e-15);
  EXPECT_NEAR(m[0][1], 15.0 / 256, 1e-15);
  EXPECT_NEAR(m[0][2], 9.0 / 256, 1e-15);
  EXPECT_NEAR(m[0][3], 15.0 / 256, 1e-15);
  EXPECT_NEAR(m[1][1], 25.0 / 256, 1e-15);
}

TEST(SeepagePointTerms, HydrostaticPressureDrivesNoFlux) {
  // p = p0 - rho g y: grad p = (0, -rho g), so grad p + rho g e_y = 0 and F_a = 0.
  // On the unit square p at the nodes (0,0),(1,0),(1,1),(0,1) with rho g = 9810:
  // 9810, 9810, 0, 0.
  const PointShape shape = centreShape();
  const Real p[4] = {9810, 9810, 0, 0};
  Real f[4] = {0, 0, 0, 0};
  addPointFluxVector(shape, 4, p, 3.0, 9810, f);
  for (int a = 0; a < 4; ++a) EXPECT_NEAR(f[a], 0.0, 1e-9);
  // Without gravity the same p drives flow upward: grad p = (0, -9810); F_a = 3 dN_a/dy
  // (-9810) = -3 x 9810 x (-1/2) = +14715 at the lower nodes, -14715 at the upper ones.
  Real g[4] = {0, 0, 0, 0};
  addPointFluxVector(shape, 4, p, 3.0, 0, g);
  EXPECT_NEAR(g[0], 14715, 1e-9);
  EXPECT_NEAR(g[1], 14715, 1e-9);
  EXPECT_NEAR(g[2], -14715, 1e-9);
  EXPECT_NEAR(g[3], -14715, 1e-9);
  EXPECT_DOUBLE_EQ(interpolateAtPoint(shape, 4, p), 4905);
}

TEST(SeepagePointTerms, ContentChangeMobilityAndSlope) {
  const MaterialTable table(std::vector<MaterialSpec>{test::infiltrationSoil()});
  const PointMaterial& soil = table.host(0);
  // Saturated side: S = 1, S rho change = rho0 (exp(p1/K) - exp(p0/K)).
  const Real p0 = 1000, p1 = 1000.5, K = 2.2e9;
  EXPECT_NEAR(liquidContentChange(soil, p1, p0),
              1000 * std::exp(p0 / K) * std::expm1((p1 - p0) / K), 1e-20);
  // Unsaturated: the plain difference of S rho.
  const Real a = -2000, b = -1500;
  EXPECT_NEAR(liquidContentChange(soil, b, a), liquidContent(soil, b) - liquidContent(soil, a),
              1e-10);
  // Mobility rho k / (rho0 9.81) at p = 0: 1e-4 / 9.81 s.
  EXPECT_NEAR(darcyMobility(soil, 0.0), 1e-4 / 9.81, 1e-18);
  // Slope = central difference of S rho (lambda = 0.7 needs no regularisation).
  const Real h = 1e-2;
  EXPECT_NEAR(storageSlope(soil, a, 1e-2),
              (liquidContent(soil, a + h) - liquidContent(soil, a - h)) / (2 * h), 1e-9);
  EXPECT_FALSE(needsSuctionRegularisation(soil));
}

TEST(SeepagePointTerms, MinimumSuctionRegularisationForSmallLambda) {
  MaterialSpec spec = test::infiltrationSoil();
  spec.retention.lambda = 0.3;  // dS/ds ~ s^(0.3/0.7): not Lipschitz at s = 0
  const MaterialTable table(std::vector<MaterialSpec>{spec});
  const PointMaterial& soil = table.host(0);
  ASSERT_TRUE(needsSuctionRegularisation(soil));
  // s_reg = 1e-2 x 3000 = 30 Pa: at s = 1 Pa the matrix takes the slope at 30 Pa.
  // rho (S/K_L - dS/ds) with S and rho at s = 1 Pa, dS/ds at 30 Pa.
  const Real rho = liquidDensity(soil.liquid, -1.0);
  EXPECT_DOUBLE_EQ(storageSlope(soil, -1.0, 1e-2),
                   liquidContentSlope(rho, saturation(soil.retention, 1.0),
                                      saturationSuctionDerivative(soil.retention, 30.0), 2.2e9));
  EXPECT_GT(storageSlope(soil, -30.0, 1e-2), storageSlope(soil, -1.0, 0.0));
  // Beyond s_reg and when saturated it is the plain slope.
  EXPECT_DOUBLE_EQ(storageSlope(soil, -100.0, 1e-2), storageSlope(soil, -100.0, 0.0));
  EXPECT_DOUBLE_EQ(storageSlope(soil, 10.0, 1e-2), 1000 * std::exp(10.0 / 2.2e9) / 2.2e9);
}

TEST(SeepagePointTerms, ConductivityAndMobilityPressureDerivatives) {
  // Gardner HCC k = k_sat exp(-alpha s), alpha = 1e-3 1/Pa, k_sat = 1e-5 m/s: at p = -1000 Pa
  // (s = 1000) dk/dp = -dk/ds = k_sat alpha exp(-1) = 1e-8 x 0.36787944117144233.
  MaterialSpec spec = test::infiltrationSoil();
  spec.conductivity.model = ConductivityModel::Gardner;
  spec.conductivity.gardner_alpha = 1e-3;
  spec.conductivity.saturated_conductivity = 1e-5;
  MaterialSpec constant = test::infiltrationSoil();
  const MaterialTable table(std::vector<MaterialSpec>{spec, constant});
  const PointMaterial& gardner = table.host(0);
  EXPECT_NEAR(conductivityPressureDerivative(gardner, -1000.0), 3.6787944117144233e-9, 1e-22);
  // Saturated (s <= 0) and a constant HCC: no slope.
  EXPECT_EQ(conductivityPressureDerivative(gardner, 100.0), 0.0);
  EXPECT_EQ(conductivityPressureDerivative(table.host(1), -1000.0), 0.0);
  // dm/dp = m / K_L + rho dk/dp / (rho0 g_k). At p = 0 (rho = rho0, k = k_sat, dk/dp = 0):
  // m = 1e-5 / 9.81 s, dm/dp = m / 2.2e9.
  const Real m = 1e-5 / 9.81;
  EXPECT_NEAR(darcyMobilityPressureDerivative(gardner, 0.0, m), m / 2.2e9, 1e-25);
  // At p = -1000: rho = 1000 exp(-1000/2.2e9); dm/dp = m/K_L + rho 3.6788e-9 / 9810.
  const Real rho = 1000 * std::exp(-1000 / 2.2e9);
  EXPECT_NEAR(darcyMobilityPressureDerivative(gardner, -1000.0, m),
              m / 2.2e9 + rho * 3.6787944117144233e-9 / 9810, 1e-24);
}

TEST(SeepagePointTerms, NewtonFluxJacobianCorrection) {
  // Centre of the unit square, nodal p = (0, 4, 4, 0): grad p = (4, 0); rho g = 10, so
  // d = (4, 10). grad N_a . d = 4 dN_a/dx + 10 dN_a/dy = -7, -3, 7, 3.
  // Row a: 2 (grad N_a . d) + 4 dN_a/dy = -16, -8, 16, 8; out[a][b] = row_a N_b = row_a / 4.
  const PointShape shape = centreShape();
  const Real p[4] = {0, 4, 4, 0};
  Real out[4][4] = {};
  addPointFluxJacobianCorrection(shape, 4, p, 10.0, 2.0, 4.0, out);
  const Real expected[4] = {-4, -2, 4, 2};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) EXPECT_NEAR(out[a][b], expected[a], 1e-15);
}

}  // namespace
}  // namespace argine
