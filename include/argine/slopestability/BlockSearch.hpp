#pragma once
/// @file BlockSearch.hpp
/// The critical non-circular surface of a block sliding on a weak plane (a "block search",
/// e.g. Duncan & Wright 2005, Sec. 8.3): four-point polylines
///   (left end on the ground) - (left vertex) - (right vertex) - (right end on the ground),
/// the two vertices at a common offset above a given plane y_p(x) (the base of a weak seam),
/// each of the five abscissae/offset in a window. A grid over the five windows, then a
/// compass (pattern) search from the best grid point (Kolda, Lewis & Torczon 2003): each
/// parameter moved by +/- its step while F falls, all steps halved when none does, until the
/// steps are below a tolerance. The objective is Spencer's F (Spencer.hpp).

#include <cmath>

#include "argine/core/Types.hpp"
#include "argine/slopestability/Slice.hpp"
#include "argine/slopestability/SlopeSection.hpp"
#include "argine/slopestability/Spencer.hpp"

namespace argine {

/// The windows of a block search (m).
struct BlockSearchWindows {
  Real left_end_min = 0, left_end_max = 0;        ///< x of the left end (on the ground)
  Real left_vertex_min = 0, left_vertex_max = 0;  ///< x of the left vertex
  Real right_vertex_min = 0, right_vertex_max = 0;
  Real right_end_min = 0, right_end_max = 0;
  Polyline plane;  ///< the sliding plane y_p(x)
  Real offset_min = 0, offset_max = 0;
  /// Steepest admissible end segments (rad from the horizontal); steeper ones are skipped.
  /// A toe segment no steeper than the passive wedge, 45 deg - phi'/2 (Rankine), keeps the
  /// search off nearly vertical toe cuts on which Spencer's equations can have spurious roots
  /// (doc/theory.md, Sec. 9).
  Real max_left_end_inclination = M_PI / 2;
  Real max_right_end_inclination = M_PI / 2;  ///< vertex elevation above y_p (m)
  int grid_count = 5;                         ///< grid points per window (>= 1)
  Real step_tolerance = 1e-3;                 ///< stop the pattern search below this step (m)
  int max_evaluations = 20000;
  int slice_count = 50;
  bool split_at_materials = true;  ///< slicePolyline's option: no base across two materials
};

/// The result: the critical polyline, its Spencer F and slices, and the bookkeeping.
struct CriticalBlock {
  bool found = false;
  Polyline surface;
  SpencerFactor spencer;
  SlipMass mass;
  int evaluated = 0;
  int rejected = 0;  ///< no mass, or Spencer not admissible
};

/// Lowest Spencer F over the windows (see the file comment).
CriticalBlock searchCriticalBlock(const SlopeSection& section, const BlockSearchWindows& windows,
                                  const SpencerOptions& options = {});

}  // namespace argine
