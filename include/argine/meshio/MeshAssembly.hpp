#pragma once
/// @file MeshAssembly.hpp
/// What every mesh reader does once it has the file's nodes and element blocks: build the
/// Mesh's views and blocks, make every element counter-clockwise, and refuse zero-area and
/// non-convex elements. One place for these rules, so that an Exodus II file and a gmsh file
/// of the same mesh give the same Mesh and the same messages.

#include <string>
#include <vector>

#include "argine/mesh/Mesh.hpp"

namespace argine {

/// An element block as a reader found it.
struct RawElementBlock {
  std::string name;               ///< block name (the deck maps it to a material)
  int id = 0;                     ///< the file's number for it
  std::vector<int> connectivity;  ///< 0-based node indices, nodesPerElement(type) per element
};

/// The nodes, elements and blocks of a mesh, checked.
struct AssembledMesh {
  Mesh mesh;                  ///< node sets and side sets still empty
  std::vector<char> flipped;  ///< per element: its node order was reversed
};

/// Builds the mesh of nodes (x, y) and `blocks` (elements numbered block by block, in order).
/// Clockwise elements are reordered counter-clockwise: new local node k = old (nv - k) % nv,
/// so old side s becomes side nv - 1 - s (flippedSide). Throws InputError naming
/// `path` for a node number out of range, a zero-area element or a quad with a reflex corner
/// ("element <n> (block <name>)", n 1-based over all blocks).
AssembledMesh assembleMesh(const std::string& path, ElementType type, const std::vector<Real>& x,
                           const std::vector<Real>& y, const std::vector<RawElementBlock>& blocks);

/// The 0-based side index, after reordering, of the element side that was 0-based side
/// `side` of a flipped element with `nv` nodes (side s joins local nodes s and s + 1).
inline int flippedSide(int side, int nv) {
  return nv - 1 - side;
}

}  // namespace argine
