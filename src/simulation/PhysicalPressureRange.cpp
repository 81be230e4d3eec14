#include "argine/simulation/PhysicalPressureRange.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "argine/boundary/HydraulicConditions.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/materials/RetentionCurve.hpp"

namespace argine {

namespace {

/// The largest value a condition's series reaches (its rows; a constant is one row).
Real largestValue(const TimeSeriesSpec& spec) {
  const TimeSeries series = makeTimeSeries(spec, 0);
  return *std::max_element(series.values().begin(), series.values().end());
}

}  // namespace

StageSurcharge stageSurcharge(const StageSpec& stage) {
  StageSurcharge surcharge;
  for (const auto& boundary : stage.boundaries) {
    switch (boundary.kind) {
      case BoundaryKind::TotalHead: {
        const Real level = largestValue(boundary.hydraulic.series);
        if (level > surcharge.water_level) {
          surcharge.water_level = level;
          surcharge.water_density = boundary.hydraulic.liquid_density;
        }
        break;
      }
      case BoundaryKind::PressureSeries:
        surcharge.surface_pressure =
            std::max(surcharge.surface_pressure, largestValue(boundary.hydraulic.series));
        if (boundary.hydraulic.linear_in_x)  // the other end of a pressure linear in x
          surcharge.surface_pressure =
              std::max(surcharge.surface_pressure, largestValue(boundary.hydraulic.end_series));
        break;
      case BoundaryKind::LiquidPressure:
        surcharge.surface_pressure = std::max(surcharge.surface_pressure, boundary.pressure);
        break;
      case BoundaryKind::Traction:
        surcharge.surface_pressure = std::max(
            surcharge.surface_pressure, std::hypot(boundary.traction[0], boundary.traction[1]));
        break;
      default:
        break;
    }
  }
  return surcharge;
}

namespace {

/// The located points' largest mixture density (M_S + M_L)/V and their top and bottom (centre
/// +- half the side sqrt(V) of the point's square); top < bottom without located points.
struct PointsExtent {
  Real density = 0, top = -kmath::infinity(), bottom = kmath::infinity();
};
PointsExtent pointsExtent(const MaterialPoints& points) {
  const MaterialPoints pts = points;
  PointsExtent e;
  Kokkos::parallel_reduce(
      "overburden_extent", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, Real& rho, Real& high, Real& low) {
        if (pts.element(p) < 0) return;
        const Real volume = pts.volume(p);
        const Real half = 0.5 * kmath::sqrt(volume);  // half the side of the point's square
        const Real y = pts.position(p, 1);
        const Real mixture = (pts.mass_solid(p) + pts.mass_liquid(p)) / volume;
        if (mixture > rho) rho = mixture;
        if (y + half > high) high = y + half;
        if (y - half < low) low = y - half;
      },
      Kokkos::Max<Real>(e.density), Kokkos::Max<Real>(e.top), Kokkos::Min<Real>(e.bottom));
  return e;
}

}  // namespace

Real largestTotalVerticalStress(const MaterialPoints& points, Real gravity,
                                const StageSurcharge& surcharge) {
  const PointsExtent e = pointsExtent(points);
  if (!(e.top >= e.bottom)) return 0;  // no located point
  const Real water_above = std::max<Real>(surcharge.water_level - e.top, 0);
  return gravity * (e.density * (e.top - e.bottom) + surcharge.water_density * water_above) +
         surcharge.surface_pressure;
}

std::vector<Real> lowestPhysicalPressures(const MaterialPoints& initial,
                                          const std::vector<MaterialSpec>& materials,
                                          Real gravity) {
  const auto material = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), initial.material);
  const auto pressure =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), initial.pressure_liquid);
  std::vector<Real> lowest(materials.size(), 0.0);  // p_L = 0 is always reachable
  for (int p = 0; p < initial.count; ++p) {
    const int m = material(p);
    if (m >= 0 && m < static_cast<int>(lowest.size())) lowest[m] = std::min(lowest[m], pressure(p));
  }
  const PointsExtent extent = pointsExtent(initial);
  const Real height = extent.top >= extent.bottom ? extent.top - extent.bottom : 0;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    if (materials[m].phase == PhaseModel::Dry) {
      lowest[m] = -kmath::infinity();
      continue;
    }
    // drained to a water table at the bottom of the model: rho_L g H of suction at the top
    lowest[m] = std::min(lowest[m], -materials[m].liquid.density * gravity * height);
    if (materials[m].phase != PhaseModel::Unsaturated) continue;
    const RetentionSpec& retention = materials[m].retention;
    const Real largest_suction = suctionFromSaturation(retention, retention.saturation_min);
    if (std::isfinite(largest_suction)) lowest[m] = std::max(lowest[m], -largest_suction);
  }
  return lowest;
}

PressureRangeCount countPressuresOutsideRange(const MaterialPoints& points,
                                              const std::vector<MaterialSpec>& materials,
                                              const std::vector<Real>& lowest, Real highest) {
  PressureRangeCount count;
  count.highest = highest;
  if (points.count == 0) return count;
  const int materials_count = static_cast<int>(materials.size());
  Kokkos::View<Real*, MemSpace> lowest_m("pressure_range_lowest", materials_count);
  auto lowest_h = Kokkos::create_mirror_view(lowest_m);
  for (int m = 0; m < materials_count; ++m)
    lowest_h(m) = materials[m].phase == PhaseModel::Dry || m >= static_cast<int>(lowest.size())
                      ? -kmath::infinity()
                      : lowest[m];
  Kokkos::deep_copy(lowest_m, lowest_h);
  const MaterialPoints pts = points;
  // How far a point lies outside its range (Pa, > 0 outside); dry materials (lowest
  // -infinity, p_L 0) never are.
  auto excess = KOKKOS_LAMBDA(const int p) {
    const Real pressure = pts.pressure_liquid(p);
    const Real low = lowest_m(pts.material(p));
    if (pts.element(p) < 0 || low == -kmath::infinity()) return Real(0);
    if (pressure > highest) return pressure - highest;
    if (pressure < low) return low - pressure;
    return Real(0);
  };
  int outside = 0, above = 0;
  Kokkos::parallel_reduce(
      "pressures_outside_range", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& out, int& up) {
        if (!(excess(p) > 0)) return;
        out += 1;
        if (pts.pressure_liquid(p) > highest) up += 1;
      },
      Kokkos::Sum<int>(outside), Kokkos::Sum<int>(above));
  // (Kokkos 3.4 cannot combine a MaxLoc with other reducers: a second pass, only when needed.)
  using Reducer = Kokkos::MaxLoc<Real, int>;
  Reducer::value_type worst;
  if (outside > 0)
    Kokkos::parallel_reduce(
        "worst_pressure_outside_range", Kokkos::RangePolicy<ExecSpace>(0, points.count),
        KOKKOS_LAMBDA(const int p, Reducer::value_type& max) {
          const Real e = excess(p);
          if (e > max.val) {
            max.val = e;
            max.loc = p;
          }
        },
        Reducer(worst));
  count.outside = outside;
  count.above = above;
  if (outside == 0) return count;
  const int p = worst.loc;
  auto one = std::make_pair(p, p + 1);
  const auto id =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(points.id, one));
  const auto material = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(),
                                                            Kokkos::subview(points.material, one));
  const auto pressure = Kokkos::create_mirror_view_and_copy(
      Kokkos::HostSpace(), Kokkos::subview(points.pressure_liquid, one));
  const auto position = Kokkos::create_mirror_view_and_copy(
      Kokkos::HostSpace(), Kokkos::subview(points.position, one, Kokkos::ALL));
  count.worst_id = id(0);
  count.worst_pressure = pressure(0);
  count.worst_bound = pressure(0) > highest ? highest : lowest_h(material(0));
  for (int d = 0; d < kDim; ++d) count.worst_position[d] = position(0, d);
  return count;
}

std::string describePressureRange(const PressureRangeCount& count, Real time) {
  char line[320];
  std::snprintf(line, sizeof line,
                "%d point(s) with p_L outside the physical range at t = %.6g s (%d above "
                "sigma_v,max = %.4g kPa, %d below their material's lowest p_L); worst: point %d "
                "at (%.4g, %.4g) m, p_L = %.4g kPa (bound %.4g kPa)",
                count.outside, time, count.above, count.highest / 1e3, count.outside - count.above,
                count.worst_id, count.worst_position[0], count.worst_position[1],
                count.worst_pressure / 1e3, count.worst_bound / 1e3);
  return line;
}

}  // namespace argine
