#pragma once
/// @file SectionTriangulator.hpp
/// Conforming triangulation of a section graph with triangles of about a given size.
///
/// Why a lattice + Delaunay: interior points on an equilateral lattice of spacing h give
/// equilateral triangles of exactly the requested size over most of the section (a
/// predictable element count and no size drift), while the Delaunay triangulation of lattice
/// points plus points spaced <= h along every graph edge joins the two without any special
/// cases. Lattice points closer than 0.6 h to an edge are dropped so that no sliver forms
/// against a boundary. The mesh is then made to CONFORM to the graph: every piece of an
/// edge that is not a Delaunay edge is split at its midpoint until all are (they become
/// Gabriel edges eventually), so region borders are element edges and block areas equal
/// polygon areas. Ruppert steps (insert the circumcentre of a triangle with an angle below
/// 25 degrees, or split the edge piece it would encroach) clean up the transition band
/// between lattice and boundary and resolve features smaller than h, down to 0.05 h (0.3 h
/// next to input angles below 60 degrees, where refinement would cascade; there the
/// smallest element angle is about the input angle). A "smart" Laplacian smoothing (a node
/// moves only if the worst angle around it improves) evens the mesh out; nodes on graph
/// edges never move. Everything is deterministic: the same spec gives the same mesh.

#include <array>
#include <vector>

#include "argine/meshio/SectionGraph.hpp"

namespace argine {

/// A triangulation of the box of a section graph.
struct SectionTriangulation {
  std::vector<Point2> points;                 ///< node coordinates (m)
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise
  std::vector<char> on_edge;                  ///< 1 for nodes on a graph edge (never moved)
};

/// Options of the triangulator (defaults are what the generator uses).
struct TriangulatorOptions {
  Real lattice_clearance = 0.6;    ///< drop lattice points closer than this * h to an edge
  Real refine_below_degrees = 25;  ///< Ruppert refinement of triangles with a smaller angle
  int smoothing_sweeps = 4;        ///< smart Laplacian sweeps
};

/// Triangulates the box of `graph` with triangles of edge about `element_size`, conforming
/// to every graph edge.
SectionTriangulation triangulateSection(const SectionGraph& graph, Real element_size,
                                        const TriangulatorOptions& options = {});

}  // namespace argine
