#pragma once
/// @file AveragingPatches.hpp
/// The patches of the `element` volumetric averaging with an `Averaging Length (m)` L
/// (doc/theory.md Sec. 3.3.4): square cells of side L tiling the mesh's bounding box from its
/// lower left corner; an element belongs to the patch holding its centre. A patch of one
/// element per cell (L = h on a structured grid of cells h anchored at the same corner) gives
/// the element averages themselves.
///
/// Why: one value per element averages over a length that halves with the cells, so a
/// sliding body's volumetric response is smoothed over a different length on every mesh
/// (doc/verification.md, "An averaging length that does not shrink with the cells"). With a fixed L
/// the averaged field has the same support on every mesh finer than L.

#include "argine/core/Types.hpp"

namespace argine {

struct Mesh;

struct AveragingPatches {
  /// Per element: its patch, 0 .. count - 1 (numbered along x, then y, over the patches
  /// that hold an element).
  Kokkos::View<int*, MemSpace> patch_e;
  int count = 0;
};

/// Which rows of the element averages (elements, or patches) touch along an edge: the
/// checkerboard filter's neighbours (`Checkerboard Filter`, PointValueAveraging.hpp).
struct RowNeighbours {
  /// Row r's neighbours are rows(start(r)) .. rows(start(r + 1) - 1), each once.
  Kokkos::View<int*, MemSpace> start, rows;
  int most = 0;  ///< the most neighbours a row has (4 on a grid of cells, 3 on triangles)
};

/// The edge neighbours of `row_count` rows, row_e(e) the row of element e (empty: the
/// element itself): two rows are neighbours where an element of one shares an edge (two
/// consecutive corners) with an element of the other.
RowNeighbours buildRowNeighbours(const Mesh& mesh, Kokkos::View<const int*, MemSpace> row_e,
                                 int row_count);

/// The patches of side `length` (> 0) over `mesh`'s elements.
AveragingPatches buildAveragingPatches(const Mesh& mesh, Real length);

}  // namespace argine
