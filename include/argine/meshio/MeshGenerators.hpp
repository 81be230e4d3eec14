#pragma once
/// @file MeshGenerators.hpp
/// Built-in meshes (`Mesh/Generate`): a structured rectangle (optionally with soil regions
/// seeded at point resolution) and a polygon cross-section (soil layers of a levee or slope
/// inside a background box, the elements following the layer edges). Both name the box sides
/// "left", "right", "bottom", "top" as node sets AND side sets (ids 1-4 in that order).

#include <array>
#include <string>
#include <vector>

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

/// Dispatches on spec.kind to generateRectangle or generatePolygonSection.
Mesh generateMesh(const GeneratorSpec& spec);

/// Structured grid over [lower_left, upper_right]: nx = ceil(width / element_size) by
/// ny = ceil(height / element_size) quads (or each quad split into two triangles along
/// alternating diagonals, so no direction is preferred), one block `spec.block` (id 1).
/// Nodes are numbered row by row from the lower left (x fastest), elements likewise; for
/// quads mesh.structured describes that grid. With `spec.regions` the grid is the same but
/// the blocks are the regions' (RectangleRegions.hpp) and mesh.regions holds the polygons.
/// Throws InputError for an empty box, a non-positive element size or bad regions.
Mesh generateRectangle(const GeneratorSpec& spec);

/// Unstructured mesh of the box with one block per distinct region block name (ids 1.., in
/// order of first appearance) and block "empty" for the rest of the box (last; left out when
/// the regions fill the box). Element edges follow every region edge. Tri3: triangles of
/// edge about element_size (see SectionTriangulator.hpp). Quad4: a triangle mesh of size
/// 2 * element_size with every triangle split into three quads (centroid + edge
/// midpoints), giving quads with sides of about element_size. Throws InputError for bad
/// geometry (see buildSectionGraph) and for overlapping regions.
Mesh generatePolygonSection(const GeneratorSpec& spec);

/// Adds node sets and side sets "left", "right", "bottom", "top" (ids 1-4): the nodes and
/// element sides lying on each side of the box (within 1e-9 box sizes), sorted along it.
void addBoxSideSets(Mesh& mesh, const std::array<Real, 2>& lower_left,
                    const std::array<Real, 2>& upper_right);

/// Builds a Mesh from host lists: elements (counter-clockwise, `nodesPerElement(type)`
/// entries used) are grouped by block index into `block_names.size()` blocks with ids
/// 1..n, in the order given. Nodes no element uses are dropped.
Mesh assembleMesh(ElementType type, const std::vector<std::array<Real, 2>>& points,
                  const std::vector<std::array<int, 4>>& elements,
                  const std::vector<int>& element_block,
                  const std::vector<std::string>& block_names);

}  // namespace argine
