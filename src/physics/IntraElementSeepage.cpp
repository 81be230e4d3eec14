#include "argine/physics/IntraElementSeepage.hpp"

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
  if (active_) heads_.allocateSums(1, patch, elements, nodes);
}

void IntraElementSeepage::apply(const MaterialTable& table, const MaterialPoints& points,
                                const PointShapes& shapes, const ActiveNodes& active,
                                PointRates& rates, Real dt, Real gravity) {
  if (!active_) return;
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
        mode_p(p) = kAverageNone;
        weight_p(p) = 0;
        head_p(p) = 0;
        if (!carriesLiquid(material.phase) || !material.locking.intra_element_seepage ||
            pts.element(p) < 0)
          return;
        const Real pressure = pts.pressure_liquid(p);
        const Real storage = pointLiquidStorage(material, pts, p);            // kg/Pa
        const Real conductance = pointDarcyConductance(pts.conductivity(p));  // kg/(Pa s)
        const Real weight = starExchangeWeight(conductance, storage, dt);
        if (!(weight > 0)) return;
        mode_p(p) = static_cast<int>(material.locking.seepage_patch);
        weight_p(p) = weight;
        head_p(p) = piezometricPressure(material, pressure, pts.position(p, 1), gravity);
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
