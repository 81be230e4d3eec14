#pragma once
/// @file SectionProfiles.hpp
/// V4's sampled profiles (VERIFICATION.md V4): p_L and S_L on the sections S1 (x = 1.5 m) and
/// S2 (x = 3.0 m) at 72, 160 and 300 s, at the heights y = 0.0125 + 0.025 k (k = 0..29), and
/// the error of a run against a reference there. Shared by the implicit driver (which
/// samples its finite-element field and compares every run) and the accuracy-against-cost
/// study of both paths.
#include <string>
#include <utility>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine::verification::v4 {

inline const std::vector<Real> kTimes{72, 160, 300};
inline const std::vector<std::pair<std::string, Real>> kSections{{"S1", 1.5}, {"S2", 3.0}};
constexpr Real kStrip = 0.03;    ///< points this close to a section belong to it (m)
constexpr Real kFitHalf = 0.05;  ///< half-height of the least-squares window (m)

/// y = 0.0125 + 0.025 k, k = 0..29 (up to the slope at y = 0.75 m on S1).
std::vector<Real> sampleHeights();

/// Samples (p, S) in the order time, section, height; NaN where a run has no value.
struct Samples {
  std::vector<Real> p, s;
};

/// One point of a section strip at one sample time (the rows of <tag>_sections.csv).
struct PointRow {
  Real t, x, y, p, s;
  std::string section;
};

/// The explicit path's profile: at each sample, a least-squares plane p = a + b dx + c dy
/// through the strip's points within `half_height` in y, evaluated at (x_s, y) (one pressure
/// per point with Tri3 checkerboard modes; the plane reads the local mean). NaN with fewer
/// than three points. Coarser meshes than 0.05 m need a window of about one element.
Samples fitRows(const std::vector<PointRow>& rows, Real half_height = kFitHalf);

/// Rows of a <tag>_sections.csv (time,section,x,y,pressure,saturation); empty when the file
/// cannot be read.
std::vector<PointRow> readSectionCsv(const std::string& path);

/// The samples of run `run` in a <tag>_profiles.csv (run,time,section,y,pressure,saturation),
/// in the order of Samples; empty when the run is not in the file.
Samples readProfiles(const std::string& path, const std::string& run);

/// max |a - ref| / (max - min of ref) for p and S over the samples where both exist.
struct Errors {
  Real p = 0, s = 0;
  int compared = 0;
};
Errors compare(const Samples& a, const Samples& reference);

}  // namespace argine::verification::v4
