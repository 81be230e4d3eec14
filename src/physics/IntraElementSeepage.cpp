#include "argine/physics/IntraElementSeepage.hpp"

#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/PointRates.hpp"

namespace argine {

namespace {

/// The gravity with which a conductivity in m/s is defined: k / (rho_L g0) = kappa / mu_L.
constexpr Real kConductivityGravity = 9.81;

/// phi = p_L + rho_L0 g y (Pa), gravity acting in -y.
KOKKOS_INLINE_FUNCTION Real piezometricPressure(const PointMaterial& material, Real pressure,
                                                Real y, Real gravity) {
  return pressure + material.liquid.density * gravity * y;
}

}  // namespace

IntraElementSeepage::IntraElementSeepage(const MaterialTable& table, int elements, int nodes) {
  for (int m = 0; m < table.count(); ++m) {
    const PointMaterial& material = table.host(m);
    active_ = active_ || (carriesLiquid(material.phase) && material.locking.intra_element_seepage);
  }
  if (active_) heads_.allocateSums(1, elements, nodes);
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
        const Real ds_ds =
            material.phase == PhaseModel::Unsaturated
                ? saturationSuctionDerivative(material.retention, suctionOfPressure(pressure))
                : 0;
        const Real storage = pts.porosity(p) * pts.volume(p) *
                             liquidContentSlope(pts.density_liquid(p), pts.saturation(p), ds_ds,
                                                material.liquid.bulk_modulus);  // dM_L/dp_L (kg/Pa)
        const Real conductance = pts.conductivity(p) / kConductivityGravity;    // kg/(Pa s)
        const Real weight = starExchangeWeight(conductance, storage, dt);
        if (!(weight > 0)) return;
        mode_p(p) = kAverageElement;
        weight_p(p) = weight;
        head_p(p) = piezometricPressure(material, pressure, pts.position(p, 1), gravity);
      });
  averagePointValues(points, shapes, active, heads_, nullptr);  // element sums: rank-local
  const auto flux_divergence_p = rates.content_flux_divergence_increment_p;
  const auto divergence_p = rates.liquid_divergence_increment_p;
  Kokkos::parallel_for(
      "intra_element_seepage_out", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        if (mode_p(p) == kAverageNone) return;
        const PointMaterial& material = materials_m(pts.material(p));
        // The point's own phi (its p_L and position are unchanged since the first kernel)
        // against the element's centre value phi_c now in head_p.
        const Real own =
            piezometricPressure(material, pts.pressure_liquid(p), pts.position(p, 1), gravity);
        const Real mass_change = weight_p(p) * (head_p(p) - own);  // kg, into the point
        if (material.mass_balance == MassBalanceForm::Complete)
          // M_L^{k+1} = M_L^k - V^k dt div(c w) (LiquidState.hpp), V^k the volume now.
          flux_divergence_p(p) -= mass_change / pts.volume(p);
        else
          // M_L^{k+1} = M_L^k (1 - dt div w): the same change as a relative divergence.
          divergence_p(p) -= mass_change / pts.mass_liquid(p);
      });
}

}  // namespace argine
