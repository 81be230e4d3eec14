// The Darcy exchange between the points of one element (physics/IntraElementSeepage.hpp):
// the implicit star weight by hand, a saturated point's excess pressure shared within its
// element with the element's liquid mass kept (at its Darcy rate, and without overshoot in a
// long step), unsaturated points at their Darcy rate, and hydrostatic elements left alone;
// the nodal patch: a point alone in its cell exchanges with its neighbours across the edge.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "../transfer/TestScenes.hpp"
#include "LiquidPointStates.hpp"
#include "argine/physics/IntraElementSeepage.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointLiquidExchange.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {
namespace {

using test::hostCopy;

constexpr Real kPorosity = 0.4, kConductivity = 3.92e-4, kBulk = 8e7, kSlope = 4e-7;

/// dM_L/dp_L (kg/Pa) of point q at its pressure, by hand: n V rho_L (S_L/K_L - dS_L/ds).
Real pointStorage(const MaterialPoints& points, const PointMaterial& material, int q) {
  const Real p = hostCopy(points.pressure_liquid)(q);
  const Real ds_ds = saturationSuctionDerivative(material.retention, suctionOfPressure(p));
  return kPorosity * hostCopy(points.volume)(q) *
         liquidContentSlope(hostCopy(points.density_liquid)(q), hostCopy(points.saturation)(q),
                            ds_ds, kBulk);
}

TEST(IntraElementSeepage, StarWeightByHand) {
  // dt g = 0.5 x 2 = 1 kg/Pa, C = 3 kg/Pa: w = 1 x 3 / (1 + 3) = 0.75
  EXPECT_DOUBLE_EQ(starExchangeWeight(2.0, 3.0, 0.5), 0.75);
  // no storage: nothing moves; no conductance: nothing moves
  EXPECT_EQ(starExchangeWeight(2.0, 0.0, 0.5), 0.0);
  EXPECT_EQ(starExchangeWeight(0.0, 3.0, 0.5), 0.0);
  // C << dt g: w -> C (the point takes the centre's phi); dt g << C: w -> dt g (explicit)
  EXPECT_NEAR(starExchangeWeight(1.0, 1e-12, 1.0), 1e-12, 1e-23);
  EXPECT_NEAR(starExchangeWeight(1e-12, 1.0, 1.0), 1e-12, 1e-23);
}

/// Two triangles of a 0.2 m square, three points each, the levee's soil (linear retention
/// a_v = 4e-7 1/Pa, k = 3.92e-4 m/s, K_L = 80 MPa), p_L set per point.
struct TwoTriangles {
  Mesh mesh = test::rectangleMesh(1, 1, 0.2, 0.2, ElementType::Tri3);
  MaterialPoints points = test::seedUniform(mesh);
  MaterialTable table;
  PointShapes shapes;
  PointRates rates;
  ActiveNodes active{mesh.numNodes()};
  TwoTriangles() {
    MaterialSpec soil = test::elasticMaterial("soil", PhaseModel::Unsaturated, 5e7, 0.3, kPorosity,
                                              kConductivity, kBulk);
    soil.retention.model = RetentionModel::Linear;
    soil.retention.linear_slope = kSlope;
    soil.locking.intra_element_seepage = true;
    table = MaterialTable({soil});
    evaluatePointShapes(mesh, points, shapes);
    rates.allocate(points.count);
    active.rebuild(mesh, points);
  }
  const PointMaterial& material() const { return table.host(0); }
  void setPressure(const std::function<Real(int, Real)>& pressure) {  // (point, y)
    test::setLiquidStates(points, material(), kPorosity,
                          [&](int q, Real, Real y) { return pressure(q, y); });
  }
  /// The liquid mass each point gains in one step of `dt` (kg): -V dt div(c w) added by the
  /// exchange (the rates start at zero, no strain).
  std::vector<Real> massChanges(Real dt, Real gravity) {
    Kokkos::deep_copy(rates.content_flux_divergence_increment_p, 0.0);
    IntraElementSeepage seepage(table, mesh.numElements(), mesh.numNodes());
    EXPECT_TRUE(seepage.active());
    seepage.apply(table, points, shapes, active, rates, dt, gravity);
    const auto flux = hostCopy(rates.content_flux_divergence_increment_p);
    const auto volume = hostCopy(points.volume);
    std::vector<Real> change(points.count);
    for (int q = 0; q < points.count; ++q) change[q] = -volume(q) * flux(q);
    return change;
  }
  Real storage(int q) const { return pointStorage(points, material(), q); }
};

// Element 0 as in the levee slide: one saturated point at +300 kPa beside two unsaturated
// ones at -3 kPa; element 1 uniform at +5 kPa. No gravity (phi = p_L). Storage C = n V rho_L
// (S_L/K_L - dS_L/ds): saturated 3.3e-8 kg/Pa, unsaturated 1.1e-6 kg/Pa (33 times more).
TEST(IntraElementSeepage, SaturatedExcessSharedWithinTheElement) {
  TwoTriangles scene;
  const auto element = hostCopy(scene.points.element);
  int high = -1;
  scene.setPressure([&](int q, Real) {
    if (element(q) != 0) return 5000.0;
    if (high < 0) {
      high = q;
      return 300e3;
    }
    return -3000.0;
  });
  const auto pressure = hostCopy(scene.points.pressure_liquid);
  const Real g = kConductivity / 9.81;
  // By hand: w_q = dt g C_q / (C_q + dt g), phi_c = sum w phi / sum w, dM_q = w_q (phi_c -
  // phi_q), and the point's new p_L = p_L + dM / C (linearised).
  auto byHand = [&](Real dt, std::vector<Real>& next) {
    Real sum_w = 0, sum_wphi = 0;
    for (int q = 0; q < scene.points.count; ++q) {
      if (element(q) != 0) continue;
      const Real w = dt * g * scene.storage(q) / (scene.storage(q) + dt * g);
      sum_w += w;
      sum_wphi += w * pressure(q);
    }
    const Real centre = sum_wphi / sum_w;
    const std::vector<Real> change = scene.massChanges(dt, 0.0);
    Real element_sum = 0;
    next.assign(scene.points.count, 0.0);
    for (int q = 0; q < scene.points.count; ++q) {
      if (element(q) != 0) {  // uniform: nothing moves (round-off only)
        EXPECT_LT(std::fabs(change[q]), 1e-12 * std::fabs(change[high]));
        continue;
      }
      const Real w = dt * g * scene.storage(q) / (scene.storage(q) + dt * g);
      EXPECT_NEAR(change[q], w * (centre - pressure(q)), 1e-12 * std::fabs(w * pressure(q)));
      element_sum += change[q];
      next[q] = pressure(q) + change[q] / scene.storage(q);
    }
    EXPECT_NEAR(element_sum, 0.0, 1e-12 * std::fabs(change[high]));  // the element's mass kept
    return centre;
  };
  // The levee's step, dt g = 1.2e-9 kg/Pa < C: all three move at their Darcy rate; the
  // saturated point 3.5 % of its gap to the centre per step (time scale C / g = 0.8 ms), the
  // unsaturated ones 33 times slower.
  std::vector<Real> next;
  const Real centre = byHand(3e-5, next);
  EXPECT_NEAR((pressure(high) - next[high]) / (pressure(high) - centre), 0.035, 0.002);
  // A step much longer than both time scales (dt = 1 s, dt g = 4e-5 kg/Pa >> C): implicit, so
  // no overshoot; every point lands within 1 kPa of the equilibrium, the storage-weighted mean
  // (3.3e-8 x 300 kPa - 2 x 1.1e-6 x 3 kPa) / 2.2e-6 = +1.5 kPa.
  Real storage_sum = 0, equilibrium = 0;
  for (int q = 0; q < scene.points.count; ++q) {
    if (element(q) != 0) continue;
    storage_sum += scene.storage(q);
    equilibrium += scene.storage(q) * pressure(q);
  }
  equilibrium /= storage_sum;
  EXPECT_NEAR(equilibrium, 1500.0, 200.0);
  byHand(1.0, next);
  for (int q = 0; q < scene.points.count; ++q) {
    if (element(q) != 0) continue;
    EXPECT_NEAR(next[q], equilibrium, 1000.0) << "point " << q;
  }
}

// The unsaturated points of an element (dt g << C) exchange at their Darcy rate; a
// hydrostatic pair of elements (phi uniform under gravity) is left alone.
TEST(IntraElementSeepage, UnsaturatedAtDarcyRateAndHydrostaticLeftAlone) {
  TwoTriangles scene;
  const Real gravity = 9.81, rho_g = 1000 * gravity;
  scene.setPressure([&](int, Real y) { return rho_g * (0.1 - y); });  // water table at 0.1 m
  std::vector<Real> change = scene.massChanges(3e-5, gravity);
  // phi = p_L + rho_L0 g y = 981 Pa everywhere: no exchange (round-off of the sums only)
  for (const Real dm : change) EXPECT_LT(std::fabs(dm), 1e-20);

  const auto element = hostCopy(scene.points.element);
  bool first = true;
  scene.setPressure([&](int q, Real) {
    if (element(q) != 0) return -5000.0;
    const Real p = first ? -20000.0 : -5000.0;
    first = false;
    return p;
  });
  const Real dt = 3e-5, g = kConductivity / 9.81;
  change = scene.massChanges(dt, 0.0);
  // S_L < 1: C = n V rho (S_L/K_L + a_v) ~ 1.1e-6 kg/Pa >> dt g = 1.2e-9: w = dt g to 1e-3,
  // phi_c = the mean of the three (equal w to 1e-3): -10 kPa; the low point gains dt g 10 kPa
  for (int q = 0; q < scene.points.count; ++q) {
    if (element(q) != 0) continue;
    const Real p = hostCopy(scene.points.pressure_liquid)(q);
    EXPECT_NEAR(change[q], dt * g * (-10000.0 - p), 2e-3 * dt * g * 10000.0);
  }
}

/// Three 0.2 m quad4 cells in a row, the levee's soil; cells 0 and 1 seeded with 2 x 2
/// points, then the last point of cell 1 moved into cell 2 at the same local position, so
/// that it is alone in its cell and shares the nodes of the edge x = 0.4 m with cell 1's
/// three points (as a shear band on a grid leaves single points in cells). `patch` is the
/// material's Seepage Patch.
struct LonePointInACell {
  static constexpr Real kCell = 0.2;
  Mesh mesh = test::rectangleMesh(3, 1, 3 * kCell, kCell, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh, 0, [](int e) { return e < 2; });
  MaterialTable table;
  PointShapes shapes;
  PointRates rates;
  ActiveNodes active{mesh.numNodes()};
  int lone = -1;
  explicit LonePointInACell(IncrementAveraging patch) {
    MaterialSpec soil = test::elasticMaterial("soil", PhaseModel::Unsaturated, 5e7, 0.3, kPorosity,
                                              kConductivity, kBulk);
    soil.retention.model = RetentionModel::Linear;
    soil.retention.linear_slope = kSlope;
    soil.locking.intra_element_seepage = true;
    soil.locking.seepage_patch = patch;
    table = MaterialTable({soil});
    lone = points.count - 1;
    auto element = hostCopy(points.element);
    auto position = hostCopy(points.position);
    EXPECT_EQ(element(lone), 1);
    element(lone) = 2;
    position(lone, 0) += kCell;
    Kokkos::deep_copy(points.element, element);
    Kokkos::deep_copy(points.position, position);
    evaluatePointShapes(mesh, points, shapes);
    rates.allocate(points.count);
    active.rebuild(mesh, points);
  }
  /// Bilinear N of the node at (X, Y) at (x, y) on these cells (tensor-product hats).
  static Real hat(Real X, Real Y, Real x, Real y) {
    return std::max(0.0, 1 - std::fabs(x - X) / kCell) *
           std::max(0.0, 1 - std::fabs(y - Y) / kCell);
  }
};

// With the element patch the lone point exchanges with nobody, whatever its excess; with the
// nodal patch it is drawn to the weighted centres of its nodes by hand (phi_i = sum N w phi /
// sum N w, target sum N phi_i, dM = w (target - phi)), it loses liquid to its neighbours
// across the edge, and the body's liquid mass is kept.
TEST(IntraElementSeepage, NodalPatchReachesAPointAloneInItsCell) {
  const Real dt = 3e-5, g = kConductivity / 9.81;
  for (const IncrementAveraging patch : {IncrementAveraging::Element, IncrementAveraging::Nodal}) {
    LonePointInACell scene(patch);
    const PointMaterial& material = scene.table.host(0);
    test::setLiquidStates(scene.points, material, kPorosity,
                          [&](int q, Real, Real) { return q == scene.lone ? 300e3 : -3000.0; });
    Kokkos::deep_copy(scene.rates.content_flux_divergence_increment_p, 0.0);
    IntraElementSeepage seepage(scene.table, scene.mesh.numElements(), scene.mesh.numNodes());
    seepage.apply(scene.table, scene.points, scene.shapes, scene.active, scene.rates, dt, 0.0);
    const auto flux = hostCopy(scene.rates.content_flux_divergence_increment_p);
    const auto volume = hostCopy(scene.points.volume);
    const auto pressure = hostCopy(scene.points.pressure_liquid);
    const auto x = hostCopy(scene.points.position);
    const int n = scene.points.count;
    std::vector<Real> change(n), weight(n);
    Real total = 0;
    for (int q = 0; q < n; ++q) {
      change[q] = -volume(q) * flux(q);
      total += change[q];
      weight[q] = starExchangeWeight(g, pointStorage(scene.points, material, q), dt);
    }
    const Real scale = weight[scene.lone] * 300e3;
    EXPECT_NEAR(total, 0.0, 1e-12 * scale);  // the liquid mass of the body kept
    if (patch == IncrementAveraging::Element) {
      EXPECT_EQ(change[scene.lone], 0.0);  // alone in its element: no exchange
      continue;
    }
    const auto X = hostCopy(scene.mesh.coordinates);
    for (int q = 0; q < n; ++q) {
      Real target = 0;
      for (int i = 0; i < scene.mesh.numNodes(); ++i) {
        const Real N_q = LonePointInACell::hat(X(i, 0), X(i, 1), x(q, 0), x(q, 1));
        if (N_q == 0) continue;
        Real sum_w = 0, sum_wphi = 0;
        for (int r = 0; r < n; ++r) {
          const Real N_r = LonePointInACell::hat(X(i, 0), X(i, 1), x(r, 0), x(r, 1));
          sum_w += N_r * weight[r];
          sum_wphi += N_r * weight[r] * pressure(r);
        }
        target += N_q * sum_wphi / sum_w;
      }
      EXPECT_NEAR(change[q], weight[q] * (target - pressure(q)), 1e-10 * scale) << "point " << q;
    }
    EXPECT_LT(change[scene.lone], -0.1 * scale);  // it drains into its neighbours
  }
}

// The element patch exchanges in its own two kernels (IntraElementSeepage::applyOverElements):
// the same as the generic averaging of the heads (averagePointValues, element mode) followed
// by the exchange, bit for bit, with gravity and unequal pressures in both elements.
TEST(IntraElementSeepage, ElementPatchEqualsTheGenericAveragingBitForBit) {
  TwoTriangles scene;
  scene.setPressure(
      [](int q, Real y) { return -4000.0 + 2500.0 * std::sin(1.0 + 3 * q) - 9810 * y; });
  const Real dt = 2e-4, gravity = 9.81;
  const std::vector<Real> change = scene.massChanges(dt, gravity);

  const PointMaterial& material = scene.material();
  const int n = scene.points.count;
  AveragingScratch heads;
  AveragingUse use;
  use.add(kAverageElement);
  heads.allocateSums(1, use, scene.mesh.numElements(), scene.mesh.numNodes());
  heads.fitPoints(n);
  auto mode = Kokkos::create_mirror_view(heads.mode_pc);
  auto value = Kokkos::create_mirror_view(heads.value_pc);
  auto weight = Kokkos::create_mirror_view(heads.weight_p);
  const auto pressure = hostCopy(scene.points.pressure_liquid);
  const auto position = hostCopy(scene.points.position);
  const auto conductivity = hostCopy(scene.points.conductivity);
  const auto volume = hostCopy(scene.points.volume);
  std::vector<Real> own(n);
  for (int q = 0; q < n; ++q) {
    weight(q) = starExchangeWeight(pointDarcyConductance(conductivity(q)), scene.storage(q), dt);
    mode(q, 0) = weight(q) > 0 ? kAverageElement : kAverageNone;
    own[q] = piezometricPressure(material, pressure(q), position(q, 1), gravity);
    value(q, 0) = own[q];
  }
  Kokkos::deep_copy(heads.mode_pc, mode);
  Kokkos::deep_copy(heads.value_pc, value);
  Kokkos::deep_copy(heads.weight_p, weight);
  averagePointValues(scene.points, scene.shapes, scene.active, heads, nullptr);
  Kokkos::deep_copy(value, heads.value_pc);
  for (int q = 0; q < n; ++q) {
    const Real mass_change = weight(q) * (value(q, 0) - own[q]);
    const Real flux = 0.0 - mass_change / volume(q);  // addPointLiquidMassChange, complete form
    EXPECT_EQ(change[q], -volume(q) * flux) << "point " << q;
    EXPECT_NE(change[q], 0.0) << "point " << q;
  }
}

}  // namespace
}  // namespace argine
