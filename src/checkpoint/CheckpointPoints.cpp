// The material points in a checkpoint: every SoA field as a named record, in point order
// (the order decides the order of the P2G sums, so it is kept for a bit-identical restart).
#include <string>

#include "argine/checkpoint/CheckpointFile.hpp"
#include "argine/core/Error.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/points/PointFields.hpp"

namespace argine {

namespace {

template <class ViewType>
std::uint64_t columnsOf(const ViewType& view) {
  return ViewType::rank == 1 ? 1 : static_cast<std::uint64_t>(view.extent(1));
}

}  // namespace

void putPoints(CheckpointWriter& out, const MaterialPoints& points) {
  out.put<std::int64_t>(points.count);
  forEachPointField(points, [&](const char* name, const auto& view) {
    using Value = typename std::decay_t<decltype(view)>::non_const_value_type;
    const auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
    out.putString(name);
    out.put<std::uint32_t>(sizeof(Value));
    out.put<std::uint64_t>(view.extent(0));
    out.put<std::uint64_t>(columnsOf(view));
    out.putBytes(host.data(), host.span() * sizeof(Value));
  });
}

void getPoints(CheckpointReader& in, MaterialPoints& points) {
  const auto count = in.get<std::int64_t>();
  if (count != points.count)
    throw InputError(in.path(), "checkpoint of " + std::to_string(count) +
                                    " material points; the deck seeds " +
                                    std::to_string(points.count));
  forEachPointField(points, [&](const char* name, auto& view) {
    using Value = typename std::decay_t<decltype(view)>::non_const_value_type;
    const std::string stored = in.getString();
    const auto size = in.get<std::uint32_t>();
    const auto rows = in.get<std::uint64_t>();
    const auto columns = in.get<std::uint64_t>();
    if (stored != name || size != sizeof(Value) || rows != view.extent(0) ||
        columns != columnsOf(view))
      in.fail("point field '" + stored + "' (" + std::to_string(rows) + " x " +
              std::to_string(columns) + " of " + std::to_string(size) +
              " bytes) where this argine expects '" + name + "' (" +
              std::to_string(view.extent(0)) + " x " + std::to_string(columnsOf(view)) + " of " +
              std::to_string(sizeof(Value)) + " bytes)");
    auto host = Kokkos::create_mirror_view(Kokkos::HostSpace(), view);
    in.getBytes(host.data(), host.span() * sizeof(Value));
    Kokkos::deep_copy(view, host);
  });
}

}  // namespace argine
