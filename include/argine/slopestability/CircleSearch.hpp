#pragma once
/// @file CircleSearch.hpp
/// The critical circle of a section: a grid of centres and, for each centre, a range of
/// tangent elevations (radius = centre_y - tangent_y, i.e. circles tangent to horizontal
/// lines), Bishop's F of each (or the F of another method, searchCriticalCircleBy), then the
/// grid repeatedly refined around the lowest F.

#include <functional>
#include <limits>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/slopestability/Bishop.hpp"
#include "argine/slopestability/CircularSlip.hpp"
#include "argine/slopestability/SlopeSection.hpp"

namespace argine {

/// The search grid (m). Counts >= 1; a count of 1 takes the minimum.
struct CircleSearchGrid {
  Real centre_x_min = 0, centre_x_max = 0;
  int centre_x_count = 11;
  Real centre_y_min = 0, centre_y_max = 0;
  int centre_y_count = 11;
  Real tangent_y_min = 0, tangent_y_max = 0;
  int tangent_count = 11;
  /// Passes after the first: each a grid of the same counts spanning one former spacing on
  /// either side of the best point, so the spacing shrinks by about (count - 1) / 2 a pass.
  int refinements = 3;
  /// Refinements start from this many of the first pass's local minima, lowest first (1: from
  /// its best point only); the lowest F over all of them is the result.
  int starts = 1;
  int slice_count = 50;
  /// Circles whose deepest slice base lies less than this below the ground are not tried
  /// (m): in a cohesionless slope the critical circle otherwise shrinks to the surface,
  /// where F tends to the infinite-slope value tan(phi') / tan(beta) of a skin of no volume.
  Real min_depth = 0;
  /// The sliding mass must lie between these abscissae (m), e.g. one side of a levee.
  Real mass_x_min = -std::numeric_limits<Real>::infinity();
  Real mass_x_max = std::numeric_limits<Real>::infinity();
  bool split_at_materials = false;  ///< sliceCircle's option: no base across two materials
};

/// The result: the critical circle, its Bishop F and slices, and the search's bookkeeping.
struct CriticalCircle {
  bool found = false;
  SlipCircle circle;
  FactorOfSafety objective;  ///< F of the searched method (searchCriticalCircle: Bishop)
  FactorOfSafety bishop;     ///< Bishop's F on the critical circle
  FactorOfSafety ordinary;   ///< the ordinary method on the same circle, for comparison
  SlipMass mass;             ///< the slice table of the critical circle
  int evaluated = 0;         ///< circles tried
  int rejected = 0;          ///< of which no slip mass or an inadmissible F
};

/// Lowest Bishop F over the grid (see the file comment).
CriticalCircle searchCriticalCircle(const SlopeSection& section, const CircleSearchGrid& grid,
                                    const BishopOptions& options = {});

/// The F of a method on a sliced circle (admissible = false: not a candidate).
using CircleObjective = std::function<FactorOfSafety(const SlipMass&, const SlipCircle&)>;

/// Lowest F of `objective` over the grid, by the same passes; `bishop` and `ordinary` of the
/// result are Bishop's (default options) and the ordinary F on the critical circle.
CriticalCircle searchCriticalCircleBy(const SlopeSection& section, const CircleSearchGrid& grid,
                                      const CircleObjective& objective);

}  // namespace argine
