#include "argine/physics/IntraElementSeepage.hpp"

#include <Kokkos_ScatterView.hpp>

#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointLiquidExchange.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/PointRates.hpp"

namespace argine {

static_assert(static_cast<int>(IncrementAveraging::Element) == kAverageElement &&
                  static_cast<int>(IncrementAveraging::Nodal) == kAverageNodal,
              "the patch is read as the averaging mode");

IntraElementSeepage::IntraElementSeepage(const MaterialTable& table, int elements, int nodes,
                                         NodalExchange* exchange)
    : exchange_(exchange) {
  AveragingUse patch;
  for (int m = 0; m < table.count(); ++m) {
    const PointMaterial& material = table.host(m);
    if (!carriesLiquid(material.phase) || !material.locking.intra_element_seepage) continue;
    active_ = true;
    patch.add(static_cast<int>(material.locking.seepage_patch));
  }
  element_patches_ = active_ && !patch.nodes;
  if (active_) heads_.allocateSums(1, patch, elements, nodes);
}

namespace {

/// Point p's exchange weight w_p (0: the point does not exchange) and piezometric pressure
/// phi_p: the one formula of both paths.
KOKKOS_INLINE_FUNCTION void exchangeWeightAndHead(const PointMaterial& material,
                                                  const MaterialPoints& pts, int p, Real dt,
                                                  Real gravity, Real& weight, Real& head) {
  weight = 0;
  head = 0;
  if (!carriesLiquid(material.phase) || !material.locking.intra_element_seepage ||
      pts.element(p) < 0)
    return;
  const Real pressure = pts.pressure_liquid(p);
  const Real storage = pointLiquidStorage(material, pts, p);            // kg/Pa
  const Real conductance = pointDarcyConductance(pts.conductivity(p));  // kg/(Pa s)
  const Real w = starExchangeWeight(conductance, storage, dt);
  if (!(w > 0)) return;
  weight = w;
  head = piezometricPressure(material, pressure, pts.position(p, 1), gravity);
}

}  // namespace

void IntraElementSeepage::applyOverElements(const MaterialTable& table,
                                            const MaterialPoints& points, PointRates& rates,
                                            Real dt, Real gravity) {
  const int count = points.count;
  heads_.fitPoints(count);
  const auto materials_m = table.materials();
  const MaterialPoints pts = points;
  const auto weight_p = heads_.weight_p;
  auto sums = heads_.element_sums;  // (element, 0): sum w phi, (element, 1): sum w
  Kokkos::deep_copy(sums, 0.0);
  auto scatter = Kokkos::Experimental::create_scatter_view(sums);
  Kokkos::parallel_for(
      "intra_element_seepage_sums", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        Real weight, head;
        exchangeWeightAndHead(materials_m(pts.material(p)), pts, p, dt, gravity, weight, head);
        weight_p(p) = weight;
        if (!(weight > 0)) return;
        const int e = pts.element(p);
        auto access = scatter.access();
        access(e, 0) += weight * head;
        access(e, 1) += weight;
      });
  Kokkos::Experimental::contribute(sums, scatter);
  const PointRates rts = rates;
  Kokkos::parallel_for(
      "intra_element_seepage_exchange", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        const Real weight = weight_p(p);
        if (!(weight > 0)) return;
        const PointMaterial& material = materials_m(pts.material(p));
        const int e = pts.element(p);
        const Real centre = sums(e, 0) / sums(e, 1);
        const Real own =
            piezometricPressure(material, pts.pressure_liquid(p), pts.position(p, 1), gravity);
        addPointLiquidMassChange(material, pts, rts, p, weight * (centre - own));
      });
}

void IntraElementSeepage::apply(const MaterialTable& table, const MaterialPoints& points,
                                const PointShapes& shapes, const ActiveNodes& active,
                                PointRates& rates, Real dt, Real gravity) {
  if (!active_) return;
  if (element_patches_ && !heads_.compensated())
    return applyOverElements(table, points, rates, dt, gravity);
  const int count = points.count;
  heads_.fitPoints(count);
  const auto materials_m = table.materials();
  const MaterialPoints pts = points;
  const auto head_p = Kokkos::subview(heads_.value_pc, Kokkos::ALL, 0);
  const auto weight_p = heads_.weight_p;
  const auto mode_p = Kokkos::subview(heads_.mode_pc, Kokkos::ALL, 0);
  Kokkos::parallel_for(
      "intra_element_seepage_in", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        const PointMaterial& material = materials_m(pts.material(p));
        Real weight, head;
        exchangeWeightAndHead(material, pts, p, dt, gravity, weight, head);
        mode_p(p) = weight > 0 ? static_cast<int>(material.locking.seepage_patch) : kAverageNone;
        weight_p(p) = weight;
        head_p(p) = head;
      });
  averagePointValues(points, shapes, active, heads_, exchange_);
  const PointRates rts = rates;
  Kokkos::parallel_for(
      "intra_element_seepage_out", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        if (mode_p(p) == kAverageNone) return;
        const PointMaterial& material = materials_m(pts.material(p));
        // The point's own phi (its p_L and position are unchanged since the first kernel)
        // against the element's centre value phi_c now in head_p.
        const Real own =
            piezometricPressure(material, pts.pressure_liquid(p), pts.position(p, 1), gravity);
        addPointLiquidMassChange(material, pts, rts, p, weight_p(p) * (head_p(p) - own));
      });
}

}  // namespace argine
