#include "argine/boundary/FrictionalContact.hpp"

#include <algorithm>
#include <cmath>

namespace argine {

void FrictionalContact::add(int node, const Real normal[kDim], Real friction, bool impermeable) {
  Walls& walls = pending_[node];
  walls.normals.push_back({normal[0], normal[1]});
  walls.friction = std::max(walls.friction, friction);
  walls.impermeable = walls.impermeable || impermeable;
}

namespace {

constexpr Real kPi = 3.14159265358979323846;

/// The merged normal of a node's walls; false at a corner (two normals further apart than
/// FrictionalContact::kCornerAngleDegrees).
bool mergedNormal(const std::vector<std::array<Real, kDim>>& normals, Real merged[kDim]) {
  const Real corner_cosine = std::cos(FrictionalContact::kCornerAngleDegrees * kPi / 180);
  Real sum[kDim] = {0, 0};
  for (std::size_t a = 0; a < normals.size(); ++a) {
    for (std::size_t b = a + 1; b < normals.size(); ++b)
      if (normals[a][0] * normals[b][0] + normals[a][1] * normals[b][1] < corner_cosine)
        return false;
    for (int d = 0; d < kDim; ++d) sum[d] += normals[a][d];
  }
  const Real length = std::hypot(sum[0], sum[1]);  // > 0: the normals are within 10 degrees
  for (int d = 0; d < kDim; ++d) merged[d] = sum[d] / length;
  return true;
}

}  // namespace

void FrictionalContact::finalise(NodalConstraints& constraints) {
  resolved_.clear();
  for (const auto& [node, walls] : pending_) {
    ContactNode& c = resolved_[node];
    if (!mergedNormal(walls.normals, c.normal)) c.flags |= kContactHeld;
    c.friction = walls.friction;
    if (walls.impermeable) c.flags |= kContactImpermeable;
    c.flags |= constraints.flagsOf(node) & (kSolidFixedX | kSolidFixedY);
    c.flags |= constraints.take(node, kLiquidLockedX | kLiquidLockedY);
  }
  const std::size_t count = resolved_.size();
  nodes_ = Kokkos::View<int*, MemSpace>("contact_nodes", count);
  normals_ = Kokkos::View<Real* [kDim], MemSpace>("contact_normals", count);
  friction_ = Kokkos::View<Real*, MemSpace>("contact_friction", count);
  flags_ = Kokkos::View<unsigned*, MemSpace>("contact_flags", count);
  at_rest_ = Kokkos::View<unsigned char*, MemSpace>("contact_at_rest", count);
  auto nodes = Kokkos::create_mirror_view(nodes_);
  auto normals = Kokkos::create_mirror_view(normals_);
  auto friction = Kokkos::create_mirror_view(friction_);
  auto flags = Kokkos::create_mirror_view(flags_);
  int j = 0;
  for (const auto& [node, c] : resolved_) {
    nodes(j) = node;
    for (int d = 0; d < kDim; ++d) normals(j, d) = c.normal[d];
    friction(j) = c.friction;
    flags(j) = c.flags;
    ++j;
  }
  Kokkos::deep_copy(nodes_, nodes);
  Kokkos::deep_copy(normals_, normals);
  Kokkos::deep_copy(friction_, friction);
  Kokkos::deep_copy(flags_, flags);
}

const ContactNode* FrictionalContact::find(int node) const {
  const auto found = resolved_.find(node);
  return found == resolved_.end() ? nullptr : &found->second;
}

void FrictionalContact::constrainVelocities(
    const Kokkos::View<const Real*, MemSpace>& mass_solid_i,
    const Kokkos::View<const Real*, MemSpace>& mass_liquid_i,
    const Kokkos::View<Real* [kDim], MemSpace>& velocity_solid_i,
    const Kokkos::View<Real* [kDim], MemSpace>& velocity_liquid_i, bool liquid_with_solid) const {
  if (count() == 0) return;  // no wall: not even the kernel's captures
  const auto nodes = nodes_;
  const auto normals = normals_;
  const auto friction = friction_;
  const auto flags = flags_;
  const auto at_rest = at_rest_;
  Kokkos::parallel_for(
      "wall_contact_velocities", Kokkos::RangePolicy<ExecSpace>(0, count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        const Real mass_solid = mass_solid_i(i);
        if (!(mass_solid > 0)) return;  // no soil at the node (or not on this rank)
        const unsigned bits = flags(j);
        // The wall stops the liquid's normal motion with the solid's: the liquid's mass then
        // adds to the normal force (solidFrictionCoefficient).
        const bool locked = liquid_with_solid || (bits & kContactImpermeable);
        const Real n[kDim] = {normals(j, 0), normals(j, 1)};
        const Real v[kDim] = {velocity_solid_i(i, 0), velocity_solid_i(i, 1)};
        Real solid[kDim] = {0, 0};
        if (!at_rest(j))
          wallSolidVelocity(
              bits, v, n,
              solidFrictionCoefficient(friction(j), mass_solid, locked ? mass_liquid_i(i) : 0),
              solid);
        holdFixedComponents(bits, solid);
        Real liquid[kDim] = {velocity_liquid_i(i, 0), velocity_liquid_i(i, 1)};
        wallLiquidComponents(bits, locked, n, solid, liquid);
        for (int d = 0; d < kDim; ++d) {
          velocity_solid_i(i, d) = solid[d];
          velocity_liquid_i(i, d) = liquid[d];
        }
      });
}

}  // namespace argine
