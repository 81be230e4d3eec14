#pragma once
// The ACADS slope-stability test problems (Donald & Giam 1989, the ACADS survey of slope
// stability programs; Giam & Donald 1992) used to verify argine's limit equilibrium, with the
// published answers they are judged against. Geometry and materials as given in the SLOPE/W
// Verification Manual (GeoStudio, Oct 2022, Secs. 2.1, 2.3, 2.7-2.9) and the Slide2
// Verification Manual (Rocscience, problems 1, 3, 7-9), transcribed with the coordinates of
// the public repository github.com/njones61/xslope (benchmarks/build_lem.py,
// benchmarks/rocscience/build_problems.py; problem data only, no code). SI units.

#include <string>
#include <vector>

#include "argine/slopestability/BlockSearch.hpp"
#include "argine/slopestability/CircleSearch.hpp"
#include "argine/slopestability/SlopeSection.hpp"

namespace argine::lem_acads {

enum class SurfaceKind { CircleSearch, BlockSearch, Specified };

/// One problem: the section, how its critical surface is found, and the published answers.
struct AcadsProblem {
  std::string key;    ///< CTest / CSV name
  std::string title;  ///< e.g. "ACADS 1(c) three layers"
  SlopeSection section;
  SurfaceKind kind = SurfaceKind::CircleSearch;
  CircleSearchGrid grid;       ///< CircleSearch
  BlockSearchWindows windows;  ///< BlockSearch
  Polyline surface;            ///< Specified
  int slice_count = 50;        ///< Specified
  Real referee = 0;            ///< the ACADS referee F (the centre of a referee range)
  /// The published spread: argine's F (Bishop on circles, Spencer always) must lie in
  /// [band_min, band_max]; band_source says where each end comes from.
  Real band_min = 0, band_max = 0;
  std::string band_source;
  /// A published critical circle, if the source prints one (radius 0: none). argine's
  /// Bishop and Spencer F on it are reported beside the published F, not judged: they
  /// separate the method from the search (the published F came from the source's own search
  /// and slicing).
  SlipCircle published_circle;
  Real published_circle_bishop = 0, published_circle_spencer = 0;
  std::string published_circle_source;
};

/// All problems, in the order of the report.
std::vector<AcadsProblem> acadsProblems();

}  // namespace argine::lem_acads
