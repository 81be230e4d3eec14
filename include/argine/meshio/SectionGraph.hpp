#pragma once
/// @file SectionGraph.hpp
/// The validated geometry of a polygon cross-section (`Mesh/Generate` with regions): the
/// background box and the region polygons turned into one planar straight-line graph —
/// vertices merged within a tolerance, edges split where another vertex lies on them,
/// shared borders of neighbouring layers stored once, and no two edges crossing.

#include <array>
#include <string>
#include <vector>

#include "argine/input/Deck.hpp"
#include "argine/meshio/Geometry2D.hpp"

namespace argine {

struct SectionGraph {
  Point2 lower_left;                         ///< background box (m)
  Point2 upper_right;                        ///< background box (m)
  Real tolerance = 0;                        ///< merge distance of vertices (m)
  std::vector<Point2> vertices;              ///< box corners (0..3) then region corners
  std::vector<std::array<int, 2>> segments;  ///< straight edges; none crosses another
  std::vector<std::vector<Point2>> regions;  ///< region polygons, counter-clockwise
  std::vector<std::string> region_blocks;    ///< block name of each region
};

/// Builds and checks the graph of `spec` (box, element size, regions). Throws InputError
/// ("Mesh/Generate..." as where) for an empty box, a non-positive element size, a region with
/// fewer than 3 distinct vertices or zero area, a vertex outside the box, or edges that cross
/// (regions that overlap, or a region that intersects itself). Clockwise regions are
/// accepted and reversed. Overlaps without crossing edges (a region inside another) are
/// found later, when elements are classified.
SectionGraph buildSectionGraph(const GeneratorSpec& spec);

}  // namespace argine
