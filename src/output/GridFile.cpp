#include "argine/output/GridFile.hpp"

#include <set>
#include <stdexcept>

#include <exodusII.h>

#include "argine/core/Error.hpp"
#include "argine/meshio/ExodusMesh.hpp"

namespace argine {

namespace {
const std::vector<std::string>& checkedNames(const std::vector<std::string>& names) {
  std::set<std::string> seen;
  for (const auto& name : names) {
    if (name.empty()) throw std::invalid_argument("grid results: empty nodal field name");
    if (!seen.insert(name).second)
      throw std::invalid_argument("grid results: nodal field " + name + " declared twice");
  }
  return names;
}
}  // namespace

GridFile::GridFile(const std::string& path, const Mesh& mesh,
                   const std::vector<std::string>& field_names)
    : field_names_(checkedNames(field_names)),
      num_nodes_(mesh.numNodes()),
      file_(path, [&](int exoid) {
        putMeshGeometry(exoid, mesh, "argine background mesh");
        defineNodalVariables(exoid, path, field_names_);
      }) {}

GridFile::GridFile(const std::string& path, const Mesh& mesh,
                   const std::vector<std::string>& field_names, ExodusResume resume)
    : field_names_(checkedNames(field_names)), num_nodes_(mesh.numNodes()), file_(path, resume) {
  const auto nodes = ex_inquire_int(file_.id(), EX_INQ_NODES);
  if (nodes != num_nodes_)
    throw InputError(path, "has " + std::to_string(nodes) + " nodes, the mesh " +
                               std::to_string(num_nodes_) + ": not the checkpointed run's file");
}

void GridFile::write(Real time, const std::vector<NodalField>& fields) {
  // Match the given fields to the declared variables before touching the file.
  std::vector<const NodalField*> field_of_variable(field_names_.size(), nullptr);
  for (const auto& field : fields) {
    std::size_t v = 0;
    while (v < field_names_.size() && field_names_[v] != field.name) ++v;
    if (v == field_names_.size())
      throw std::invalid_argument(path() + ": nodal field " + field.name + " was not declared");
    if (field_of_variable[v] != nullptr)
      throw std::invalid_argument(path() + ": nodal field " + field.name + " given twice");
    if (static_cast<int>(field.values.extent(0)) != num_nodes_)
      throw std::invalid_argument(path() + ": nodal field " + field.name + " has " +
                                  std::to_string(field.values.extent(0)) + " values for " +
                                  std::to_string(num_nodes_) + " nodes");
    field_of_variable[v] = &field;
  }
  for (std::size_t v = 0; v < field_names_.size(); ++v)
    if (field_of_variable[v] == nullptr)
      throw std::invalid_argument(path() + ": nodal field " + field_names_[v] + " is missing");

  const int step = file_.beginStep(time);
  std::vector<Real> values(num_nodes_);
  for (std::size_t v = 0; v < field_names_.size(); ++v) {
    auto host =
        Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), field_of_variable[v]->values);
    for (int n = 0; n < num_nodes_; ++n) values[n] = host(n);
    file_.putNodal(step, static_cast<int>(v) + 1, values);
  }
  file_.finishStep();
}

}  // namespace argine
