#pragma once
// Resolution of a `frictional wall` condition against the mesh (private to the boundary
// room; StageBoundaryConditions calls it).

#include <string>

#include "BoundaryGeometry.hpp"

namespace argine {

class FrictionalContact;
struct BoundarySpec;

namespace boundary_detail {

/// Adds the wall normals of `spec` to `contact`: each side of a side set gives its outward
/// normal to its two end nodes; a node set gives its `Normal` to every node or, without one,
/// the normals of the mesh-boundary sides joining two of its nodes. InputError at
/// `where`/Node Set for a node of the set on no such side.
void addFrictionalWall(const Mesh& mesh, const BoundarySpec& spec, const HostMesh& host,
                       const std::string& where, FrictionalContact& contact);

}  // namespace boundary_detail
}  // namespace argine
