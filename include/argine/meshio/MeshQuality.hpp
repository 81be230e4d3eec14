#pragma once
/// @file MeshQuality.hpp
/// Shape and conformity measures of a 2D mesh, for tests of the generators and for the
/// mesh summary printed at start-up.

#include <vector>

#include "argine/mesh/Mesh.hpp"

namespace argine {

struct MeshQuality {
  Real min_angle_degrees = 0;  ///< smallest interior angle of any element
  Real max_angle_degrees = 0;  ///< largest interior angle of any element
  Real min_area = 0;           ///< smallest signed element area (m^2); <= 0 means inverted
  Real total_area = 0;         ///< sum of element areas (m^2)
  int non_ccw_elements = 0;    ///< elements with a corner turning clockwise (or straight)
  int unmatched_edges = 0;     ///< element edges not on the mesh boundary shared by != 2
                               ///< elements (hanging nodes or overlaps); see measureQuality
};

/// Measures the mesh. An edge counts as boundary when it lies on the bounding box of the
/// mesh; any other edge must be shared by exactly two elements, with opposite directions.
MeshQuality measureQuality(const Mesh& mesh);

/// Area (m^2) of each block, in the order of `mesh.blocks`.
std::vector<Real> blockAreas(const Mesh& mesh);

}  // namespace argine
