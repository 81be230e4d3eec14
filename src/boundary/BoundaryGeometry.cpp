#include "BoundaryGeometry.hpp"

#include <cmath>
#include <set>

#include "argine/core/Error.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/mesh/MeshGeometry.hpp"

namespace argine::boundary_detail {

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
  return out.empty() ? "(none)" : out;
}

}  // namespace

HostMesh::HostMesh(const Mesh& mesh)
    : coordinates(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates)),
      connectivity(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity)),
      per(mesh.nodesPerElement()) {}

Side HostMesh::side(int e, int s) const {
  Side side;
  side.a = connectivity(e, s);
  side.b = connectivity(e, (s + 1) % per);
  const Real tx = coordinates(side.b, 0) - coordinates(side.a, 0);
  const Real ty = coordinates(side.b, 1) - coordinates(side.a, 1);
  side.length = std::sqrt(tx * tx + ty * ty);
  side.normal[0] = ty / side.length;
  side.normal[1] = -tx / side.length;
  return side;
}

const NodeSet& requireNodeSet(const Mesh& mesh, const std::string& where, const std::string& name) {
  const NodeSet* set = mesh.findNodeSet(name);
  if (!set)
    throw InputError(where, "node set '" + name + "' is not in the mesh; the mesh has node sets: " +
                                joined(mesh.nodeSetNames()));
  return *set;
}

const SideSet& requireSideSet(const Mesh& mesh, const std::string& where, const std::string& name) {
  const SideSet* set = mesh.findSideSet(name);
  if (!set)
    throw InputError(where, "side set '" + name + "' is not in the mesh; the mesh has side sets: " +
                                joined(mesh.sideSetNames()));
  return *set;
}

std::vector<Side> sidesOf(const SideSet& set, const HostMesh& host) {
  std::vector<Side> sides;
  for (std::size_t k = 0; k < set.elements.size(); ++k)
    sides.push_back(host.side(set.elements[k], set.sides[k]));
  return sides;
}

std::vector<Side> boundarySidesWithin(const Mesh& mesh, const NodeSet& set, const HostMesh& host) {
  const std::set<int> members(set.nodes.begin(), set.nodes.end());
  const auto neighbours =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), computeElementNeighbours(mesh));
  std::vector<Side> sides;
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int s = 0; s < host.per; ++s) {
      if (neighbours(e, s) >= 0) continue;
      const Side side = host.side(e, s);
      if (members.count(side.a) && members.count(side.b)) sides.push_back(side);
    }
  return sides;
}

}  // namespace argine::boundary_detail
