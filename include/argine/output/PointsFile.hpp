#pragma once
/// @file PointsFile.hpp
/// One Exodus II file of the material-points restart series: one node per point and one
/// CIRCLE element per node, one element block per material (block name = material name,
/// block id = material index + 1). The nodes are a fixed set of points, found at every
/// write by their permanent id (points are sorted during a run). Reference coordinates are
/// the positions when the file is made; motion is the nodal vector displ_x/_y, which
/// ParaView applies as a displacement.

#include <memory>
#include <string>
#include <vector>

#include "argine/output/ExodusFile.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

/// Nodal variables of a points file, in file order. displ_ comes first: ParaView moves the
/// nodes by the first nodal vector whose name starts with "dis". Stress is written with
/// the 6 symmetric-tensor components xx yy zz xy xz yz (xz = yz = 0 in plane strain)
/// because ParaView only groups those 6 suffixes into a tensor.
const std::vector<std::string>& pointVariableNames();

class PointsFile {
 public:
  /// Creates `path` (atomically) with the current points as its nodes. Throws RunError if a
  /// point's material index is not in `material_names`.
  PointsFile(const std::string& path, const std::vector<std::string>& material_names,
             const MaterialPoints& points);

  /// Reopens a points file of a checkpointed run (ExodusResume): its nodes, ids and reference
  /// coordinates are read back from the file.
  PointsFile(const std::string& path, ExodusResume resume);

  /// True when `points` are exactly this file's points: same count, every id a file node.
  bool holds(const MaterialPoints& points) const;

  /// Appends a time step with every variable of pointVariableNames(). Throws
  /// std::logic_error when !holds(points).
  void write(Real time, const MaterialPoints& points);

  const std::string& path() const { return file_->path(); }
  /// Number of time steps written so far.
  int steps() const { return file_->steps(); }
  /// Number of points (nodes) in the file.
  int numPoints() const { return static_cast<int>(reference_x_.size()); }

 private:
  std::vector<int> node_of_id_;    ///< file node (0-based) of each point id, -1 if none
  std::vector<Real> reference_x_;  ///< reference x of each file node (m)
  std::vector<Real> reference_y_;  ///< reference y of each file node (m)
  std::unique_ptr<ExodusFile> file_;
};

}  // namespace argine
