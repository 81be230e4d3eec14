#include "argine/transfer/GridFields.hpp"

#include "argine/core/UntrackedViews.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/CompensatedSum.hpp"

namespace argine {

void GridFields::allocate(int num_nodes) {
  mass_solid_i = View<Real*>("mass_solid_i", num_nodes);
  mass_liquid_i = View<Real*>("mass_liquid_i", num_nodes);
  mass_liquid_intrinsic_i = View<Real*>("mass_liquid_intrinsic_i", num_nodes);
  drag_i = View<Real*>("drag_i", num_nodes);
  volume_liquid_i = View<Real*>("volume_liquid_i", num_nodes);
  liquid_content_i = View<Real*>("liquid_content_i", num_nodes);
  momentum_solid_i = View<Real* [kDim]>("momentum_solid_i", num_nodes);
  momentum_liquid_i = View<Real* [kDim]>("momentum_liquid_i", num_nodes);
  velocity_solid_i = View<Real* [kDim]>("velocity_solid_i", num_nodes);
  velocity_liquid_i = View<Real* [kDim]>("velocity_liquid_i", num_nodes);
  acceleration_solid_i = View<Real* [kDim]>("acceleration_solid_i", num_nodes);
  acceleration_liquid_i = View<Real* [kDim]>("acceleration_liquid_i", num_nodes);
  force_mixture_i = View<Real* [kDim]>("force_mixture_i", num_nodes);
  force_liquid_i = View<Real* [kDim]>("force_liquid_i", num_nodes);
}

void GridFields::zero(const ActiveNodes& active) {
  const auto nodes = active.nodes();
  const GridFields g = untracked(*this);
  Kokkos::parallel_for(
      "grid_zero", Kokkos::RangePolicy<ExecSpace>(0, active.count()), KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        g.mass_solid_i(i) = 0;
        g.mass_liquid_i(i) = 0;
        g.mass_liquid_intrinsic_i(i) = 0;
        g.drag_i(i) = 0;
        g.volume_liquid_i(i) = 0;
        g.liquid_content_i(i) = 0;
        for (int d = 0; d < kDim; ++d) {
          g.momentum_solid_i(i, d) = 0;
          g.momentum_liquid_i(i, d) = 0;
          g.velocity_solid_i(i, d) = 0;
          g.velocity_liquid_i(i, d) = 0;
          g.acceleration_solid_i(i, d) = 0;
          g.acceleration_liquid_i(i, d) = 0;
          g.force_mixture_i(i, d) = 0;
          g.force_liquid_i(i, d) = 0;
        }
      });
}

void foldCompensatedGridSums(const ActiveNodes& nodes, GridFields& g,
                             const LowParts<GridFields>& lo) {
  using G = GridFields;
  foldCompensatedSums(nodes, g.mass_solid_i, lowPartsOf(lo, &G::mass_solid_i));
  foldCompensatedSums(nodes, g.mass_liquid_i, lowPartsOf(lo, &G::mass_liquid_i));
  foldCompensatedSums(nodes, g.mass_liquid_intrinsic_i,
                      lowPartsOf(lo, &G::mass_liquid_intrinsic_i));
  foldCompensatedSums(nodes, g.drag_i, lowPartsOf(lo, &G::drag_i));
  foldCompensatedSums(nodes, g.volume_liquid_i, lowPartsOf(lo, &G::volume_liquid_i));
  foldCompensatedSums(nodes, g.force_mixture_i, lowPartsOf(lo, &G::force_mixture_i));
  foldCompensatedSums(nodes, g.force_liquid_i, lowPartsOf(lo, &G::force_liquid_i));
  foldCompensatedMomenta(nodes, g, lo);
}

void foldCompensatedMomenta(const ActiveNodes& nodes, GridFields& g,
                            const LowParts<GridFields>& lo) {
  foldCompensatedSums(nodes, g.momentum_solid_i, lowPartsOf(lo, &GridFields::momentum_solid_i));
  foldCompensatedSums(nodes, g.momentum_liquid_i, lowPartsOf(lo, &GridFields::momentum_liquid_i));
}

}  // namespace argine
