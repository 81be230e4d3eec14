#include "FrictionalWall.hpp"

#include <set>
#include <sstream>

#include "argine/boundary/FrictionalContact.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine::boundary_detail {

namespace {

void addSides(const std::vector<Side>& sides, const BoundarySpec& spec,
              FrictionalContact& contact) {
  for (const Side& side : sides)
    for (const int node : {side.a, side.b})
      contact.add(node, side.normal, spec.friction_coefficient, spec.wall_impermeable);
}

}  // namespace

void addFrictionalWall(const Mesh& mesh, const BoundarySpec& spec, const HostMesh& host,
                       const std::string& where, FrictionalContact& contact) {
  if (!spec.side_set.empty()) {
    addSides(sidesOf(requireSideSet(mesh, where, spec.side_set), host), spec, contact);
    return;
  }
  const NodeSet& set = requireNodeSet(mesh, where, spec.node_set);
  if (spec.has_normal) {  // the deck's normal wins over the geometry
    for (const int node : set.nodes)
      contact.add(node, spec.normal.data(), spec.friction_coefficient, spec.wall_impermeable);
    return;
  }
  const std::vector<Side> sides = boundarySidesWithin(mesh, set, host);
  std::set<int> covered;
  for (const Side& side : sides) covered.insert({side.a, side.b});
  for (const int node : set.nodes)
    if (!covered.count(node)) {
      std::ostringstream out;
      out << "node " << node + 1 << " (1-based) of node set '" << set.name
          << "' lies on no mesh-boundary side joining two nodes of the set, so the wall "
             "normal there is unknown; give the wall's Normal or use a side set";
      throw InputError(where + "/Node Set", out.str());
    }
  addSides(sides, spec, contact);
}

}  // namespace argine::boundary_detail
