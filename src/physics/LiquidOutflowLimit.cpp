#include "argine/physics/LiquidOutflowLimit.hpp"

#include <Kokkos_ScatterView.hpp>

#include "argine/core/UntrackedViews.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/parallel/NodalExchange.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace {

namespace KE = Kokkos::Experimental;

/// The residual (immobile) liquid mass n S_min rho_L V of a point (kg per m); 0 for a
/// saturated material, whose whole content is mobile. -1 marks the points the limit skips:
/// lost, dry, or with the simplified balance (4.14), which never moves more than M_L dt div w.
KOKKOS_INLINE_FUNCTION Real residualMass(const PointMaterial& material, const MaterialPoints& pts,
                                         int p) {
  if (pts.element(p) < 0 || !carriesLiquid(material.phase) ||
      material.mass_balance != MassBalanceForm::Complete)
    return -1;
  if (material.phase != PhaseModel::Unsaturated) return 0;
  return pts.porosity(p) * material.retention.saturation_min * pts.density_liquid(p) *
         pts.volume(p);
}

}  // namespace

void LiquidOutflowLimit::sumOverRanks(Real* values, int count) const {
  if (exchange_) MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, comm_);
}

OutflowLimitTotals LiquidOutflowLimit::apply(const MaterialTable& table,
                                             const MaterialPoints& points,
                                             const PointShapes& shapes, PointRates& rates) {
  const auto materials_m = table.materials();
  const MaterialPoints pts = untracked(points);
  const auto flux_p = rates.content_flux_divergence_increment_p;
  OutflowLimitTotals totals;

  // 1. Is any point asked for more than its mobile content? (Usually not: then nothing.)
  Real excess_sum = 0;
  int limited = 0;
  Kokkos::parallel_reduce(
      "outflow_limit_find", Kokkos::RangePolicy<ExecSpace>(0, pts.count),
      KOKKOS_LAMBDA(const int p, Real& sum, int& count) {
        const Real residual = residualMass(materials_m(pts.material(p)), pts, p);
        if (residual < 0) return;
        const Real excess = excessOutflow(pts.volume(p) * flux_p(p), pts.mass_liquid(p), residual);
        if (excess > 0) {
          sum += excess;
          ++count;
        }
      },
      excess_sum, limited);
  {  // over all ranks: every rank takes part in the exchanges below, or none does
    Real sums[2] = {excess_sum, static_cast<Real>(limited)};
    sumOverRanks(sums, 2);
    excess_sum = sums[0];
    limited = static_cast<int>(sums[1]);
  }
  totals.limited_points = limited;
  totals.excess = excess_sum;
  if (limited == 0) return totals;

  // Steps 2-3 on the shapes of the transfers (their family chosen once).
  Real withdrawn = 0, remaining_gain = 0;
  withShapeFamily(shapes, [&](auto family) {
    using Family = decltype(family);
    // Nodal scratch up to the highest node the points touch (only reached when limiting).
    int max_node = 0;
    Kokkos::parallel_reduce(
        "outflow_limit_nodes", Kokkos::RangePolicy<ExecSpace>(0, pts.count),
        KOKKOS_LAMBDA(const int p, int& m) {
          typename Family::Record scratch;
          const auto& shape = Family::of(shapes, p, pts.element, pts.local, scratch);
          for (int a = 0; a < Family::kNodes; ++a)
            if (shape.node[a] + 1 > m) m = shape.node[a] + 1;
        },
        Kokkos::Max<int>(max_node));
    if (exchange_) max_node = nodes_;  // the exchange completes arrays of all nodes
    if (static_cast<int>(deficit_i_.extent(0)) < max_node) {
      deficit_i_ = Kokkos::View<Real*, MemSpace>("outflow_limit_deficit", max_node);
      gain_i_ = Kokkos::View<Real*, MemSpace>("outflow_limit_gain", max_node);
    } else {
      Kokkos::deep_copy(deficit_i_, 0.0);
      Kokkos::deep_copy(gain_i_, 0.0);
    }

    // 2. Donors: cap the outflow at the mobile content; scatter the excess and the gains.
    auto deficit_sv = KE::create_scatter_view(deficit_i_);
    auto gain_sv = KE::create_scatter_view(gain_i_);
    Kokkos::parallel_for(
        "outflow_limit_cap", Kokkos::RangePolicy<ExecSpace>(0, pts.count),
        KOKKOS_LAMBDA(const int p) {
          const Real residual = residualMass(materials_m(pts.material(p)), pts, p);
          if (residual < 0) return;
          const Real volume = pts.volume(p);
          const Real outflow = volume * flux_p(p);
          typename Family::Record scratch;
          const auto& shape = Family::of(shapes, p, pts.element, pts.local, scratch);
          if (outflow < 0) {
            auto gain_i = gain_sv.access();
            for (int a = 0; a < Family::kNodes; ++a)
              gain_i(shape.node[a]) += shape.value[a] * -outflow;
            return;
          }
          const Real excess = excessOutflow(outflow, pts.mass_liquid(p), residual);
          if (!(excess > 0)) return;
          flux_p(p) = (outflow - excess) / volume;
          auto deficit_i = deficit_sv.access();
          for (int a = 0; a < Family::kNodes; ++a)
            deficit_i(shape.node[a]) += shape.value[a] * excess;
        });
    KE::contribute(deficit_i_, deficit_sv);
    KE::contribute(gain_i_, gain_sv);
    if (exchange_) exchange_->sum({nodalField(deficit_i_), nodalField(gain_i_)});

    // 3. Gaining points give back, through each node, their share of the node's deficit
    //    (at most their gain: the fraction min(1, deficit / gain) of it).
    const auto deficit_i = deficit_i_;
    const auto gain_i = gain_i_;
    Kokkos::parallel_reduce(
        "outflow_limit_withdraw", Kokkos::RangePolicy<ExecSpace>(0, pts.count),
        KOKKOS_LAMBDA(const int p, Real& taken, Real& left) {
          const Real residual = residualMass(materials_m(pts.material(p)), pts, p);
          if (residual < 0) return;
          const Real volume = pts.volume(p);
          const Real gain = -volume * flux_p(p);
          if (!(gain > 0)) return;
          typename Family::Record scratch;
          const auto& shape = Family::of(shapes, p, pts.element, pts.local, scratch);
          Real back = 0;
          for (int a = 0; a < Family::kNodes; ++a) {
            const int i = shape.node[a];
            if (gain_i(i) > 0 && deficit_i(i) > 0)
              back += shape.value[a] * gain * kmath::fmin(Real(1), deficit_i(i) / gain_i(i));
          }
          flux_p(p) += back / volume;
          taken += back;
          left += gain - back;
        },
        withdrawn, remaining_gain);
    {
      Real sums[2] = {withdrawn, remaining_gain};
      sumOverRanks(sums, 2);
      withdrawn = sums[0];
      remaining_gain = sums[1];
    }
  });

  // 4. A rest (a donor node with no gaining neighbour, or more deficit than gain there):
  //    from all gaining points, in proportion to what they still gain.
  const Real rest = excess_sum - withdrawn;
  if (rest > 0 && remaining_gain > 0) {
    const Real fraction = kmath::fmin(Real(1), rest / remaining_gain);
    Real taken_rest = 0;
    Kokkos::parallel_reduce(
        "outflow_limit_rest", Kokkos::RangePolicy<ExecSpace>(0, pts.count),
        KOKKOS_LAMBDA(const int p, Real& taken) {
          const Real residual = residualMass(materials_m(pts.material(p)), pts, p);
          if (residual < 0) return;
          const Real volume = pts.volume(p);
          const Real gain = -volume * flux_p(p);
          if (!(gain > 0)) return;
          flux_p(p) += fraction * gain / volume;
          taken += fraction * gain;
        },
        taken_rest);
    sumOverRanks(&taken_rest, 1);
    withdrawn += taken_rest;
  }
  totals.withdrawn = withdrawn;
  return totals;
}

}  // namespace argine
