#include "argine/transfer/NodeRecords.hpp"

#include "argine/core/UntrackedViews.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"

namespace argine {

void NodeRecords::allocate(int num_nodes) {
  if (numNodes() == num_nodes && values_i.extent(0) == sums_i.extent(0)) return;
  sums_i = Kokkos::View<Real* [kNodeSumRow], MemSpace>("node_sums_i", num_nodes);
  values_i = Kokkos::View<Real* [kNodeReadRow], MemSpace>("node_values_i", num_nodes);
}

namespace {

/// f(i) for every active node i.
template <class Function>
void forEachActiveNode(const char* name, const ActiveNodes& active, const Function& f) {
  const auto nodes = active.nodes();
  Kokkos::parallel_for(
      name, Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) { f(nodes(j)); });
}

/// field(i, d) += sums(i, slot + d) for d < kDim, and those sums zeroed.
template <class Sums, class Field>
KOKKOS_FORCEINLINE_FUNCTION void takeVectorSum(const Sums& sums, int i, int slot,
                                               const Field& field) {
  for (int d = 0; d < kDim; ++d) {
    field(i, d) += sums(i, slot + d);
    sums(i, slot + d) = 0;
  }
}

template <class Sums, class Field>
KOKKOS_FORCEINLINE_FUNCTION void takeScalarSum(const Sums& sums, int i, int slot,
                                               const Field& field) {
  field(i) += sums(i, slot);
  sums(i, slot) = 0;
}

}  // namespace

namespace {

/// grid += sums at the active nodes: the momenta, and with kAll every other slot too.
template <bool kAll>
void addSumsToGrid(const char* name, const ActiveNodes& active, NodeRecords& records,
                   GridFields& grid) {
  const auto sums = records.sums_i;
  const GridFields g = untracked(grid);
  forEachActiveNode(
      name, active, KOKKOS_LAMBDA(const int i) {
        takeVectorSum(sums, i, kSumMomentumSolid, g.momentum_solid_i);
        takeVectorSum(sums, i, kSumMomentumLiquid, g.momentum_liquid_i);
        if constexpr (kAll) {
          takeScalarSum(sums, i, kSumMassSolid, g.mass_solid_i);
          takeScalarSum(sums, i, kSumMassLiquid, g.mass_liquid_i);
          takeScalarSum(sums, i, kSumMassIntrinsic, g.mass_liquid_intrinsic_i);
          takeScalarSum(sums, i, kSumDrag, g.drag_i);
          takeScalarSum(sums, i, kSumVolumeLiquid, g.volume_liquid_i);
          takeVectorSum(sums, i, kSumForceMixture, g.force_mixture_i);
          takeVectorSum(sums, i, kSumForceLiquid, g.force_liquid_i);
        }
      });
}

}  // namespace

void addNodeSumsToGrid(const ActiveNodes& active, NodeRecords& records, GridFields& grid) {
  addSumsToGrid<true>("add_node_sums_to_grid", active, records, grid);
}

void addMomentumSumsToGrid(const ActiveNodes& active, NodeRecords& records, GridFields& grid) {
  addSumsToGrid<false>("add_momentum_sums_to_grid", active, records, grid);
}

namespace {

/// values(i, slot + d) = field(i, d) for d < kDim.
template <class Values, class Field>
KOKKOS_FORCEINLINE_FUNCTION void readVector(const Values& values, int i, int slot,
                                            const Field& field) {
  for (int d = 0; d < kDim; ++d) values(i, slot + d) = field(i, d);
}

}  // namespace

void readVelocityUpdateValues(const ActiveNodes& active, const GridFields& grid,
                              NodeRecords& records) {
  const auto values = records.values_i;
  const GridFields g = untracked(grid);
  forEachActiveNode(
      "read_velocity_update_values", active, KOKKOS_LAMBDA(const int i) {
        readVector(values, i, kReadAccelerationSolid, g.acceleration_solid_i);
        readVector(values, i, kReadAccelerationLiquid, g.acceleration_liquid_i);
        readVector(values, i, kReadVelocitySolid, g.velocity_solid_i);
        readVector(values, i, kReadVelocityLiquid, g.velocity_liquid_i);
      });
}

void readStrainValues(const ActiveNodes& active, const GridFields& grid,
                      Kokkos::View<const unsigned char*, MemSpace> conditioned_i,
                      NodeRecords& records) {
  const auto values = records.values_i;
  const GridFields g = untracked(grid);
  const bool any_condition = conditioned_i.extent(0) > 0;
  forEachActiveNode(
      "read_strain_values", active, KOKKOS_LAMBDA(const int i) {
        readVector(values, i, kReadStrainVelocitySolid, g.velocity_solid_i);
        readVector(values, i, kReadStrainVelocityLiquid, g.velocity_liquid_i);
        values(i, kReadStrainLiquidContent) = g.liquid_content_i(i);
        values(i, kReadStrainLiquidVolume) = g.volume_liquid_i(i);
        values(i, kReadStrainConditioned) = any_condition && conditioned_i(i) ? 1 : 0;
      });
}

}  // namespace argine
