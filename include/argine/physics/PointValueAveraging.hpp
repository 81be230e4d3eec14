#pragma once
/// @file PointValueAveraging.hpp
/// The volume-weighted smoothing of one point quantity that the locking mitigation
/// (VolumetricAveraging) and the liquid head stabilisation (LiquidHeadStabilisation) share:
///
///   element  q_p <- sum_{q in e} w_q q_q / sum_{q in e} w_q  over the points of the point's
///            element e with the same mode;
///   nodal    q_i = sum_p N_i(x_p) w_p q_p / sum_p N_i(x_p) w_p at the nodes, then
///            q_p <- sum_i N_i(x_p) q_i.
///
/// Both keep sum_p w_p q_p over an element (element) or over the body (nodal, with complete
/// node sums): sum_p w_p sum_i N_i(x_p) q_i = sum_i q_i sum_p N_i(x_p) w_p.

#include "argine/core/Types.hpp"

namespace argine {

class ActiveNodes;
class NodalExchange;
struct MaterialPoints;
struct PointShapes;

/// What a point takes part in (IncrementAveraging's values, as int for the kernels).
constexpr int kAverageNone = 0;
constexpr int kAverageElement = 1;
constexpr int kAverageNodal = 2;

/// Low parts of the averaging's sums for reproducible sums (transfer/CompensatedSum.hpp),
/// shaped as the element and node sums; empty: plain sums.
struct AveragingCompensation {
  Kokkos::View<Real* [2], MemSpace> element_lo;
  Kokkos::View<Real* [2], MemSpace> node_lo;
  bool enabled() const { return node_lo.extent(0) > 0; }
  /// Allocates both for `elements` and `nodes` (reproducible sums on), or empties them.
  void allocate(bool on, int elements, int nodes) {
    element_lo = Kokkos::View<Real* [2], MemSpace>("averaging_element_lo", on ? elements : 0);
    node_lo = Kokkos::View<Real* [2], MemSpace>("averaging_node_lo", on ? nodes : 0);
  }
};

/// Replaces value(p) by its element or nodal average (file comment of the header) at the
/// points with mode(p) != none; weight(p) > 0 there. Elements and nodes see only the points
/// of the same mode. With `compensation` enabled the sums are compensated (and exchanged so).
void averagePointValues(const MaterialPoints& points, const PointShapes& shapes,
                        const ActiveNodes& active, Kokkos::View<const int*, MemSpace> mode_p,
                        Kokkos::View<const Real*, MemSpace> weight_p,
                        Kokkos::View<Real*, MemSpace> value_p,
                        Kokkos::View<Real* [2], MemSpace> element_sums,
                        Kokkos::View<Real* [2], MemSpace> node_sums, NodalExchange* exchange,
                        const AveragingCompensation& compensation = {});

}  // namespace argine
