#pragma once
/// @file Seeding.hpp
/// Initial material points: a fixed pattern of local positions in every element of the
/// requested blocks, and sorting of points by element.
///
/// Patterns (local coordinates; every point represents an equal share of its element):
///   Tri3  1: centroid (1/3, 1/3).
///   Tri3  3: (1/6,1/6), (2/3,1/6), (1/6,2/3): the 3-point Gauss rule with its equal weights,
///            the positions Anura3D (and the thesis) uses for 3 points per element.
///   Tri3  4: centroids of the 4 sub-triangles cut by the edge midpoints:
///            (1/6,1/6), (2/3,1/6), (1/6,2/3), (1/3,1/3).
///   Tri3  6: centroids of the 6 equal triangles cut by the three medians: barycentric
///            coordinates all permutations of (11, 5, 2)/18.
///   Tri3 12: the 3-point pattern in each of the 4 midpoint sub-triangles (12 = 4 x 3).
///   Quad4 m^2 (1, 4, 9, 16): centres of an m x m grid of equal reference sub-squares.
/// Tri3 patterns are symmetric under the triangle's rotations/reflections; every point gets
/// volume = element area / n exactly (equal quadrature weights; for 1/4/6 also equal
/// sub-triangles). Quad4: a point's volume is the physical area of its sub-square,
/// det J(centre) x 4/m^2 (exact since det J is linear on a bilinear quad), equal to
/// area / n for parallelograms and still summing to the element area when distorted.
/// Quad4 with 3, 6 or 12 points is rejected: no symmetric pattern of equal sub-areas.
///
/// Regions (a `rectangle` mesh with Regions, Mesh::regions): a block that has regions is
/// seeded from its polygons, not from its elements. In every element a polygon of the block
/// touches, the pattern positions that the region rule (mesh/MeshRegions.hpp: first region
/// in deck order whose closed polygon holds the position) gives to a region of the block
/// become points, whatever the element's own block. So a 45-degree slope or a column whose
/// width is not a multiple of the cell is represented at point resolution, and a position
/// on an edge shared by two regions is seeded once. Each point keeps the volume of its
/// pattern share (det J x reference sub-area, as above), not the part of its sub-square
/// inside the polygon: the body's volume is the area of the sub-squares whose centres lie
/// inside, which tends to the polygon's area as the pattern refines (the error is at most
/// the sub-squares the outline crosses: about perimeter x sub-square side). Clipped volumes
/// would match the area exactly but give points of any small volume along the outline
/// (mass and time step then vary point by point), so they are not used.

#include <string>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

/// Points to create in one element block.
struct SeedRequest {
  int block = 0;               ///< index into mesh.blocks
  int material = 0;            ///< material index stored in every point
  int points_per_element = 1;  ///< number of points per element (see the patterns above)
  /// Key path for error messages, e.g. "Materials/clay/Points Per Element"; when empty,
  /// errors name "Points Per Element (block '<name>')".
  std::string where = {};
};

/// Supported points per element for an element type, e.g. "1, 3, 4, 6, 12".
std::string supportedPointsPerElement(ElementType type);

/// Local coordinates of the seeding pattern (2 values per point: xi, eta).
/// Throws InputError(where, ...) for an unsupported number of points.
std::vector<Real> seedingPattern(ElementType type, int points_per_element,
                                 const std::string& where);

/// Creates the points of all requests, sorted by element, ids 0..n-1 in that order (within
/// an element: a whole-element request's points, then region points by request and
/// pattern position). Fills id, element, local, position, initial_position, material,
/// volume, initial_volume; all other fields are zero. Throws InputError for an unknown block
/// index, an unsupported number of points, a block given two materials, or a whole-element
/// block (e.g. `empty`) sharing an element with region points.
MaterialPoints seedMaterialPoints(const Mesh& mesh, const std::vector<SeedRequest>& requests);

/// Sorts points by element (points outside the mesh, element -1, last), by id within an
/// element, permuting every field listed in PointFields.hpp with Kokkos::BinSort.
void sortPointsByElement(MaterialPoints& points);

}  // namespace argine
