#pragma once
/// @file NodalConstraints.hpp
/// Essential (velocity) boundary conditions on grid nodes (thesis Sec. 4: "imposed on the
/// nodes of the computational grid"), as a compact list of constrained nodes with one flag
/// word each, so kernels loop over the constrained nodes only.
///
/// Two kinds, per axis direction:
///  - solid fixed: the solid velocity and acceleration component is zero (SolidFixity);
///  - liquid locked: the liquid moves with the solid in that direction, i.e. the RELATIVE
///    liquid velocity component (v_L - v_S) is zero: an impermeable boundary whose outward
///    normal is that axis (ImpermeableBoundary). Where the solid is also fixed, both phases
///    are at rest in that direction.

#include <map>

#include "argine/core/Types.hpp"

namespace argine {

/// Flag bits of a constrained node.
enum NodalConstraintBits : unsigned {
  kSolidFixedX = 1u << 0,    ///< v_S,x = a_S,x = 0
  kSolidFixedY = 1u << 1,    ///< v_S,y = a_S,y = 0
  kLiquidLockedX = 1u << 2,  ///< v_L,x - v_S,x = 0 (impermeable, normal along x)
  kLiquidLockedY = 1u << 3,  ///< v_L,y - v_S,y = 0 (impermeable, normal along y)
};

/// The flag bit of a solid fixity in direction d (0 = x, 1 = y).
KOKKOS_INLINE_FUNCTION constexpr unsigned solidFixedBit(int d) {
  return d == 0 ? kSolidFixedX : kSolidFixedY;
}
/// The flag bit of a liquid lock (impermeable) in direction d.
KOKKOS_INLINE_FUNCTION constexpr unsigned liquidLockedBit(int d) {
  return d == 0 ? kLiquidLockedX : kLiquidLockedY;
}

class NodalConstraints {
 public:
  /// Adds `bits` to node `node` (host side, while the stage's conditions are resolved).
  void add(int node, unsigned bits) { pending_[node] |= bits; }
  /// Removes `bits` from `node` (host side, before finalise()) and returns those of them
  /// that were set: a frictional wall applies the liquid locks of its nodes itself, after
  /// its contact (FrictionalContact::finalise).
  unsigned take(int node, unsigned bits);
  /// Copies the collected constraints into the device lists; call once after the adds.
  void finalise();

  /// Constrained node indices, entries [0, count()).
  Kokkos::View<const int*, MemSpace> nodes() const { return nodes_; }
  /// Flag word (NodalConstraintBits) of each listed node.
  Kokkos::View<const unsigned*, MemSpace> flags() const { return flags_; }
  /// Number of constrained nodes.
  int count() const { return static_cast<int>(nodes_.extent(0)); }
  /// Flags of `node` as collected (host lookup, for tests and diagnostics); 0 if free.
  unsigned flagsOf(int node) const;

  /// Applies the velocity conditions to nodal velocities: v_S,d = 0 where solid-fixed, then
  /// v_L,d = v_S,d where liquid-locked. Nodes without liquid (`liquid_mass_i` == 0) keep
  /// v_L = v_S anyway. At a solid-fixed direction that is not locked the liquid keeps its
  /// mapped velocity v_L,d (the thesis), or, with `keep_relative_velocity`, its mapped
  /// RELATIVE velocity: v_L,d -= v_S,d before v_S,d = 0, so the fixity removes the motion
  /// both phases share and no Darcy flux appears that the points do not carry
  /// (StageSpec::fixity_keeps_relative_velocity; doc/theory.md Sec. 5.1).
  void constrainVelocities(const Kokkos::View<Real* [kDim], MemSpace>& velocity_solid_i,
                           const Kokkos::View<Real* [kDim], MemSpace>& velocity_liquid_i,
                           bool keep_relative_velocity = false) const;

 private:
  std::map<int, unsigned> pending_;
  Kokkos::View<int*, MemSpace> nodes_;
  Kokkos::View<unsigned*, MemSpace> flags_;
};

}  // namespace argine
