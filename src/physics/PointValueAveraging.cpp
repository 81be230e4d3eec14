#include "argine/physics/PointValueAveraging.hpp"

#include <Kokkos_ScatterView.hpp>
#include <type_traits>
#include <vector>

#include "argine/materials/KernelMath.hpp"
#include "argine/parallel/NodalExchange.hpp"
#include "argine/physics/DistributedStep.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/CompensatedSum.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace KE = Kokkos::Experimental;

void AveragingScratch::allocateSums(int channels, int elements, int nodes) {
  element_sums = Kokkos::View<Real**, MemSpace>("averaging_element_sums", elements, 2 * channels);
  node_sums = Kokkos::View<Real**, MemSpace>("averaging_node_sums", nodes, 2 * channels);
  mode_pc = {};
  weight_p = {};
  value_pc = {};
  compensate(compensated());
}

void AveragingScratch::fitPoints(int points) {
  if (static_cast<int>(weight_p.extent(0)) == points && weight_p.data() != nullptr) return;
  mode_pc = Kokkos::View<int**, Kokkos::LayoutLeft, MemSpace>("averaging_mode", points, channels());
  weight_p = Kokkos::View<Real*, MemSpace>("averaging_weight", points);
  value_pc =
      Kokkos::View<Real**, Kokkos::LayoutLeft, MemSpace>("averaging_value", points, channels());
}

void AveragingScratch::compensate(bool on) {
  const int columns = static_cast<int>(node_sums.extent(1));
  for (int k = 0; k < kLowParts; ++k) {
    element_lo[k] = Kokkos::View<Real**, MemSpace>("averaging_element_lo",
                                                   on ? element_sums.extent(0) : 0, columns);
    node_lo[k] =
        Kokkos::View<Real**, MemSpace>("averaging_node_lo", on ? node_sums.extent(0) : 0, columns);
  }
}

namespace {

/// Calls f(std::integral_constant<int, n>) with n = `channels` for the counts the solver uses
/// (1, 3 and 8: the loops over the channels unrolled), else n = 0 (use `channels` at run time).
template <class Function>
void withChannelCount(int channels, Function&& f) {
  if (channels == 1)
    f(std::integral_constant<int, 1>{});
  else if (channels == 3)
    f(std::integral_constant<int, 3>{});
  else if (channels == 8)
    f(std::integral_constant<int, 8>{});
  else
    f(std::integral_constant<int, 0>{});
}

/// The averaging's element and node sums of w q and w per channel, plain or compensated;
/// kChannels = s.channels() (0: read at run time).
template <class Family, bool kCompensated, int kChannels>
void scatterAverageSums(const MaterialPoints& points, const PointShapes& shapes,
                        const AveragingScratch& s) {
  const auto element_p = points.element;
  const auto local_p = points.local;
  constexpr int nodes_per_element = Family::kNodes;
  const int channels = kChannels > 0 ? kChannels : s.channels();
  const auto mode_pc = s.mode_pc;
  const auto weight_p = s.weight_p;
  const auto value_pc = s.value_pc;
  auto element_sums = s.element_sums, node_sums = s.node_sums;  // (contribute: not const)
  const auto element_lo = s.element_lo;  // (empty and unused with plain sums)
  const auto node_lo = s.node_lo;
  auto element_sv = KE::create_scatter_view(element_sums);
  auto node_sv = KE::create_scatter_view(node_sums);
  const auto patch_e = s.patch_e;
  const bool patches = patch_e.extent(0) > 0;
  const bool nodal = s.nodal();  // else no channel reads the point's shapes: not expanded
  Kokkos::parallel_for(
      "averaging_scatter", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        const int e = element_p(p);
        if (e < 0) return;
        const Real w = weight_p(p);
        typename Family::Record scratch;
        const auto* shape = nodal ? &Family::of(shapes, p, element_p, local_p, scratch) : nullptr;
        for (int c = 0; c < channels; ++c) {
          const int mode = mode_pc(p, c);
          if (mode == kAverageNone) continue;
          const Real wq = w * value_pc(p, c);
          if (mode == kAverageElement) {
            auto sums = element_sv.access();
            const int row = patches ? patch_e(e) : e;
            addToNode<kCompensated>(sums, element_sums, element_lo, row, 2 * c, wq);
            addToNode<kCompensated>(sums, element_sums, element_lo, row, 2 * c + 1, w);
            continue;
          }
          auto sums = node_sv.access();
          for (int a = 0; a < nodes_per_element; ++a) {
            const int i = shape->node[a];
            addToNode<kCompensated>(sums, node_sums, node_lo, i, 2 * c, shape->value[a] * wq);
            addToNode<kCompensated>(sums, node_sums, node_lo, i, 2 * c + 1, shape->value[a] * w);
          }
        }
      });
  KE::contribute(element_sums, element_sv);
  KE::contribute(node_sums, node_sv);
}

/// value_pc(p, c) <- the element or nodal average of channel c at every point in it;
/// kChannels as in scatterAverageSums.
template <class Family, int kChannels>
void gatherAverages(const MaterialPoints& points, const PointShapes& shapes,
                    const AveragingScratch& scratch) {
  const int count = points.count;
  const auto element_p = points.element;
  const auto local_p = points.local;
  constexpr int nodes_per_element = Family::kNodes;
  const auto element_sums = scratch.element_sums, node_sums = scratch.node_sums;
  const auto mode_pc = scratch.mode_pc;
  const auto value_pc = scratch.value_pc;
  const int channels = kChannels > 0 ? kChannels : scratch.channels();
  const auto patch_e = scratch.patch_e;
  const bool patches = patch_e.extent(0) > 0;
  const bool nodal = scratch.nodal();  // else no channel reads the point's shapes
  Kokkos::parallel_for(
      "averaging_gather", Kokkos::RangePolicy<ExecSpace>(0, count), KOKKOS_LAMBDA(const int p) {
        const int e = element_p(p);
        if (e < 0) return;
        typename Family::Record scratch;
        const auto* shape = nodal ? &Family::of(shapes, p, element_p, local_p, scratch) : nullptr;
        for (int c = 0; c < channels; ++c) {
          const int mode = mode_pc(p, c);
          if (mode == kAverageNone) continue;
          if (mode == kAverageElement) {
            const int row = patches ? patch_e(e) : e;
            value_pc(p, c) = element_sums(row, 2 * c) / element_sums(row, 2 * c + 1);
            continue;
          }
          Real average = 0;
          for (int a = 0; a < nodes_per_element; ++a) {
            // a node of no weight may have no sums at all (a grid family's stencil corner)
            if (shape->value[a] == 0) continue;
            average += shape->value[a] * node_sums(shape->node[a], 2 * c);  // the node's average
          }
          value_pc(p, c) = average;
        }
      });
}

/// With patches on several ranks: each patch's sums completed over the ranks (a patch may
/// hold elements of several ranks), folded where they are compensated.
void sumPatchesOverRanks(AveragingScratch& scratch) {
  const auto sums = scratch.element_sums;
  const int rows = static_cast<int>(sums.extent(0)), columns = static_cast<int>(sums.extent(1));
  if (!scratch.compensated()) {
    MPI_Allreduce(MPI_IN_PLACE, sums.data(), rows * columns, MPI_DOUBLE, MPI_SUM,
                  scratch.patch_comm);
    return;
  }
  // every rank's binned sums merged in rank order: the same bits as one rank's sum
  std::vector<CompensatedReal>& all = scratch.patch_parts;
  all.resize(static_cast<std::size_t>(rows) * columns);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      Real* parts[kSumParts];
      partsAt(sums, scratch.element_lo, r, c, parts);
      for (int k = 0; k < kSumParts; ++k) all[r * columns + c].part[k] = *parts[k];
    }
  sumCompensatedOverRanks(scratch.patch_comm, all, scratch.patch_buffer);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      Real* parts[kSumParts];
      partsAt(sums, scratch.element_lo, r, c, parts);
      *parts[0] = all[r * columns + c].value();
      for (int k = 1; k < kSumParts; ++k) *parts[k] = 0;
    }
}

/// The checkerboard filter of the element sums (AveragingScratch::useCheckerboardFilter):
/// two passes over the rows, the averages q = S / W first, then the filtered sums
/// S_r + share sum_s min(W_r, W_s) (q_s - q_r).
void filterElementAverages(AveragingScratch& s) {
  const int rows = static_cast<int>(s.element_sums.extent(0)), channels = s.channels();
  if (static_cast<int>(s.filter_averages.extent(0)) != rows)
    s.filter_averages = Kokkos::View<Real**, MemSpace>("averaging_filter", rows, channels);
  const auto sums = s.element_sums;
  const auto average = s.filter_averages;
  const auto start = s.neighbour_start, neighbour = s.neighbour_rows;
  const Real share = s.neighbour_share;
  Kokkos::parallel_for(
      "averaging_filter_averages", Kokkos::RangePolicy<ExecSpace>(0, rows),
      KOKKOS_LAMBDA(const int r) {
        for (int c = 0; c < channels; ++c) {
          const Real weight = sums(r, 2 * c + 1);
          average(r, c) = weight == 0 ? Real(0) : sums(r, 2 * c) / weight;
        }
      });
  Kokkos::parallel_for(
      "averaging_filter_sums", Kokkos::RangePolicy<ExecSpace>(0, rows), KOKKOS_LAMBDA(const int r) {
        for (int c = 0; c < channels; ++c) {
          const Real weight = sums(r, 2 * c + 1);
          if (weight == 0) continue;
          Real exchanged = 0;  // an empty neighbour (weight 0) exchanges nothing
          for (int k = start(r); k < start(r + 1); ++k) {
            const int other = neighbour(k);
            const Real pair = kmath::fmin(weight, sums(other, 2 * c + 1));
            exchanged += pair * (average(other, c) - average(r, c));
          }
          sums(r, 2 * c) += share * exchanged;
        }
      });
}

}  // namespace

void divideNodeSums(const ActiveNodes& active, const AveragingScratch& scratch) {
  const auto active_nodes = active.nodes();
  const int channels = scratch.channels();
  const auto node_sums = scratch.node_sums;
  Kokkos::parallel_for(
      "averaging_node_averages", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = active_nodes(j);
        for (int c = 0; c < channels; ++c) node_sums(i, 2 * c) /= node_sums(i, 2 * c + 1);
      });
}

void sumPointValues(const MaterialPoints& points, const PointShapes& shapes,
                    const ActiveNodes& active, AveragingScratch& scratch, NodalExchange* exchange) {
  const auto active_nodes = active.nodes();
  const int columns = 2 * scratch.channels();
  const auto element_sums = scratch.element_sums, node_sums = scratch.node_sums;
  Kokkos::deep_copy(element_sums, 0.0);
  const bool nodal = scratch.nodal();  // else no point adds to a node: no node work at all
  Kokkos::parallel_for(
      "averaging_zero_nodes", Kokkos::RangePolicy<ExecSpace>(0, nodal ? active.count() : 0),
      KOKKOS_LAMBDA(const int j) {
        for (int k = 0; k < columns; ++k) node_sums(active_nodes(j), k) = 0;
      });
  withShapeFamily(shapes, [&](auto family) {
    withChannelCount(scratch.channels(), [&](auto n) {
      using Family = decltype(family);
      if (scratch.compensated())  // lo is zero: the last call folded it (below)
        scatterAverageSums<Family, true, decltype(n)::value>(points, shapes, scratch);
      else
        scatterAverageSums<Family, false, decltype(n)::value>(points, shapes, scratch);
    });
  });
  // Several ranks: a node shared with another rank also has that rank's points in its sums.
  // `active` includes the shared nodes, so every rank sends freshly zeroed partial sums.
  // (Every rank has the same materials, so all take the same branch of the collectives.)
  if (scratch.compensated()) {
    if (exchange && nodal) {
      std::vector<NodalFieldRef> lo;
      for (int k = 0; k < kLowParts; ++k) lo.push_back(nodalField(scratch.node_lo[k]));
      exchange->sumCompensated({nodalField(node_sums)}, lo);
    }
    if (nodal) foldCompensatedSums(active, node_sums, scratch.node_lo);
    if (scratch.patch_comm != MPI_COMM_NULL)
      sumPatchesOverRanks(scratch);  // folds them too
    else
      foldCompensatedSums(element_sums, scratch.element_lo);
  } else {
    if (exchange && nodal) exchange->sum({nodalField(node_sums)});
    if (scratch.patch_comm != MPI_COMM_NULL) sumPatchesOverRanks(scratch);
  }
}

void averagePointValues(const MaterialPoints& points, const PointShapes& shapes,
                        const ActiveNodes& active, AveragingScratch& scratch,
                        NodalExchange* exchange) {
  sumPointValues(points, shapes, active, scratch, exchange);
  if (scratch.filtersElementAverages()) filterElementAverages(scratch);
  if (scratch.nodal()) divideNodeSums(active, scratch);
  withShapeFamily(shapes, [&](auto family) {
    withChannelCount(scratch.channels(), [&](auto n) {
      gatherAverages<decltype(family), decltype(n)::value>(points, shapes, scratch);
    });
  });
}

}  // namespace argine
