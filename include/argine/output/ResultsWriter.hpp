#pragma once
/// @file ResultsWriter.hpp
/// Exodus II results of a run, for ParaView: `<dir>/<stem>_grid.e` (background mesh and
/// nodal fields) and the material-points restart series `<dir>/<stem>_points.e`,
/// `<stem>_points.e-s0002`, ... (a new file each time the set of points changes).
/// Every write ends with ex_update, so a killed run leaves files readable up to the last
/// complete step.

#include <memory>
#include <string>
#include <vector>

#include "argine/mesh/Mesh.hpp"
#include "argine/output/GridFile.hpp"
#include "argine/output/PointsFile.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

/// Where a restarted run continues the results (recorded by a checkpoint).
struct ResultsResume {
  int grid_steps = 0;         ///< time steps in the grid file
  int points_file_count = 1;  ///< files of the points series
  int points_steps = 0;       ///< time steps in the last of them
};

class ResultsWriter {
 public:
  /// Creates `directory` if missing (InputError naming it if that fails), removes stale
  /// `<stem>_points.e-sNNNN` files of an earlier run, and creates the grid file and the first
  /// points file (reference coordinates = current positions). Block i of the points file is
  /// material i (`points.material` indexes `material_names`).
  ResultsWriter(const std::string& directory, const std::string& stem, const Mesh& mesh,
                const std::vector<std::string>& material_names,
                const std::vector<std::string>& nodal_field_names, const MaterialPoints& points);

  /// Continues the files of a checkpointed run (restart): reopens the grid file and the last
  /// points file after the recorded steps (ExodusResume) and removes later files of the
  /// points series a killed run may have started. InputError naming a file that does not fit.
  ResultsWriter(const std::string& directory, const std::string& stem, const Mesh& mesh,
                const std::vector<std::string>& material_names,
                const std::vector<std::string>& nodal_field_names, const ResultsResume& resume);

  /// Where the files stand now, for a checkpoint.
  ResultsResume resumePoint() const;

  /// Writes one time step to both files. When the set of points changed (points removed or
  /// added), first starts the next points file of the series.
  void write(Real time, const MaterialPoints& points, const std::vector<NodalField>& nodal);

  /// Path of the grid file.
  const std::string& gridPath() const { return grid_.path(); }
  /// Path of the points file currently written.
  const std::string& pointsPath() const { return points_->path(); }
  /// Number of points files made so far (1 + restarts of the series).
  int pointsFileCount() const { return points_file_count_; }
  /// Number of time steps written.
  int steps() const { return grid_.steps(); }

  /// Path of file `index` (1-based) of the points series: `<stem>_points.e` for 1,
  /// `<stem>_points.e-s0002` for 2, ...
  static std::string pointsSeriesPath(const std::string& directory, const std::string& stem,
                                      int index);

 private:
  std::string directory_;
  std::string stem_;
  std::vector<std::string> material_names_;
  GridFile grid_;
  std::unique_ptr<PointsFile> points_;
  int points_file_count_ = 1;
};

}  // namespace argine
