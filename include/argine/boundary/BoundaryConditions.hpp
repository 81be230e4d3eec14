#pragma once
/// @file BoundaryConditions.hpp
/// The boundary conditions of a stage on the fixed background mesh (thesis Sec. 4), resolved
/// once when the stage begins from its StageSpec::boundaries:
///  - SolidFixity: solid velocity/acceleration components held at zero on a node set;
///  - ImpermeableBoundary: zero relative liquid velocity normal to the boundary (liquid
///    fixity). Only axis-aligned boundaries are supported: the normal component is then the
///    x or y component, which is locked (see NodalConstraints). The normal comes from the
///    side set's sides or, for a node set, from the mesh-boundary sides joining its nodes;
///    an inclined side is an InputError for now;
///  - TractionBoundary: a total traction vector on a side set, integrated with the linear
///    edge shape functions (each end node of a side gets t L / 2) into the MIXTURE external
///    force (4.42): the thesis loads the mixture with the total traction, the liquid sees a
///    loaded surface only through a prescribed pressure;
///  - FrictionalContact: rigid walls with Coulomb friction on side or node sets
///    (FrictionalContact.hpp): the solid cannot enter the wall and slides along it against
///    mu times the normal force; the liquid's relative velocity normal to an impermeable wall
///    is zero;
///  - LiquidPressureBoundary: a prescribed liquid pressure p^ (compression positive) on a
///    side set: nodal force -p^ n L / 2 per end node (n the outward normal) in the liquid
///    (4.41) external force, and -max(p^, 0) n L / 2 in the mixture (4.42) external force
///    (mixtureLoadPressure): the mixture's boundary term is the total traction sigma n, which
///    is the free water's -p^ n where water stands on the surface (p^ > 0, S_L = 1: the water
///    load of thesis Sec. 4.1) and 0 where a surface at suction (p^ < 0) touches air; with
///    Bishop (4.5), sigma' n = S_L p^ n there. A drained boundary is p^ = 0: the natural
///    condition, nothing to add.
///
/// Moving boundaries (hydraulic head, seepage face, infiltration on the current soil
/// surface) come later: they will add their own loads and constraints through the same
/// addNodalForces / NodalConstraints interfaces each step.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "argine/boundary/FrictionalContact.hpp"
#include "argine/boundary/NodalConstraints.hpp"
#include "argine/boundary/SideWalls.hpp"
#include "argine/core/Types.hpp"

namespace argine {

struct BoundarySpec;
struct Mesh;
struct StageSpec;

/// A nodal force list: one entry per node, forces on the mixture and on the liquid (N).
struct NodalLoads {
  Kokkos::View<int*, MemSpace> node;             ///< mesh node
  Kokkos::View<Real* [kDim], MemSpace> mixture;  ///< added to f^ext (N)
  Kokkos::View<Real* [kDim], MemSpace> liquid;   ///< added to f_L^ext (N)
  int count() const { return static_cast<int>(node.extent(0)); }
};

/// Zero solid velocity components on a node set.
class SolidFixity {
 public:
  SolidFixity(std::string name, std::vector<int> nodes, bool fix_x, bool fix_y);
  /// Marks the fixed directions in `constraints`.
  void constrain(NodalConstraints& constraints) const;
  const std::string& name() const { return name_; }
  const std::vector<int>& nodes() const { return nodes_; }

 private:
  std::string name_;
  std::vector<int> nodes_;
  bool fix_x_, fix_y_;
};

/// Zero relative liquid velocity along the (axis-aligned) outward normal of each node.
class ImpermeableBoundary {
 public:
  /// `locked[j]` = kLiquidLockedX and/or kLiquidLockedY for `nodes[j]`.
  ImpermeableBoundary(std::string name, std::vector<int> nodes, std::vector<unsigned> locked);
  void constrain(NodalConstraints& constraints) const;
  const std::string& name() const { return name_; }
  const std::vector<int>& nodes() const { return nodes_; }

 private:
  std::string name_;
  std::vector<int> nodes_;
  std::vector<unsigned> locked_;
};

/// A constant total traction on a side set (into the mixture equation).
class TractionBoundary {
 public:
  TractionBoundary(std::string name, NodalLoads loads);
  /// Adds the loads at `time` to the nodes that carry mass (mass_solid_i > 0), so a node the
  /// soil has left gets nothing.
  void addNodalForces(Real time, const Kokkos::View<const Real*, MemSpace>& mass_solid_i,
                      const Kokkos::View<Real* [kDim], MemSpace>& force_mixture_i,
                      const Kokkos::View<Real* [kDim], MemSpace>& force_liquid_i) const;
  const std::string& name() const { return name_; }
  const NodalLoads& loads() const { return loads_; }

 private:
  std::string name_;
  NodalLoads loads_;
};

/// A constant prescribed liquid pressure on a side set (into the liquid; its free-water part
/// p^ > 0 into the mixture).
class LiquidPressureBoundary {
 public:
  LiquidPressureBoundary(std::string name, NodalLoads loads);
  /// As TractionBoundary::addNodalForces.
  void addNodalForces(Real time, const Kokkos::View<const Real*, MemSpace>& mass_solid_i,
                      const Kokkos::View<Real* [kDim], MemSpace>& force_mixture_i,
                      const Kokkos::View<Real* [kDim], MemSpace>& force_liquid_i) const;
  const std::string& name() const { return name_; }
  const NodalLoads& loads() const { return loads_; }

 private:
  std::string name_;
  NodalLoads loads_;
};

/// Every condition of one stage, resolved against the mesh.
class StageBoundaryConditions {
 public:
  StageBoundaryConditions() = default;
  /// Resolves each BoundarySpec of `stage`; throws InputError with where =
  /// "Stages/<stage>/Boundary Conditions/<name>" for a missing node/side set or an inclined
  /// impermeable side, ".../<name>/Node Set" for a frictional node set without a wall normal.
  StageBoundaryConditions(const Mesh& mesh, const StageSpec& stage);

  /// The velocity constraints of all fixities and impermeable boundaries (except the liquid
  /// locks at frictional-wall nodes, which frictionalContact() applies).
  const NodalConstraints& constraints() const { return constraints_; }
  /// The nodes of all frictional walls.
  const FrictionalContact& frictionalContact() const { return frictional_; }
  /// The walls of a quasi-2D channel, if the stage has them (physics/SideWallFriction.hpp).
  const std::optional<SideWallParameters>& sideWalls() const { return side_walls_; }

  /// Adds the tractions and liquid pressures at `time` (see the classes).
  void addNodalForces(Real time, const Kokkos::View<const Real*, MemSpace>& mass_solid_i,
                      const Kokkos::View<Real* [kDim], MemSpace>& force_mixture_i,
                      const Kokkos::View<Real* [kDim], MemSpace>& force_liquid_i) const;

  /// Sum over all nodes of |force| of the tractions and pressures (N): a load scale for the
  /// energy bound of the instability check.
  Real totalLoadMagnitude() const;

  const std::vector<SolidFixity>& solidFixities() const { return solid_fixities_; }
  const std::vector<ImpermeableBoundary>& impermeableBoundaries() const { return impermeable_; }
  const std::vector<TractionBoundary>& tractions() const { return tractions_; }
  const std::vector<LiquidPressureBoundary>& liquidPressures() const { return pressures_; }
  /// The end nodes of every `liquid pressure` side, p^ = 0 included (which loads nothing),
  /// possibly repeated: where the deck gives p_L (the atmosphere leaves them alone).
  const std::vector<int>& prescribedPressureNodes() const { return pressure_nodes_; }

 private:
  std::vector<SolidFixity> solid_fixities_;
  std::vector<ImpermeableBoundary> impermeable_;
  std::vector<TractionBoundary> tractions_;
  std::vector<LiquidPressureBoundary> pressures_;
  std::vector<int> pressure_nodes_;
  NodalConstraints constraints_;
  FrictionalContact frictional_;
  std::optional<SideWallParameters> side_walls_;
  std::string side_walls_name_;
};

}  // namespace argine
