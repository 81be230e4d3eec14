#include "argine/physics/PointValueAveraging.hpp"

#include <Kokkos_ScatterView.hpp>

#include "argine/parallel/NodalExchange.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace KE = Kokkos::Experimental;

void averagePointValues(const MaterialPoints& points, const PointShapes& shapes,
                        const ActiveNodes& active, Kokkos::View<const int*, MemSpace> mode_p,
                        Kokkos::View<const Real*, MemSpace> weight_p,
                        Kokkos::View<Real*, MemSpace> value_p,
                        Kokkos::View<Real* [2], MemSpace> element_sums,
                        Kokkos::View<Real* [2], MemSpace> node_sums, NodalExchange* exchange) {
  const int count = points.count;
  const auto element_p = points.element;
  const auto shape_p = shapes.shape_p;
  const int nodes_per_element = shapes.type == ElementType::Tri3 ? 3 : 4;
  const auto active_nodes = active.nodes();
  Kokkos::deep_copy(element_sums, 0.0);
  Kokkos::parallel_for(
      "averaging_zero_nodes", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        node_sums(active_nodes(j), 0) = 0;
        node_sums(active_nodes(j), 1) = 0;
      });
  auto element_sv = KE::create_scatter_view(element_sums);
  auto node_sv = KE::create_scatter_view(node_sums);
  Kokkos::parallel_for(
      "averaging_scatter", Kokkos::RangePolicy<ExecSpace>(0, count), KOKKOS_LAMBDA(const int p) {
        const int mode = mode_p(p);
        const int e = element_p(p);
        if (mode == kAverageNone || e < 0) return;
        const Real w = weight_p(p), wq = w * value_p(p);
        if (mode == kAverageElement) {
          auto sums = element_sv.access();
          sums(e, 0) += wq;
          sums(e, 1) += w;
          return;
        }
        auto sums = node_sv.access();
        const PointShape& shape = shape_p(p);
        for (int a = 0; a < nodes_per_element; ++a) {
          sums(shape.node[a], 0) += shape.value[a] * wq;
          sums(shape.node[a], 1) += shape.value[a] * w;
        }
      });
  KE::contribute(element_sums, element_sv);
  KE::contribute(node_sums, node_sv);
  // Several ranks: a node shared with another rank also has that rank's points in its sums.
  // `active` includes the shared nodes, so every rank sends freshly zeroed partial sums.
  if (exchange) exchange->sum({nodalField(node_sums)});
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
