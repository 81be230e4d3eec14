#include "argine/physics/StabilityCheck.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "argine/physics/MaterialTable.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

namespace {

KOKKOS_INLINE_FUNCTION Real kineticEnergy(const MaterialPoints& pts, int p) {
  const Real vs2 = pts.velocity_solid(p, 0) * pts.velocity_solid(p, 0) +
                   pts.velocity_solid(p, 1) * pts.velocity_solid(p, 1);
  const Real vl2 = pts.velocity_liquid(p, 0) * pts.velocity_liquid(p, 0) +
                   pts.velocity_liquid(p, 1) * pts.velocity_liquid(p, 1);
  return 0.5 * (pts.mass_solid(p) * vs2 + pts.mass_liquid(p) * vl2);
}

/// The array reduction of sumPointTotals: [KE_S, KE_L, M_L, non-finite count].
struct TotalsFunctor {
  using value_type = Real[];
  using size_type = int;
  size_type value_count = 4;
  MaterialPoints pts;

  KOKKOS_INLINE_FUNCTION void operator()(const int p, value_type sum) const {
    addPointTotals(pts, p, sum);
  }
  KOKKOS_INLINE_FUNCTION void init(value_type sum) const {
    for (int k = 0; k < value_count; ++k) sum[k] = 0;
  }
  KOKKOS_INLINE_FUNCTION void join(volatile value_type dst, const volatile value_type src) const {
    for (int k = 0; k < value_count; ++k) dst[k] += src[k];
  }
};

}  // namespace

PointTotals pointTotalsOf(const Real sums[4]) {
  PointTotals totals;
  totals.kinetic_energy_solid = sums[0];
  totals.kinetic_energy_liquid = sums[1];
  totals.liquid_mass = sums[2];
  totals.non_finite_points = static_cast<int>(sums[3]);
  return totals;
}

PointTotals sumPointTotals(const MaterialPoints& points) {
  Real sums[4] = {0, 0, 0, 0};
  TotalsFunctor functor;
  functor.pts = points;
  Kokkos::parallel_reduce("point_totals", Kokkos::RangePolicy<ExecSpace>(0, points.count), functor,
                          sums);
  return pointTotalsOf(sums);
}

int firstNonFinitePoint(const MaterialPoints& points) {
  const MaterialPoints pts = points;
  int first = std::numeric_limits<int>::max();
  Kokkos::parallel_reduce(
      "first_non_finite_point", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& min) {
        if (!pointIsValid(pts, p) && p < min) min = p;
      },
      Kokkos::Min<int>(first));
  return first == std::numeric_limits<int>::max() ? -1 : first;
}

int mostEnergeticPoint(const MaterialPoints& points) {
  if (points.count == 0) return -1;
  const MaterialPoints pts = points;
  using Reducer = Kokkos::MaxLoc<Real, int>;
  Reducer::value_type best;
  Kokkos::parallel_reduce(
      "most_energetic_point", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, Reducer::value_type& max) {
        const Real energy = kineticEnergy(pts, p);
        if (energy > max.val) {
          max.val = energy;
          max.loc = p;
        }
      },
      Reducer(best));
  return best.loc >= 0 && best.loc < points.count ? best.loc : 0;
}

std::string describePoint(const MaterialPoints& points, int index, bool non_finite) {
  auto one = std::make_pair(index, index + 1);
  auto copy = [&](const auto& view) {
    return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(view, one));
  };
  auto copy2 = [&](const auto& view) {
    return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(),
                                               Kokkos::subview(view, one, Kokkos::ALL));
  };
  const auto id = copy(points.id);
  const auto position = copy2(points.position);
  std::ostringstream out;
  out << "point " << id(0) << " (index " << index << ") at (" << position(0, 0) << ", "
      << position(0, 1) << ")";
  if (!non_finite) return out.str();

  auto report = [&](const char* name, Real value) {
    out << ": " << name << " is " << value;
    return out.str();
  };
  const char* axis[] = {"x", "y"};
  const char* component[] = {"xx", "yy", "zz", "xy"};
  const auto velocity_solid = copy2(points.velocity_solid);
  const auto velocity_liquid = copy2(points.velocity_liquid);
  const auto stress = copy2(points.stress_effective);
  const auto pressure = copy(points.pressure_liquid);
  const auto volume = copy(points.volume);
  for (int d = 0; d < kDim; ++d)
    if (!std::isfinite(position(0, d)))
      return report((std::string("position ") + axis[d]).c_str(), position(0, d));
  for (int d = 0; d < kDim; ++d)
    if (!std::isfinite(velocity_solid(0, d)))
      return report((std::string("solid velocity ") + axis[d]).c_str(), velocity_solid(0, d));
  for (int d = 0; d < kDim; ++d)
    if (!std::isfinite(velocity_liquid(0, d)))
      return report((std::string("liquid velocity ") + axis[d]).c_str(), velocity_liquid(0, d));
  if (!std::isfinite(pressure(0))) return report("liquid pressure", pressure(0));
  for (int c = 0; c < kStressComponents; ++c)
    if (!std::isfinite(stress(0, c)))
      return report((std::string("effective stress ") + component[c]).c_str(), stress(0, c));
  if (!std::isfinite(volume(0)) || !(volume(0) > 0)) return report("volume", volume(0));
  return out.str();
}

namespace {

/// Point p's term of storedElasticEnergy: V |sigma'|^2 / (2 E), plus V n p_L^2 / (2 K_L)
/// where it carries liquid.
KOKKOS_INLINE_FUNCTION Real pointStoredEnergy(const MaterialPoints& pts,
                                              const PointMaterial& material, int p) {
  Real s2 = 0, e = 0;
  for (int c = 0; c < kStressComponents; ++c)
    s2 += pts.stress_effective(p, c) * pts.stress_effective(p, c);
  const Real young = material.solid.youngs_modulus;
  if (young > 0) e += pts.volume(p) * s2 / (2 * young);
  if (carriesLiquid(material.phase)) {
    const Real pressure = pts.pressure_liquid(p);
    e += pts.volume(p) * pts.porosity(p) * pressure * pressure / (2 * material.liquid.bulk_modulus);
  }
  return e;
}

}  // namespace

Real storedElasticEnergy(const MaterialPoints& points, const MaterialTable& table) {
  const MaterialPoints pts = points;
  const auto materials_m = table.materials();
  Real stored = 0;
  Kokkos::parallel_reduce(
      "stored_elastic_energy", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, Real& e) {
        e += pointStoredEnergy(pts, materials_m(pts.material(p)), p);
      },
      stored);
  return stored;
}

CompensatedReal compensatedStoredElasticEnergy(const MaterialPoints& points,
                                               const MaterialTable& table) {
  const MaterialPoints pts = points;
  const auto materials_m = table.materials();
  Kokkos::View<Real*, MemSpace> terms("stored_elastic_energy_terms", points.count);
  Kokkos::parallel_for(
      "stored_elastic_energy_terms", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        terms(p) = pointStoredEnergy(pts, materials_m(pts.material(p)), p);
      });
  return compensatedSum(terms);
}

PointEnergies pointEnergies(const MaterialPoints& points, const MaterialTable& table, Real gravity,
                            Real datum) {
  const MaterialPoints pts = points;
  Real height = 0;  // sum M max(y - datum, 0) over the points inside the mesh
  Kokkos::parallel_reduce(
      "energy_scale_potential", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, Real& sum) {
        if (pts.element(p) < 0) return;  // left the mesh: frozen, releases nothing more
        const Real above = pts.position(p, 1) - datum;
        if (above > 0) sum += (pts.mass_solid(p) + pts.mass_liquid(p)) * above;
      },
      height);
  PointEnergies energies;
  energies.potential = gravity * height;
  energies.stored = storedElasticEnergy(points, table);
  const PointTotals totals = sumPointTotals(points);
  energies.kinetic = totals.kinetic_energy_solid + totals.kinetic_energy_liquid;
  return energies;
}

Real inflowEnergyPerMass(BoundaryKind kind, Real value, Real pressure_above, Real liquid_density,
                         Real gravity, Real top, Real datum) {
  const Real lift = gravity * (top - datum);  // entering at the top of the mesh
  switch (kind) {
    case BoundaryKind::TotalHead:  // g (H - datum) below the level, the pressure above it
      return std::max(gravity * (value - datum), lift) +
             std::max<Real>(pressure_above, 0) / liquid_density;
    case BoundaryKind::PressureSeries:
      return lift + std::max<Real>(value, 0) / liquid_density;
    default:  // infiltration (rain at p_L <= 0), seepage face (outflow only)
      return lift;
  }
}

}  // namespace argine
