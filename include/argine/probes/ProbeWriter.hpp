#pragma once
/// @file ProbeWriter.hpp
/// The deck's `Probes` as CSV time series (SPEC "Results": tracked material points and
/// sections). Files in the output directory, one row per write:
///   <stem>_probe_<name>.csv    one material point, followed by its id (points are sorted
///                              during a run, so indices change):
///     time, id, x, y, displacement_x, displacement_y, velocity_x, velocity_y,
///     liquid_pressure, saturation, deviatoric_strain, stress_xx, stress_yy (effective)
///   <stem>_section_<name>.csv  band: one row per point within Width/2 of the segment at
///                              the time of writing (same columns after time: id, distance
///                              along the segment, ...); profile: one row per sample:
///     time, sample, distance, x, y, liquid_pressure, saturation, points
///                              (inverse-distance average of the liquid-carrying points
///                              within Width/2 of the sample; NaN and 0 points when none).
/// The point probe picks, at construction, the point nearest to its Position; InputError
/// ("Probes/Points/<name>/Position (m)") when none lies within Tolerance.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "argine/input/Deck.hpp"

namespace argine {

struct MaterialPoints;
class CsvWriter;

/// A host copy of the point fields the probes read.
struct ProbeSnapshot {
  std::vector<int> id;
  std::vector<Real> x, y, ux, uy, vx, vy, pressure, saturation, deviatoric, sxx, syy;
  std::vector<int> liquid;       ///< 1 where the point carries liquid
  std::vector<int> index_of_id;  ///< point index by id (-1: absent)
  explicit ProbeSnapshot(const MaterialPoints& points);
};

/// Index of the point nearest to `position`, or -1 without points.
int nearestPoint(const ProbeSnapshot& points, const std::array<Real, 2>& position);

/// Distance along the segment from->to of the foot of the perpendicular from (x, y), and the
/// distance from the segment itself (to the nearer end when the foot lies outside).
struct SegmentDistance {
  Real along = 0;  ///< (m), clamped to [0, length]
  Real off = 0;    ///< (m) >= 0
};
SegmentDistance segmentDistance(const std::array<Real, 2>& from, const std::array<Real, 2>& to,
                                Real x, Real y);

class ProbeWriter {
 public:
  /// Resolves the point probes on `points` (their current positions are the initial ones)
  /// and creates the files.
  /// `resume_bytes` (restart): one size per file in paths() order; the files of the
  /// checkpointed run are continued after that many bytes (CsvWriter CsvResume).
  ProbeWriter(const ProbesSpec& spec, const std::string& directory, const std::string& stem,
              const MaterialPoints& points, const std::vector<std::uintmax_t>& resume_bytes = {});
  ~ProbeWriter();

  /// Appends one row per probe (a band section: one per point in the band) at `time`.
  void write(Real time, const MaterialPoints& points);

  /// Ids of the point probes, in deck order.
  const std::vector<int>& pointIds() const { return point_ids_; }
  /// Paths of all files, point probes first.
  std::vector<std::string> paths() const;
  /// Bytes written to each file so far, in paths() order (for checkpoints).
  std::vector<std::uintmax_t> fileBytes() const;
  /// Probe interval (s); 0: at every output.
  Real interval() const { return spec_.interval; }

 private:
  ProbesSpec spec_;
  std::vector<int> point_ids_;
  std::vector<std::unique_ptr<CsvWriter>> point_files_;
  std::vector<std::unique_ptr<CsvWriter>> section_files_;
};

}  // namespace argine
