#include "argine/physics/VolumetricAveraging.hpp"

#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/PointRates.hpp"

namespace argine {

namespace {

// The deck's IncrementAveraging values are the modes of averagePointValues.
constexpr int kNone = static_cast<int>(IncrementAveraging::None);
constexpr int kNodal = static_cast<int>(IncrementAveraging::Nodal);
static_assert(kNone == kAverageNone && kNodal == kAverageNodal &&
              static_cast<int>(IncrementAveraging::Element) == kAverageElement);

}  // namespace

VolumetricAveraging::VolumetricAveraging(const MaterialTable& table, int elements, int nodes,
                                         NodalExchange* exchange)
    : exchange_(exchange) {
  for (int m = 0; m < table.count(); ++m) {
    const PointMaterial& material = table.host(m);
    strain_ = strain_ || material.locking.volumetric_strain != IncrementAveraging::None;
    pressure_ = pressure_ || (material.phase == PhaseModel::Saturated &&
                              material.locking.liquid_pressure != IncrementAveraging::None);
  }
  if (!strain_ && !pressure_) return;
  element_sums_ = Kokkos::View<Real* [2], MemSpace>("averaging_element_sums", elements);
  node_sums_ = Kokkos::View<Real* [2], MemSpace>("averaging_node_sums", nodes);
}

void VolumetricAveraging::averageStrainIncrements(const MaterialTable& table,
                                                  const MaterialPoints& points,
                                                  const PointShapes& shapes,
                                                  const ActiveNodes& active, PointRates& rates) {
  if (!strain_) return;
  const int count = points.count;
  if (static_cast<int>(value_point_.extent(0)) != count) {
    value_point_ = Kokkos::View<Real*, MemSpace>("averaging_value", count);
    weight_point_ = Kokkos::View<Real*, MemSpace>("averaging_weight", count);
    mode_point_ = Kokkos::View<int*, MemSpace>("averaging_mode", count);
  }
  const auto materials_m = table.materials();
  const auto material_p = points.material;
  const auto volume_p = points.volume;
  const auto element_p = points.element;
  const auto strain_increment_p = rates.strain_increment_p;
  const auto divergence_p = rates.liquid_divergence_increment_p;
  const auto flux_divergence_p = rates.content_flux_divergence_increment_p;
  const auto value_p = value_point_;
  const auto weight_p = weight_point_;
  const auto mode_p = mode_point_;
  // The liquid terms first, at liquid-carrying points: the relative divergence dt div(v_L -
  // v_S) and the flux divergence dt div(c w) get the same averaging as d eps_vol, so the
  // pore pressure follows S (B u_L) with one smoothing operator S for both phases. (Smoothing
  // the solid's volume change alone couples the phases through S - I in the liquid equation
  // only: a non-symmetric coupling that the explicit step amplifies.)
  auto averageLiquid = [&](bool relative) {
    Kokkos::parallel_for(
        "averaging_liquid_in", Kokkos::RangePolicy<ExecSpace>(0, count),
        KOKKOS_LAMBDA(const int p) {
          const PointMaterial& material = materials_m(material_p(p));
          mode_p(p) = carriesLiquid(material.phase)
                          ? static_cast<int>(material.locking.volumetric_strain)
                          : kNone;
          weight_p(p) = volume_p(p);
          value_p(p) =
              relative ? divergence_p(p) - (strain_increment_p(p, XX) + strain_increment_p(p, YY))
                       : flux_divergence_p(p);
        });
    averagePointValues(points, shapes, active, mode_point_, weight_point_, value_point_,
                       element_sums_, node_sums_, exchange_, compensation_);
    Kokkos::parallel_for(
        "averaging_liquid_out", Kokkos::RangePolicy<ExecSpace>(0, count),
        KOKKOS_LAMBDA(const int p) {
          if (mode_p(p) == kNone || element_p(p) < 0) return;
          if (relative)
            divergence_p(p) = value_p(p);  // the solid's d eps_vol is added below
          else
            flux_divergence_p(p) = value_p(p);
        });
  };
  averageLiquid(false);
  averageLiquid(true);
  Kokkos::parallel_for(
      "averaging_strain_in", Kokkos::RangePolicy<ExecSpace>(0, count), KOKKOS_LAMBDA(const int p) {
        mode_p(p) = static_cast<int>(materials_m(material_p(p)).locking.volumetric_strain);
        weight_p(p) = volume_p(p);
        value_p(p) = strain_increment_p(p, XX) + strain_increment_p(p, YY);
      });
  averagePointValues(points, shapes, active, mode_point_, weight_point_, value_point_,
                     element_sums_, node_sums_, exchange_, compensation_);
  Kokkos::parallel_for(
      "averaging_strain_out", Kokkos::RangePolicy<ExecSpace>(0, count), KOKKOS_LAMBDA(const int p) {
        if (mode_p(p) == kNone || element_p(p) < 0) return;
        const Real shift = value_p(p) - (strain_increment_p(p, XX) + strain_increment_p(p, YY));
        strain_increment_p(p, XX) += shift / 2;
        strain_increment_p(p, YY) += shift / 2;
        // dt div v_L = averaged relative divergence + averaged d eps_vol.
        if (carriesLiquid(materials_m(material_p(p)).phase)) divergence_p(p) += value_p(p);
      });
}

void VolumetricAveraging::rememberPressures(const MaterialPoints& points) {
  if (!pressure_) return;
  if (static_cast<int>(old_pressure_.extent(0)) != points.count)
    old_pressure_ = Kokkos::View<Real*, MemSpace>("averaging_old_pressure", points.count);
  Kokkos::deep_copy(old_pressure_, points.pressure_liquid);
}

void VolumetricAveraging::averagePressureIncrements(const MaterialTable& table,
                                                    const MaterialPoints& points,
                                                    const PointShapes& shapes,
                                                    const ActiveNodes& active) {
  if (!pressure_) return;
  const int count = points.count;
  if (static_cast<int>(value_point_.extent(0)) != count) {
    value_point_ = Kokkos::View<Real*, MemSpace>("averaging_value", count);
    weight_point_ = Kokkos::View<Real*, MemSpace>("averaging_weight", count);
    mode_point_ = Kokkos::View<int*, MemSpace>("averaging_mode", count);
  }
  const auto materials_m = table.materials();
  const MaterialPoints pts = points;
  const auto old_p = old_pressure_;
  const auto value_p = value_point_;
  const auto weight_p = weight_point_;
  const auto mode_p = mode_point_;
  Kokkos::parallel_for(
      "averaging_pressure_in", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        const PointMaterial& material = materials_m(pts.material(p));
        mode_p(p) = material.phase == PhaseModel::Saturated
                        ? static_cast<int>(material.locking.liquid_pressure)
                        : kNone;
        weight_p(p) = pts.porosity(p) * pts.volume(p);
        value_p(p) = pts.pressure_liquid(p) - old_p(p);
      });
  averagePointValues(points, shapes, active, mode_point_, weight_point_, value_point_,
                     element_sums_, node_sums_, exchange_, compensation_);
  Kokkos::parallel_for(
      "averaging_pressure_out", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        if (mode_p(p) == kNone || pts.element(p) < 0) return;
        const PointMaterial& material = materials_m(pts.material(p));
        const Real pressure = old_p(p) + value_p(p);
        const Real rho = liquidDensity(material.liquid, pressure);  // 4.13
        pts.pressure_liquid(p) = pressure;
        pts.density_liquid(p) = rho;
        pts.mass_liquid(p) = pts.porosity(p) * rho * pts.volume(p);  // S_L = 1
      });
}

}  // namespace argine
