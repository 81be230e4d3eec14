#pragma once
// Mesh geometry the resolution of boundary conditions shares (private to the boundary room):
// straight sides with their outward normals, the host copy of the mesh they are read from,
// and the node and side sets a condition names.

#include <string>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct Mesh;
struct NodeSet;
struct SideSet;

namespace boundary_detail {

/// A straight side of the mesh: end nodes, length and outward unit normal.
struct Side {
  int a = 0, b = 0;
  Real length = 0;
  Real normal[kDim] = {0, 0};
};

/// Host copies of what the resolution needs.
struct HostMesh {
  Kokkos::View<Real* [kDim], MemSpace>::HostMirror coordinates;
  Kokkos::View<int**, MemSpace>::HostMirror connectivity;
  int per = 0;
  explicit HostMesh(const Mesh& mesh);

  /// Side s of element e (local nodes s and s+1, counter-clockwise: outward normal is the
  /// edge vector turned clockwise).
  Side side(int e, int s) const;
};

/// The node set `name`, or an InputError at `where` listing the mesh's node sets.
const NodeSet& requireNodeSet(const Mesh& mesh, const std::string& where, const std::string& name);
/// The side set `name`, or an InputError at `where` listing the mesh's side sets.
const SideSet& requireSideSet(const Mesh& mesh, const std::string& where, const std::string& name);

/// The sides of the side set.
std::vector<Side> sidesOf(const SideSet& set, const HostMesh& host);
/// The mesh-boundary sides (no neighbour element) whose two end nodes are both in `set`:
/// the geometry a node set stands for.
std::vector<Side> boundarySidesWithin(const Mesh& mesh, const NodeSet& set, const HostMesh& host);

}  // namespace boundary_detail
}  // namespace argine
