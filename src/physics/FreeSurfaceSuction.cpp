#include "argine/physics/FreeSurfaceSuction.hpp"

#include "argine/physics/HydraulicBoundaryStep.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"

namespace argine {

void holdSuctionAtFreeSurfaces(const ActiveNodes& active,
                               Kokkos::View<const unsigned char*, MemSpace> conditioned,
                               const BoundaryGradientFields& fields, GridFields& grid) {
  const auto nodes = active.nodes();
  const auto volume_gradient_i = fields.volume_gradient_i;
  const auto pressure_volume_i = fields.pressure_volume_i;
  const auto volume_i = grid.volume_liquid_i;  // sum_p N_i V of the liquid-carrying points
  const auto force_i = grid.force_liquid_i;
  const bool has_conditions = conditioned.extent(0) > 0;
  Kokkos::parallel_for(
      "hold_suction_at_free_surfaces", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        if (has_conditions && conditioned(i) != 0) return;
        const Real surface = surfaceLiquidPressure(pressure_volume_i(i), volume_i(i));
        if (surface == 0) return;
        for (int d = 0; d < kDim; ++d) force_i(i, d) -= surface * volume_gradient_i(i, d);
      });
}

}  // namespace argine
