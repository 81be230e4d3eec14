// [2Phase][GridShapes] On the grid families (GIMP, B-spline) the liquid flux divergence of
// 4.12 / 4.16 is one per cell, as linear elements take it at the element centre: the points of
// a cell must not get different flux divergences, else the saturated zone stores a pressure
// pattern the nodal forces cannot see (doc/theory.md Sec. 3.11; V3 per shape family).
#include <gtest/gtest.h>

#include <cmath>

#include "Harness.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/NodeRecords.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"

namespace argine {
namespace {

using test::hostCopy;

/// Four saturated points (2 x 2, as seeded) in cell (2, 2) of a
/// 5 x 5 grid of 1 m cells on `family`, the solid at rest and the liquid velocity a quadratic
/// field v_L = (0, 1e-3 y^2) with a content c = rho_L n S_L that the P2G gives; their flux
/// increments over dt = 1e-3 s.
PointRates fluxesOfOneCell(ShapeFamily family) {
  Mesh mesh = test::rectangleMesh(5, 5, 5.0, 5.0, ElementType::Quad4);
  mesh.structured.cells[0] = mesh.structured.cells[1] = 5;
  mesh.structured.spacing[0] = mesh.structured.spacing[1] = 1;
  mesh.shape_functions = family;
  MaterialPoints points;
  points.allocate(4);
  const Real offsets[2] = {0.25, 0.75};
  for (int p = 0; p < points.count; ++p) {
    points.element(p) = 12;  // cell (2, 2)
    points.local(p, 0) = 2 * offsets[p % 2] - 1;
    points.local(p, 1) = 2 * offsets[p / 2] - 1;
    points.position(p, 0) = 2 + offsets[p % 2];
    points.position(p, 1) = 2 + offsets[p / 2];
    points.volume(p) = points.initial_volume(p) = 0.25;
    points.mass_solid(p) = 400;
    points.mass_liquid(p) = 100;
    points.density_liquid(p) = 1000;
    points.porosity(p) = 0.4;
    points.saturation(p) = 1;
    points.conductivity(p) = 1e-4;
  }
  PointShapes shapes;
  evaluatePointShapes(mesh, points, shapes);
  ActiveNodes active(mesh.numNodes());
  active.rebuild(mesh, points, &shapes, Kokkos::View<const int*, MemSpace>());
  GridFields grid;
  grid.allocate(mesh.numNodes());
  NodeRecords records;
  Kokkos::View<int*, MemSpace> liquid("liquid_m", 1);
  liquid(0) = 1;
  mapPointsToGrid(points, shapes, liquid, 0.0, TransferSettings{}, active, records, grid);
  computeNodalVelocities(active, grid);
  const auto X = hostCopy(mesh.coordinates);
  for (int i = 0; i < mesh.numNodes(); ++i) {
    grid.velocity_liquid_i(i, 0) = 0;
    grid.velocity_liquid_i(i, 1) = 1e-3 * X(i, 1) * X(i, 1);
  }
  Kokkos::View<unsigned char*, MemSpace> conditioned("conditioned_i", mesh.numNodes());
  PointRates rates;
  interpolateVelocityGradients(points, shapes, liquid, active, grid, records, 1e-3, rates,
                               conditioned);
  return rates;
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
