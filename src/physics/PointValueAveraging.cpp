#include "argine/physics/PointValueAveraging.hpp"

#include <Kokkos_ScatterView.hpp>

#include "argine/parallel/NodalExchange.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/CompensatedSum.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace KE = Kokkos::Experimental;

namespace {

/// The averaging's element and node sums of w q and w, plain or compensated (lo given).
template <bool kCompensated>
void scatterAverageSums(const MaterialPoints& points, const PointShapes& shapes,
                        Kokkos::View<const int*, MemSpace> mode_p,
                        Kokkos::View<const Real*, MemSpace> weight_p,
                        Kokkos::View<const Real*, MemSpace> value_p,
                        Kokkos::View<Real* [2], MemSpace> element_sums,
                        Kokkos::View<Real* [2], MemSpace> node_sums,
                        Kokkos::View<Real* [2], MemSpace> element_lo,
                        Kokkos::View<Real* [2], MemSpace> node_lo) {
  const auto element_p = points.element;
  const auto shape_p = shapes.shape_p;
  const int nodes_per_element = shapes.type == ElementType::Tri3 ? 3 : 4;
  auto element_sv = KE::create_scatter_view(element_sums);
  auto node_sv = KE::create_scatter_view(node_sums);
  Kokkos::parallel_for(
      "averaging_scatter", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        const int mode = mode_p(p);
        const int e = element_p(p);
        if (mode == kAverageNone || e < 0) return;
        const Real w = weight_p(p), wq = w * value_p(p);
        if (mode == kAverageElement) {
          auto sums = element_sv.access();
          addToNode<kCompensated>(sums, element_sums, element_lo, e, 0, wq);
          addToNode<kCompensated>(sums, element_sums, element_lo, e, 1, w);
          return;
        }
        auto sums = node_sv.access();
        const PointShape& shape = shape_p(p);
        for (int a = 0; a < nodes_per_element; ++a) {
          addToNode<kCompensated>(sums, node_sums, node_lo, shape.node[a], 0, shape.value[a] * wq);
          addToNode<kCompensated>(sums, node_sums, node_lo, shape.node[a], 1, shape.value[a] * w);
        }
      });
  KE::contribute(element_sums, element_sv);
  KE::contribute(node_sums, node_sv);
}

}  // namespace

void averagePointValues(const MaterialPoints& points, const PointShapes& shapes,
                        const ActiveNodes& active, Kokkos::View<const int*, MemSpace> mode_p,
                        Kokkos::View<const Real*, MemSpace> weight_p,
                        Kokkos::View<Real*, MemSpace> value_p,
                        Kokkos::View<Real* [2], MemSpace> element_sums,
                        Kokkos::View<Real* [2], MemSpace> node_sums, NodalExchange* exchange,
                        const AveragingCompensation& compensation) {
  const int count = points.count;
  const auto element_p = points.element;
  const auto shape_p = shapes.shape_p;
  const int nodes_per_element = shapes.type == ElementType::Tri3 ? 3 : 4;
  const auto active_nodes = active.nodes();
  const bool compensated = compensation.enabled();
  Kokkos::deep_copy(element_sums, 0.0);
  Kokkos::parallel_for(
      "averaging_zero_nodes", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        node_sums(active_nodes(j), 0) = 0;
        node_sums(active_nodes(j), 1) = 0;
      });
  if (compensated) {  // lo is zero: the last call folded it (below)
    scatterAverageSums<true>(points, shapes, mode_p, weight_p, value_p, element_sums, node_sums,
                             compensation.element_lo, compensation.node_lo);
  } else {
    scatterAverageSums<false>(points, shapes, mode_p, weight_p, value_p, element_sums, node_sums,
                              element_sums, node_sums);
  }
  // Several ranks: a node shared with another rank also has that rank's points in its sums.
  // `active` includes the shared nodes, so every rank sends freshly zeroed partial sums.
  if (compensated) {
    if (exchange)
      exchange->sumCompensated({nodalField(node_sums)}, {nodalField(compensation.node_lo)});
    foldCompensatedSums(active, node_sums, compensation.node_lo);
    const auto element_lo = compensation.element_lo;
    Kokkos::parallel_for(
        "averaging_fold_elements", Kokkos::RangePolicy<ExecSpace>(0, element_sums.extent(0)),
        KOKKOS_LAMBDA(const int e) {
          for (int c = 0; c < 2; ++c) {
            element_sums(e, c) += element_lo(e, c);
            element_lo(e, c) = 0;
          }
        });
  } else if (exchange) {
    exchange->sum({nodalField(node_sums)});
  }
  Kokkos::parallel_for(
      "averaging_gather", Kokkos::RangePolicy<ExecSpace>(0, count), KOKKOS_LAMBDA(const int p) {
        const int mode = mode_p(p);
        const int e = element_p(p);
        if (mode == kAverageNone || e < 0) return;
        if (mode == kAverageElement) {
          value_p(p) = element_sums(e, 0) / element_sums(e, 1);
          return;
        }
        const PointShape& shape = shape_p(p);
        Real average = 0;
        for (int a = 0; a < nodes_per_element; ++a) {
          const int i = shape.node[a];
          average += shape.value[a] * node_sums(i, 0) / node_sums(i, 1);
        }
        value_p(p) = average;
      });
}

}  // namespace argine
