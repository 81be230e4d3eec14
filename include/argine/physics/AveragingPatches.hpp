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

/// The patches of side `length` (> 0) over `mesh`'s elements.
AveragingPatches buildAveragingPatches(const Mesh& mesh, Real length);

}  // namespace argine
