#pragma once
// Support of the flux tests (LonePointTest, GridCellFluxTest): saturated points at rest in one
// cell of a grid of 1 m quad4 cells, a prescribed nodal liquid velocity, and the strain
// kernel's liquid increments over dt = 1e-3 s.
#include <array>
#include <functional>
#include <vector>

#include "Harness.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/NodeRecords.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"

namespace argine::test {

/// Saturated points (0.25 m3 each, n 0.4, rho_L 1000 kg/m3, k 1e-4 m/s, at rest) at `inside`
/// (coordinates in [0, 1]^2 within cell (cx, cy)) of a `cells` x `cells` grid of 1 m quad4
/// cells with the transfers on `family`; the nodal liquid velocity v_L(x, y) (the solid at
/// rest); a hydraulic condition on the given nodes. Returns the points' rates over 1e-3 s.
inline PointRates wetPointsFlux(int cells, ShapeFamily family, int cx, int cy,
                                const std::vector<std::array<Real, 2>>& inside,
                                const std::function<std::array<Real, 2>(Real, Real)>& v_liquid,
                                const std::vector<int>& conditioned_nodes = {}) {
  Mesh mesh = rectangleMesh(cells, cells, cells, cells, ElementType::Quad4);
  mesh.structured.cells[0] = mesh.structured.cells[1] = cells;
  mesh.structured.spacing[0] = mesh.structured.spacing[1] = 1;
  mesh.shape_functions = family;
  MaterialPoints points;
  points.allocate(static_cast<int>(inside.size()));
  for (int p = 0; p < points.count; ++p) {
    points.element(p) = cx + cells * cy;
    for (int d = 0; d < kDim; ++d) {
      points.local(p, d) = 2 * inside[p][d] - 1;
      points.position(p, d) = (d == 0 ? cx : cy) + inside[p][d];
    }
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
    const std::array<Real, 2> v = v_liquid(X(i, 0), X(i, 1));
    grid.velocity_liquid_i(i, 0) = v[0];
    grid.velocity_liquid_i(i, 1) = v[1];
  }
  Kokkos::View<unsigned char*, MemSpace> conditioned("conditioned_i", mesh.numNodes());
  for (const int node : conditioned_nodes) conditioned(node) = 1;
  PointRates rates;
  interpolateVelocityGradients(points, shapes, liquid, active, grid, records, 1e-3, rates,
                               conditioned);
  return rates;
}

}  // namespace argine::test
