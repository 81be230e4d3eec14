#pragma once
/// @file GridRelocation.hpp
/// The relocation of the grid families (GIMP, B-spline) on a structured Quad4 mesh whose
/// elements are the grid's cells: a point's cell by index arithmetic from its position,
/// its element from AffineElementMaps::cell_element, its local coordinates, and its
/// TensorShape, in one pass. No element map, node gather or linear shape record: the
/// transfers on these families read the TensorShape alone (PointShapes::grid_p).

#include "argine/transfer/PointShapes.hpp"

namespace argine {

/// Relocates every point of `points` on mesh.structured: first keeps it clear of the grid's
/// edges (clearOfGridEdges: position and displacement moved together), then element (-1
/// outside the grid, or in a cell without an element of cell_element), local coordinates and
/// tensor shape.
/// `tolerance`: the locator's containment tolerance (local coordinates); a point on the line
/// between two cells goes to the lower one, as PointLocator chooses (the lowest element
/// index). Counts the lost points and, as changed_element, the points whose element or
/// stencil changed (either changes the active nodes). PointShapes::stored_p is not written.
RelocationCounts relocateOnGrid(const Mesh& mesh, Real tolerance,
                                Kokkos::View<const int*, MemSpace> cell_element,
                                MaterialPoints& points, PointShapes& shapes);

}  // namespace argine
