#include "argine/output/PointsFile.hpp"

#include <exodusII.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "PointVariables.hpp"
#include "argine/core/Error.hpp"

namespace argine {

namespace {

// Writes the fixed part of a points file: nodes (in the given order), one CIRCLE block per
// material, names, the node id map and the variable names.
void definePointsFile(int exoid, const std::string& path,
                      const std::vector<std::string>& material_names,
                      const std::vector<int>& block_sizes, const std::vector<int>& id_of_node,
                      const std::vector<Real>& x, const std::vector<Real>& y) {
  const auto num_nodes = static_cast<int64_t>(x.size());
  const auto num_blocks = static_cast<int64_t>(material_names.size());
  checkExodus(
      ex_put_init(exoid, "argine material points", kDim, num_nodes, num_nodes, num_blocks, 0, 0),
      path, "ex_put_init");
  checkExodus(ex_put_coord(exoid, x.data(), y.data(), nullptr), path, "ex_put_coord");
  char coordinate_x[] = "x";
  char coordinate_y[] = "y";
  char* coordinate_names[] = {coordinate_x, coordinate_y};
  checkExodus(ex_put_coord_names(exoid, coordinate_names), path, "ex_put_coord_names");

  // Nodes are ordered by block, so block b holds the consecutive nodes after `first`.
  int first = 0;
  for (int b = 0; b < num_blocks; ++b) {
    const int block_id = b + 1;
    checkExodus(ex_put_block(exoid, EX_ELEM_BLOCK, block_id, "CIRCLE", block_sizes[b], 1, 0, 0, 0),
                path, "ex_put_block");
    checkExodus(ex_put_name(exoid, EX_ELEM_BLOCK, block_id, material_names[b].c_str()), path,
                "ex_put_name");
    if (block_sizes[b] > 0) {
      std::vector<int> connectivity(block_sizes[b]);
      std::iota(connectivity.begin(), connectivity.end(), first + 1);  // 1-based nodes
      checkExodus(
          ex_put_conn(exoid, EX_ELEM_BLOCK, block_id, connectivity.data(), nullptr, nullptr), path,
          "ex_put_conn");
    }
    first += block_sizes[b];
  }

  // Node numbers = point id + 1 (exodus ids are positive): ParaView shows them as ids.
  std::vector<int> node_numbers(id_of_node.size());
  for (std::size_t n = 0; n < id_of_node.size(); ++n) node_numbers[n] = id_of_node[n] + 1;
  // A file without points (all left the grid) has times only: exodus defines no nodal
  // variables without nodes.
  if (num_nodes == 0) return;
  checkExodus(ex_put_id_map(exoid, EX_NODE_MAP, node_numbers.data()), path, "ex_put_id_map");
  defineNodalVariables(exoid, path, pointVariableNames());
}

}  // namespace

PointsFile::PointsFile(const std::string& path, const std::vector<std::string>& material_names,
                       const MaterialPoints& points) {
  auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.id);
  auto material = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.material);
  auto position = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
  const int n = points.count;
  const int num_materials = static_cast<int>(material_names.size());

  // File node order: by material (so each block is a run of nodes), then by id.
  std::vector<int> point_of_node(n);
  std::iota(point_of_node.begin(), point_of_node.end(), 0);
  std::sort(point_of_node.begin(), point_of_node.end(), [&](int a, int b) {
    return material(a) != material(b) ? material(a) < material(b) : id(a) < id(b);
  });

  std::vector<int> block_sizes(num_materials, 0);
  std::vector<int> id_of_node(n);
  reference_x_.resize(n);
  reference_y_.resize(n);
  int max_id = -1;
  for (int node = 0; node < n; ++node) {
    const int p = point_of_node[node];
    if (material(p) < 0 || material(p) >= num_materials)
      throw RunError(path + ": point " + std::to_string(id(p)) + " has material index " +
                     std::to_string(material(p)) + ", expected 0.." +
                     std::to_string(num_materials - 1));
    if (id(p) < 0) throw RunError(path + ": point id " + std::to_string(id(p)) + " is negative");
    ++block_sizes[material(p)];
    id_of_node[node] = id(p);
    reference_x_[node] = position(p, 0);
    reference_y_[node] = position(p, 1);
    max_id = std::max(max_id, id(p));
  }
  node_of_id_.assign(max_id + 1, -1);
  for (int node = 0; node < n; ++node) {
    if (node_of_id_[id_of_node[node]] != -1)
      throw RunError(path + ": point id " + std::to_string(id_of_node[node]) + " appears twice");
    node_of_id_[id_of_node[node]] = node;
  }

  file_ = std::make_unique<ExodusFile>(path, [&](int exoid) {
    definePointsFile(exoid, path, material_names, block_sizes, id_of_node, reference_x_,
                     reference_y_);
  });
}

PointsFile::PointsFile(const std::string& path, ExodusResume resume)
    : file_(std::make_unique<ExodusFile>(path, resume)) {
  const int exoid = file_->id();
  const int n = static_cast<int>(ex_inquire_int(exoid, EX_INQ_NODES));
  reference_x_.resize(n);
  reference_y_.resize(n);
  if (n == 0) return;
  std::vector<int> node_numbers(n);
  if (ex_get_coord(exoid, reference_x_.data(), reference_y_.data(), nullptr) < 0 ||
      ex_get_id_map(exoid, EX_NODE_MAP, node_numbers.data()) < 0)
    throw InputError(path, "cannot read the points (coordinates, id map) back");
  int max_id = -1;
  for (const int number : node_numbers) max_id = std::max(max_id, number - 1);
  node_of_id_.assign(max_id + 1, -1);
  for (int node = 0; node < n; ++node) {
    const int id = node_numbers[node] - 1;
    if (id < 0 || node_of_id_[id] != -1)
      throw InputError(path,
                       "its node id map is not a points file's (id " + std::to_string(id) + ")");
    node_of_id_[id] = node;
  }
}

bool PointsFile::holds(const MaterialPoints& points) const {
  if (points.count != numPoints()) return false;
  auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.id);
  const int num_ids = static_cast<int>(node_of_id_.size());
  for (int p = 0; p < points.count; ++p)
    if (id(p) < 0 || id(p) >= num_ids || node_of_id_[id(p)] < 0) return false;
  return true;
}

void PointsFile::write(Real time, const MaterialPoints& points) {
  if (!holds(points))
    throw std::logic_error(path() + ": the points changed since the file was made");
  PointSnapshot snapshot(points);
  const int n = points.count;
  std::vector<int> node_of_point(n);
  snapshot.reference_x.resize(n);
  snapshot.reference_y.resize(n);
  for (int p = 0; p < n; ++p) {
    node_of_point[p] = node_of_id_[snapshot.id(p)];
    snapshot.reference_x[p] = reference_x_[node_of_point[p]];
    snapshot.reference_y[p] = reference_y_[node_of_point[p]];
  }

  const int step = file_->beginStep(time);
  std::vector<Real> values(n);
  const auto& variables = pointVariables();
  for (std::size_t v = 0; v < variables.size() && n > 0; ++v) {
    for (int p = 0; p < n; ++p) values[node_of_point[p]] = variables[v].value(snapshot, p);
    file_->putNodal(step, static_cast<int>(v) + 1, values);
  }
  file_->finishStep();
}

}  // namespace argine
