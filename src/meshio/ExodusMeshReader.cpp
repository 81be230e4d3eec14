/// @file ExodusMeshReader.cpp
/// Reads a 2D Exodus II mesh into a Mesh with the generic calls only, and checks it:
/// one element type, node numbers in range; the elements' orientation and shape are checked
/// by assembleMesh (MeshAssembly.hpp), as for every reader.
#include <exodusII.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "argine/core/Error.hpp"
#include "argine/meshio/ExodusLayoutCheck.hpp"
#include "argine/meshio/ExodusMesh.hpp"
#include "argine/meshio/MeshAssembly.hpp"
#include "argine/meshio/NetcdfHeaderCheck.hpp"

namespace argine {

namespace {

/// Closes the exodus file on every way out of the reader.
struct ExodusFile {
  int id;
  ~ExodusFile() { ex_close(id); }
};

/// Exodus II names are netCDF names: at most NC_MAX_NAME = 256 bytes with the terminator.
constexpr int64_t kLongestName = 255;

/// Reads things from one open file; every failure becomes an InputError naming the file.
class Reader {
 public:
  Reader(const std::string& path, int exoid) : path_(path), exoid_(exoid) {}

  void check(int status, const std::string& call) const {
    if (status < 0)
      throw InputError(path_, call + " failed (exodus error " + std::to_string(status) +
                                  "): not a valid Exodus II mesh");
  }

  std::vector<int> ids(ex_entity_type type, int64_t count) const {
    std::vector<int> ids(count);
    if (count > 0) check(ex_get_ids(exoid_, type, ids.data()), "ex_get_ids");
    return ids;
  }

  /// Names of all blocks or sets of one kind, with `prefix + id` for unnamed ones.
  std::vector<std::string> names(ex_entity_type type, const std::vector<int>& ids,
                                 const std::string& prefix) const {
    const std::size_t count = ids.size();
    std::vector<std::string> names(count);
    if (count == 0) return names;
    // Names longer than the default 32 characters are returned only after asking for them.
    // The requested length may be library-wide (exodus 6), so the buffers take the larger
    // of it and the file's longest name.
    const int64_t used = ex_inquire_int(exoid_, EX_INQ_DB_MAX_USED_NAME_LENGTH);
    if (used > kLongestName)  // a damaged attribute would size huge buffers
      throw InputError(path_, "the file says its names are up to " + std::to_string(used) +
                                  " characters long; Exodus names have at most " +
                                  std::to_string(kLongestName));
    if (used > MAX_NAME_LENGTH) ex_set_max_name_length(exoid_, static_cast<int>(used));
    const int64_t requested = ex_inquire_int(exoid_, EX_INQ_MAX_READ_NAME_LENGTH);
    const std::size_t length = static_cast<std::size_t>(
        std::max<int64_t>({used, requested, static_cast<int64_t>(MAX_NAME_LENGTH)}));
    std::vector<std::vector<char>> buffers(count, std::vector<char>(length + 1, '\0'));
    std::vector<char*> pointers;
    for (auto& buffer : buffers) pointers.push_back(buffer.data());
    check(ex_get_names(exoid_, type, pointers.data()), "ex_get_names");
    for (std::size_t i = 0; i < count; ++i) {
      std::string name(buffers[i].data());
      while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back())))
        name.pop_back();
      names[i] = name.empty() ? prefix + std::to_string(ids[i]) : name;
    }
    return names;
  }

  const std::string& path() const { return path_; }
  int exoid() const { return exoid_; }

 private:
  std::string path_;
  int exoid_;
};

/// Element type from an Exodus type name and node count; false when unsupported.
bool parseElementType(std::string name, int nodes, ElementType* type) {
  for (auto& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if ((name == "TRI" || name == "TRI3" || name == "TRIANGLE") && nodes == 3) {
    *type = ElementType::Tri3;
    return true;
  }
  if ((name == "QUAD" || name == "QUAD4") && nodes == 4) {
    *type = ElementType::Quad4;
    return true;
  }
  return false;
}

/// Throws when two blocks or sets share a name (the deck refers to them by name).
void checkUniqueNames(const std::string& path, const std::vector<std::string>& names,
                      const std::vector<int>& ids, const std::string& what) {
  std::map<std::string, int> first_id;
  for (std::size_t i = 0; i < names.size(); ++i) {
    auto [it, inserted] = first_id.emplace(names[i], ids[i]);
    if (!inserted)
      throw InputError(path, "two " + what + " are named '" + names[i] + "' (ids " +
                                 std::to_string(it->second) + " and " + std::to_string(ids[i]) +
                                 "); names must be unique");
  }
}

/// The header's counts must be possible: positive where needed, within int, and not more
/// than the file can hold (each node has 2 coordinates of io_ws bytes, each element at least
/// 3 node numbers of 4 bytes). A damaged header otherwise asks for gigabytes (P8 fuzzing).
void checkHeaderCounts(const std::string& path, const ex_init_params& init, int io_ws) {
  const auto count = [&](const char* what, int64_t value, int64_t least) {
    if (value < least || value > std::numeric_limits<int>::max())
      throw InputError(path, std::string("the header's number of ") + what + " is " +
                                 std::to_string(value) + "; expected " + std::to_string(least) +
                                 " to " + std::to_string(std::numeric_limits<int>::max()));
  };
  count("nodes", init.num_nodes, 1);
  if (init.num_elem == 0) throw InputError(path, "the mesh has no elements");
  count("elements", init.num_elem, 1);
  count("element blocks", init.num_elem_blk, 1);
  count("node sets", init.num_node_sets, 0);
  count("side sets", init.num_side_sets, 0);
  std::error_code error;
  const auto bytes = static_cast<double>(std::filesystem::file_size(path, error));
  const double needed = static_cast<double>(init.num_nodes) * 2 * std::max(io_ws, 4) +
                        static_cast<double>(init.num_elem) * 3 * 4;
  if (!error && needed > bytes)
    throw InputError(path, "the header says " + std::to_string(init.num_nodes) + " nodes and " +
                               std::to_string(init.num_elem) + " elements, more than the file's " +
                               std::to_string(static_cast<long long>(bytes)) +
                               " bytes can hold (truncated or damaged file)");
}

struct RawBlock {
  int id;
  std::string name;
  std::string type_name;
  ElementType type;
  std::vector<int> connectivity;  // 1-based, as in the file
  int count;
};

}  // namespace

Mesh readExodusMesh(const std::string& path) {
  if (!std::ifstream(path).good())
    throw InputError(path, "cannot open the mesh file (missing or unreadable)");
  int comp_ws = sizeof(double);
  int io_ws = 0;
  float version = 0;
  checkNetcdfClassicHeader(path);  // (P8) before libnetcdf trusts its counts
  checkExodusLayout(path);         // (P8) before libexoIIv2c trusts the variables' shapes
  const int exoid = ex_open(path.c_str(), EX_READ, &comp_ws, &io_ws, &version);
  if (exoid < 0) throw InputError(path, "cannot open as an Exodus II file (ex_open failed)");
  ExodusFile file{exoid};
  // ex_open merges the file's int64_status attribute into the integer sizes of the API, so a
  // file could make ex_get_ids or ex_get_conn write 64-bit integers into argine's int arrays
  // (a heap overflow: fuzz/fuzz_exodus_reader, session 9). argine passes 32-bit integers,
  // whatever the file says.
  ex_set_int64_status(exoid, 0);
  Reader reader(path, exoid);

  ex_init_params init{};
  reader.check(ex_get_init_ext(exoid, &init), "ex_get_init_ext");
  if (init.num_dim != 2)
    throw InputError(path, "only 2D meshes are supported; the file has " +
                               std::to_string(init.num_dim) + " dimensions");
  checkHeaderCounts(path, init, io_ws);
  const int num_nodes = static_cast<int>(init.num_nodes);
  const int num_elements = static_cast<int>(init.num_elem);

  std::vector<double> x(num_nodes), y(num_nodes);
  reader.check(ex_get_coord(exoid, x.data(), y.data(), nullptr), "ex_get_coord");

  // Element blocks.
  const std::vector<int> block_ids = reader.ids(EX_ELEM_BLOCK, init.num_elem_blk);
  const std::vector<std::string> block_names = reader.names(EX_ELEM_BLOCK, block_ids, "block_");
  checkUniqueNames(path, block_names, block_ids, "element blocks");
  std::vector<RawBlock> raw;
  const RawBlock* first_typed = nullptr;
  int total = 0;
  for (std::size_t b = 0; b < block_ids.size(); ++b) {
    char type_name[MAX_STR_LENGTH + 1] = {0};
    int count = 0, nodes = 0, edges = 0, faces = 0, attributes = 0;
    reader.check(ex_get_block(exoid, EX_ELEM_BLOCK, block_ids[b], type_name, &count, &nodes, &edges,
                              &faces, &attributes),
                 "ex_get_block");
    RawBlock block{block_ids[b], block_names[b], type_name, ElementType::Tri3, {}, count};
    if (count < 0 || count > num_elements - total)
      throw InputError(path, "block " + block.name + " has " + std::to_string(count) +
                                 " elements, but the header says " + std::to_string(num_elements) +
                                 " in all blocks");
    total += count;
    if (count > 0) {
      if (!parseElementType(type_name, nodes, &block.type))
        throw InputError(path, "block " + block.name + " has elements of type " + block.type_name +
                                   " with " + std::to_string(nodes) +
                                   " nodes; supported are TRI3 (TRI, TRIANGLE) and QUAD4 (QUAD)");
      block.connectivity.resize(static_cast<std::size_t>(count) * nodes);
      reader.check(ex_get_conn(exoid, EX_ELEM_BLOCK, block_ids[b], block.connectivity.data(),
                               nullptr, nullptr),
                   "ex_get_conn");
      for (int node : block.connectivity)
        if (node < 1 || node > num_nodes)
          throw InputError(path, "block " + block.name + " refers to node " + std::to_string(node) +
                                     " but the mesh has " + std::to_string(num_nodes) + " nodes");
    }
    raw.push_back(std::move(block));
  }
  for (const auto& block : raw) {
    if (block.count == 0) continue;
    if (!first_typed) first_typed = &block;
    if (block.type != first_typed->type)
      throw InputError(path, std::string("mixed element types are not supported: block ") +
                                 first_typed->name + " is " + exodusName(first_typed->type) +
                                 ", block " + block.name + " is " + exodusName(block.type));
  }
  if (total != num_elements)
    throw InputError(path, "the element blocks hold " + std::to_string(total) +
                               " elements but the header says " + std::to_string(num_elements));

  std::vector<RawElementBlock> blocks;
  for (const auto& block : raw) {
    RawElementBlock assembled{block.name, block.id, block.connectivity};
    for (int& node : assembled.connectivity) --node;  // 1-based in the file
    blocks.push_back(std::move(assembled));
  }
  AssembledMesh assembled = assembleMesh(path, first_typed->type, x, y, blocks);
  Mesh& mesh = assembled.mesh;
  const std::vector<char>& flipped = assembled.flipped;
  const int nv = mesh.nodesPerElement();

  // Node sets.
  const std::vector<int> node_set_ids = reader.ids(EX_NODE_SET, init.num_node_sets);
  const auto node_set_names = reader.names(EX_NODE_SET, node_set_ids, "nodelist_");
  checkUniqueNames(path, node_set_names, node_set_ids, "node sets");
  for (std::size_t s = 0; s < node_set_ids.size(); ++s) {
    int count = 0, factors = 0;
    reader.check(ex_get_set_param(exoid, EX_NODE_SET, node_set_ids[s], &count, &factors),
                 "ex_get_set_param");
    NodeSet set;
    set.name = node_set_names[s];
    set.id = node_set_ids[s];
    if (count < 0 || count > num_nodes)
      throw InputError(path, "node set " + set.name + " has " + std::to_string(count) +
                                 " entries; the mesh has " + std::to_string(num_nodes) + " nodes");
    set.nodes.resize(count);
    if (count > 0)
      reader.check(ex_get_set(exoid, EX_NODE_SET, set.id, set.nodes.data(), nullptr), "ex_get_set");
    for (int& node : set.nodes) {
      if (node < 1 || node > num_nodes)
        throw InputError(path, "node set " + set.name + " refers to node " + std::to_string(node) +
                                   " but the mesh has " + std::to_string(num_nodes) + " nodes");
      --node;
    }
    mesh.node_sets.push_back(std::move(set));
  }

  // Side sets (sides of reordered elements are renumbered: old side s -> nv - 1 - s).
  const std::vector<int> side_set_ids = reader.ids(EX_SIDE_SET, init.num_side_sets);
  const auto side_set_names = reader.names(EX_SIDE_SET, side_set_ids, "surface_");
  checkUniqueNames(path, side_set_names, side_set_ids, "side sets");
  for (std::size_t s = 0; s < side_set_ids.size(); ++s) {
    int count = 0, factors = 0;
    reader.check(ex_get_set_param(exoid, EX_SIDE_SET, side_set_ids[s], &count, &factors),
                 "ex_get_set_param");
    SideSet set;
    set.name = side_set_names[s];
    set.id = side_set_ids[s];
    if (count < 0 || count > static_cast<int64_t>(num_elements) * nv)
      throw InputError(path, "side set " + set.name + " has " + std::to_string(count) +
                                 " entries; the mesh has " + std::to_string(num_elements) +
                                 " elements of " + std::to_string(nv) + " sides");
    set.elements.resize(count);
    set.sides.resize(count);
    if (count > 0)
      reader.check(ex_get_set(exoid, EX_SIDE_SET, set.id, set.elements.data(), set.sides.data()),
                   "ex_get_set");
    for (int i = 0; i < count; ++i) {
      const int element = set.elements[i], side = set.sides[i];
      if (element < 1 || element > num_elements || side < 1 || side > nv)
        throw InputError(path, "side set " + set.name + " has side " + std::to_string(side) +
                                   " of element " + std::to_string(element) + "; the mesh has " +
                                   std::to_string(num_elements) + " elements of " +
                                   std::to_string(nv) + " sides");
      set.elements[i] = element - 1;
      set.sides[i] = flipped[element - 1] ? flippedSide(side - 1, nv) : side - 1;
    }
    mesh.side_sets.push_back(std::move(set));
  }

  return std::move(assembled.mesh);
}

}  // namespace argine
