#include "argine/boundary/BoundaryConditions.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "BoundaryGeometry.hpp"
#include "FrictionalWall.hpp"
#include "argine/boundary/HydraulicAlgebra.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

namespace {

using boundary_detail::HostMesh;
using boundary_detail::requireNodeSet;
using boundary_detail::requireSideSet;
using boundary_detail::Side;

/// The lock bit of an axis-aligned outward normal; InputError for an inclined side.
unsigned lockBitOfNormal(const Side& side, const HostMesh& host, const std::string& where) {
  constexpr Real kAligned = 1e-9;  // |component| below this counts as zero
  if (std::fabs(side.normal[1]) <= kAligned) return kLiquidLockedX;
  if (std::fabs(side.normal[0]) <= kAligned) return kLiquidLockedY;
  std::ostringstream out;
  out << "impermeable boundaries must be axis-aligned for now (the normal component is "
         "locked); the side from ("
      << host.coordinates(side.a, 0) << ", " << host.coordinates(side.a, 1) << ") to ("
      << host.coordinates(side.b, 0) << ", " << host.coordinates(side.b, 1) << ") has normal ("
      << side.normal[0] << ", " << side.normal[1] << ")";
  throw InputError(where, out.str());
}

/// Per-node lock bits of impermeable sides.
std::map<int, unsigned> locksOfSides(const std::vector<Side>& sides, const HostMesh& host,
                                     const std::string& where) {
  std::map<int, unsigned> locks;
  for (const Side& side : sides) {
    const unsigned bit = lockBitOfNormal(side, host, where);
    locks[side.a] |= bit;
    locks[side.b] |= bit;
  }
  return locks;
}

/// Per-node lock bits of an impermeable node set: from the mesh-boundary sides whose two
/// end nodes are both in the set.
std::map<int, unsigned> locksOfNodeSet(const Mesh& mesh, const NodeSet& set, const HostMesh& host,
                                       const std::string& where) {
  const std::map<int, unsigned> locks =
      locksOfSides(boundary_detail::boundarySidesWithin(mesh, set, host), host, where);
  for (const int node : set.nodes)
    if (!locks.count(node)) {
      std::ostringstream out;
      out << "node " << node + 1 << " (1-based) of node set '" << set.name
          << "' lies on no mesh-boundary side joining two nodes of the set, so the "
             "impermeable direction is unknown; use a side set";
      throw InputError(where, out.str());
    }
  return locks;
}

/// Integrates a constant traction vector (mixture) and/or pressure over the sides of a side
/// set with linear edge shape functions: each end node of a side gets the load times L / 2.
/// The pressure loads the liquid in full (4.41) and the mixture with its free-water part
/// mixtureLoadPressure(p) = max(p, 0) (4.42): a surface at suction touches air (sigma n = 0).
NodalLoads integrateSideLoads(const SideSet& set, const HostMesh& host,
                              const std::array<Real, 2>& traction, Real pressure) {
  std::map<int, std::array<Real, 4>> sums;  // node -> mixture x, y, liquid x, y
  for (const Side& side : boundary_detail::sidesOf(set, host)) {
    const Real half = 0.5 * side.length;
    const Real mixture_pressure = mixtureLoadPressure(pressure);
    for (const int node : {side.a, side.b}) {
      auto& f = sums[node];
      for (int d = 0; d < kDim; ++d) {
        f[d] += (traction[d] - mixture_pressure * side.normal[d]) * half;
        f[2 + d] += -pressure * side.normal[d] * half;
      }
    }
  }
  NodalLoads loads;
  loads.node = Kokkos::View<int*, MemSpace>("load_node", sums.size());
  loads.mixture = Kokkos::View<Real* [kDim], MemSpace>("load_mixture", sums.size());
  loads.liquid = Kokkos::View<Real* [kDim], MemSpace>("load_liquid", sums.size());
  auto node = Kokkos::create_mirror_view(loads.node);
  auto mixture = Kokkos::create_mirror_view(loads.mixture);
  auto liquid = Kokkos::create_mirror_view(loads.liquid);
  int j = 0;
  for (const auto& [n, f] : sums) {
    node(j) = n;
    for (int d = 0; d < kDim; ++d) {
      mixture(j, d) = f[d];
      liquid(j, d) = f[2 + d];
    }
    ++j;
  }
  Kokkos::deep_copy(loads.node, node);
  Kokkos::deep_copy(loads.mixture, mixture);
  Kokkos::deep_copy(loads.liquid, liquid);
  return loads;
}

/// Adds `loads` to the nodes that carry mass. Each node appears once per list, so plain
/// adds are race-free.
void addLoads(const NodalLoads& loads, const Kokkos::View<const Real*, MemSpace>& mass_solid_i,
              const Kokkos::View<Real* [kDim], MemSpace>& force_mixture_i,
              const Kokkos::View<Real* [kDim], MemSpace>& force_liquid_i) {
  const auto node = loads.node;
  const auto mixture = loads.mixture;
  const auto liquid = loads.liquid;
  Kokkos::parallel_for(
      "add_boundary_loads", Kokkos::RangePolicy<ExecSpace>(0, loads.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = node(j);
        if (!(mass_solid_i(i) > 0)) return;
        for (int d = 0; d < kDim; ++d) {
          force_mixture_i(i, d) += mixture(j, d);
          force_liquid_i(i, d) += liquid(j, d);
        }
      });
}

Real loadMagnitude(const NodalLoads& loads) {
  const auto mixture = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), loads.mixture);
  Real sum = 0;
  for (int j = 0; j < loads.count(); ++j) sum += std::hypot(mixture(j, 0), mixture(j, 1));
  return sum;
}

}  // namespace

// ------------------------------------------------------------------ SolidFixity

SolidFixity::SolidFixity(std::string name, std::vector<int> nodes, bool fix_x, bool fix_y)
    : name_(std::move(name)), nodes_(std::move(nodes)), fix_x_(fix_x), fix_y_(fix_y) {}

void SolidFixity::constrain(NodalConstraints& constraints) const {
  const unsigned bits = (fix_x_ ? kSolidFixedX : 0u) | (fix_y_ ? kSolidFixedY : 0u);
  for (const int node : nodes_) constraints.add(node, bits);
}

// ------------------------------------------------------------------ ImpermeableBoundary

ImpermeableBoundary::ImpermeableBoundary(std::string name, std::vector<int> nodes,
                                         std::vector<unsigned> locked)
    : name_(std::move(name)), nodes_(std::move(nodes)), locked_(std::move(locked)) {}

void ImpermeableBoundary::constrain(NodalConstraints& constraints) const {
  for (std::size_t j = 0; j < nodes_.size(); ++j) constraints.add(nodes_[j], locked_[j]);
}

// ------------------------------------------------------------------ loads

TractionBoundary::TractionBoundary(std::string name, NodalLoads loads)
    : name_(std::move(name)), loads_(std::move(loads)) {}

void TractionBoundary::addNodalForces(
    Real /*time: constant for now*/, const Kokkos::View<const Real*, MemSpace>& mass_solid_i,
    const Kokkos::View<Real* [kDim], MemSpace>& force_mixture_i,
    const Kokkos::View<Real* [kDim], MemSpace>& force_liquid_i) const {
  addLoads(loads_, mass_solid_i, force_mixture_i, force_liquid_i);
}

LiquidPressureBoundary::LiquidPressureBoundary(std::string name, NodalLoads loads)
    : name_(std::move(name)), loads_(std::move(loads)) {}

void LiquidPressureBoundary::addNodalForces(
    Real /*time: constant for now*/, const Kokkos::View<const Real*, MemSpace>& mass_solid_i,
    const Kokkos::View<Real* [kDim], MemSpace>& force_mixture_i,
    const Kokkos::View<Real* [kDim], MemSpace>& force_liquid_i) const {
  addLoads(loads_, mass_solid_i, force_mixture_i, force_liquid_i);
}

// ------------------------------------------------------------------ StageBoundaryConditions

StageBoundaryConditions::StageBoundaryConditions(const Mesh& mesh, const StageSpec& stage) {
  const HostMesh host(mesh);
  for (const BoundarySpec& spec : stage.boundaries) {
    const std::string where = "Stages/" + stage.name + "/Boundary Conditions/" + spec.name;
    switch (spec.kind) {
      case BoundaryKind::SolidFixity: {
        const NodeSet& set = requireNodeSet(mesh, where, spec.node_set);
        if (!spec.fix_x && !spec.fix_y)
          throw InputError(where, "a solid fixity needs a direction (x, y or both)");
        solid_fixities_.emplace_back(spec.name, set.nodes, spec.fix_x, spec.fix_y);
        break;
      }
      case BoundaryKind::LiquidFixity: {
        std::map<int, unsigned> locks;
        if (!spec.side_set.empty()) {
          locks = locksOfSides(
              boundary_detail::sidesOf(requireSideSet(mesh, where, spec.side_set), host), host,
              where);
        } else {
          const NodeSet& set = requireNodeSet(mesh, where, spec.node_set);
          if (spec.fix_x || spec.fix_y) {  // explicit directions win over the geometry
            const unsigned bits =
                (spec.fix_x ? kLiquidLockedX : 0u) | (spec.fix_y ? kLiquidLockedY : 0u);
            for (const int node : set.nodes) locks[node] |= bits;
          } else {
            locks = locksOfNodeSet(mesh, set, host, where);
          }
        }
        std::vector<int> nodes;
        std::vector<unsigned> bits;
        for (const auto& [node, lock] : locks) {
          nodes.push_back(node);
          bits.push_back(lock);
        }
        impermeable_.emplace_back(spec.name, std::move(nodes), std::move(bits));
        break;
      }
      case BoundaryKind::Traction: {
        const SideSet& set = requireSideSet(mesh, where, spec.side_set);
        tractions_.emplace_back(spec.name, integrateSideLoads(set, host, spec.traction, 0.0));
        break;
      }
      case BoundaryKind::LiquidPressure: {
        const SideSet& set = requireSideSet(mesh, where, spec.side_set);
        for (const Side& side : boundary_detail::sidesOf(set, host))
          for (const int node : {side.a, side.b}) pressure_nodes_.push_back(node);
        if (spec.pressure == 0) break;  // drained: the natural condition, no load
        pressures_.emplace_back(spec.name,
                                integrateSideLoads(set, host, {0.0, 0.0}, spec.pressure));
        break;
      }
      case BoundaryKind::FrictionalWall:
        boundary_detail::addFrictionalWall(mesh, spec, host, where, frictional_);
        break;
      case BoundaryKind::SideWalls:
        // one channel: a second pair of walls would be a second width
        if (side_walls_)
          throw InputError(where, "a stage has one channel: side walls are already given as '" +
                                      side_walls_name_ + "'");
        side_walls_ = SideWallParameters{spec.channel_width, spec.friction_coefficient};
        side_walls_name_ = spec.name;
        break;
      case BoundaryKind::TotalHead:  // on the moving boundary: HydraulicConditions
      case BoundaryKind::PressureSeries:
      case BoundaryKind::Infiltration:
      case BoundaryKind::SeepageFace:
        break;
    }
  }
  for (const auto& fixity : solid_fixities_) fixity.constrain(constraints_);
  for (const auto& boundary : impermeable_) boundary.constrain(constraints_);
  frictional_.finalise(constraints_);  // takes the liquid locks of its nodes
  constraints_.finalise();
}

void StageBoundaryConditions::addNodalForces(
    Real time, const Kokkos::View<const Real*, MemSpace>& mass_solid_i,
    const Kokkos::View<Real* [kDim], MemSpace>& force_mixture_i,
    const Kokkos::View<Real* [kDim], MemSpace>& force_liquid_i) const {
  for (const auto& traction : tractions_)
    traction.addNodalForces(time, mass_solid_i, force_mixture_i, force_liquid_i);
  for (const auto& pressure : pressures_)
    pressure.addNodalForces(time, mass_solid_i, force_mixture_i, force_liquid_i);
}

Real StageBoundaryConditions::totalLoadMagnitude() const {
  Real sum = 0;
  for (const auto& traction : tractions_) sum += loadMagnitude(traction.loads());
  for (const auto& pressure : pressures_) sum += loadMagnitude(pressure.loads());
  return sum;
}

}  // namespace argine
