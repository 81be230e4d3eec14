#include "argine/parallel/PointMigration.hpp"

#include <mpi.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "argine/parallel/RankDecomposition.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/points/PointFields.hpp"

namespace argine {

namespace {

template <class View>
int componentsOf(const View& view) {
  return View::rank == 2 ? static_cast<int>(view.extent(1)) : 1;
}

}  // namespace

int migratedValuesPerPoint(const MaterialPoints& points) {
  int values = 0;
  forEachPointField(points, [&](const char*, const auto& field) { values += componentsOf(field); });
  return values;
}

namespace {

// Packs point p (all fields) into out[0, values) as doubles.
void packPoint(const MaterialPoints& points, int p, Real* out) {
  forEachPointField(points, [&](const char*, const auto& field) {
    if constexpr (std::decay_t<decltype(field)>::rank == 2) {
      for (int c = 0; c < static_cast<int>(field.extent(1)); ++c)
        *out++ = static_cast<Real>(field(p, c));
    } else {
      *out++ = static_cast<Real>(field(p));
    }
  });
}

void unpackPoint(const Real* in, MaterialPoints& points, int p) {
  forEachPointField(points, [&](const char*, auto& field) {
    using Value = typename std::decay_t<decltype(field)>::value_type;
    if constexpr (std::decay_t<decltype(field)>::rank == 2) {
      for (int c = 0; c < static_cast<int>(field.extent(1)); ++c)
        field(p, c) = static_cast<Value>(*in++);
    } else {
      field(p) = static_cast<Value>(*in++);
    }
  });
}

// A new set of points: the kept ones of `points` (in order), then the received values.
MaterialPoints rebuildPoints(const MaterialPoints& points, const std::vector<int>& kept,
                             const std::vector<Real>& received, int values) {
  const int arrived = static_cast<int>(received.size() / values);
  MaterialPoints next;
  next.allocate(static_cast<int>(kept.size()) + arrived);
  std::vector<Real> buffer(values);
  for (std::size_t k = 0; k < kept.size(); ++k) {
    packPoint(points, kept[k], buffer.data());
    unpackPoint(buffer.data(), next, static_cast<int>(k));
  }
  for (int k = 0; k < arrived; ++k)
    unpackPoint(&received[static_cast<std::size_t>(k) * values], next,
                static_cast<int>(kept.size()) + k);
  return next;
}

}  // namespace

int countEmigrants(const RankDecomposition& decomposition, const MaterialPoints& points) {
  if (decomposition.size() == 1) return 0;
  const auto owner_e = decomposition.elementOwnerView();
  const auto element_p = points.element;
  const int me = decomposition.rank();
  int count = 0;
  Kokkos::parallel_reduce(
      "count_emigrants", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& sum) {
        const int e = element_p(p);
        sum += (e >= 0 && owner_e(e) != me) ? 1 : 0;
      },
      count);
  return count;
}

MigrationCounts migratePoints(const RankDecomposition& decomposition, MaterialPoints& points) {
  if (decomposition.size() == 1) return MigrationCounts{};
  long long total = countEmigrants(decomposition, points);
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_LONG_LONG, MPI_SUM, decomposition.comm());
  return exchangePoints(decomposition, points, total);
}

MigrationCounts exchangePoints(const RankDecomposition& decomposition, MaterialPoints& points,
                               long long total) {
  static_assert(Kokkos::SpaceAccessibility<Kokkos::HostSpace, MemSpace>::accessible,
                "point migration packs on the host");
  MigrationCounts counts;
  counts.total = total;
  const int ranks = decomposition.size(), me = decomposition.rank();
  if (ranks == 1 || total == 0) return counts;
  const auto& owner = decomposition.elementOwners();
  const int values = migratedValuesPerPoint(points);

  std::vector<int> send_counts(ranks, 0);
  for (int p = 0; p < points.count; ++p) {
    const int e = points.element(p);
    if (e >= 0 && owner[e] != me) ++send_counts[owner[e]];
  }
  std::vector<int> receive_counts(ranks, 0);
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT,
               decomposition.comm());
  for (int r = 0; r < ranks; ++r)
    counts.sent += send_counts[r], counts.received += receive_counts[r];

  std::vector<int> send_offsets(ranks + 1, 0), receive_offsets(ranks + 1, 0);
  for (int r = 0; r < ranks; ++r) {
    send_offsets[r + 1] = send_offsets[r] + send_counts[r] * values;
    receive_offsets[r + 1] = receive_offsets[r] + receive_counts[r] * values;
  }
  std::vector<Real> send(send_offsets[ranks]), received(receive_offsets[ranks]);
  std::vector<int> fill(send_offsets.begin(), send_offsets.end() - 1);
  std::vector<int> kept;
  kept.reserve(points.count);
  for (int p = 0; p < points.count; ++p) {
    const int e = points.element(p);
    if (e >= 0 && owner[e] != me) {
      packPoint(points, p, &send[fill[owner[e]]]);
      fill[owner[e]] += values;
    } else {
      kept.push_back(p);
    }
  }
  std::vector<int> send_sizes(ranks), receive_sizes(ranks);
  for (int r = 0; r < ranks; ++r) {
    send_sizes[r] = send_counts[r] * values;
    receive_sizes[r] = receive_counts[r] * values;
  }
  MPI_Alltoallv(send.data(), send_sizes.data(), send_offsets.data(), MPI_DOUBLE, received.data(),
                receive_sizes.data(), receive_offsets.data(), MPI_DOUBLE, decomposition.comm());
  if (counts.sent > 0 || counts.received > 0)
    points = rebuildPoints(points, kept, received, values);
  return counts;
}

void keepOwnedPoints(const RankDecomposition& decomposition, MaterialPoints& points) {
  const auto& owner = decomposition.elementOwners();
  const int me = decomposition.rank();
  std::vector<int> kept;
  for (int p = 0; p < points.count; ++p) {
    const int e = points.element(p);
    if (e >= 0 ? owner[e] == me : me == 0) kept.push_back(p);
  }
  if (static_cast<int>(kept.size()) == points.count) return;
  points = rebuildPoints(points, kept, {}, migratedValuesPerPoint(points));
}

namespace {

/// Every rank's points packed (packPoint), rank after rank, on rank 0 or on every rank when
/// `to_all_ranks` (empty elsewhere); `sizes[r]` = values of rank r (on the receiving ranks).
std::vector<Real> gatherPacked(MPI_Comm comm, const MaterialPoints& points, bool to_all_ranks,
                               std::vector<int>& sizes) {
  static_assert(Kokkos::SpaceAccessibility<Kokkos::HostSpace, MemSpace>::accessible,
                "the gather packs on the host");
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  const int values = migratedValuesPerPoint(points);
  std::vector<Real> mine(static_cast<std::size_t>(points.count) * values);
  for (int p = 0; p < points.count; ++p)
    packPoint(points, p, &mine[static_cast<std::size_t>(p) * values]);
  const int size = static_cast<int>(mine.size());
  sizes.assign(ranks, 0);
  std::vector<int> offsets(ranks + 1, 0);
  if (to_all_ranks)
    MPI_Allgather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, comm);
  else
    MPI_Gather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, comm);
  for (int r = 0; r < ranks; ++r) offsets[r + 1] = offsets[r] + sizes[r];
  std::vector<Real> all(static_cast<std::size_t>(offsets[ranks]));
  if (to_all_ranks)
    MPI_Allgatherv(mine.data(), size, MPI_DOUBLE, all.data(), sizes.data(), offsets.data(),
                   MPI_DOUBLE, comm);
  else
    MPI_Gatherv(mine.data(), size, MPI_DOUBLE, all.data(), sizes.data(), offsets.data(), MPI_DOUBLE,
                0, comm);
  return all;
}

}  // namespace

MaterialPoints gatherPoints(MPI_Comm comm, const MaterialPoints& points, bool to_all_ranks) {
  int me = 0;
  MPI_Comm_rank(comm, &me);
  std::vector<int> sizes;
  const std::vector<Real> all = gatherPacked(comm, points, to_all_ranks, sizes);
  MaterialPoints gathered;
  if (!to_all_ranks && me != 0) {
    gathered.allocate(0);
    return gathered;
  }
  // The id is a field of the packed point: find its slot from a point packed with known ids.
  const int values = migratedValuesPerPoint(points);
  const int count = static_cast<int>(all.size() / values);
  std::vector<Real> id_of(count);
  {
    int slot = 0, id_slot = -1;
    forEachPointField(points, [&](const char* name, const auto& field) {
      if (std::string(name) == "id") id_slot = slot;
      slot += componentsOf(field);
    });
    for (int k = 0; k < count; ++k) id_of[k] = all[static_cast<std::size_t>(k) * values + id_slot];
  }
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return id_of[a] < id_of[b]; });
  gathered.allocate(count);
  for (int k = 0; k < count; ++k)
    unpackPoint(&all[static_cast<std::size_t>(order[k]) * values], gathered, k);
  return gathered;
}

MaterialPoints gatherPointsByRank(MPI_Comm comm, const MaterialPoints& points,
                                  std::vector<long long>& counts) {
  int me = 0;
  MPI_Comm_rank(comm, &me);
  std::vector<int> sizes;
  const std::vector<Real> all = gatherPacked(comm, points, false, sizes);
  MaterialPoints gathered;
  counts.clear();
  if (me != 0) {
    gathered.allocate(0);
    return gathered;
  }
  const int values = migratedValuesPerPoint(points);
  for (const int size : sizes) counts.push_back(size / values);
  const int count = static_cast<int>(all.size() / values);
  gathered.allocate(count);
  for (int k = 0; k < count; ++k)
    unpackPoint(&all[static_cast<std::size_t>(k) * values], gathered, k);
  return gathered;
}

MaterialPoints pointRange(const MaterialPoints& points, int first, int count) {
  if (first < 0 || count < 0 || first + count > points.count)
    throw std::out_of_range("pointRange: [" + std::to_string(first) + ", " +
                            std::to_string(first + count) + ") of " + std::to_string(points.count) +
                            " points");
  std::vector<int> kept(count);
  std::iota(kept.begin(), kept.end(), first);
  return rebuildPoints(points, kept, {}, migratedValuesPerPoint(points));
}

}  // namespace argine
