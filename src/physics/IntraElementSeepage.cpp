#include "argine/physics/IntraElementSeepage.hpp"

#include <Kokkos_ScatterView.hpp>

#include "argine/core/UntrackedViews.hpp"
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

/// Whether the kLanes points p .. p + kLanes - 1 (all below `count`) take the lanes' forms
/// below: located points of one material that exchanges, saturated or unsaturated on the
/// linear retention curve (the slope's lanes form, RetentionCurve.hpp).
KOKKOS_INLINE_FUNCTION bool lanesExchangeTogether(
    const Kokkos::View<const PointMaterial*, MemSpace>& materials_m, const MaterialPoints& pts,
    int p, int count) {
  if (p + kLanes > count) return false;
  const int material = pts.material(p);
  for (int l = 0; l < kLanes; ++l)
    if (pts.element(p + l) < 0 || pts.material(p + l) != material) return false;
  const PointMaterial& m = materials_m(material);
  return carriesLiquid(m.phase) && m.locking.intra_element_seepage &&
         (m.phase == PhaseModel::Saturated || m.retention.model == RetentionModel::Linear);
}

/// exchangeWeightAndHead of kLanes such points at once: the same formulas lane by lane (the
/// storage of pointLiquidStorage with the linear curve's slope), so the same bits.
KOKKOS_INLINE_FUNCTION void exchangeWeightAndHeadLanes(const PointMaterial& material,
                                                       const MaterialPoints& pts, int p, Real dt,
                                                       Real gravity, Lanes& weight, Lanes& head) {
  const Lanes pressure = load<Lanes>(pts.pressure_liquid, p);
  Lanes ds_ds = splat<Lanes>(0);
  if (material.phase == PhaseModel::Unsaturated) {
    Lanes unused;
    linearSaturationAndSlopeAtPressure(material.retention, pressure, unused, ds_ds);
  }
  const Lanes storage = pointLiquidStorage(material, pts, p, ds_ds);
  const Lanes conductance = pointDarcyConductance(load<Lanes>(pts.conductivity, p));
  const Lanes w = starExchangeWeight(conductance, storage, dt);
  const LaneMask exchanges = w > 0;
  weight = select(exchanges, w, splat<Lanes>(0));
  head = select(exchanges,
                piezometricPressure(material, pressure, load<Lanes>(pts.position, p, 1), gravity),
                splat<Lanes>(0));
}

}  // namespace

void IntraElementSeepage::applyOverElements(const MaterialTable& table,
                                            const MaterialPoints& points, PointRates& rates,
                                            Real dt, Real gravity) {
  const int count = points.count;
  heads_.fitPoints(count);
  const auto materials_m = table.materials();
  const MaterialPoints pts = untracked(points);
  const auto weight_p = heads_.weight_p;
  auto sums = heads_.element_sums;  // (element, 0): sum w phi, (element, 1): sum w
  Kokkos::deep_copy(sums, 0.0);
  auto scatter = Kokkos::Experimental::create_scatter_view(sums);
  // By chunks of kLanes points: where they exchange together (lanesExchangeTogether), their
  // weights, heads and exchanges at once; the element sums are added point by point in
  // point order either way, so the bits are those of the one-point forms.
  const int chunks = (count + kLanes - 1) / kLanes;
  Kokkos::parallel_for(
      "intra_element_seepage_sums", Kokkos::RangePolicy<ExecSpace>(0, chunks),
      KOKKOS_LAMBDA(const int chunk) {
        const int first = chunk * kLanes, end = first + kLanes < count ? first + kLanes : count;
        auto access = scatter.access();
        const auto add = [&](int p, Real weight, Real head) {
          if (!(weight > 0)) return;
          const int e = pts.element(p);
          access(e, 0) += weight * head;
          access(e, 1) += weight;
        };
        if (lanesExchangeTogether(materials_m, pts, first, count)) {
          Lanes weight, head;
          exchangeWeightAndHeadLanes(materials_m(pts.material(first)), pts, first, dt, gravity,
                                     weight, head);
          store(weight_p, first, weight);
          for (int l = 0; l < kLanes; ++l) add(first + l, weight[l], head[l]);
          return;
        }
        for (int p = first; p < end; ++p) {
          Real weight, head;
          exchangeWeightAndHead(materials_m(pts.material(p)), pts, p, dt, gravity, weight, head);
          weight_p(p) = weight;
          add(p, weight, head);
        }
      });
  Kokkos::Experimental::contribute(sums, scatter);
  const PointRates rts = rates;
  Kokkos::parallel_for(
      "intra_element_seepage_exchange", Kokkos::RangePolicy<ExecSpace>(0, chunks),
      KOKKOS_LAMBDA(const int chunk) {
        const int first = chunk * kLanes, end = first + kLanes < count ? first + kLanes : count;
        // together: one material, every lane exchanging (so located)
        bool together = end - first == kLanes;
        for (int l = 0; l < kLanes && together; ++l)
          together = weight_p(first + l) > 0 && pts.material(first + l) == pts.material(first);
        if (together) {
          const PointMaterial& material = materials_m(pts.material(first));
          Lanes weighted_heads, weights;
          for (int l = 0; l < kLanes; ++l) {
            const int e = pts.element(first + l);
            weighted_heads[l] = sums(e, 0);
            weights[l] = sums(e, 1);
          }
          exchangeTowards(material, pts, rts, first, load<Lanes>(weight_p, first),
                          weighted_heads / weights, gravity);
          return;
        }
        for (int p = first; p < end; ++p) {
          const Real weight = weight_p(p);
          if (!(weight > 0)) continue;
          const int e = pts.element(p);
          exchangeTowards(materials_m(pts.material(p)), pts, rts, p, weight,
                          sums(e, 0) / sums(e, 1), gravity);
        }
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
  const MaterialPoints pts = untracked(points);
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
        // The point's own phi (its p_L and position are unchanged since the first kernel)
        // against the patch's centre value phi_c now in head_p.
        exchangeTowards(materials_m(pts.material(p)), pts, rts, p, weight_p(p), head_p(p), gravity);
      });
}

}  // namespace argine
