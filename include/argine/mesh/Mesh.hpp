#pragma once
/// @file Mesh.hpp
/// The fixed background mesh of the MPM: nodes, elements (one element type per mesh),
/// element blocks (mapped to materials by name), node sets and side sets (mapped to
/// boundary conditions by name). Read from Exodus II or made by a built-in generator.

#include <array>
#include <string>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

/// Element shapes of the background mesh. A mesh uses one type for all its blocks.
enum class ElementType { Tri3, Quad4 };

/// Number of nodes (= number of sides in 2D) of an element type.
KOKKOS_INLINE_FUNCTION constexpr int nodesPerElement(ElementType type) {
  return type == ElementType::Tri3 ? 3 : 4;
}

/// Exodus name of an element type ("TRI3", "QUAD4").
const char* exodusName(ElementType type);

/// A named group of elements; the deck maps block names to materials. Blocks with no
/// material are initially empty (no material points) but still part of the grid. In a
/// mesh with regions (Mesh::regions) a block names cells for output only: a region's points
/// may start in cells of another block, and none is seeded from the block's elements.
struct ElementBlock {
  std::string name;           ///< block name (Exodus block name, or "block_<id>" if unnamed)
  int id = 0;                 ///< Exodus block id
  std::vector<int> elements;  ///< element indices (0-based) of this block
};

/// A named group of nodes, used for solid fixities.
struct NodeSet {
  std::string name;        ///< set name (Exodus name, or "nodelist_<id>")
  int id = 0;              ///< Exodus set id
  std::vector<int> nodes;  ///< node indices (0-based)
};

/// A named group of element sides, used for tractions and hydraulic conditions on fixed
/// boundaries. Side s of an element joins its local nodes s and (s+1) % nodesPerElement
/// (Exodus convention for 2D elements, stored 0-based here).
struct SideSet {
  std::string name;           ///< set name (Exodus name, or "surface_<id>")
  int id = 0;                 ///< Exodus set id
  std::vector<int> elements;  ///< element index (0-based) of each side
  std::vector<int> sides;     ///< local side index (0-based) of each side
};

/// A structured grid of equal axis-aligned Quad4 cells (generateRectangle): node (i, j) =
/// i + j (cells[0] + 1), element (i, j) = i + j cells[0], i along x from the lower left.
struct StructuredGrid {
  int cells[kDim] = {0, 0};     ///< cells along x and y; 0: the mesh is not structured
  Real origin[kDim] = {0, 0};   ///< lower-left corner (m)
  Real spacing[kDim] = {0, 0};  ///< cell sizes along x and y (m)
  bool valid() const { return cells[0] > 0 && cells[1] > 0; }
};

/// The shape functions of the particle-grid transfers (deck `Mesh/Shape Functions`).
enum class ShapeFamily {
  Linear,   ///< the element's own: linear Tri3, bilinear Quad4 (the thesis)
  Gimp,     ///< uGIMP (Bardenhagen & Kober 2004) on a StructuredGrid
  BSpline,  ///< quadratic B-splines on a StructuredGrid, boundary-modified at its edges
};

/// A soil region of a `rectangle` mesh with Regions, filled at point resolution: the
/// material of block `block` is seeded at the pattern positions inside the polygon in every
/// element the polygon touches, whatever the block of that element (points/Seeding.hpp;
/// which region holds a position: mesh/MeshRegions.hpp).
struct BlockRegion {
  int block = 0;                                 ///< index into Mesh::blocks
  std::vector<std::array<Real, kDim>> vertices;  ///< polygon corners, counter-clockwise (m)
};

/// Background mesh. Views live in MemSpace so kernels read them directly.
struct Mesh {
  ElementType type = ElementType::Tri3;
  /// Node coordinates (m), one row per node.
  Kokkos::View<Real* [kDim], MemSpace> coordinates;
  /// Element connectivity (0-based node indices), one row per element, counter-clockwise.
  Kokkos::View<int**, MemSpace> connectivity;
  /// Block index (into `blocks`) of each element.
  Kokkos::View<int*, MemSpace> element_block;

  std::vector<ElementBlock> blocks;
  std::vector<NodeSet> node_sets;
  std::vector<SideSet> side_sets;

  StructuredGrid structured;  ///< set by generateRectangle (Quad4); invalid otherwise
  /// The transfers' shape functions: Linear, or (on a structured grid) GIMP or B-spline.
  ShapeFamily shape_functions = ShapeFamily::Linear;
  /// Regions of a `rectangle` with Regions, in deck order (the earlier region wins a
  /// position on a shared edge); empty for every other mesh, whose blocks are seeded whole.
  std::vector<BlockRegion> regions;

  int numNodes() const { return static_cast<int>(coordinates.extent(0)); }
  int numElements() const { return static_cast<int>(connectivity.extent(0)); }
  int nodesPerElement() const { return argine::nodesPerElement(type); }

  /// Lookups by name; nullptr when absent.
  const ElementBlock* findBlock(const std::string& name) const;
  const NodeSet* findNodeSet(const std::string& name) const;
  const SideSet* findSideSet(const std::string& name) const;

  /// Names, for error messages ("mesh has side sets: base, riverside").
  std::vector<std::string> blockNames() const;
  std::vector<std::string> nodeSetNames() const;
  std::vector<std::string> sideSetNames() const;
};

}  // namespace argine
