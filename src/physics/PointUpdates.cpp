#include "argine/physics/PointUpdates.hpp"

namespace argine {

namespace {

/// One pass: the five point updates, then the point's share of the sums [M_L, points with an
/// invalid state] (an array reduction).
struct PointStateUpdate {
  using value_type = Real[];
  using size_type = int;
  size_type value_count = 2;
  PointUpdateViews v;

  KOKKOS_INLINE_FUNCTION void operator()(const int p, value_type sum) const {
    if (v.points.element(p) >= 0) {
      updatePorosityAndVolume(v, p);
      updateLiquidPressure(v, p);
      updateEffectiveStress(v, p);
      updateLiquidState(v, p);
      updatePointPosition(v, p);
    }
    sum[0] += v.points.mass_liquid(p);
    if (!pointStateIsValid(v.points, p)) sum[1] += 1;
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
                              MaterialPoints& points, bool hold_liquid_pressure) {
  PointStateUpdate kernel;
  kernel.v = PointUpdateViews{table.materials(), points, rates, hold_liquid_pressure};
  Real sums[2] = {0, 0};
  Kokkos::parallel_reduce("update_point_states", Kokkos::RangePolicy<ExecSpace>(0, points.count),
                          kernel, sums);
  PointTotals totals;
  totals.liquid_mass = sums[0];
  totals.non_finite_points = static_cast<int>(sums[1]);
  return totals;
}

}  // namespace argine
