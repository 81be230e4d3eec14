#include "argine/parallel/NodalExchange.hpp"

#include <stdexcept>

#include <mpi.h>

#include "argine/parallel/RankDecomposition.hpp"
#include "argine/transfer/CompensatedSum.hpp"

namespace argine {

NodalExchange::NodalExchange(const RankDecomposition& decomposition)
    : decomposition_(decomposition),
      send_(decomposition.neighbours().size()),
      receive_(decomposition.neighbours().size()) {}

void NodalExchange::sum(std::initializer_list<NodalFieldRef> fields) {
  fields_.assign(fields.begin(), fields.end());
  sum(fields_);
}

void NodalExchange::sum(const std::vector<NodalFieldRef>& fields) {
  exchange(fields, 0);
}

void NodalExchange::sumCompensated(const std::vector<NodalFieldRef>& hi,
                                   const std::vector<NodalFieldRef>& lo) {
  fields_.assign(hi.begin(), hi.end());
  int width = 0;
  for (const auto& f : fields_) width += f.components;
  if (lo.size() != kLowParts * hi.size())
    throw std::logic_error("NodalExchange::sumCompensated: every field needs its low parts");
  fields_.insert(fields_.end(), lo.begin(), lo.end());
  exchange(fields_, width);
}

void NodalExchange::exchange(const std::vector<NodalFieldRef>& fields, int compensated_width) {
  const auto& neighbours = decomposition_.neighbours();
  ++traffic_.exchanges;
  traffic_.last_bytes = 0;
  if (neighbours.empty()) return;
  int width = 0;  // values per node
  for (const auto& f : fields) width += f.components;
  const auto& shared = decomposition_.sharedNodes();
  const std::size_t slots = shared.size();
  // Buffers only grow (the same phases repeat every step): no allocation after the first.
  if (own_.size() < slots * width) own_.resize(slots * width), total_.resize(slots * width);

  for (std::size_t j = 0; j < slots; ++j) {
    Real* own = &own_[j * width];
    const std::size_t i = static_cast<std::size_t>(shared[j]);
    for (const auto& f : fields)
      for (int c = 0; c < f.components; ++c)
        *own++ = f.data[i * f.node_stride + c * f.component_stride];
  }
  requests_.resize(2 * neighbours.size());
  int request_count = 0;
  const MPI_Comm comm = decomposition_.comm();
  constexpr int kTag = 7301;
  for (std::size_t k = 0; k < neighbours.size(); ++k) {
    const auto& neighbour = neighbours[k];
    const std::size_t n = neighbour.nodes.size() * width;
    if (receive_[k].size() < n) receive_[k].resize(n), send_[k].resize(n);
    Real* send = send_[k].data();
    for (const int slot : neighbour.slots)
      for (int c = 0; c < width; ++c) *send++ = own_[slot * width + c];
    MPI_Irecv(receive_[k].data(), static_cast<int>(n), MPI_DOUBLE, neighbour.rank, kTag, comm,
              &requests_[request_count++]);
    MPI_Isend(send_[k].data(), static_cast<int>(n), MPI_DOUBLE, neighbour.rank, kTag, comm,
              &requests_[request_count++]);
    ++traffic_.messages;
    traffic_.last_bytes += static_cast<long long>(n * sizeof(Real));
  }
  MPI_Waitall(request_count, requests_.data(), MPI_STATUSES_IGNORE);
  traffic_.bytes += traffic_.last_bytes;

  // Ascending rank order at every node: the lower neighbours, this rank, the higher ones.
  // Reproducible sums: the first `compensated_width` values of a node are the sums' part 0,
  // each next as many a low part; a rank's sum is merged into the total's (exact: the order
  // of the ranks does not matter to these).
  std::fill(total_.begin(), total_.begin() + slots * width, 0.0);
  const int me = decomposition_.rank();
  const int sums = compensated_width;
  auto add_node = [&](Real* total, const Real* partial) {
    for (int c = 0; c < sums; ++c) {
      Real* into[kSumParts];
      Real from[kSumParts];
      for (int k = 0; k < kSumParts; ++k) {
        into[k] = &total[c + k * sums];
        from[k] = partial[c + k * sums];
      }
      addSumToSum(into, from);
    }
    for (int c = kSumParts * sums; c < width; ++c) total[c] += partial[c];
  };
  bool own_added = false;
  auto add_own = [&] {
    for (std::size_t j = 0; j < slots; ++j) add_node(&total_[j * width], &own_[j * width]);
    own_added = true;
  };
  for (std::size_t k = 0; k < neighbours.size(); ++k) {
    if (!own_added && neighbours[k].rank > me) add_own();
    const Real* received = receive_[k].data();
    for (const int slot : neighbours[k].slots) {
      add_node(&total_[slot * width], received);
      received += width;
    }
  }
  if (!own_added) add_own();

  for (std::size_t j = 0; j < slots; ++j) {
    const Real* total = &total_[j * width];
    const std::size_t i = static_cast<std::size_t>(shared[j]);
    for (const auto& f : fields)
      for (int c = 0; c < f.components; ++c)
        f.data[i * f.node_stride + c * f.component_stride] = *total++;
  }
}

}  // namespace argine
