#include "argine/physics/AirPath.hpp"

#include <algorithm>

#include "argine/boundary/FreeBoundary.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

AirPath::AirPath(const MaterialTable& table, int elements) {
  air_filled_m_.assign(table.count(), 0);
  for (int m = 0; m < table.count(); ++m)
    if (table.host(m).phase == PhaseModel::Unsaturated &&
        table.host(m).tension_cracks == TensionCracks::AirFilled) {
      air_filled_m_[m] = 1;
      enabled_ = true;
    }
  if (!enabled_) return;
  cracked_.assign(elements, 0);
  reaches_e_ = Kokkos::View<unsigned char*, MemSpace>("air_reaches_e", elements);
  reaches_h_ = Kokkos::create_mirror_view(reaches_e_);
}

void AirPath::update(const FreeBoundary& boundary, const MaterialPoints& points, MPI_Comm comm) {
  if (!enabled_) return;
  const auto element = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.element);
  const auto material = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.material);
  const auto separation =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.separation);
  std::fill(cracked_.begin(), cracked_.end(), 0);
  for (int p = 0; p < points.count; ++p)
    if (element(p) >= 0 && separation(p) > 0 && air_filled_m_[material(p)])
      cracked_[element(p)] = 1;
  const int elements = static_cast<int>(cracked_.size());
  if (comm != MPI_COMM_NULL)
    MPI_Allreduce(MPI_IN_PLACE, cracked_.data(), elements, MPI_UNSIGNED_CHAR, MPI_BOR, comm);
  Kokkos::deep_copy(reaches_h_, 0);
  for (const FreeSide& side : boundary.sides())
    if (!side.mesh_edge) reaches_h_(side.element) = 1;
  const int sides = boundary.sidesPerElement();
  cracked_count_ = 0;
  for (int e = 0; e < elements; ++e) {
    if (!cracked_[e]) continue;
    ++cracked_count_;
    reaches_h_(e) = 1;
    for (int s = 0; s < sides; ++s) {
      const int across = boundary.neighbour(e, s);
      if (across >= 0) reaches_h_(across) = 1;
    }
  }
  Kokkos::deep_copy(reaches_e_, reaches_h_);  // no copy where the two are the same memory
}

}  // namespace argine
