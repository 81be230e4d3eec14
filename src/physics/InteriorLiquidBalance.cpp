#include "argine/physics/InteriorLiquidBalance.hpp"

#include "argine/core/UntrackedViews.hpp"
#include "argine/physics/HydraulicBoundaryStep.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointLiquidExchange.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

void liquidMadeAtClosedNodes(const ActiveNodes& active,
                             Kokkos::View<const unsigned char*, MemSpace> free_side,
                             Kokkos::View<const unsigned char*, MemSpace> conditioned,
                             const BoundaryGradientFields& fields, const GridFields& grid, Real dt,
                             Kokkos::View<Real*, MemSpace> made_i) {
  const auto nodes = active.nodes();
  const auto weight_i = fields.flux_weight_i;
  const auto vl_i = grid.velocity_liquid_i;
  const auto vs_i = grid.velocity_solid_i;
  const bool sided = free_side.extent(0) > 0;
  const bool has_conditions = conditioned.extent(0) > 0;
  Kokkos::parallel_for(
      "liquid_made_at_closed_nodes", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        const bool closed = (!sided || (free_side(i) & kNodeOnOpenSide) == 0) &&
                            (!has_conditions || conditioned(i) == 0);
        made_i(i) = closed ? pointBalanceInflowAtNode(dt, vl_i, vs_i, weight_i, i) : 0;
      });
}

namespace {

template <class Family>
void returnLiquidMadeInsideImpl(const MaterialTable& table, const MaterialPoints& points,
                                const PointShapes& shapes, const BoundaryGradientFields& fields,
                                Kokkos::View<const Real*, MemSpace> made_i, PointRates& rates) {
  const auto materials_m = table.materials();
  const auto liquid_m = table.liquidCarrying();
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto wet_i = fields.wet_volume_i;
  const MaterialPoints pts = untracked(points);
  const PointRates rts = rates;
  Kokkos::parallel_for(
      "return_liquid_made_inside", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        if (element_p(p) < 0 || liquid_m(pts.material(p)) == 0) return;
        typename Family::Record scratch;
        const auto& shape = Family::of(shapes, p, element_p, local_p, scratch);
        if (shape.node[0] < 0) return;
        Real per_wet_volume = 0;  // sum_a N_a made_a / W_a (kg/m^3)
        for (int a = 0; a < Family::kNodes; ++a) {
          const int i = shape.node[a];
          const Real made = made_i(i), wet = wet_i(i);
          if (made != 0 && wet > 0) per_wet_volume += shape.value[a] * made / wet;
        }
        if (per_wet_volume == 0) return;
        const Real wet_volume = pts.porosity(p) * pts.saturation(p) * pts.volume(p);
        addPointLiquidMassChange(materials_m(pts.material(p)), pts, rts, p,
                                 -wet_volume * per_wet_volume);
      });
}

}  // namespace

void returnLiquidMadeInside(const MaterialTable& table, const MaterialPoints& points,
                            const PointShapes& shapes, const BoundaryGradientFields& fields,
                            Kokkos::View<const Real*, MemSpace> made_i, PointRates& rates) {
  withShapeFamily(shapes, [&](auto family) {
    returnLiquidMadeInsideImpl<decltype(family)>(table, points, shapes, fields, made_i, rates);
  });
}

}  // namespace argine
