#pragma once
// The scene of the liquid head stabilisation tests (LiquidHeadStabilisation.hpp): on one
// rank (LiquidHeadStabilisationTest) and with the two triangles on different ranks
// (tests/parallel/HeadStabilisationRanksTest).

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "Harness.hpp"
#include "LiquidPointStates.hpp"
#include "argine/physics/LiquidHeadStabilisation.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine::test {

constexpr Real kPorosity = 0.4, kConductivity = 1e-4, kBulk = 2.2e9;

/// One point per element at its centroid, from the three seeded points of each triangle.
inline MaterialPoints centroidPoints(const Mesh& mesh) {
  const MaterialPoints three = test::seedUniform(mesh);
  const auto element = hostCopy(three.element);
  const auto position = hostCopy(three.position);
  const auto volume = hostCopy(three.volume);
  MaterialPoints points;
  points.allocate(mesh.numElements());
  auto id = hostCopy(points.id);
  auto e = hostCopy(points.element);
  auto local = hostCopy(points.local);
  auto x = hostCopy(points.position);
  auto x0 = hostCopy(points.initial_position);
  auto v = hostCopy(points.volume);
  auto v0 = hostCopy(points.initial_volume);
  auto material = hostCopy(points.material);
  for (int p = 0; p < points.count; ++p) {
    id(p) = p;
    e(p) = p;
    material(p) = 0;
    local(p, 0) = local(p, 1) = 1.0 / 3;
    x(p, 0) = x(p, 1) = v(p) = 0;
  }
  for (int q = 0; q < three.count; ++q) {
    const int p = element(q);
    for (int d = 0; d < kDim; ++d) x(p, d) += position(q, d) / 3;
    v(p) += volume(q);
  }
  for (int p = 0; p < points.count; ++p) {
    x0(p, 0) = x(p, 0);
    x0(p, 1) = x(p, 1);
    v0(p) = v(p);
  }
  Kokkos::deep_copy(points.id, id);
  Kokkos::deep_copy(points.element, e);
  Kokkos::deep_copy(points.local, local);
  Kokkos::deep_copy(points.position, x);
  Kokkos::deep_copy(points.initial_position, x0);
  Kokkos::deep_copy(points.volume, v);
  Kokkos::deep_copy(points.initial_volume, v0);
  Kokkos::deep_copy(points.material, material);
  return points;
}

/// Tri3 mesh of nx x ny squares of side `size`, one point per triangle at its centroid (or
/// the three seeded points of each triangle), van Genuchten soil (p_ref 2 kPa, lambda 0.5),
/// conductivity constant (or another model), liquid state set from p_L(x, y).
struct HeadScene {
  Mesh mesh;
  MaterialPoints points;
  MaterialTable table;
  PointShapes shapes;
  PointRates rates;
  ActiveNodes active;
  HeadScene(int nx, int ny, Real size, Real alpha, bool three_per_triangle = false,
            ConductivityModel conductivity = ConductivityModel::Constant)
      : mesh(test::rectangleMesh(nx, ny, nx * size, ny * size, ElementType::Tri3)),
        points(three_per_triangle ? test::seedUniform(mesh) : centroidPoints(mesh)) {
    MaterialSpec soil = test::elasticMaterial("soil", PhaseModel::Unsaturated, 1e7, 0.3, kPorosity,
                                              kConductivity, kBulk);
    soil.retention.model = RetentionModel::VanGenuchten;
    soil.retention.reference_pressure = 2000;
    soil.retention.lambda = 0.5;
    soil.retention.saturation_min = 0.1;
    soil.retention.saturation_max = 1;
    soil.conductivity.model = conductivity;  // Mualem: lambda* 0.5 of S_e
    soil.conductivity.use_effective_saturation = true;
    soil.locking.head_stabilisation = alpha;
    table = MaterialTable({soil});
    evaluatePointShapes(mesh, points, shapes);
    rates.allocate(points.count);
    active = ActiveNodes(mesh.numNodes());
    active.rebuild(mesh, points);
  }
  const PointMaterial& material() const { return table.host(0); }
  /// p_L at each point from `pressure(x, y)`; S_L, rho_L, k, M_L consistent with it.
  void setPressure(const std::function<Real(Real, Real)>& pressure) {
    setLiquidStates(points, material(), kPorosity,
                    [&](int, Real x, Real y) { return pressure(x, y); });
  }
  /// The liquid mass each point gains in one step of `dt` (kg): -V dt div(c w) added by the
  /// stabilisation (the rates start at zero, no strain).
  std::vector<Real> massChanges(Real dt, Real gravity, NodalExchange* exchange = nullptr) {
    Kokkos::deep_copy(rates.content_flux_divergence_increment_p, 0.0);
    LiquidHeadStabilisation stabilisation(table, mesh.numNodes(), exchange);
    stabilisation.apply(table, points, shapes, active, rates, dt, gravity);
    const auto flux = hostCopy(rates.content_flux_divergence_increment_p);
    const auto volume = hostCopy(points.volume);
    std::vector<Real> change(points.count);
    for (int q = 0; q < points.count; ++q) change[q] = -volume(q) * flux(q);
    return change;
  }
  /// dM_L/dp_L of a saturated point (kg/Pa).
  Real saturatedStorage(int q) const {
    const auto volume = hostCopy(points.volume);
    const auto rho = hostCopy(points.density_liquid);
    return kPorosity * volume(q) * rho(q) / kBulk;
  }
};

/// The checkerboard of the four-squares hand test (HeadScene(2, 2, 1.0, alpha)): + below
/// each cell's rising diagonal, - above it.
inline int checkerboardSign(Real x, Real y) {
  return x - std::floor(x) > y - std::floor(y) ? 1 : -1;
}
/// The hand value of LiquidHeadStabilisation.CheckerboardOnFourSquaresByHand: p_L 2500 +-
/// 1500 Pa (checkerboardSign), uncapped equal conductances g, no gravity. Node centres
/// (m_i; x_i): the four corners their own points' (4000 or 1000 at the point), the edge
/// middles the means of three points (3000 or 2000; (11/9, 4/9) and its mirror images), the
/// centre and the two diagonal corners 2500 at (1, 1), (1/2, 1/2), (3/2, 3/2). The gradients
/// through the centres: (4500, -4500)/7 Pa/m in the six triangles with a diagonal corner or
/// the centre, (1800, -1800) in the two at the lone corners (2, 0) and (0, 2); the node
/// slopes their means: (4500, -4500)/7 at the diagonal nodes, (7200, -7200)/7 at the edge
/// middles, (1800, -1800) at the lone corners. The points' phi_p minus their node planes
/// (Pa), by position (3x, 3y); the change is -dt g times it (kg).
inline Real fourSquaresHandChange(Real x, Real y, Real dt_conductance) {
  const int i = static_cast<int>(std::lround(3 * x)), j = static_cast<int>(std::lround(3 * y));
  Real residual = 0;
  if ((i == 2 && j == 1) || (i == 5 && j == 4)) residual = 9400.0 / 7;
  if ((i == 1 && j == 2) || (i == 4 && j == 5)) residual = -9400.0 / 7;
  if (i == 5 && j == 1) residual = 2000.0 / 7;
  if (i == 1 && j == 5) residual = -2000.0 / 7;
  if (i == 4 && j == 2) residual = -1900.0;
  if (i == 2 && j == 4) residual = 1900.0;
  return -dt_conductance * residual;
}

}  // namespace argine::test
