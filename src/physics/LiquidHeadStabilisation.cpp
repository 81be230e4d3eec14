#include "argine/physics/LiquidHeadStabilisation.hpp"

#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/PointRates.hpp"

namespace argine {

namespace {

/// The gravity with which a conductivity in m/s is defined: k / (rho_L g0) = kappa / mu_L.
constexpr Real kConductivityGravity = 9.81;
/// At most this share of the way to the nodal average per step (stability of the exchange).
constexpr Real kStableShare = 0.25;

/// phi = p_L + rho_L0 g y (Pa), gravity acting in -y.
KOKKOS_INLINE_FUNCTION Real piezometricPressure(const PointMaterial& material, Real pressure,
                                                Real y, Real gravity) {
  return pressure + material.liquid.density * gravity * y;
}

}  // namespace

LiquidHeadStabilisation::LiquidHeadStabilisation(const MaterialTable& table, int nodes,
                                                 NodalExchange* exchange)
    : exchange_(exchange) {
  for (int m = 0; m < table.count(); ++m) {
    const PointMaterial& material = table.host(m);
    active_ = active_ || (carriesLiquid(material.phase) && material.locking.head_stabilisation > 0);
  }
  if (!active_) return;
  heads_.allocateSums(1, 0, nodes);
}

void LiquidHeadStabilisation::apply(const MaterialTable& table, const MaterialPoints& points,
                                    const PointShapes& shapes, const ActiveNodes& active,
                                    PointRates& rates, Real dt, Real gravity) {
  if (!active_) return;
  const int count = points.count;
  heads_.fitPoints(count);
  const auto materials_m = table.materials();
  const MaterialPoints pts = points;
  const auto head_p = Kokkos::subview(heads_.value_pc, Kokkos::ALL, 0);
  const auto conductance_p = heads_.weight_p;
  const auto mode_p = Kokkos::subview(heads_.mode_pc, Kokkos::ALL, 0);
  Kokkos::parallel_for(
      "head_stabilisation_in", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        const PointMaterial& material = materials_m(pts.material(p));
        const Real alpha = material.locking.head_stabilisation;
        mode_p(p) = kAverageNone;
        conductance_p(p) = 0;
        head_p(p) = 0;
        if (!carriesLiquid(material.phase) || alpha <= 0 || pts.element(p) < 0) return;
        const Real pressure = pts.pressure_liquid(p);
        const Real ds_ds =
            material.phase == PhaseModel::Unsaturated
                ? saturationSuctionDerivative(material.retention, suctionOfPressure(pressure))
                : 0;
        const Real storage = pts.porosity(p) * pts.volume(p) *
                             liquidContentSlope(pts.density_liquid(p), pts.saturation(p), ds_ds,
                                                material.liquid.bulk_modulus);  // dM_L/dp_L (kg/Pa)
        Real conductance = alpha * pts.conductivity(p) / kConductivityGravity;
        if (dt * conductance > kStableShare * storage) conductance = kStableShare * storage / dt;
        if (!(conductance > 0)) return;
        mode_p(p) = kAverageNodal;
        conductance_p(p) = conductance;
        head_p(p) = piezometricPressure(material, pressure, pts.position(p, 1), gravity);
      });
  averagePointValues(points, shapes, active, heads_, exchange_);
  const auto strain_increment_p = rates.strain_increment_p;
  const auto flux_divergence_p = rates.content_flux_divergence_increment_p;
  const auto divergence_p = rates.liquid_divergence_increment_p;
  Kokkos::parallel_for(
      "head_stabilisation_out", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        if (mode_p(p) == kAverageNone) return;
        const PointMaterial& material = materials_m(pts.material(p));
        // The point's own phi (its p_L and position are unchanged since the first kernel)
        // against the nodal average now in head_p.
        const Real own =
            piezometricPressure(material, pts.pressure_liquid(p), pts.position(p, 1), gravity);
        const Real mass_change = -dt * conductance_p(p) * (own - head_p(p));  // kg
        if (material.mass_balance == MassBalanceForm::Complete) {
          // M_L^{k+1} = M_L^k - V^k dt div(c w) (LiquidState.hpp): V^k from V^{k+1}.
          const Real volumetric =
              strain_increment_p(p, XX) + strain_increment_p(p, YY) + strain_increment_p(p, ZZ);
          flux_divergence_p(p) -= mass_change * (1 + volumetric) / pts.volume(p);
        } else {
          // M_L^{k+1} = M_L^k (1 - dt div w): the same change as a relative divergence.
          divergence_p(p) -= mass_change / pts.mass_liquid(p);
        }
      });
}

}  // namespace argine
