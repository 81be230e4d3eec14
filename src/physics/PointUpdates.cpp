#include "argine/physics/PointUpdates.hpp"

#include "argine/core/UntrackedViews.hpp"

namespace argine {

namespace {

/// One pass: the gap closure and the five point updates, then the point's share of the sums [M_L,
/// points with an invalid state] (an array reduction). One call takes two chunks of kLanes
/// consecutive points: where a chunk's points are located points of one material with a lane
/// stress update (the common case once the points are sorted by element), the porosity, stress
/// and position updates run on all of them at once (core/Lanes.hpp), the liquid state point by
/// point; otherwise every point takes the one-point updates. Two such chunks of one material
/// find their liquid pressures together (updateLiquidPressureLanePair). The same bits either way,
/// and the sums add the points in their order.
struct PointStateUpdate {
  using value_type = Real[];
  using size_type = int;
  size_type value_count = 2;
  PointUpdateViews v;
  int count = 0;
  /// Chunks of kLanes points a call takes: the pair of operator() (a constant of that code,
  /// not a setting; updatePointStates sizes its range by it).
  static constexpr int kChunksPerCall = 2;

  KOKKOS_INLINE_FUNCTION bool lanesShareAMaterial(int p) const {
    if (p + kLanes > count) return false;
    const int material = v.points.material(p);
    for (int l = 0; l < kLanes; ++l)
      if (v.points.element(p + l) < 0 || v.points.material(p + l) != material) return false;
    return hasLaneStressUpdate(v.materials_m(material));
  }

  /// The updates before the liquid pressure, of the kLanes points from `first`.
  KOKKOS_INLINE_FUNCTION void beginLanes(int first) const {
    // a gap to close is rare (points that separated): one vector test for the four
    if (anyLane(load<Lanes>(v.points.separation, first) > 0))
      for (int p = first; p < first + kLanes; ++p) closeSeparation(v, p);
    updatePorosityAndVolume<Lanes>(v, first);
  }

  /// The updates after the liquid pressure, of the kLanes points from `first`.
  KOKKOS_INLINE_FUNCTION void endLanes(int first, const PointMaterial& material) const {
    updateEffectiveStressLanes(v, first, material);
    for (int p = first; p < first + kLanes; ++p) updateLiquidState(v, p);
    updatePointPosition<Lanes>(v, first);
  }

  /// The points first .. end - 1, each on its own.
  KOKKOS_INLINE_FUNCTION void updateOneByOne(int first, int end) const {
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

  /// One chunk: in lanes where lanesShareAMaterial, else point by point.
  KOKKOS_INLINE_FUNCTION void updateChunk(int first, int end) const {
    if (!lanesShareAMaterial(first)) return updateOneByOne(first, end);
    const PointMaterial& material = v.materials_m(v.points.material(first));
    beginLanes(first);
    updateLiquidPressureLanes(v, first, material);
    endLanes(first, material);
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int call, value_type sum) const {
    const int first = call * kChunksPerCall * kLanes, second = first + kLanes;
    const int end =
        first + kChunksPerCall * kLanes < count ? first + kChunksPerCall * kLanes : count;
    if (lanesShareAMaterial(first) && lanesShareAMaterial(second) &&
        v.points.material(first) == v.points.material(second)) {
      const PointMaterial& material = v.materials_m(v.points.material(first));
      beginLanes(first);
      beginLanes(second);
      updateLiquidPressureLanePair(v, first, material);
      endLanes(first, material);
      endLanes(second, material);
    } else {
      for (int chunk = first; chunk < end; chunk += kLanes)
        updateChunk(chunk, chunk + kLanes < end ? chunk + kLanes : end);
    }
    for (int p = first; p < end; ++p) sum[0] += v.points.mass_liquid(p);  // in point order
    for (int chunk = first; chunk < end; chunk += kLanes) {
      if (end - chunk >= kLanes) {
        const LaneMask valid = pointStateIsValid<Lanes>(v.points, chunk);
        for (int l = 0; l < kLanes; ++l) sum[1] += valid[l] ? 0 : 1;
      } else {
        for (int p = chunk; p < end; ++p) sum[1] += pointStateIsValid(v.points, p) ? 0 : 1;
      }
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
  // untracked: the kernel's copies count no references (UntrackedViews.hpp)
  kernel.v =
      PointUpdateViews{untracked(table.materials()), untracked(points),        untracked(rates),
                       hold_liquid_pressure,         untracked(air_reaches_e), renew_liquid_state};
  kernel.count = points.count;
  Real sums[2] = {0, 0};
  constexpr int kPointsPerCall = PointStateUpdate::kChunksPerCall * kLanes;
  const int calls = (points.count + kPointsPerCall - 1) / kPointsPerCall;
  Kokkos::parallel_reduce("update_point_states", Kokkos::RangePolicy<ExecSpace>(0, calls), kernel,
                          sums);
  PointTotals totals;
  totals.liquid_mass = sums[0];
  totals.non_finite_points = static_cast<int>(sums[1]);
  return totals;
}

}  // namespace argine
