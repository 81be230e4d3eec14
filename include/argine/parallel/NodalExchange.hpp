#pragma once
/// @file NodalExchange.hpp
/// Completes P2G sums at the nodes shared by several ranks (RankDecomposition): each rank
/// sends its partial values at the nodes it shares with a neighbour, in ONE message per
/// neighbour for all fields of a phase (packed), and adds what it receives. The partial
/// values of a node are added in ascending rank order on every rank, so all ranks holding
/// a shared node get the same value bit for bit (and a node's value depends only on the
/// partition, not on message timing). Nodes that no other rank touches are not sent.
///
/// Host-side packing: MemSpace must be host-accessible (Kokkos Serial/OpenMP); a GPU port
/// packs with a kernel into a device buffer instead.

#include <mpi.h>

#include <cstddef>
#include <initializer_list>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

class RankDecomposition;

/// A nodal field: value (node i, component c) at data[i * node_stride + c * component_stride].
struct NodalFieldRef {
  Real* data = nullptr;
  std::size_t node_stride = 1;
  std::size_t component_stride = 0;
  int components = 1;
};

/// The NodalFieldRef of a View<Real*> or View<Real*[k]> in host-accessible memory.
template <class View>
NodalFieldRef nodalField(const View& view) {
  static_assert(
      Kokkos::SpaceAccessibility<Kokkos::HostSpace, typename View::memory_space>::accessible,
      "NodalExchange packs on the host");
  NodalFieldRef ref;
  ref.data = view.data();
  ref.node_stride = view.stride(0);
  if constexpr (View::rank == 2) {
    ref.component_stride = view.stride(1);
    ref.components = static_cast<int>(view.extent(1));
  }
  return ref;
}

/// Traffic of the exchanges so far (this rank's sends).
struct ExchangeTraffic {
  long exchanges = 0;        ///< calls to sum()
  long messages = 0;         ///< messages sent
  long long bytes = 0;       ///< bytes sent
  long long last_bytes = 0;  ///< bytes sent by the last sum()
};

class NodalExchange {
 public:
  /// Keeps a reference to `decomposition` (which must outlive the exchange).
  explicit NodalExchange(const RankDecomposition& decomposition);

  /// Replaces each field's value at every shared node by the sum over the ranks sharing it.
  /// Collective over the decomposition's ranks (every rank calls it with the same field
  /// shapes, in the same order).
  void sum(std::initializer_list<NodalFieldRef> fields);
  /// Same for the fields of a vector.
  void sum(const std::vector<NodalFieldRef>& fields);
  /// Reproducible sums (transfer/CompensatedSum.hpp): field f of `hi` (part 0 of its sums)
  /// with its low parts, fields f, f + n, ..., f + (kLowParts - 1) n of `lo` (n = hi.size();
  /// same shapes: the low parts part after part). Each rank's sum is merged in ascending rank
  /// order (addSumToSum); all parts are replaced. Fold them afterwards. Collective.
  void sumCompensated(const std::vector<NodalFieldRef>& hi, const std::vector<NodalFieldRef>& lo);

  const ExchangeTraffic& traffic() const { return traffic_; }

 private:
  /// Sends and receives `fields` at the shared nodes and adds the partial values; the first
  /// `compensated_width` values per node are reproducible sums' part 0 (see above).
  void exchange(const std::vector<NodalFieldRef>& fields, int compensated_width);

  const RankDecomposition& decomposition_;
  std::vector<NodalFieldRef> fields_;
  std::vector<Real> own_;                          ///< own partial values, [slot][component]
  std::vector<Real> total_;                        ///< completed values, [slot][component]
  std::vector<std::vector<Real>> send_, receive_;  ///< per neighbour
  std::vector<MPI_Request> requests_;
  ExchangeTraffic traffic_;
};

}  // namespace argine
