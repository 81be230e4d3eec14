#pragma once
/// @file GridFile.hpp
/// The Exodus II file of the background mesh (blocks, node sets, side sets) with named
/// nodal result fields at each written time.

#include <string>
#include <vector>

#include "argine/mesh/Mesh.hpp"
#include "argine/output/ExodusFile.hpp"

namespace argine {

/// One nodal field of the background mesh to write: its name and one value per mesh node.
struct NodalField {
  std::string name;                            ///< exodus variable name
  Kokkos::View<const Real*, MemSpace> values;  ///< value at each mesh node
};

class GridFile {
 public:
  /// Creates `path` (atomically) with the mesh and the nodal variables `field_names`.
  /// Throws std::invalid_argument for an empty or repeated field name.
  GridFile(const std::string& path, const Mesh& mesh, const std::vector<std::string>& field_names);

  /// Reopens the grid file of a checkpointed run (ExodusResume); InputError naming the file
  /// when its node count is not the mesh's.
  GridFile(const std::string& path, const Mesh& mesh, const std::vector<std::string>& field_names,
           ExodusResume resume);

  /// Appends a time step. `fields` must hold each declared name once (any order), each with
  /// one value per mesh node; throws std::invalid_argument otherwise.
  void write(Real time, const std::vector<NodalField>& fields);

  const std::string& path() const { return file_.path(); }
  /// Number of time steps written so far.
  int steps() const { return file_.steps(); }

 private:
  std::vector<std::string> field_names_;
  int num_nodes_ = 0;
  ExodusFile file_;
};

}  // namespace argine
