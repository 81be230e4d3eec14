#include "argine/physics/PointUpdates.hpp"

namespace argine {

namespace {

/// One pass: the gap closure and the five point updates, then the point's share of the sums [M_L,
/// points with an invalid state] (an array reduction). One call takes kLanes consecutive points:
/// where they are located points of one material with a lane stress update (the common case once
/// the points are sorted by element), the porosity, stress and position updates run on all of them
/// at once (core/Lanes.hpp), the liquid updates point by point; otherwise every point takes the
/// one-point updates. The same bits either way, and the sums add the points in their order.
struct PointStateUpdate {
  using value_type = Real[];
  using size_type = int;
  size_type value_count = 2;
  PointUpdateViews v;
  int count = 0;

  KOKKOS_INLINE_FUNCTION bool lanesShareAMaterial(int p) const {
    if (p + kLanes > count) return false;
    const int material = v.points.material(p);
    for (int l = 0; l < kLanes; ++l)
      if (v.points.element(p + l) < 0 || v.points.material(p + l) != material) return false;
    return hasLaneStressUpdate(v.materials_m(material));
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int chunk, value_type sum) const {
    const int first = chunk * kLanes, end = first + kLanes < count ? first + kLanes : count;
    if (lanesShareAMaterial(first)) {
      const PointMaterial& material = v.materials_m(v.points.material(first));
      // a gap to close is rare (points that separated): one vector test for the four
      if (anyLane(load<Lanes>(v.points.separation, first) > 0))
        for (int p = first; p < end; ++p) closeSeparation(v, p);
      updatePorosityAndVolume<Lanes>(v, first);
      updateLiquidPressureLanes(v, first, material);
      updateEffectiveStressLanes(v, first, material);
      for (int p = first; p < end; ++p) updateLiquidState(v, p);
      updatePointPosition<Lanes>(v, first);
    } else {
      for (int p = first; p < end; ++p) {
        if (v.points.element(p) < 0) continue;
        closeSeparation(v, p);
        updatePorosityAndVolume(v, p);
        updateLiquidPressure(v, p);
        updateEffectiveStress(v, p);
        updateLiquidState(v, p);
        updatePointPosition(v, p);
      }
    }
    for (int p = first; p < end; ++p) sum[0] += v.points.mass_liquid(p);  // in point order
    if (end - first == kLanes) {
      const LaneMask valid = pointStateIsValid<Lanes>(v.points, first);
      for (int l = 0; l < kLanes; ++l) sum[1] += valid[l] ? 0 : 1;
    } else {
      for (int p = first; p < end; ++p) sum[1] += pointStateIsValid(v.points, p) ? 0 : 1;
    }
  }
  KOKKOS_INLINE_FUNCTION void init(value_type sum) const {
    for (int k = 0; k < value_count; ++k) sum[k] = 0;
  }
  KOKKOS_INLINE_FUNCTION void join(volatile value_type dst, const volatile value_type src) const {
    for (int k = 0; k < value_count; ++k) dst[k] += src[k];
  }
};

}  // namespace

PointTotals updatePointStates(const MaterialTable& table, const PointRates& rates,
                              MaterialPoints& points, bool hold_liquid_pressure,
                              Kokkos::View<const unsigned char*, MemSpace> air_reaches_e,
                              bool renew_liquid_state) {
  PointStateUpdate kernel;
  kernel.v = PointUpdateViews{table.materials(),    points,        rates,
                              hold_liquid_pressure, air_reaches_e, renew_liquid_state};
  kernel.count = points.count;
  Real sums[2] = {0, 0};
  const int chunks = (points.count + kLanes - 1) / kLanes;
  Kokkos::parallel_reduce("update_point_states", Kokkos::RangePolicy<ExecSpace>(0, chunks), kernel,
                          sums);
  PointTotals totals;
  totals.liquid_mass = sums[0];
  totals.non_finite_points = static_cast<int>(sums[1]);
  return totals;
}

}  // namespace argine
