#pragma once
/// @file FrictionalContact.hpp
/// Rigid walls with Coulomb friction on the fixed background mesh (deck `Type: frictional
/// wall`, doc/theory.md Sec. 5.6): the list of contact nodes with their wall normal, friction
/// coefficient and flags, resolved once per stage (StageBoundaryConditions), and the velocity
/// form of the contact. The acceleration form, which needs the nodal masses and the step, is
/// physics/WallContact.hpp; both apply the per-node rules below, written once.
///
/// Per node, from the wall conditions that name it:
///  - normal: the outward unit normal of the soil (into the wall), the normalised mean of the
///    normals given for the node (of the sides of a side set that end there, or of a node
///    set's sides or `Normal`);
///  - corner: where two of those normals differ by more than kCornerAngleDegrees (the corner
///    of a box, a kink of the wall) the node is HELD (its solid velocity is zero, and so is the
///    liquid's relative velocity if the wall is impermeable): no single normal describes it,
///    and a mean normal would let the node slide into one of the two walls;
///  - friction: the largest mu of the conditions (the rougher wall holds);
///  - impermeable: if any of the conditions is.
/// A solid fixity of the same node wins, component by component, over the contact; the
/// liquid locks of impermeable conditions at the node are applied here, after the contact
/// (finalise() takes them out of NodalConstraints), so that the contact can run again on its
/// own result without changing it (ExplicitTwoPhaseSolver re-applies the conditions after the
/// hydraulic corrections).

#include <array>
#include <map>
#include <vector>

#include "argine/boundary/CoulombContact.hpp"
#include "argine/boundary/NodalConstraints.hpp"
#include "argine/core/Types.hpp"

namespace argine {

/// Flag bits of a contact node, beside the node's NodalConstraintBits (solid-fixed and
/// liquid-locked directions, in the low bits).
enum FrictionalContactBits : unsigned {
  kContactImpermeable = 1u << 8,  ///< (v_L - v_S) . n = 0 where the node carries liquid
  kContactHeld = 1u << 9,         ///< a corner: the solid is held at rest
};

/// The solid's velocity after the wall at a node with flags `bits` (held: 0; else Coulomb's
/// projection with the coefficient `mu` the solid sees, solidFrictionCoefficient) for the
/// trial velocity `v`.
KOKKOS_INLINE_FUNCTION void wallSolidVelocity(unsigned bits, const Real v[kDim], const Real n[kDim],
                                              Real mu, Real out[kDim]) {
  if (bits & kContactHeld) {
    out[0] = out[1] = 0;
    return;
  }
  coulombWallVelocity(v, n, mu, out);
}

/// Solid-fixed components are zero (the fixity wins over the contact); on velocities and on
/// accelerations alike.
KOKKOS_INLINE_FUNCTION void holdFixedComponents(unsigned bits, Real solid[kDim]) {
  for (int d = 0; d < kDim; ++d)
    if (bits & solidFixedBit(d)) solid[d] = 0;
}

/// The liquid's velocity (or acceleration) at the wall once the solid's is final: if the wall
/// holds the liquid (`locked`), no relative component normal to the wall (at a held corner
/// none normal to either wall, i.e. none at all); then the axis locks of impermeable
/// conditions at the node.
KOKKOS_INLINE_FUNCTION void wallLiquidComponents(unsigned bits, bool locked, const Real n[kDim],
                                                 const Real solid[kDim], Real liquid[kDim]) {
  if (locked) {
    if (bits & kContactHeld) {
      liquid[0] = solid[0];
      liquid[1] = solid[1];
    } else {
      matchNormalComponent(solid, n, liquid);
    }
  }
  for (int d = 0; d < kDim; ++d)
    if (bits & liquidLockedBit(d)) liquid[d] = solid[d];
}

/// One contact node as resolved (host copy, for tests and diagnostics).
struct ContactNode {
  Real normal[kDim] = {0, 0};  ///< outward unit normal of the soil (into the wall)
  Real friction = 0;           ///< mu
  unsigned flags = 0;          ///< FrictionalContactBits | NodalConstraintBits
};

class FrictionalContact {
 public:
  /// Normals further apart than this make a corner (held node). A few degrees more than the
  /// kinks of a wall drawn as a polyline along a gentle curve.
  static constexpr Real kCornerAngleDegrees = 10;

  /// Adds a wall at `node` with unit normal `normal` (host side, while the stage's
  /// conditions are resolved).
  void add(int node, const Real normal[kDim], Real friction, bool impermeable);
  /// Merges the walls of each node into one ContactNode (normal, corner, friction; see the
  /// file comment), copies the node's solid fixities from `constraints` and takes its liquid
  /// locks out of them, then fills the device lists. Call once after the adds and before
  /// constraints.finalise().
  void finalise(NodalConstraints& constraints);

  /// Contact node indices, entries [0, count()).
  Kokkos::View<const int*, MemSpace> nodes() const { return nodes_; }
  /// Outward unit normal of each listed node.
  Kokkos::View<const Real* [kDim], MemSpace> normals() const { return normals_; }
  /// Coulomb coefficient of each listed node.
  Kokkos::View<const Real*, MemSpace> friction() const {
    return friction_;
  }
  /// Flag word of each listed node (FrictionalContactBits | NodalConstraintBits).
  Kokkos::View<const unsigned*, MemSpace> flags() const { return flags_; }
  int count() const { return static_cast<int>(nodes_.extent(0)); }
  /// The resolved node, nullptr if `node` is not on a frictional wall (host lookup).
  const ContactNode* find(int node) const;
  /// Scratch of one step, per listed node: 1 where the acceleration form left the solid at
  /// rest (stick, a held corner), written by it (physics/WallContact.hpp) and read by the
  /// velocity form of the same step, 0 before the first step.
  Kokkos::View<unsigned char*, MemSpace> atRest() const { return at_rest_; }

  /// The velocity form, on the remapped nodal velocities (thesis step 4, after the fixities'
  /// NodalConstraints::constrainVelocities). A node the acceleration form left at rest
  /// (atRest()) stays at rest, as a fixed node does: the remap of FLIP point velocities
  /// gives it a tangential velocity the grid never had, and with no inward normal velocity
  /// left the projection alone would let the node slide by it. Elsewhere the solid's velocity
  /// itself is the trial velocity (an inward normal part is removed and the tangential one
  /// reduced by the same Coulomb law). Then the fixities and the liquid's locks.
  /// `liquid_with_solid`: the stage holds the liquid pressure, so the liquid moves with the
  /// solid and the wall stops both.
  void constrainVelocities(const Kokkos::View<const Real*, MemSpace>& mass_solid_i,
                           const Kokkos::View<const Real*, MemSpace>& mass_liquid_i,
                           const Kokkos::View<Real* [kDim], MemSpace>& velocity_solid_i,
                           const Kokkos::View<Real* [kDim], MemSpace>& velocity_liquid_i,
                           bool liquid_with_solid) const;

 private:
  struct Walls {  ///< what the conditions said about one node
    std::vector<std::array<Real, kDim>> normals;
    Real friction = 0;
    bool impermeable = false;
  };
  std::map<int, Walls> pending_;
  std::map<int, ContactNode> resolved_;
  Kokkos::View<int*, MemSpace> nodes_;
  Kokkos::View<Real* [kDim], MemSpace> normals_;
  Kokkos::View<Real*, MemSpace> friction_;
  Kokkos::View<unsigned*, MemSpace> flags_;
  Kokkos::View<unsigned char*, MemSpace> at_rest_;
};

}  // namespace argine
