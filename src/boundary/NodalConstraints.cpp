#include "argine/boundary/NodalConstraints.hpp"

namespace argine {

void NodalConstraints::finalise() {
  nodes_ = Kokkos::View<int*, MemSpace>("constrained_nodes", pending_.size());
  flags_ = Kokkos::View<unsigned*, MemSpace>("constraint_flags", pending_.size());
  auto nodes = Kokkos::create_mirror_view(nodes_);
  auto flags = Kokkos::create_mirror_view(flags_);
  int j = 0;
  for (const auto& [node, bits] : pending_) {
    nodes(j) = node;
    flags(j) = bits;
    ++j;
  }
  Kokkos::deep_copy(nodes_, nodes);
  Kokkos::deep_copy(flags_, flags);
}

unsigned NodalConstraints::take(int node, unsigned bits) {
  const auto found = pending_.find(node);
  if (found == pending_.end()) return 0u;
  const unsigned taken = found->second & bits;
  found->second &= ~bits;
  if (found->second == 0) pending_.erase(found);  // nothing left to constrain there
  return taken;
}

unsigned NodalConstraints::flagsOf(int node) const {
  const auto found = pending_.find(node);
  return found == pending_.end() ? 0u : found->second;
}

void NodalConstraints::constrainVelocities(
    const Kokkos::View<Real* [kDim], MemSpace>& velocity_solid_i,
    const Kokkos::View<Real* [kDim], MemSpace>& velocity_liquid_i,
    const bool keep_relative_velocity) const {
  const auto nodes = nodes_;
  const auto flags = flags_;
  Kokkos::parallel_for(
      "constrain_velocities", Kokkos::RangePolicy<ExecSpace>(0, count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        const unsigned bits = flags(j);
        for (int d = 0; d < kDim; ++d) {
          if (bits & solidFixedBit(d)) {
            // the mapped v_S,d here is motion the fixity forbids; the liquid shares it (a
            // point's grid-invisible FLIP velocity, or a body sliding into a fixed node)
            if (keep_relative_velocity) velocity_liquid_i(i, d) -= velocity_solid_i(i, d);
            velocity_solid_i(i, d) = 0;
          }
          if (bits & liquidLockedBit(d)) velocity_liquid_i(i, d) = velocity_solid_i(i, d);
        }
      });
}

}  // namespace argine
