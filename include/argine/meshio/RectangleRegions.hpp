#pragma once
/// @file RectangleRegions.hpp
/// Soil regions inside a structured `rectangle` mesh (`Mesh/Generate` with Type rectangle
/// and Regions): a body of any outline on a grid that stays the structured grid. Unlike the
/// polygon generator the grid does not follow the region edges; the regions are kept in
/// Mesh::regions instead, and the seeding places each region's material at the pattern
/// positions inside its polygon (points/Seeding.hpp), so a slope is represented at point
/// resolution, not as a staircase of whole cells.
///
/// Element blocks, for output and for naming materials: an element belongs to the block of
/// the region holding its centroid (the rule of mesh/MeshRegions.hpp: the first region in
/// deck order whose closed polygon holds it), else to block `empty`. Blocks: each distinct
/// region block name in order of first appearance (ids 1..), then `empty` (left out when no
/// element lies outside every region). A region block may hold no element at all (a column
/// narrower than a cell): it is kept, as its points come from the polygon, not the block.
/// Elements keep the grid's row-by-row numbering, so a block's elements are ascending but
/// not contiguous (the Exodus writer orders them block by block).

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

/// Checks `spec.regions` and turns them into the blocks and Mesh::regions of `mesh`, the
/// grid generateRectangle made of `spec` (one block, before this call). Throws InputError
/// ("Mesh/Generate/Regions...") for the faults buildSectionGraph finds (a vertex outside the
/// box, fewer than 3 vertices, zero area, crossing edges) and for overlapping regions (one
/// inside another, or two sharing more than a border).
void applyRectangleRegions(const GeneratorSpec& spec, Mesh& mesh);

}  // namespace argine
