#include "argine/seepage/SeepageBoundary.hpp"

#include <cmath>
#include <map>

#include "argine/core/Error.hpp"
#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

void SeepageBoundaryConditions::addPressures(const std::vector<int>& nodes,
                                             const std::vector<Real>& values) {
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    bool found = false;
    for (std::size_t k = 0; k < pressure_nodes.size(); ++k)
      if (pressure_nodes[k] == nodes[j]) {
        pressures[k] = values[j];
        found = true;
      }
    if (!found) {
      pressure_nodes.push_back(nodes[j]);
      pressures.push_back(values[j]);
    }
  }
}

void SeepageBoundaryConditions::addSupplies(const std::vector<int>& nodes,
                                            const std::vector<Real>& rates, bool switchable_nodes) {
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    bool found = false;
    for (std::size_t k = 0; k < supply_nodes.size(); ++k)
      if (supply_nodes[k] == nodes[j]) {
        supplies[k] += rates[j];
        switchable[k] = switchable[k] || switchable_nodes;
        found = true;
      }
    if (!found) {
      supply_nodes.push_back(nodes[j]);
      supplies.push_back(rates[j]);
      switchable.push_back(switchable_nodes ? 1 : 0);
    }
  }
}

SideSetNodes sideSetNodeLengths(const Mesh& mesh, const SideSet& set) {
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto C = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const int per = mesh.nodesPerElement();
  std::map<int, Real> length_of;
  for (std::size_t s = 0; s < set.elements.size(); ++s) {
    const int e = set.elements[s], side = set.sides[s];
    const int a = C(e, side), b = C(e, (side + 1) % per);
    const Real length = std::hypot(X(b, 0) - X(a, 0), X(b, 1) - X(a, 1));
    length_of[a] += 0.5 * length;
    length_of[b] += 0.5 * length;
  }
  SideSetNodes result;
  for (const auto& [node, length] : length_of) {
    result.nodes.push_back(node);
    result.lengths.push_back(length);
  }
  return result;
}

SeepageBoundaryConditions seepageBoundaryConditions(const Mesh& mesh, const StageSpec& stage) {
  SeepageBoundaryConditions conditions;
  for (const BoundarySpec& spec : stage.boundaries) {
    const std::string where = "Stages/" + stage.name + "/Boundary Conditions/" + spec.name;
    auto side_set = [&]() -> const SideSet& {
      const SideSet* set = mesh.findSideSet(spec.side_set);
      if (!set)
        throw InputError(where + "/Side Set", "no side set '" + spec.side_set + "' in the mesh");
      return *set;
    };
    switch (spec.kind) {
      case BoundaryKind::LiquidPressure: {
        const SideSetNodes nodes = sideSetNodeLengths(mesh, side_set());
        conditions.addPressures(nodes.nodes, std::vector<Real>(nodes.nodes.size(), spec.pressure));
        break;
      }
      case BoundaryKind::Infiltration: {
        const SideSetNodes nodes = sideSetNodeLengths(mesh, side_set());
        std::vector<Real> rates;
        for (const Real length : nodes.lengths) rates.push_back(spec.flux * length);
        conditions.addSupplies(nodes.nodes, rates, spec.ponding);
        break;
      }
      case BoundaryKind::SeepageFace: {
        const SideSetNodes nodes = sideSetNodeLengths(mesh, side_set());
        conditions.addSupplies(nodes.nodes, std::vector<Real>(nodes.nodes.size(), 0.0), true);
        break;
      }
      case BoundaryKind::LiquidFixity:  // impermeable: the natural condition
      case BoundaryKind::SolidFixity:   // the skeleton is fixed
      case BoundaryKind::Traction:
        break;
    }
  }
  return conditions;
}

}  // namespace argine
