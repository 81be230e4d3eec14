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
  AveragingUse strain, pressure;
  for (int m = 0; m < table.count(); ++m) {
    const PointMaterial& material = table.host(m);
    strain.add(static_cast<int>(material.locking.volumetric_strain));
    pressure.add(material.phase == PhaseModel::Saturated
                     ? static_cast<int>(material.locking.liquid_pressure)
                     : kNone);
  }
  strain_ = strain.any();
  pressure_ = pressure.any();
  if (strain_) increments_.allocateSums(kChannels, strain, elements, nodes);
  if (pressure_) pressure_increments_.allocateSums(1, pressure, elements, nodes);
}

void VolumetricAveraging::averageStrainIncrements(const MaterialTable& table,
                                                  const MaterialPoints& points,
                                                  const PointShapes& shapes,
                                                  const ActiveNodes& active, PointRates& rates) {
  if (!strain_) return;
  const int count = points.count;
  increments_.fitPoints(count);
  const auto materials_m = table.materials();
  const auto material_p = points.material;
  const auto volume_p = points.volume;
  const auto element_p = points.element;
  const auto strain_increment_p = rates.strain_increment_p;
  const auto divergence_p = rates.liquid_divergence_increment_p;
  const auto flux_divergence_p = rates.content_flux_divergence_increment_p;
  const auto value_pc = increments_.value_pc;
  const auto weight_p = increments_.weight_p;
  const auto mode_pc = increments_.mode_pc;
  // At liquid-carrying points the relative divergence dt div(v_L - v_S) and the flux
  // divergence dt div(c w) get the same averaging as d eps_vol, so the pore pressure follows
  // S (B u_L) with one smoothing operator S for both phases. (Smoothing the solid's volume
  // change alone couples the phases through S - I in the liquid equation only: a
  // non-symmetric coupling that the explicit step amplifies.) The three are independent
  // (each read before any is written back): one averaging, one exchange.
  Kokkos::parallel_for(
      "averaging_increments_in", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        const PointMaterial& material = materials_m(material_p(p));
        const int mode = static_cast<int>(material.locking.volumetric_strain);
        const Real strain = strain_increment_p(p, XX) + strain_increment_p(p, YY);
        const int liquid_mode = carriesLiquid(material.phase) ? mode : kNone;
        weight_p(p) = volume_p(p);
        mode_pc(p, kFluxDivergence) = liquid_mode;
        value_pc(p, kFluxDivergence) = flux_divergence_p(p);
        mode_pc(p, kRelativeDivergence) = liquid_mode;
        value_pc(p, kRelativeDivergence) = divergence_p(p) - strain;
        mode_pc(p, kVolumetricStrain) = mode;
        value_pc(p, kVolumetricStrain) = strain;
      });
  averagePointValues(points, shapes, active, increments_, exchange_);
  Kokkos::parallel_for(
      "averaging_increments_out", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        if (element_p(p) < 0) return;
        if (mode_pc(p, kFluxDivergence) != kNone)
          flux_divergence_p(p) = value_pc(p, kFluxDivergence);
        if (mode_pc(p, kRelativeDivergence) != kNone)
          divergence_p(p) = value_pc(p, kRelativeDivergence);  // + the averaged d eps_vol below
        if (mode_pc(p, kVolumetricStrain) == kNone) return;
        const Real averaged = value_pc(p, kVolumetricStrain);
        const Real shift = averaged - (strain_increment_p(p, XX) + strain_increment_p(p, YY));
        strain_increment_p(p, XX) += shift / 2;
        strain_increment_p(p, YY) += shift / 2;
        // dt div v_L = averaged relative divergence + averaged d eps_vol.
        if (carriesLiquid(materials_m(material_p(p)).phase)) divergence_p(p) += averaged;
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
  pressure_increments_.fitPoints(count);
  const auto materials_m = table.materials();
  const MaterialPoints pts = points;
  const auto old_p = old_pressure_;
  const auto value_p = Kokkos::subview(pressure_increments_.value_pc, Kokkos::ALL, 0);
  const auto weight_p = pressure_increments_.weight_p;
  const auto mode_p = Kokkos::subview(pressure_increments_.mode_pc, Kokkos::ALL, 0);
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
  averagePointValues(points, shapes, active, pressure_increments_, exchange_);
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
