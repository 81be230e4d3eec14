#pragma once
/// @file VerticalColumns.hpp
/// Which material lies where along a vertical line through the background mesh: the K0
/// procedure integrates the unit weight through the layers actually present above a point,
/// so it needs, for a given x, the intervals [y_low, y_high] of each material-filled element
/// the vertical crosses. Empty elements (blocks without a material) contribute nothing.
/// Host-side; elements are binned by their x-range so one query touches one mesh column.
/// The soil regions of a `rectangle` mesh with Regions are seeded from their polygons, not
/// from whole elements (points/Seeding.hpp), so their materials are layered by the polygons
/// too: the intervals where the vertical crosses each region.

#include <array>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct Mesh;
struct MaterialSpec;

/// Part of a vertical line inside elements of one material.
struct ColumnInterval {
  Real y_low = 0;    ///< (m)
  Real y_high = 0;   ///< (m), > y_low
  int material = 0;  ///< material index
};

/// A polygon filled with one material (a region of Mesh::regions).
struct MaterialPolygon {
  std::vector<std::array<Real, 2>> vertices;  ///< (m)
  int material = 0;                           ///< material index
};

class VerticalColumns {
 public:
  /// `element_material[e]` is the material index of element e, or -1 for an empty element;
  /// `polygons` add the material regions not made of whole elements.
  VerticalColumns(const Mesh& mesh, std::vector<int> element_material,
                  std::vector<MaterialPolygon> polygons = {});

  /// The material intervals of the vertical line at x, clipped to [y_low, y_high], sorted by
  /// height, without overlaps (a line along a shared element edge counts that edge once).
  std::vector<ColumnInterval> intervals(Real x, Real y_low, Real y_high) const;

 private:
  int binOf(Real x) const;

  std::vector<int> element_material_;
  std::vector<MaterialPolygon> polygons_;
  std::vector<std::vector<Real>> corners_;  ///< per element: x0, y0, x1, y1, ...
  std::vector<std::vector<int>> bins_;      ///< element indices overlapping each x-bin
  Real x_min_ = 0, bin_width_ = 1;
};

/// The material index of every element: material m fills the block named
/// materials[m].block (-1 elsewhere). Blocks are matched by name as the seeding does; a
/// block with regions (Mesh::regions) fills no whole element (see regionMaterials).
std::vector<int> elementMaterials(const Mesh& mesh, const std::vector<MaterialSpec>& materials);

/// The regions of the mesh whose block holds a material, with that material.
std::vector<MaterialPolygon> regionMaterials(const Mesh& mesh,
                                             const std::vector<MaterialSpec>& materials);

}  // namespace argine
