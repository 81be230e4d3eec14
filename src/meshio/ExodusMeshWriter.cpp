/// @file ExodusMeshWriter.cpp
/// Writes a Mesh to Exodus II with the generic calls only (see ExodusMesh.hpp).
#include <exodusII.h>

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "argine/core/Error.hpp"
#include "argine/meshio/ExodusMesh.hpp"

namespace argine {

namespace {

/// Throws RunError when an exodus call returned an error code (< 0; > 0 is a warning).
void check(int status, const std::string& call) {
  if (status < 0)
    throw RunError("writing Exodus mesh: " + call + " failed (exodus error " +
                   std::to_string(status) + ")");
}

/// Exodus ids of a list of blocks or sets: the stored id when positive and not used before,
/// otherwise the next free one, so a hand-built mesh with ids left at 0 still writes.
template <class Group>
std::vector<int> exodusIds(const std::vector<Group>& groups) {
  std::vector<int> ids;
  std::set<int> used;
  for (const auto& group : groups)
    if (group.id > 0) used.insert(group.id);
  std::set<int> taken;
  int next = 1;
  for (const auto& group : groups) {
    if (group.id > 0 && taken.insert(group.id).second) {
      ids.push_back(group.id);
      continue;
    }
    while (used.count(next) || taken.count(next)) ++next;
    taken.insert(next);
    ids.push_back(next);
  }
  return ids;
}

/// Writes the names of all blocks or sets of one kind (after they were all defined).
template <class Group>
void putNames(int exoid, ex_entity_type type, const std::vector<Group>& groups) {
  if (groups.empty()) return;
  std::vector<std::string> names;
  std::vector<char*> pointers;
  for (const auto& group : groups) names.push_back(group.name);
  for (auto& name : names) pointers.push_back(name.data());
  check(ex_put_names(exoid, type, pointers.data()), "ex_put_names");
}

/// Longest block or set name, to widen the file's name length beyond the default 32.
std::size_t longestName(const Mesh& mesh) {
  std::size_t longest = 0;
  for (const auto& b : mesh.blocks) longest = std::max(longest, b.name.size());
  for (const auto& s : mesh.node_sets) longest = std::max(longest, s.name.size());
  for (const auto& s : mesh.side_sets) longest = std::max(longest, s.name.size());
  return longest;
}

}  // namespace

std::vector<int> exodusElementOrder(const Mesh& mesh) {
  const int num_elements = mesh.numElements();
  std::vector<int> order;
  order.reserve(num_elements);
  std::vector<char> seen(num_elements, 0);
  for (const auto& block : mesh.blocks)
    for (int e : block.elements) {
      if (e < 0 || e >= num_elements || seen[e])
        throw std::invalid_argument("mesh block " + block.name + " lists element " +
                                    std::to_string(e) + " out of range or twice");
      seen[e] = 1;
      order.push_back(e);
    }
  if (static_cast<int>(order.size()) != num_elements)
    throw std::invalid_argument("mesh blocks hold " + std::to_string(order.size()) + " of " +
                                std::to_string(num_elements) + " elements");
  return order;
}

void putMeshGeometry(int exoid, const Mesh& mesh, const std::string& title) {
  const int nv = mesh.nodesPerElement();
  const std::vector<int> order = exodusElementOrder(mesh);
  std::vector<int> file_number(order.size());  // mesh element -> 1-based file number
  for (std::size_t i = 0; i < order.size(); ++i) file_number[order[i]] = static_cast<int>(i) + 1;

  const std::size_t longest = longestName(mesh);
  if (longest > static_cast<std::size_t>(MAX_NAME_LENGTH))
    check(ex_set_max_name_length(exoid, static_cast<int>(longest)), "ex_set_max_name_length");

  const std::string file_title = title.substr(0, MAX_LINE_LENGTH);
  check(ex_put_init(exoid, file_title.c_str(), kDim, mesh.numNodes(), mesh.numElements(),
                    static_cast<int64_t>(mesh.blocks.size()),
                    static_cast<int64_t>(mesh.node_sets.size()),
                    static_cast<int64_t>(mesh.side_sets.size())),
        "ex_put_init");

  // Coordinates.
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  std::vector<double> x(mesh.numNodes()), y(mesh.numNodes());
  for (int n = 0; n < mesh.numNodes(); ++n) {
    x[n] = coordinates(n, 0);
    y[n] = coordinates(n, 1);
  }
  check(ex_put_coord(exoid, x.data(), y.data(), nullptr), "ex_put_coord");
  char coord_x[] = "x";
  char coord_y[] = "y";
  char* coord_names[] = {coord_x, coord_y};
  check(ex_put_coord_names(exoid, coord_names), "ex_put_coord_names");

  // Element blocks: all parameters first, then names, then connectivity.
  auto connectivity = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const std::vector<int> block_ids = exodusIds(mesh.blocks);
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    check(ex_put_block(exoid, EX_ELEM_BLOCK, block_ids[b], exodusName(mesh.type),
                       static_cast<int64_t>(mesh.blocks[b].elements.size()), nv, 0, 0, 0),
          "ex_put_block (block " + mesh.blocks[b].name + ")");
  putNames(exoid, EX_ELEM_BLOCK, mesh.blocks);
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& elements = mesh.blocks[b].elements;
    if (elements.empty()) continue;
    std::vector<int> conn;
    conn.reserve(elements.size() * nv);
    for (int e : elements)
      for (int k = 0; k < nv; ++k) conn.push_back(connectivity(e, k) + 1);
    check(ex_put_conn(exoid, EX_ELEM_BLOCK, block_ids[b], conn.data(), nullptr, nullptr),
          "ex_put_conn (block " + mesh.blocks[b].name + ")");
  }

  // Node sets.
  const std::vector<int> node_set_ids = exodusIds(mesh.node_sets);
  for (std::size_t s = 0; s < mesh.node_sets.size(); ++s) {
    const auto& nodes = mesh.node_sets[s].nodes;
    check(ex_put_set_param(exoid, EX_NODE_SET, node_set_ids[s], static_cast<int64_t>(nodes.size()),
                           0),
          "ex_put_set_param (node set " + mesh.node_sets[s].name + ")");
    if (nodes.empty()) continue;
    std::vector<int> list;
    for (int n : nodes) list.push_back(n + 1);
    check(ex_put_set(exoid, EX_NODE_SET, node_set_ids[s], list.data(), nullptr),
          "ex_put_set (node set " + mesh.node_sets[s].name + ")");
  }
  putNames(exoid, EX_NODE_SET, mesh.node_sets);

  // Side sets.
  const std::vector<int> side_set_ids = exodusIds(mesh.side_sets);
  for (std::size_t s = 0; s < mesh.side_sets.size(); ++s) {
    const SideSet& set = mesh.side_sets[s];
    if (set.elements.size() != set.sides.size())
      throw std::invalid_argument("side set " + set.name + " has " +
                                  std::to_string(set.elements.size()) + " elements but " +
                                  std::to_string(set.sides.size()) + " sides");
    check(ex_put_set_param(exoid, EX_SIDE_SET, side_set_ids[s],
                           static_cast<int64_t>(set.elements.size()), 0),
          "ex_put_set_param (side set " + set.name + ")");
    if (set.elements.empty()) continue;
    std::vector<int> elements, sides;
    for (std::size_t i = 0; i < set.elements.size(); ++i) {
      const int e = set.elements[i];
      if (e < 0 || e >= mesh.numElements() || set.sides[i] < 0 || set.sides[i] >= nv)
        throw std::invalid_argument("side set " + set.name + " has an invalid side");
      elements.push_back(file_number[e]);
      sides.push_back(set.sides[i] + 1);
    }
    check(ex_put_set(exoid, EX_SIDE_SET, side_set_ids[s], elements.data(), sides.data()),
          "ex_put_set (side set " + set.name + ")");
  }
  putNames(exoid, EX_SIDE_SET, mesh.side_sets);
  check(ex_update(exoid), "ex_update");
}

void writeExodusMesh(const std::string& path, const Mesh& mesh, const std::string& title) {
  const std::string temporary = path + ".tmp";
  int comp_ws = sizeof(double);
  int io_ws = sizeof(double);
  const int exoid = ex_create(temporary.c_str(), EX_CLOBBER, &comp_ws, &io_ws);
  if (exoid < 0)
    throw InputError(path, "cannot create the Exodus file " + temporary +
                               " (does the directory exist and is it writable?)");
  try {
    putMeshGeometry(exoid, mesh, title);
  } catch (...) {
    ex_close(exoid);
    std::remove(temporary.c_str());
    throw;
  }
  if (ex_close(exoid) < 0) {
    std::remove(temporary.c_str());
    throw RunError("writing Exodus mesh " + path + ": ex_close failed");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw InputError(path, "cannot rename " + temporary + " to the final file name");
  }
}

}  // namespace argine
