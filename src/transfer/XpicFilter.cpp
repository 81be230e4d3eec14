#include "argine/transfer/XpicFilter.hpp"

#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"

namespace argine {

namespace {

/// filtered (+)= coefficient v of both phases at the active nodes (`assign`: =).
void accumulateNodalVelocities(const ActiveNodes& active, const GridFields& grid, Real coefficient,
                               bool assign, const XpicScratch& scratch) {
  const auto nodes = active.nodes();
  const auto vs = grid.velocity_solid_i, vl = grid.velocity_liquid_i;
  const auto filtered = scratch.filtered_i;
  Kokkos::parallel_for(
      "xpic_accumulate", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int d = 0; d < kDim; ++d) {
          const Real solid = coefficient * vs(i, d), liquid = coefficient * vl(i, d);
          filtered(i, d) = assign ? solid : filtered(i, d) + solid;
          filtered(i, kDim + d) = assign ? liquid : filtered(i, kDim + d) + liquid;
        }
      });
}

}  // namespace

void filterNodalVelocitiesXpic(int order, const PointShapes& shapes, const LiquidCarrying& liquid_m,
                               const ActiveNodes& active, MaterialPoints& points,
                               NodeRecords& records, GridFields& grid, XpicScratch& scratch,
                               const LowParts<GridFields>* compensation,
                               const std::function<void()>& complete_momenta) {
  if (order <= 1) return;  // XPIC(1): v* = v^(1), PIC
  if (static_cast<int>(scratch.filtered_i.extent(0)) != grid.numNodes())
    scratch.filtered_i =
        Kokkos::View<Real * [2 * kDim], MemSpace>("xpic_filtered_i", grid.numNodes());
  if (static_cast<int>(scratch.velocity_solid_p.extent(0)) < points.count) {
    scratch.velocity_solid_p = Kokkos::View<Real* [kDim], MemSpace>("xpic_vs_p", points.count);
    scratch.velocity_liquid_p = Kokkos::View<Real* [kDim], MemSpace>("xpic_vl_p", points.count);
  }
  const std::pair<int, int> own(0, points.count);
  const auto saved_solid = Kokkos::subview(scratch.velocity_solid_p, own, Kokkos::ALL);
  const auto saved_liquid = Kokkos::subview(scratch.velocity_liquid_p, own, Kokkos::ALL);
  const auto point_solid = Kokkos::subview(points.velocity_solid, own, Kokkos::ALL);
  const auto point_liquid = Kokkos::subview(points.velocity_liquid, own, Kokkos::ALL);
  Kokkos::deep_copy(saved_solid, point_solid);
  Kokkos::deep_copy(saved_liquid, point_liquid);
  // (-1)^(k+1) C(m, k), k = 1 .. m: m, then c_k (m - k) / (k + 1) with the sign turned
  Real coefficient = order;
  accumulateNodalVelocities(active, grid, coefficient, true, scratch);
  TransferSettings round_trip;  // TPIC: v_p = S+ v, then its momenta to the grid (S)
  round_trip.scheme = TransferScheme::Tpic;
  for (int k = 1; k < order; ++k) {
    updatePointVelocitiesAndMapMomenta(shapes, liquid_m, active, 0.0, round_trip, points, records,
                                       grid, compensation);
    if (complete_momenta) complete_momenta();
    computeNodalVelocities(active, grid);  // v^(k+1) (the liquid content again as it was)
    coefficient = -coefficient * (order - k) / (k + 1);
    accumulateNodalVelocities(active, grid, coefficient, false, scratch);
  }
  const auto nodes = active.nodes();
  const auto vs = grid.velocity_solid_i, vl = grid.velocity_liquid_i;
  const auto filtered = scratch.filtered_i;
  Kokkos::parallel_for(
      "xpic_store", Kokkos::RangePolicy<ExecSpace>(0, active.count()), KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int d = 0; d < kDim; ++d) {
          vs(i, d) = filtered(i, d);
          vl(i, d) = filtered(i, kDim + d);
        }
      });
  Kokkos::deep_copy(point_solid, saved_solid);
  Kokkos::deep_copy(point_liquid, saved_liquid);
}

}  // namespace argine
